// The technique table (see technique.h) and the checks that keep a scene within its row.
#include "technique.h"

#include "scene_limits.h"

#include <GL/glcorearb.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sl {
namespace {

using F = FilterKind;

// Bias parameters shared by the depth-comparing rows (hard, pcf, pcss). Units: relative depth
// for the constant, shadow-map texels for the slope and the normal offset.
std::vector<TechniqueParameter> depthBiasParameters() {
    return {
        {"constantBias", 5e-4, 0.0, 0.1, false, false,
         "constant bias subtracted from the receiver's relative depth"},
        {"slopeBias", 1.0, 0.0, 16.0, false, false,
         "slope-scaled bias: texels of depth change across one texel at the receiver's slope"},
        {"normalOffset", 0.0, 0.0, 8.0, false, false,
         "normal-offset bias: the receiver moves along its normal by this many texels"},
    };
}

// Rows are listed positionally up to their parameters; `solvesStage`, set on two rows below,
// is left to its default elsewhere.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
std::vector<TechniqueRow> makeTable() {
    const std::vector<F> any = {F::Gaussian, F::Sat, F::None};
    std::vector<TechniqueRow> t;
    t.push_back({Technique::Hard, "hard", "depth compare, one tap", "depth z", 1, 32, {F::None},
                 false, false, false, false, "techniques/hard.glsl", "SL_TECHNIQUE_HARD",
                 "SL_STORE_DEPTH", depthBiasParameters()});
    t.push_back({Technique::SecondDepth, "second-depth", "midpoint of first and second depth",
                 "z1; the peeling pass z2 (lighting: (z1 + z2) / 2)", 1, 32, {F::None}, false, false, true, false,
                 "techniques/second_depth.glsl", "SL_TECHNIQUE_SECOND_DEPTH", "SL_STORE_DEPTH",
                 {{"peelEpsilon", 1e-5, 0.0, 0.01, false, false,
                   "a second surface lies at least this far (relative depth) behind the first"}}});
    t.push_back({Technique::Pcf, "pcf", "percentage-closer filtering, kernel of the filter",
                 "depth z", 1, 32, any, true, false, false, false, "techniques/pcf.glsl",
                 "SL_TECHNIQUE_PCF", "SL_STORE_DEPTH", depthBiasParameters()});
    {
        auto p = depthBiasParameters();
        p.push_back({"maxKernelTexels", 48, 1, 256, false, false,
                     "largest blocker search / PCF kernel, texels"});
        t.push_back({Technique::Pcss, "pcss", "blocker search, penumbra from light size, PCF",
                     "depth z", 1, 32, {F::None}, false, false, false, true,
                     "techniques/pcss.glsl", "SL_TECHNIQUE_PCSS", "SL_STORE_DEPTH", p});
    }
    t.push_back({Technique::Vsm, "vsm", "variance shadow maps (Chebyshev–Cantelli)", "(z, z²)", 2,
                 32, any, false, false, false, false, "techniques/vsm.glsl", "SL_TECHNIQUE_VSM",
                 "SL_STORE_VSM",
                 {{"minVariance", 1e-5, 0.0, 0.1, false, false, "lower bound of σ²"},
                  {"bleedReduction", 0.18, 0.0, 0.99, false, false,
                   "light-bleeding reduction: lit fractions below it become 0"}}});
    const std::vector<TechniqueParameter> evsmCommon = {
        {"positiveExponent", 40.0, 0.0, 100.0, false, false,
         "c+ of exp(c+ z'), clamped to 42 (float32)"},
        {"minVariance", 1e-7, 0.0, 0.1, false, false,
         "lower bound of σ², in depth units squared (scaled by the warp's slope)"},
        {"bleedReduction", 0.0, 0.0, 0.99, false, false, "as for vsm"}};
    t.push_back({Technique::Evsm2, "evsm2", "exponential VSM, positive warp", "(e^{c+z'}, e^{2c+z'})",
                 2, 32, any, false, false, false, false, "techniques/evsm2.glsl",
                 "SL_TECHNIQUE_EVSM2", "SL_STORE_EVSM2", evsmCommon});
    {
        auto p = evsmCommon;
        p.insert(p.begin() + 1, {"negativeExponent", 5.0, 0.0, 100.0, false, false,
                                 "c- of -exp(-c- z'), clamped to 42 (float32)"});
        t.push_back({Technique::Evsm4, "evsm4", "exponential VSM, positive and negative warps",
                     "(e^{c+z'}, e^{2c+z'}, -e^{-c-z'}, e^{-2c-z'})", 4, 32, any, false, false,
                     false, false, "techniques/evsm4.glsl", "SL_TECHNIQUE_EVSM4",
                     "SL_STORE_EVSM4", p});
    }
    t.push_back({Technique::Csm, "csm", "convolution shadow maps (Fourier series)",
                 "(cos c_k z, sin c_k z), k = 1..M", 4, 32, any, false, false, false, false,
                 "techniques/csm.glsl", "SL_TECHNIQUE_CSM", "SL_STORE_CSM",
                 {{"terms", 8, 1, 8, true, true, "M, Fourier terms (2M channels, M/2 maps)"},
                  {"damping", 1.0, 0.0, 20.0, false, false,
                   "α of the damping exp(-α (k/M)²) against ringing"},
                  {"offset", 0.03, 0.0, 0.5, false, false,
                   "the test depth moves this far toward the light (self-shadowing)"},
                  {"sharpen", 3.0, 1.0, 16.0, false, false,
                   "visibility v -> clamp(sharpen (v - 1/2) + 1/2)"}}});
    t.push_back({Technique::Msm4, "msm4", "Hamburger 4MSM (the student stages)",
                 "(z, z², z³, z⁴)", 4, 32, {F::Gaussian, F::Sat, F::None}, false, true, false,
                 false, "techniques/msm4.glsl", "SL_TECHNIQUE_MSM4", "SL_STORE_MOMENTS4", {}});
    t.push_back({Technique::Msm4Hausdorff, "msm4-hausdorff", "Hausdorff 4MSM (Peters & Klein)",
                 "(z, z², z³, z⁴)", 4, 32, any, false, true, false, false,
                 "techniques/msm4_hausdorff.glsl", "SL_TECHNIQUE_MSM4_HAUSDORFF",
                 "SL_STORE_MOMENTS4", {}});
    t.back().solvesStage =
        "its test for the Hausdorff case needs the canonical representation's roots, the msm "
        "stage's solution";
    t.push_back({Technique::Msm4_16bit, "msm4-16bit", "4MSM, optimised quantised moments",
                 "4×4-transformed (z, z², z³, z⁴) + offset, UNORM16", 4, 16, any, false, true,
                 false, false, "techniques/msm4_16bit.glsl", "SL_TECHNIQUE_MSM4_16BIT",
                 "SL_STORE_MOMENTS4_16BIT",
                 {{"quantizedMomentBias", 6e-5, 0.0, 0.1, false, false,
                   "α for 16-bit moments, toward the bias vector of the quantised case"}}});
    t.push_back({Technique::MsmSoft, "msm-soft", "moment soft shadows (per-pixel SAT kernel)",
                 "(z, z², z³, z⁴)", 4, 32, {F::Sat}, false, true, false, true,
                 "techniques/msm_soft.glsl", "SL_TECHNIQUE_MSM_SOFT", "SL_STORE_MOMENTS4",
                 {{"searchTexels", 32, 2, 256, false, false, "blocker search box, texels"},
                  {"maxKernelTexels", 64, 1, 256, false, false, "largest filter box, texels"}}});
    t.back().solvesStage =
        "its blocker search needs the canonical representation's roots, the msm stage's solution";
    return t;
}
#pragma GCC diagnostic pop

std::string names(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ", \"" : "\"") + items[i] + "\"";
    return out;
}

