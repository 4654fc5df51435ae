// golden_encoding: the precision a reference image is graded at, live or from the goldens. The
// goldens are committed, so they are kept small: moment maps stay float32 (their tolerance is
// relative and reaches 1e-4 near 0, below half's precision) with the mantissa rounded to
// kMomentMantissaBits bits, a relative error of 2^-16 that lets ZIP compress the low bits away;
// shadow and colour images are half floats (error <= 5e-4, 20x inside their tolerance). A live
// grade rounds the reference's images the same way before any stage reads or compares them, so
// a submission gets the same grade from a live reference as from goldens made on the same Mesa.
#pragma once

#include "image.h"

#include <string>

namespace sl::grader {

constexpr int kMomentMantissaBits = 15;

// v with its float32 mantissa rounded to `bits` bits (half up on the magnitude); NaN, Inf kept.
float roundMantissa(float v, int bits);

// v as a half float holds it (IEEE round to nearest even; beyond 65504: Inf), back as float.
float roundToHalf(float v);

// Whether the image of this name is stored as a moment map (float32, rounded mantissa: the
// moment maps and a camera's relative depth, whose zf the msm stage is sensitive to) or as
// half floats.
bool storedAsMoments(const std::string& imageName);

// Rounds every sample as the golden file of that name stores it.
void roundAsGolden(const std::string& imageName, Image& image);

}  // namespace sl::grader
