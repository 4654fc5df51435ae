// What follows from a technique's row (technique.h): lookups, the map's layout, the permutation
// defines, and the checks that keep a scene within its row. The rows: technique_table.cpp.
#include "technique.h"

#include "scene_limits.h"

#include <GL/glcorearb.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sl {
namespace {

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
    return std::ifstream(shaders + "/" + row.file).good();
}

const char* toString(StoreKind k) {
    switch (k) {
        case StoreKind::Depth: return "DEPTH";
        case StoreKind::Vsm: return "VSM";
        case StoreKind::Evsm2: return "EVSM2";
        case StoreKind::Evsm4: return "EVSM4";
        case StoreKind::Csm: return "CSM";
        case StoreKind::Moments4: return "MOMENTS4";
        case StoreKind::Moments4_16bit: return "MOMENTS4_16BIT";
        case StoreKind::File: return "FILE";
    }
    return "?";
}

std::vector<glm::vec4> clearToOne(const ShadowEffect&) { return {glm::vec4(1.0f)}; }

const TechniqueRow& techniqueRow(Technique t) {
    const auto& table = techniqueTable();
    const size_t i = size_t(t);
    if (i >= table.size()) throw std::logic_error("technique index past the table");
    return table[i];
}

std::string techniqueDefine(const TechniqueRow& row) {
    std::string d = "SL_TECHNIQUE_";
    for (char c : row.name) d += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
    return d;
}

std::string storeDefine(const TechniqueRow& row) {
    return std::string("SL_STORE_") + toString(row.store);
}

std::vector<std::string> techniqueNames() {
    std::vector<std::string> out;
    for (const auto& row : techniqueTable()) out.push_back(row.name);
    return out;
}

Technique techniqueFromName(const std::string& name) {
    const auto& table = techniqueTable();
    for (size_t i = 0; i < table.size(); ++i)
        if (table[i].name == name) return Technique(int(i));
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
    m.usedChannels = row.channels;
    if (*row.grows.parameter) {
        m.usedChannels = row.grows.channels * int(techniqueParameter(fx, row.grows.parameter));
        m.layers = (m.usedChannels + row.channels - 1) / row.channels;
    }
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
    std::vector<std::string> d = {techniqueDefine(row), storeDefine(row),
                                  "SL_TECHNIQUE_FILE=" + row.file,
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
    if (!row.perPixelSat) fx.satPerPixel = false;
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
    return techniqueRow(fx.technique).clear(fx);
}

}  // namespace sl