const TechniqueParameter* findParameter(const TechniqueRow& row, const std::string& name) {
    for (const auto& p : row.parameters)
        if (p.name == name) return &p;
    return nullptr;
}

std::vector<std::string> parameterNames(const TechniqueRow& row) {
    std::vector<std::string> out;
    for (const auto& p : row.parameters) out.push_back(p.name);
    return out;
}

// "" if `value` is fine for `p`, else what was expected.
std::string checkValue(const TechniqueParameter& p, double value) {
    char buf[160];
    const bool ok = std::isfinite(value) && value >= p.min && value <= p.max &&
                    (!p.integer || value == std::floor(value));
    if (ok) return "";
    std::snprintf(buf, sizeof buf, "%s in [%g, %g]", p.integer ? "an integer" : "a number", p.min,
                  p.max);
    return buf;
}

std::string filterNames(const TechniqueRow& row) {
    std::vector<std::string> out;
    for (FilterKind f : row.filters) out.push_back(toString(f));
    return names(out);
}

bool allows(const TechniqueRow& row, FilterKind f) {
    return std::find(row.filters.begin(), row.filters.end(), f) != row.filters.end();
}

}  // namespace

bool techniqueInKit(const TechniqueRow& row, const std::string& shaders) {
    return std::ifstream(shaders + "/" + row.lightingFile).good();
}

const std::vector<TechniqueRow>& techniqueTable() {
    static const std::vector<TechniqueRow> table = makeTable();
    return table;
}

const TechniqueRow& techniqueRow(Technique t) {
    const auto& table = techniqueTable();
    const size_t i = size_t(t);
    if (i >= table.size() || table[i].id != t) throw std::logic_error("technique table out of order");
    return table[i];
}

