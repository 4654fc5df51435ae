// image_io: OpenImageIO output and input, previews, hashes (see image_io.h).
#include "image_io.h"

#include "codec_child.h"
#include "image_codec.h"

#include <dlfcn.h>
#include <openssl/evp.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace sl {
namespace {

// libshadowlab_oiio.so sits beside the program (build/shadowlab) or one folder up (the test
// binary in build/tests/).
const ImageCodec* loadCodec() {
    const char* name = "libshadowlab_oiio.so";
    std::error_code ec;
    const fs::path exeDir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    std::string tried, why;
    for (const fs::path& dir : {exeDir, exeDir.parent_path()}) {
        const fs::path candidate = dir / name;
        tried += (tried.empty() ? "" : ", ") + candidate.string();
        if (!fs::exists(candidate)) continue;
        // RTLD_LOCAL: OpenImageIO's libraries stay out of the program's symbol lookups.
        void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) { why = dlerror(); continue; }
        auto entry = reinterpret_cast<const ImageCodec* (*)()>(dlsym(module, "shadowlabImageCodec"));
        if (entry) return entry();
        why = candidate.string() + " has no shadowlabImageCodec";
    }
    throw std::runtime_error("cannot load the image reader/writer (" + std::string(name) +
                             ", built with the shadowlab program): tried " + tried +
                             (why.empty() ? "" : "; " + why) + ". Rebuild: ./kit demo");
}

}  // namespace

const ImageCodec& moduleCodec() {
    static const ImageCodec* codec = loadCodec();
    return *codec;
}

const ImageCodec& imageCodec() {
    // SHADOWLAB_CODEC=child: OpenImageIO stays out of this process (codec_child.h).
    static const ImageCodec* codec = codecInChild() ? &childCodec() : loadCodec();
    return *codec;
}

void writeExr(const Image& image, const fs::path& path, SampleType stored,
              Compression compression) {
    imageCodec().write(path.string(), image.width, image.height, image.channels,
                       image.pixels.data(), SampleType::Float, stored, compression, true);
}

Image readImage(const fs::path& path) {
    return imageCodec().read(path.string(), true);
}

void writePngPreview(const Image& image, const fs::path& path, bool srgb) {
    // 8-bit RGB in one pass, in the image's (bottom-first) row order; the codec flips.
    std::vector<unsigned char> bytes(size_t(image.width) * image.height * 3);
    bool anyBroken = false;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            bool broken = false;
            for (int c = 0; c < image.channels; ++c) {
                float v = image.at(x, y, c);
                broken |= !std::isfinite(v) || v == -1.0f;
            }
            anyBroken |= broken;
            unsigned char* out = &bytes[(size_t(y) * image.width + x) * 3];
            for (int c = 0; c < 3; ++c) {
                float v = image.at(x, y, std::min(c, image.channels - 1));
                if (srgb) v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
                v = broken ? (c == 1 ? 0.0f : 1.0f) : std::clamp(v, 0.0f, 1.0f);
                out[c] = static_cast<unsigned char>(std::lround(v * 255.0f));
            }
        }
    // Grey images stay single-channel unless magenta must show: keep every third byte.
    const int channels = (image.channels == 1 && !anyBroken) ? 1 : 3;
    if (channels == 1) {
        for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i)
            bytes[i] = bytes[i * 3];
        bytes.resize(size_t(image.width) * image.height);
    }
    imageCodec().write(path.string(), image.width, image.height, channels, bytes.data(),
                       SampleType::U8, SampleType::U8, Compression::Fast, true);
}

namespace {
std::string hexDigest(EVP_MD_CTX* ctx) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int len = 0;
    EVP_DigestFinal_ex(ctx, digest, &len);
    EVP_MD_CTX_free(ctx);
    static const char* hex = "0123456789abcdef";
    std::string s;
    for (unsigned i = 0; i < len; ++i) s += {hex[digest[i] >> 4], hex[digest[i] & 15]};
    return s;
}
}  // namespace

std::string sha256File(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path.string() + ": cannot be read");
    EVP_MD_CTX* ctx = EVP_MD_CTX_new();
    EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) EVP_DigestUpdate(ctx, buf, in.gcount());
    return hexDigest(ctx);
}

std::string sha256Pixels(const Image& image) {
    std::string data = std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                       std::to_string(image.channels) + ":";
    data.append(reinterpret_cast<const char*>(image.pixels.data()),
                image.pixels.size() * sizeof(float));
    return sha256Hex(data);
}

std::string imageLibraryVersion() { return imageCodec().version(); }

std::string sha256Hex(const std::string& data) {
    EVP_MD_CTX* ctx = EVP_MD_CTX_new();
    EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
    EVP_DigestUpdate(ctx, data.data(), data.size());
    return hexDigest(ctx);
}

}  // namespace sl
