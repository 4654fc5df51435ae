// raw_image.h: the grader's scratch image format between a worker and the grader.
#pragma once

#include "image.h"

#include <filesystem>

namespace sl::grader {

// "<name>.raw": a 16-byte header (magic, width, height, channels) and the float pixels as in
// memory (bottom row first). Workers' images live for one grade run only; compressing them
// into EXR and back cost more than the comparisons themselves.
void writeRaw(const Image& image, const std::filesystem::path& path);
Image readRaw(const std::filesystem::path& path);  // throws std::runtime_error

// A .raw file, or anything OpenImageIO reads (the goldens' EXRs).
Image readAnyImage(const std::filesystem::path& path);

}  // namespace sl::grader
