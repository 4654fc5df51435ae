// oiio_codec: libshadowlab_oiio.so, the only code that calls OpenImageIO (image_codec.h says
// why it is a module of its own). Rows are taken and given top first; flipping GL's bottom-first
// rows is image_io's business.
#include "image_codec.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <stdexcept>

// OIIO is the library's own alias for its versioned namespace (oiioversion.h, 2.4 and 3.x).
namespace {

OIIO::TypeDesc typeOf(sl::SampleType t) {
    switch (t) {
        case sl::SampleType::U8: return OIIO::TypeDesc::UINT8;
        case sl::SampleType::Half: return OIIO::TypeDesc::HALF;
        case sl::SampleType::Float: break;
    }
    return OIIO::TypeDesc::FLOAT;
}

void write(const std::string& path, int width, int height, int channels, const void* data,
           sl::SampleType dataType, sl::SampleType fileType, sl::Compression compression,
           bool bottomUp) {
    OIIO::ImageSpec spec(width, height, channels, typeOf(fileType));
    const bool fast = compression == sl::Compression::Fast;
    if (fileType != sl::SampleType::U8) {  // EXR
        spec.attribute("compression", fast ? "zip:1" : "zip");  // "zip:N": zlib level N
        if (channels == 1) spec.channelnames = {"Y"};
    } else if (fast) {
        // zlib level 1 and one row filter (Sub) instead of libpng's try-every-filter heuristic:
        // a 1024² preview 110 -> 60 ms, 2 % larger.
        spec.attribute("png:compressionLevel", 1);
        spec.attribute("png:filter", 16);  // PNG_FILTER_SUB
    }
    // OIIO stamps the current time unless DateTime is set; empty keeps files reproducible.
    spec.attribute("DateTime", "");
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error(path + ": " + OIIO::geterror());
    // Bottom-first rows: start at the last row and step back (OIIO takes negative strides).
    const OIIO::TypeDesc type = typeOf(dataType);
    const OIIO::stride_t row = OIIO::stride_t(width) * channels * OIIO::stride_t(type.size());
    const char* first =
        static_cast<const char*>(data) + (bottomUp && height > 0 ? row * (height - 1) : 0);
    if (!out->open(path, spec) ||
        !out->write_image(type, first, OIIO::AutoStride, bottomUp ? -row : OIIO::AutoStride))
        throw std::runtime_error(path + ": " + out->geterror());
    out->close();
}

// Bottom-first rows, as write(): the file's first row goes to the last row, strides step back.
sl::Image read(const std::string& path, bool bottomUp) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error(path + ": " + OIIO::geterror());
    const auto& spec = in->spec();
    sl::Image img(spec.width, spec.height, spec.nchannels);
    const OIIO::stride_t row = OIIO::stride_t(spec.width) * spec.nchannels * OIIO::stride_t(sizeof(float));
    char* first = reinterpret_cast<char*>(img.pixels.data()) +
                  (bottomUp && spec.height > 0 ? row * (spec.height - 1) : 0);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, first, OIIO::AutoStride,
                        bottomUp ? -row : OIIO::AutoStride))
        throw std::runtime_error(path + ": " + in->geterror());
    return img;
}

sl::ImageFigures compare(const sl::Image& a, const sl::Image& b) {
    OIIO::ImageSpec spec(a.width, a.height, a.channels, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf A(spec, const_cast<float*>(a.pixels.data())),
        B(spec, const_cast<float*>(b.pixels.data()));
    const auto cr = OIIO::ImageBufAlgo::compare(A, B, 1e-3f, 1e-4f);
    return {cr.meanerror, cr.rms_error, cr.maxerror, cr.PSNR};
}

// Labels need OIIO built with FreeType and the DejaVu font; without them the grid stays
// unlabelled.
void contactSheet(const std::string& path, const std::vector<std::string>& files,
                  const std::vector<std::string>& labels, int columns) {
    std::vector<OIIO::ImageBuf> images;
    int w = 0, h = 0;
    for (const auto& f : files) {
        images.emplace_back(f);
        if (!images.back().read(0, 0, true, OIIO::TypeDesc::UINT8))
            throw std::runtime_error(f + ": " + images.back().geterror());
        w = std::max(w, images.back().spec().width);
        h = std::max(h, images.back().spec().height);
    }
    const int band = 28, pad = 4;
    const int rows = (int(files.size()) + columns - 1) / columns;
    OIIO::ImageSpec spec(columns * (w + pad) + pad, rows * (h + band + pad) + pad, 3,
                         OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf sheet(spec);
    const float bg[3] = {0.1f, 0.1f, 0.12f}, white[3] = {1, 1, 1};
    OIIO::ImageBufAlgo::fill(sheet, bg);
    for (size_t i = 0; i < files.size(); ++i) {
        const int x = pad + int(i % columns) * (w + pad);
        const int y = pad + int(i / columns) * (h + band + pad);
        OIIO::ImageBufAlgo::paste(sheet, x, y + band, 0, 0, images[i]);
        if (i < labels.size() && !labels[i].empty())
            OIIO::ImageBufAlgo::render_text(sheet, x + 4, y + band - 8, labels[i], 18, "DejaVuSans", white);
    }
    if (!sheet.write(path)) throw std::runtime_error(path + ": " + sheet.geterror());
}

const char* version() { return OIIO_VERSION_STRING; }

const sl::ImageCodec kCodec = {write, read, compare, contactSheet, version};

}  // namespace

extern "C" __attribute__((visibility("default"))) const sl::ImageCodec* shadowlabImageCodec() {
    return &kCodec;
}
