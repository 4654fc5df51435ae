// gaussian_cases: the Gaussian probe's named maps (see the header).
#include "gaussian_cases.h"

#include <random>
#include <stdexcept>

namespace sl {
namespace {

Image caseMap(const std::string& kind, int w, int h) {
    Image m(w, h, 4, 0.0f);
    if (kind == "impulse") {
        const float v[4] = {1.0f, 0.5f, 0.25f, 0.125f};
        for (int c = 0; c < 4; ++c) m.at(w / 2, h / 2, c) = v[c];
    } else if (kind == "edge") {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                m.at(x, y, 0) = x == w - 1 ? 1.0f : 0.0f;
                m.at(x, y, 1) = y == 0 ? 1.0f : 0.0f;
                m.at(x, y, 2) = x == 0 ? 1.0f : 0.0f;
                m.at(x, y, 3) = y == h - 1 ? 1.0f : 0.0f;
            }
    } else if (kind == "constant") {
        const float v[4] = {0.7f, 0.49f, 0.343f, 0.2401f};
        for (size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = v[i % 4];
    } else if (kind == "random") {
        std::mt19937 rng(uint32_t(1000 * w + h));
        std::uniform_real_distribution<float> d(0.0f, 1.0f);
        for (float& v : m.pixels) v = d(rng);
    } else {
        throw std::invalid_argument("no Gaussian case '" + kind +
                                    "' (impulse, edge, constant, random or all)");
    }
    return m;
}

}  // namespace

std::vector<std::string> gaussianCaseKinds() { return {"impulse", "edge", "constant", "random"}; }

std::vector<GaussianCase> gaussianCases(const std::string& kind, int width, int height) {
    std::vector<std::string> kinds = kind == "all" ? gaussianCaseKinds() : std::vector<std::string>{kind};
    std::vector<std::pair<int, int>> sizes = {{7, 5}, {67, 3}, {3, 67}, {1, 1}};
    if (width > 0 && height > 0) sizes = {{width, height}};
    std::vector<GaussianCase> out;
    for (const auto& k : kinds)
        for (auto [w, h] : sizes)
            out.push_back({k + "-" + std::to_string(w) + "x" + std::to_string(h), caseMap(k, w, h)});
    return out;
}

}  // namespace sl