std::vector<std::string> techniqueNames() {
    std::vector<std::string> out;
    for (const auto& row : techniqueTable()) out.push_back(row.name);
    return out;
}

Technique techniqueFromName(const std::string& name) {
    for (const auto& row : techniqueTable())
        if (row.name == name) return row.id;
    throw std::invalid_argument("unknown technique \"" + name + "\": expected one of " +
                                names(techniqueNames()));
}

const char* toString(Technique t) { return techniqueRow(t).name.c_str(); }

double techniqueParameter(const ShadowEffect& fx, const std::string& name) {
    const TechniqueRow& row = techniqueRow(fx.technique);
    const TechniqueParameter* p = findParameter(row, name);
    if (!p)
        throw std::invalid_argument("technique \"" + row.name + "\" has no parameter \"" + name +
                                    "\"");
    auto it = fx.parameters.find(name);
    return it != fx.parameters.end() ? it->second : p->defaultValue;
}

std::vector<std::pair<std::string, double>> resolvedParameters(const ShadowEffect& fx) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& p : techniqueRow(fx.technique).parameters)
        out.emplace_back(p.name, techniqueParameter(fx, p.name));
    return out;
}

MapLayout mapLayout(const ShadowEffect& fx) {
    const TechniqueRow& row = techniqueRow(fx.technique);
    MapLayout m;
    m.channels = row.channels;
    m.layers = 1;
    if (row.id == Technique::Csm) m.layers = (int(techniqueParameter(fx, "terms")) + 1) / 2;
    const bool filtered = !row.filterInLighting && fx.filter != FilterKind::None;
    static const unsigned f32[5] = {0, GL_R32F, GL_RG32F, 0, GL_RGBA32F};
    static const char* n32[5] = {"", "R32F", "RG32F", "", "RGBA32F"};
    if (row.bitsPerChannel == 16) {
        m.glFormat = GL_RGBA16;
        m.formatName = "RGBA16";
        m.bytesPerTexel = 8;
    } else if (filtered) {
        m.glFormat = GL_RGBA32F;
        m.formatName = "RGBA32F";
        m.bytesPerTexel = 16;
    } else {
        m.glFormat = f32[m.channels];
        m.formatName = n32[m.channels];
        m.bytesPerTexel = 4 * m.channels;
    }
    return m;
}

std::vector<std::string> techniqueDefines(const ShadowEffect& fx) {
    const TechniqueRow& row = techniqueRow(fx.technique);
    std::vector<std::string> d = {row.define, row.storeDefine,
                                  "SL_MAP_LAYERS=" + std::to_string(mapLayout(fx).layers)};
    for (const auto& p : row.parameters)
        if (p.compileTime)
            d.push_back("SL_PARAM_" + p.name + "=" + std::to_string(int(techniqueParameter(fx, p.name))));
    if (row.msmStage) d.push_back("SL_STAGE_MSM");
    if (fx.filter == FilterKind::Gaussian) d.push_back("SL_FILTER_GAUSSIAN");
    if (fx.filter == FilterKind::Sat) d.push_back("SL_FILTER_SAT");
    if (fx.filter == FilterKind::Sat && fx.satPerPixel) d.push_back("SL_SAT_PER_PIXEL");
    for (const std::string& limit : limitDefines()) d.push_back(limit);
    return d;
}

void validateTechnique(ShadowEffect& fx, bool filterDeclared, const nlohmann::json* parameters,
                       const std::string& file, const std::string& pointer) {
    const TechniqueRow& row = techniqueRow(fx.technique);
    auto fail = [&](const std::string& ptr, const std::string& expected, const std::string& found) {
        throw SceneError(file + ": " + ptr + ": expected " + expected + ", found " + found);
    };
    if (!allows(row, fx.filter)) {
        if (filterDeclared)
            fail(pointer + "/filter/type",
                 "one of " + filterNames(row) + " for technique \"" + row.name + "\"",
                 std::string("\"") + toString(fx.filter) + "\"");
        fx.filter = row.filters.front();
    }
    fx.parameters.clear();
    if (!parameters) return;
    if (!parameters->is_object())
        fail(pointer + "/parameters", "an object of numbers (parameters of \"" + row.name + "\")",
             parameters->dump());
    for (const auto& item : parameters->items()) {
        const std::string ptr = pointer + "/parameters/" + item.key();
        const TechniqueParameter* p = findParameter(row, item.key());
        if (!p)
            fail(ptr,
                 row.parameters.empty()
                     ? "no parameters (technique \"" + row.name + "\" has none)"
                     : "one of the parameters " + names(parameterNames(row)) + " of technique \"" +
                           row.name + "\"",
                 "unknown key \"" + item.key() + "\"");
        if (!item.value().is_number())
            fail(ptr, checkValue(*p, NAN), item.value().dump());
        const double v = item.value().get<double>();
        if (std::string e = checkValue(*p, v); !e.empty()) fail(ptr, e, item.value().dump());
        fx.parameters[p->name] = v;
    }
}

