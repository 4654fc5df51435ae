// raw_image: see raw_image.h.
#include "raw_image.h"

#include "image_io.h"

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace sl::grader {

namespace {
constexpr std::int32_t kMagic = 0x57415253;  // "SRAW"
}

void writeRaw(const Image& image, const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary);
    const std::int32_t header[4] = {kMagic, image.width, image.height, image.channels};
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    out.write(reinterpret_cast<const char*>(image.pixels.data()),
              std::streamsize(image.pixels.size() * sizeof(float)));
    if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

Image readRaw(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::int32_t header[4] = {};
    in.read(reinterpret_cast<char*>(header), sizeof header);
    if (!in || header[0] != kMagic || header[1] <= 0 || header[2] <= 0 || header[3] <= 0 ||
        header[1] > 16384 || header[2] > 16384 || header[3] > 4)
        throw std::runtime_error(path.string() + ": not a grader image");
    Image img(header[1], header[2], header[3]);
    in.read(reinterpret_cast<char*>(img.pixels.data()),
            std::streamsize(img.pixels.size() * sizeof(float)));
    if (!in) throw std::runtime_error(path.string() + ": truncated");
    return img;
}

Image readAnyImage(const std::filesystem::path& path) {
    return path.extension() == ".raw" ? readRaw(path) : readImage(path);
}

}  // namespace sl::grader
