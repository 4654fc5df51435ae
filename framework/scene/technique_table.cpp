// The rows of the technique table (technique.h), one per technique, in the order `render
// --technique all`, the study and the contact sheet list them. Adding a technique is one row here
// and its GLSL file under shaders/techniques/ (docs/architecture.md says which files else).
#include "technique.h"

#include <cmath>

namespace sl {
namespace {

using F = FilterKind;

// Bias parameters shared by the depth-comparing rows (hard, pcf, pcss). Units: relative depth
// for the constant, shadow-map texels for the slope and the normal offset.
std::vector<TechniqueParameter> depthBiasParameters() {
    return {
        {.name = "constantBias", .defaultValue = 5e-4, .min = 0.0, .max = 0.1,
         .meaning = "constant bias subtracted from the receiver's relative depth"},
        {.name = "slopeBias", .defaultValue = 1.0, .min = 0.0, .max = 16.0,
         .meaning = "slope-scaled bias: texels of depth change across one texel at the "
                    "receiver's slope"},
        {.name = "normalOffset", .defaultValue = 0.0, .min = 0.0, .max = 8.0,
         .meaning = "normal-offset bias: the receiver moves along its normal by this many texels"},
    };
}

template <class T>
std::vector<T> operator+(std::vector<T> a, const std::vector<T>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The clear values (the store of relative depth 1) of the built-in stores other than depth.
std::vector<glm::vec4> clearVsm(const ShadowEffect&) { return {glm::vec4(1, 1, 0, 0)}; }

std::vector<glm::vec4> clearEvsm(const ShadowEffect& fx) {
    const bool negative = techniqueRow(fx.technique).store == StoreKind::Evsm4;
    const double cp = clampedWarpExponent(techniqueParameter(fx, "positiveExponent"));
    const double cn = negative ? clampedWarpExponent(techniqueParameter(fx, "negativeExponent")) : 0.0;
    // z' = 2z - 1 = 1 at relative depth 1.
    return {glm::vec4(float(std::exp(cp)), float(std::exp(2 * cp)), float(-std::exp(-cn)),
                      float(std::exp(-2 * cn)))};
}

std::vector<glm::vec4> clearCsm(const ShadowEffect& fx) {
    const int terms = int(techniqueParameter(fx, "terms"));
    std::vector<glm::vec4> layers(size_t((terms + 1) / 2), glm::vec4(0.0f));
    for (int k = 1; k <= terms; ++k) {
        const double c = M_PI * (2 * k - 1);
        glm::vec4& l = layers[size_t((k - 1) / 2)];
        const int o = (k - 1) % 2 * 2;
        l[o] = float(std::cos(c));
        l[o + 1] = float(std::sin(c));
    }
    return layers;
}

std::vector<glm::vec4> clearMoments16(const ShadowEffect&) {
    return {glm::vec4(quantizeMoments16(glm::dvec4(1.0)))};
}

std::vector<TechniqueRow> makeTable() {
    const std::vector<F> any = {F::Gaussian, F::Sat, F::None};
    const std::vector<TechniqueParameter> vsmParameters = {
        {.name = "minVariance", .defaultValue = 1e-5, .min = 0.0, .max = 0.1,
         .meaning = "lower bound of σ²"},
        {.name = "bleedReduction", .defaultValue = 0.18, .min = 0.0, .max = 0.99,
         .meaning = "light-bleeding reduction: lit fractions below it become 0"}};
    const TechniqueParameter positiveExponent = {
        .name = "positiveExponent", .defaultValue = 40.0, .min = 0.0, .max = 100.0,
        .meaning = "c+ of exp(c+ z'), clamped to 42 (float32)"};
    const std::vector<TechniqueParameter> evsmBounds = {
        {.name = "minVariance", .defaultValue = 1e-7, .min = 0.0, .max = 0.1,
         .meaning = "lower bound of σ², in depth units squared (scaled by the warp's slope)"},
        {.name = "bleedReduction", .defaultValue = 0.0, .min = 0.0, .max = 0.99,
         .meaning = "as for vsm"}};
    return {
        {.name = "hard", .summary = "depth compare, one tap", .stored = "depth z",
         .filters = {F::None}, .file = "techniques/hard.glsl", .store = StoreKind::Depth,
         .parameters = depthBiasParameters()},
        {.name = "second-depth", .summary = "midpoint of first and second depth",
         .stored = "z1; the peeling pass z2 (lighting: (z1 + z2) / 2)", .filters = {F::None},
         .secondDepth = true, .file = "techniques/second_depth.glsl", .store = StoreKind::Depth,
         .parameters = {{.name = "peelEpsilon", .defaultValue = 1e-5, .min = 0.0, .max = 0.01,
                         .meaning = "a second surface lies at least this far (relative depth) "
                                    "behind the first"}}},
        {.name = "pcf", .summary = "percentage-closer filtering, kernel of the filter",
         .stored = "depth z", .filters = any, .filterInLighting = true,
         .file = "techniques/pcf.glsl", .store = StoreKind::Depth,
         .parameters = depthBiasParameters()},
        {.name = "pcss", .summary = "blocker search, penumbra from light size, PCF",
         .stored = "depth z", .filters = {F::None}, .blockerSearch = true,
         .file = "techniques/pcss.glsl", .store = StoreKind::Depth,
         .parameters = depthBiasParameters() +
                       std::vector<TechniqueParameter>{
                           {.name = "maxKernelTexels", .defaultValue = 48, .min = 1, .max = 256,
                            .meaning = "largest blocker search / PCF kernel, texels"}}},
        {.name = "vsm", .summary = "variance shadow maps (Chebyshev–Cantelli)", .stored = "(z, z²)",
         .channels = 2, .filters = any, .file = "techniques/vsm.glsl", .store = StoreKind::Vsm,
         .clear = clearVsm, .parameters = vsmParameters},
        {.name = "esm", .summary = "exponential shadow maps", .stored = "e^{c (z − 1)}",
         .filters = any, .file = "techniques/esm.glsl", .store = StoreKind::File,
         .parameters = {{.name = "exponent", .defaultValue = 80.0, .min = 1.0, .max = 80.0,
                         .meaning = "c of e^{c (z − 1)}, at most 80 (e^{-c} a normal float32): "
                                    "larger is sharper and leaks less light at contact"}}},
        {.name = "evsm2", .summary = "exponential VSM, positive warp",
         .stored = "(e^{c+z'}, e^{2c+z'})", .channels = 2, .filters = any,
         .file = "techniques/evsm2.glsl", .store = StoreKind::Evsm2, .clear = clearEvsm,
         .parameters = std::vector<TechniqueParameter>{positiveExponent} + evsmBounds},
        {.name = "evsm4", .summary = "exponential VSM, positive and negative warps",
         .stored = "(e^{c+z'}, e^{2c+z'}, -e^{-c-z'}, e^{-2c-z'})", .channels = 4,
         .filters = any, .file = "techniques/evsm4.glsl", .store = StoreKind::Evsm4,
         .clear = clearEvsm,
         .parameters = std::vector<TechniqueParameter>{
                           positiveExponent,
                           {.name = "negativeExponent", .defaultValue = 5.0, .min = 0.0,
                            .max = 100.0, .meaning = "c- of -exp(-c- z'), clamped to 42 (float32)"}} +
                       evsmBounds},
        {.name = "csm", .summary = "convolution shadow maps (Fourier series)",
         .stored = "(cos c_k z, sin c_k z), k = 1..M", .channels = 4,
         .grows = {.parameter = "terms", .channels = 2}, .filters = any,
         .file = "techniques/csm.glsl", .store = StoreKind::Csm, .clear = clearCsm,
         .parameters = {{.name = "terms", .defaultValue = 8, .min = 1, .max = 8, .integer = true,
                         .compileTime = true,
                         .meaning = "M, Fourier terms (2M channels, M/2 maps)"},
                        {.name = "damping", .defaultValue = 1.0, .min = 0.0, .max = 20.0,
                         .meaning = "α of the damping exp(-α (k/M)²) against ringing"},
                        {.name = "offset", .defaultValue = 0.03, .min = 0.0, .max = 0.5,
                         .meaning = "the test depth moves this far toward the light "
                                    "(self-shadowing)"},
                        {.name = "sharpen", .defaultValue = 3.0, .min = 1.0, .max = 16.0,
                         .meaning = "visibility v -> clamp(sharpen (v - 1/2) + 1/2)"}}},
        {.name = "msm4", .summary = "Hamburger 4MSM (the student stages)",
         .stored = "(z, z², z³, z⁴)", .channels = 4, .filters = {F::Gaussian, F::Sat, F::None},
         .msmStage = true, .perPixelSat = true, .file = "techniques/msm4.glsl",
         .store = StoreKind::Moments4},
        {.name = "msm4-hausdorff", .summary = "Hausdorff 4MSM (Peters & Klein)",
         .stored = "(z, z², z³, z⁴)", .channels = 4, .filters = any, .msmStage = true,
         .file = "techniques/msm4_hausdorff.glsl", .store = StoreKind::Moments4,
         .solvesStage = "its test for the Hausdorff case needs the canonical representation's "
                        "roots, the msm stage's solution"},
        {.name = "msm4-16bit", .summary = "4MSM, optimised quantised moments",
         .stored = "4×4-transformed (z, z², z³, z⁴) + offset, UNORM16", .channels = 4,
         .bitsPerChannel = 16, .filters = any, .msmStage = true,
         .file = "techniques/msm4_16bit.glsl", .store = StoreKind::Moments4_16bit,
         .clear = clearMoments16,
         .parameters = {{.name = "quantizedMomentBias", .defaultValue = 6e-5, .min = 0.0,
                         .max = 0.1,
                         .meaning = "α for 16-bit moments, toward the bias vector of the "
                                    "quantised case"}}},
        {.name = "msm-soft", .summary = "moment soft shadows (per-pixel SAT kernel)",
         .stored = "(z, z², z³, z⁴)", .channels = 4, .filters = {F::Sat}, .msmStage = true,
         .blockerSearch = true, .file = "techniques/msm_soft.glsl", .store = StoreKind::Moments4,
         .parameters = {{.name = "searchTexels", .defaultValue = 32, .min = 2, .max = 256,
                         .meaning = "blocker search box, texels"},
                        {.name = "maxKernelTexels", .defaultValue = 64, .min = 1, .max = 256,
                         .meaning = "largest filter box, texels"}},
         .solvesStage = "its blocker search needs the canonical representation's roots, the msm "
                        "stage's solution"},
    };
}

}  // namespace

const std::vector<TechniqueRow>& techniqueTable() {
    static const std::vector<TechniqueRow> table = [] {
        std::vector<TechniqueRow> rows = makeTable();
        for (size_t i = 0; i < rows.size(); ++i) rows[i].id = Technique(int(i));
        return rows;
    }();
    return table;
}

}  // namespace sl