void overrideTechnique(ShadowEffect& fx, Technique t,
                       const std::vector<std::pair<std::string, double>>& parameters) {
    const TechniqueRow& row = techniqueRow(t);
    // The scene's own technique keeps the scene's parameters (the given ones change them);
    // another technique starts from its row's defaults.
    if (t != fx.technique) fx.parameters.clear();
    fx.technique = t;
    if (!allows(row, fx.filter)) fx.filter = row.filters.front();
    // A per-pixel SAT box is msm4's lighting (satKernelTexels); others keep the search box.
    if (t != Technique::Msm4) fx.satPerPixel = false;
    for (const auto& [name, value] : parameters) {
        const TechniqueParameter* p = findParameter(row, name);
        if (!p)
            throw std::invalid_argument(
                "technique \"" + row.name + "\" has no parameter \"" + name + "\"" +
                (row.parameters.empty() ? "" : " (it has " + names(parameterNames(row)) + ")"));
        if (std::string e = checkValue(*p, value); !e.empty())
            throw std::invalid_argument("technique \"" + row.name + "\": parameter \"" + name +
                                        "\": expected " + e);
        fx.parameters[name] = value;
    }
}

std::pair<Technique, std::vector<std::pair<std::string, double>>> parseTechniqueSpec(
    const std::string& spec) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t i = 0; i <= spec.size(); ++i)
        if (i == spec.size() || spec[i] == ':') {
            parts.push_back(spec.substr(start, i - start));
            start = i + 1;
        }
    const Technique t = techniqueFromName(parts.front());
    std::vector<std::pair<std::string, double>> params;
    for (size_t i = 1; i < parts.size(); ++i) {
        const size_t eq = parts[i].find('=');
        char* end = nullptr;
        const double v = eq == std::string::npos ? NAN : std::strtod(parts[i].c_str() + eq + 1, &end);
        if (eq == std::string::npos || !end || *end != '\0' || end == parts[i].c_str() + eq + 1)
            throw std::invalid_argument("technique spec \"" + spec +
                                        "\": expected name=number after ':', found \"" +
                                        parts[i] + "\"");
        params.emplace_back(parts[i].substr(0, eq), v);
    }
    return {t, params};
}

double clampedWarpExponent(double c) { return std::min(c, 42.0); }

glm::dvec4 quantizeMoments16(const glm::dvec4& b) {
    static const double M[4][4] = {  // q_j = Σ_i b_i M[i][j] (Peters et al. 2015)
        {-2.07224649, 13.7948857237, 0.105877704, 9.7924062118},
        {32.23703778, -59.4683975703, -1.9077466311, -33.7652110555},
        {-68.571074599, 82.0359750338, 9.3496555107, 47.9456096605},
        {39.3703274134, -35.364903257, -6.6543490743, -23.9728048165}};
    glm::dvec4 q(0.0);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) q[j] += b[i] * M[i][j];
    q.x += 0.035955884801;
    return q;
}

glm::dvec4 dequantizeMoments16(const glm::dvec4& qIn) {
    static const double N[4][4] = {
        {0.2227744146, 0.1549679261, 0.1451988946, 0.163127443},
        {0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266},
        {0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497},
        {0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734}};
    glm::dvec4 q = qIn;
    q.x -= 0.035955884801;
    glm::dvec4 b(0.0);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) b[j] += q[i] * N[i][j];
    return b;
}

std::vector<glm::vec4> shadowClearValues(const ShadowEffect& fx) {
    const TechniqueRow& row = techniqueRow(fx.technique);
    const std::string& s = row.storeDefine;
    if (s == "SL_STORE_VSM") return {glm::vec4(1, 1, 0, 0)};
    if (s == "SL_STORE_EVSM2" || s == "SL_STORE_EVSM4") {
        const double cp = clampedWarpExponent(techniqueParameter(fx, "positiveExponent"));
        const double cn = s == "SL_STORE_EVSM4"
                              ? clampedWarpExponent(techniqueParameter(fx, "negativeExponent"))
                              : 0.0;
        // z' = 2z - 1 = 1 at relative depth 1.
        return {glm::vec4(float(std::exp(cp)), float(std::exp(2 * cp)), float(-std::exp(-cn)),
                          float(std::exp(-2 * cn)))};
    }
    if (s == "SL_STORE_CSM") {
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
    if (s == "SL_STORE_MOMENTS4_16BIT") return {glm::vec4(quantizeMoments16(glm::dvec4(1.0)))};
    return {glm::vec4(1.0f)};  // depth 1; moments (1, 1, 1, 1)
}

}  // namespace sl
