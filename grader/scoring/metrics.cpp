// metrics: the per-texel tolerances and the Hausdorff-style image metric (metrics.h), plus
// OpenImageIO's compare figures, which the report shows but the score does not use: a mean
// or PSNR cannot tell "1 pixel off along every edge" (fine) from "a wrong value in a small
// region" (a bug), a per-pixel pass fraction can.
#include "metrics.h"

#include "image_codec.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sl::grader {
namespace {

bool finiteTexel(const Image& img, size_t i) {
    for (int c = 0; c < img.channels; ++c)
        if (!std::isfinite(img.pixels[i * img.channels + c])) return false;
    return true;
}

std::string mismatch(const Image& s, const Image& r) {
    if (s.width == r.width && s.height == r.height && s.channels == r.channels) return "";
    auto d = [](const Image& i) {
        return std::to_string(i.width) + "x" + std::to_string(i.height) + "x" +
               std::to_string(i.channels);
    };
    return "image is " + d(s) + ", expected " + d(r);
}

// OIIO's figures on finite copies (NaN would poison every one of them; it is counted apart).
void oiioFigures(const Image& s, const Image& r, Comparison& out) {
    Image a = s, b = r;
    for (auto& v : a.pixels) if (!std::isfinite(v)) v = 0.0f;
    for (auto& v : b.pixels) if (!std::isfinite(v)) v = 0.0f;
    const ImageFigures f = imageCodec().compare(a, b);
    out.mean = f.mean;
    out.rms = f.rms;
    out.max = f.max;
    out.psnr = std::isfinite(f.psnr) ? f.psnr : 999.0;
}

void countCommon(const Image& s, const Image& r, Comparison& out) {
    const size_t n = size_t(s.width) * s.height;
    for (size_t i = 0; i < n; ++i) {
        if (!finiteTexel(s, i)) ++out.nonFinite;
        if (s.stubTexel(i) && !r.stubTexel(i)) ++out.stubTexels;
    }
}

}  // namespace

nlohmann::json Comparison::toJson() const {
    nlohmann::json j = {{"fraction_within_tolerance", fraction},
                        {"non_finite", nonFinite},
                        {"stub_texels", stubTexels},
                        {"oiio", {{"mean", mean}, {"rms", rms}, {"max", max}, {"psnr", psnr}}}};
    if (worstX >= 0)
        j["worst_texel"] = {{"x", worstX}, {"y", worstY}, {"channel", worstChannel},
                            {"value", std::isfinite(worstValue) ? nlohmann::json(worstValue) : nlohmann::json(nullptr)},
                            {"expected", worstExpected}, {"error_over_tolerance", std::min(worst, 1e30)}};
    if (!error.empty()) j["error"] = error;
    return j;
}

Comparison compareMoments(const Image& s, const Image& r, double absTol, double relTol,
                          const std::vector<double>& extra) {
    Comparison out;
    out.error = mismatch(s, r);
    if (!out.error.empty()) return out;
    const size_t n = size_t(s.width) * s.height;
    out.errorMap = Image(s.width, s.height, 1);
    size_t ok = 0;
    for (size_t i = 0; i < n; ++i) {
        double worst = 0.0;  // error / tolerance, worst channel
        for (int c = 0; c < s.channels; ++c) {
            const double sv = s.pixels[i * s.channels + c], rv = r.pixels[i * r.channels + c];
            const double tol = absTol + relTol * std::fabs(rv) + (c < int(extra.size()) ? extra[c] : 0);
            const double e = std::isfinite(sv) ? std::fabs(sv - rv) / tol
                                               : std::numeric_limits<double>::infinity();
            worst = std::max(worst, e);
            if (e > out.worst || out.worstX < 0) {
                out.worst = e;
                out.worstX = int(i % size_t(s.width));
                out.worstY = int(i / size_t(s.width));
                out.worstChannel = c;
                out.worstValue = sv;
                out.worstExpected = rv;
            }
        }
        out.errorMap.pixels[i] = float(std::min(worst, 1e6));
        if (worst <= 1.0) ++ok;
    }
    out.fraction = n ? double(ok) / double(n) : 0.0;
    countCommon(s, r, out);
    oiioFigures(s, r, out);
    return out;
}

Comparison compareImages(const Image& s, const Image& r, double tol) {
    Comparison out;
    out.error = mismatch(s, r);
    if (!out.error.empty()) return out;
    const int w = s.width, h = s.height, ch = s.channels;
    // d(a → b)(p): the smallest worst-channel difference between a(p) and b in p's 3×3.
    auto directed = [&](const Image& a, const Image& b, int x, int y) {
        double best = std::numeric_limits<double>::infinity();
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int qx = x + dx, qy = y + dy;
                if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                double worst = 0.0;
                for (int c = 0; c < ch; ++c) {
                    const double d = std::fabs(double(a.at(x, y, c)) - b.at(qx, qy, c));
                    worst = std::max(worst, std::isfinite(d) ? d : 1e30);
                }
                best = std::min(best, worst);
            }
        return best;
    };
    out.errorMap = Image(w, h, 1);
    size_t ok = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            double e = std::max(directed(s, r, x, y), directed(r, s, x, y)) / tol;
            if (!finiteTexel(s, i)) e = 1e6;
            out.errorMap.pixels[i] = float(std::min(e, 1e6));
            if (e <= 1.0) ++ok;
        }
    out.fraction = double(ok) / double(size_t(w) * h);
    countCommon(s, r, out);
    oiioFigures(s, r, out);
    return out;
}

}  // namespace sl::grader
