// image_codec: the part of image_io that needs OpenImageIO, behind a table of functions that a
// loadable module fills (framework/oiio/oiio_codec.cpp, libshadowlab_oiio.so next to the
// program). Debian's OpenImageIO pulls ~250 shared libraries (codecs, OpenCV, GDAL) whose
// loading costs ~0.5 s of CPU at every start; loaded on first use, a command that reads or
// writes no image file (help, info, probe, a grade's workers, most tests) never pays it.
#pragma once

#include "image.h"

#include <string>
#include <vector>

namespace sl {

enum class SampleType { U8, Half, Float };

// How hard the lossless compressor works. Compact: zlib's default level, for files that are
// kept (goldens, ground truth). Fast: zlib level 1 (PNG: also one row filter), for a render's
// outputs and previews and the grade report's images, written at every render (zlib was ~30 %
// of a render's CPU; the files grow ~7-10 %). Both are deterministic: equal pixels give equal
// bytes.
enum class Compression { Compact, Fast };

// OpenImageIO's comparison figures (ImageBufAlgo::compare) over every channel.
struct ImageFigures {
    double mean = 0, rms = 0, max = 0, psnr = 0;
};

struct ImageCodec {
    // Writes width × height × channels samples of `dataType`, stored as `fileType` (Half,
    // Float: EXR with zip compression, one channel named "Y"; U8: PNG). `data`'s rows are top
    // first, or bottom first (GL's order) if `bottomUp`: the file is top first either way,
    // without a flipped copy. No timestamp, so equal pixels give equal bytes. Throws
    // std::runtime_error naming the file.
    void (*write)(const std::string& path, int width, int height, int channels, const void* data,
                  SampleType dataType, SampleType fileType, Compression compression,
                  bool bottomUp);
    // Any format OpenImageIO reads, as float: rows top first, or bottom first (GL's order, as
    // Image holds them) if `bottomUp`, read into place without a flipped copy.
    Image (*read)(const std::string& path, bool bottomUp);
    ImageFigures (*compare)(const Image& a, const Image& b);
    // A grid of `columns` PNGs (8-bit), each under a label band ("" leaves it empty), as a PNG.
    void (*contactSheet)(const std::string& path, const std::vector<std::string>& images,
                         const std::vector<std::string>& labels, int columns);
    // OpenImageIO's version, e.g. "2.4.7" (goldens record it: its encoders' bytes differ).
    const char* (*version)();
};

// The module's table, loaded on first call (thread-safe). Throws std::runtime_error if the
// module is missing or does not load. With SHADOWLAB_CODEC=child: a child process's
// (codec_child.h).
const ImageCodec& imageCodec();
// The module itself, whatever SHADOWLAB_CODEC says (the codec child's own work).
const ImageCodec& moduleCodec();

}  // namespace sl

// The one symbol the module exports.
extern "C" const sl::ImageCodec* shadowlabImageCodec();
