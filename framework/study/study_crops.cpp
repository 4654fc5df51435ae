// study_crops: see study_crops.h.
#include "study_crops.h"

#include "image_io.h"

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

// The error map paints pixels the light does not reach 0.12 grey (error_metrics.h).
bool cropReached(const Image& error, int x, int y) {
    const float r = error.at(x, y, 0);
    return !(std::abs(r - 0.12f) < 0.01f && std::abs(error.at(x, y, 1) - r) < 0.01f &&
             std::abs(error.at(x, y, 2) - r) < 0.01f);
}

float cropGrey(const Image& im, int x, int y) { return im.at(x, y, 0); }

}  // namespace

std::vector<FailureCrop> writeFailureCrops(const fs::path& dir, const StudyRow& row,
                                           const std::string& truthPng, const std::string& name) {
    std::vector<FailureCrop> out;
    if (!fs::exists(dir / row.image) || !fs::exists(dir / row.errorMap) || !fs::exists(dir / truthPng))
        return out;
    const Image g = readImage(dir / row.image), truth = readImage(dir / truthPng),
                err = readImage(dir / row.errorMap);
    if (g.width != truth.width || g.height != truth.height || err.width != g.width) return out;
    const int w = g.width, h = g.height;
    const int win = std::max(8, std::min(w, h) / 4), step = std::max(1, win / 4);
    fs::create_directories(dir / "crops");
    for (const std::string kind : {"leak", "dark"}) {
        const float sign = kind == "leak" ? -1.0f : 1.0f;  // leak: G below the truth
        // The window with the largest sum of this kind's error over 0.1 (Image rows: bottom first).
        double best = 0;
        int bx = 0, by = 0, bn = 0;
        for (int y0 = 0; y0 + win <= h; y0 += step)
            for (int x0 = 0; x0 + win <= w; x0 += step) {
                double sum = 0;
                int n = 0;
                for (int y = y0; y < y0 + win; ++y)
                    for (int x = x0; x < x0 + win; ++x) {
                        if (!cropReached(err, x, y)) continue;
                        const float d = sign * (cropGrey(g, x, y) - cropGrey(truth, x, y));
                        if (d > 0.1f) { sum += d; ++n; }
                    }
                if (sum > best) { best = sum; bx = x0; by = y0; bn = n; }
            }
        if (bn == 0) continue;
        // [G | truth | error], each enlarged so a texel-sized artefact shows.
        const int zoom = std::max(2, 192 / win), gap = 4, cw = win * zoom;
        Image sheet(3 * cw + 2 * gap, cw, 3, 1.0f);
        const Image* panels[] = {&g, &truth, &err};
        for (int p = 0; p < 3; ++p)
            for (int y = 0; y < cw; ++y)
                for (int x = 0; x < cw; ++x)
                    for (int c = 0; c < 3; ++c) {
                        const Image& src = *panels[p];
                        sheet.at(p * (cw + gap) + x, y, c) =
                            src.at(bx + x / zoom, by + y / zoom, std::min(c, src.channels - 1));
                    }
        FailureCrop crop;
        crop.kind = kind;
        crop.file = "crops/" + name + "_" + kind + ".png";
        crop.meanError = best / bn;
        crop.x = bx;
        crop.y = h - by - win;  // from the top, as the PNGs show it
        crop.size = win;
        writePngPreview(sheet, dir / crop.file, false);
        out.push_back(crop);
    }
    return out;
}

}  // namespace sl
