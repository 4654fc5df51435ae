// catalogue_entries: what the two catalogue tests share — the entries of
// tests/submissions/catalogue.json, the libraries that mix an entry's files with reference/,
// and the reference renders of the public scenes (test_catalogue.cpp, test_catalogue_grade.cpp).
#pragma once

#include "depth_ladder.h"
#include "gl_test_support.h"
#include "oracles/moment_oracles.h"
#include "probe.h"
#include "sat_kernel_ladder.h"
#include "scene.h"
#include "shader_source.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

namespace sl {
namespace {

using json = nlohmann::json;

constexpr double u = 1.0 / (1 << 24);  // float32 unit roundoff
constexpr double kTexelTolerance = 1e-3;
constexpr double kMutantMaxAbs = 1e-2;
constexpr double kMutantMinFraction = 1e-3;
// How far (texels) a per-pixel SAT box may move between correct satKernelTexels (catalogue.json's
// sat_kernel_* alternatives against the reference, scenes/penumbra.json): measured 0.062 on
// Mesa 22.3.6, both on the earlier reference's table (sat_base), whose box averages are 5.7e-6
// off; twice that, as the grader's sat_kernel_abs (grader/rubric.json).
constexpr double kKernelSpread = 0.125;

struct Entry {
    std::string name, kind, stage, file;  // file: relative to tests/submissions/
    std::vector<std::string> files;       // the submitted files: the folder's, + a SAT partner from sat_base/
    std::vector<std::string> scenes;
    std::string models;
    bool robustnessReported = false;      // msm alternative not required to be robust (Cramer)
    bool borderOnly = false;              // mutant visible only at the map's border ("touches")
    bool mutant() const { return kind == "mutant"; }
    fs::path path() const { return submissionsDir() / file; }
    fs::path folder() const { return path().parent_path(); }
    std::string fileName() const { return path().filename().string(); }
    static fs::path submissionsDir() { return repoRoot() / "tests" / "submissions"; }
};

std::vector<Entry> loadCatalogue() {
    std::ifstream in(Entry::submissionsDir() / "catalogue.json");
    if (!in) return {};
    json doc = json::parse(in, nullptr, /*allow_exceptions=*/false);
    std::vector<Entry> entries;
    if (!doc.is_object() || !doc.contains("entries")) return entries;
    for (const json& e : doc["entries"]) {
        Entry entry;
        entry.name = e.value("name", "");
        entry.kind = e.value("kind", "");
        entry.stage = e.value("stage", "");
        entry.file = e.value("file", "");
        entry.models = e.value("models", "");
        entry.robustnessReported = e.value("robustness", "") == "reported";
        entry.borderOnly = e.value("touches", "") == "border";
        if (e.contains("files"))
            for (const json& f : e["files"]) entry.files.push_back(f.get<std::string>());
        else
            entry.files.push_back(entry.file);
        if (e.contains("scenes"))
            for (const json& s : e["scenes"]) entry.scenes.push_back(s.get<std::string>());
        entries.push_back(entry);
    }
    return entries;
}

const std::vector<Entry>& catalogue() {
    static const std::vector<Entry> entries = loadCatalogue();
    return entries;
}

// Which stage a stage file belongs to (the grader's stages; sat covers both SAT files).
std::string stageOfFile(const std::string& file) {
    static const std::map<std::string, std::string> stages = {
        {"moments.glsl", "moments"}, {"gaussian_blur.comp", "gaussian"},
        {"sat.comp", "sat"},         {"sat_lookup.glsl", "sat"},
        {"msm.glsl", "msm"}};
    auto it = stages.find(file);
    return it == stages.end() ? "" : it->second;
}

// The image that holds a stage's own output.
std::string stageImage(const std::string& stage) {
    if (stage == "moments") return "moments_raw";
    if (stage == "msm") return "shadow";
    return "moments_filtered";
}

// Reference stage files, with the entry's file(s) taken from where it lists them. (A SAT entry
// carries the pair sat.comp + sat_lookup.glsl: they must agree on the table's format.)
ShaderLibrary entryLibrary(const Entry& entry) {
    std::map<std::string, fs::path> overrides;
    for (const auto& file : entry.files) {
        const fs::path path = Entry::submissionsDir() / file;
        overrides[path.filename().string()] = path.parent_path();
    }
    return ShaderLibrary::mixed(repoRoot() / "reference", overrides, repoRoot());
}

const Scene& scene(const std::string& name) {
    static std::map<std::string, Scene> scenes;
    auto it = scenes.find(name);
    if (it == scenes.end()) it = scenes.emplace(name, loadScene(test::scenePath(name))).first;
    return it->second;
}

RenderResult render(const Scene& s, ShaderLibrary library) {
    test::sharedContext();
    Renderer renderer(std::move(library));
    return renderer.render(s, planPasses(s, {.resolveSat = true}));  // the graded images
}

// The pure reference render of each scene, once per test process.
const RenderResult& referenceRender(const std::string& name) {
    static std::map<std::string, RenderResult> renders;
    auto it = renders.find(name);
    if (it == renders.end())
        it = renders.emplace(name, render(scene(name), test::library("reference"))).first;
    return it->second;
}

struct Difference {
    double maxAbs = 0.0;    // max over texels of d (inf if any non-finite value)
    double meanAbs = 0.0;   // mean of the finite d
    double fraction = 0.0;  // fraction of texels with d > threshold (non-finite ones count)
    double threshold = 0.0;
    long nonFinite = 0;
    std::string str() const {
        std::ostringstream s;
        s << "max |d| " << maxAbs << ", mean |d| " << meanAbs << ", " << 100.0 * fraction
          << " % of texels beyond " << threshold;
        if (nonFinite) s << ", " << nonFinite << " texels NaN/Inf";
        return s.str();
    }
};

Difference compare(const Image& a, const Image& b, double threshold) {
    Difference d;
    d.threshold = threshold;
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        d.maxAbs = INFINITY;
        d.fraction = 1.0;
        return d;
    }
    const long texels = long(a.width) * a.height;
    long beyond = 0;
    double sum = 0.0;
    for (long t = 0; t < texels; ++t) {
        double texelMax = 0.0;
        bool finite = true;
        for (int c = 0; c < a.channels; ++c) {
            const float x = a.pixels[t * a.channels + c], y = b.pixels[t * a.channels + c];
            if (!std::isfinite(x) || !std::isfinite(y)) {
                finite = false;
                break;
            }
            texelMax = std::max(texelMax, std::fabs(double(x) - double(y)));
        }
        if (!finite) {
            ++d.nonFinite;
            ++beyond;
            d.maxAbs = INFINITY;
            continue;
        }
        d.maxAbs = std::max(d.maxAbs, texelMax);
        sum += texelMax;
        if (texelMax > threshold) ++beyond;
    }
    d.meanAbs = texels > d.nonFinite ? sum / double(texels - d.nonFinite) : 0.0;
    d.fraction = double(beyond) / double(texels);
    return d;
}

// The images of a render that hold `base`'s output: "shadow", "shadow_overhead", ...
std::vector<std::string> outputKeys(const RenderResult& r, const std::string& base) {
    std::vector<std::string> keys;
    for (const auto& [key, image] : r.images)
        if (key == base || (key.rfind(base + "_", 0) == 0 && key.find("_light") == std::string::npos))
            keys.push_back(key);
    return keys;
}



}  // namespace
}  // namespace sl
