// golden_encoding: see golden_encoding.h.
#include "golden_encoding.h"

#include "image_name.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace sl::grader {

float roundMantissa(float v, int bits) {
    if (!std::isfinite(v)) return v;
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    const int drop = 23 - bits;
    const std::uint32_t half = 1u << (drop - 1);
    u = (u + half) & ~((1u << drop) - 1);  // round half up on the magnitude
    std::memcpy(&v, &u, 4);
    return v;
}

float roundToHalf(float v) {
    // The compiler's IEEE conversion: what OpenEXR's half (Imath) does to a float.
    return float(static_cast<_Float16>(v));
}

bool storedAsMoments(const std::string& imageName) {
    const auto parsed = ImageName::parse(imageName);
    return parsed && (parsed->moments() || parsed->kind == ImageKind::RelativeDepth);
}

void roundAsGolden(const std::string& imageName, Image& image) {
    if (storedAsMoments(imageName))
        for (float& v : image.pixels) v = roundMantissa(v, kMomentMantissaBits);
    else
        for (float& v : image.pixels) v = roundToHalf(v);
}

}  // namespace sl::grader
