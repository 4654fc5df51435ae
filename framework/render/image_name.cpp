// ImageName's one encoding (image_name.h): str() writes it, parse() reads it.
#include "image_name.h"

#include <cctype>

namespace sl {
namespace {

constexpr ImageKind kKinds[] = {ImageKind::DepthLadder, ImageKind::SatKernel, ImageKind::MomentsRaw,
                                ImageKind::MomentsFiltered, ImageKind::SecondDepth,
                                ImageKind::Sat, ImageKind::Final, ImageKind::Shadow,
                                ImageKind::RelativeDepth};

bool cameraImage(ImageKind k) {
    return k == ImageKind::Final || k == ImageKind::Shadow || k == ImageKind::RelativeDepth;
}

// Reads "_<tag><digits>" at the front of `rest` into `value`.
bool suffix(std::string_view& rest, std::string_view tag, int& value) {
    const std::string prefix = "_" + std::string(tag);
    if (rest.substr(0, prefix.size()) != prefix) return false;
    size_t i = prefix.size();
    if (i >= rest.size() || !std::isdigit(static_cast<unsigned char>(rest[i]))) return false;
    int v = 0;
    for (; i < rest.size() && std::isdigit(static_cast<unsigned char>(rest[i])) && v < 100000; ++i)
        v = v * 10 + (rest[i] - '0');
    value = v;
    rest.remove_prefix(i);
    return true;
}

}  // namespace

const char* toString(ImageKind k) {
    switch (k) {
        case ImageKind::Final: return "final";
        case ImageKind::Shadow: return "shadow";
        case ImageKind::MomentsRaw: return "moments_raw";
        case ImageKind::MomentsFiltered: return "moments_filtered";
        case ImageKind::Sat: return "sat";
        case ImageKind::SecondDepth: return "second_depth";
        case ImageKind::DepthLadder: return "moments_raw_depth_ladder";
        case ImageKind::SatKernel: return "moments_filtered_kernel";
        case ImageKind::RelativeDepth: return "relative_depth";
    }
    return "?";
}

std::string ImageName::str() const {
    std::string s = (msmIsolated ? "msm_" : "") + std::string(toString(kind));
    if (cameraImage(kind)) return camera.empty() ? s : s + "_" + camera;
    if (kind == ImageKind::DepthLadder || kind == ImageKind::SatKernel) return s;
    if (light >= 0) s += "_light" + std::to_string(light);
    if (cascade > 0) s += "_cascade" + std::to_string(cascade);
    if (layer > 0) s += "_layer" + std::to_string(layer);
    return s;
}

std::optional<ImageName> ImageName::parse(std::string_view name) {
    ImageName n;
    if (name.substr(0, 4) == "msm_") {
        n.msmIsolated = true;
        name.remove_prefix(4);
    }
    for (ImageKind k : kKinds) {
        const std::string_view head = toString(k);
        if (name.substr(0, head.size()) != head) continue;
        std::string_view rest = name.substr(head.size());
        n.kind = k;
        if (cameraImage(k)) {
            if (rest.empty()) return n;
            if (rest.size() < 2 || rest[0] != '_') return std::nullopt;
            n.camera = std::string(rest.substr(1));
            return n;
        }
        if (k == ImageKind::DepthLadder || k == ImageKind::SatKernel)
            return rest.empty() ? std::optional(n) : std::nullopt;
        suffix(rest, "light", n.light);
        suffix(rest, "cascade", n.cascade);
        suffix(rest, "layer", n.layer);
        if (!rest.empty()) return std::nullopt;
        return n;
    }
    return std::nullopt;
}

bool isImage(std::string_view name, ImageKind kind) {
    const auto n = ImageName::parse(name);
    return n && n->kind == kind && !n->msmIsolated;
}

}  // namespace sl
