// image_io: writing and reading images with OpenImageIO, the PNG previews, and SHA-256.
#pragma once

#include "image.h"
#include "image_codec.h"

#include <filesystem>
#include <string>

namespace sl {

namespace fs = std::filesystem;

// EXR of float (or, for `stored` Half, half) samples: ZIP compression (Compact: zlib's default
// level, for files that are kept; Fast: level 1, for a render's outputs), no timestamp, so equal
// pixels give equal bytes. Throws std::runtime_error naming the file. Image files go through
// libshadowlab_oiio.so, loaded on first use (image_codec.h).
void writeExr(const Image& image, const fs::path& path, SampleType stored = SampleType::Float,
              Compression compression = Compression::Compact);
Image readImage(const fs::path& path);  // any format OIIO reads, converted to float

// 8-bit PNG of `image`'s first three channels (one channel: grey), clamped to [0, 1] after an
// sRGB encoding if `srgb`. Stub values (-1) and NaN are shown in magenta so that an
// unimplemented or broken stage is visible at a glance. Written with Compression::Fast.
void writePngPreview(const Image& image, const fs::path& path, bool srgb);

// SHA-256 in lowercase hex: of a file's bytes, and of a string (cache keys, scene digests).
std::string sha256File(const fs::path& path);
std::string sha256Hex(const std::string& data);
// Of an image's size, channel count and float samples: equal for equal pixels, whatever the
// file's encoder wrote around them (OpenEXR 3.1 and 3.2 compress the same pixels differently).
std::string sha256Pixels(const Image& image);

std::string imageLibraryVersion();  // OpenImageIO's, e.g. "2.4.7"

}  // namespace sl
