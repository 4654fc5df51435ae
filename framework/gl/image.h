// Image: a float image in memory. Rows are stored bottom row first, as OpenGL reads them back;
// image files are written top row first (image_io flips), so pictures look upright.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sl {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  // width * height * channels

    Image() = default;
    Image(int w, int h, int c, float fill = 0.0f)
        : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, fill) {}

    float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const {
        return pixels[(std::size_t(y) * width + x) * channels + c];
    }
    bool empty() const { return pixels.empty(); }

    // The stub value: an unimplemented student stage writes -1 to every channel (student/*).
    // Texel i (x + y·width) holds it in every channel; every texel does (false if empty).
    bool stubTexel(std::size_t i) const {
        for (int c = 0; c < channels; ++c)
            if (pixels[i * channels + c] != -1.0f) return false;
        return true;
    }
    bool allStub() const {
        for (float v : pixels)
            if (v != -1.0f) return false;
        return !pixels.empty();
    }
};

}  // namespace sl
