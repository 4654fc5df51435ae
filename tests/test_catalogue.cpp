// The catalogue of tests/submissions/ (docs/catalogue.md) proves the grading rule "correct but
// different implementations score full marks, and plausible bugs lose points on the stage that
// holds them", at two levels:
//
// 1. Stages/CatalogueStageOutput.MutantsDifferAlternativesAgree/<stage> (no grader needed; one
//    CTest case per stage, so that each process renders each reference scene once): every entry
//    is rendered in-process on its public scene(s) with a ShaderLibrary that takes the entry's
//    file(s) from its folder and every other file from reference/, and the stage's own output
//    image is compared with the pure reference render:
//        moments -> moments_raw     gaussian, sat -> moments_filtered     msm -> shadow (G)
//    Per texel, d = max over channels |entry - reference| (NaN or Inf on either side: d = inf).
//    τ = roundingTolerance(stage, scene): what float32 rounding alone can explain.
//    - A mutant must differ visibly on at least one scene: max d >= max(1e-2, 4τ), and at least
//      0.1 % of the texels (~1000 of a 1024² map) with d > max(1e-3, 2τ). Moments and G lie in
//      [0, 1]: 1e-3 is 0.1 % of the range, far above rounding, far below what a viewer sees.
//    - An alternative must agree to rounding: max d <= τ (moments, gaussian, msm), or, for a
//      SAT, max error against a float64 oracle of the exact box mean <= τ.
// 2. CatalogueGrade (needs `shadowlab grade`): the same entries through the grader, which must
//    give a mutant less than full marks on its own stage and full marks on every other isolated
//    stage, and an alternative full marks everywhere (the end-to-end "final" stage is not
//    checked for mutants: a stage bug may legitimately cost points there too).
#include "gl_test_support.h"
#include "oracles/moment_oracles.h"
#include "probe.h"
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

struct Entry {
    std::string name, kind, stage, file;  // file: relative to tests/submissions/
    std::vector<std::string> files;       // every file of the folder (file alone if absent)
    std::vector<std::string> scenes;
    std::string models;
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

// Reference stage files, with the entry's file(s) taken from its folder instead. (A SAT entry
// carries the pair sat.comp + sat_lookup.glsl: they must agree on the table's format.)
ShaderLibrary entryLibrary(const Entry& entry) {
    const fs::path ref = repoRoot() / "reference";
    std::map<std::string, fs::path> stages;
    for (const auto& name : stageFileNames()) stages[name] = ref;
    for (const auto& file : entry.files) {
        const fs::path path = Entry::submissionsDir() / file;
        stages[path.filename().string()] = path.parent_path();
    }
    return ShaderLibrary(stages, {ref, repoRoot() / "shaders"}, repoRoot());
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
    return renderer.render(s, planPasses(s));
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


// ------------------------------------------------------------------ catalogue well-formed

TEST(Catalogue, EntriesAreWellFormed) {
    const auto& entries = catalogue();
    int mutants = 0, alternatives = 0;
    std::set<std::string> names, mutantStages;
    for (const Entry& e : entries) {
        SCOPED_TRACE(e.name);
        EXPECT_TRUE(names.insert(e.name).second) << "duplicate name";
        EXPECT_TRUE(e.kind == "mutant" || e.kind == "alternative") << e.kind;
        (e.mutant() ? mutants : alternatives)++;
        if (e.mutant()) mutantStages.insert(e.stage);
        EXPECT_EQ(stageOfFile(e.fileName()), e.stage) << e.file;
        EXPECT_EQ(e.folder().parent_path().filename(), e.mutant() ? "mutants" : "alternatives");
        EXPECT_EQ(e.folder().filename(), e.name);
        ASSERT_TRUE(fs::is_regular_file(e.path())) << e.path();
        // One stage's file(s) per folder; the rest of the submission is the reference. Only a
        // SAT entry has two: the modified file and its unchanged partner.
        std::set<std::string> onDisk, listed;
        for (const auto& f : fs::directory_iterator(e.folder()))
            onDisk.insert(f.path().filename().string());
        for (const auto& f : e.files) {
            EXPECT_EQ((Entry::submissionsDir() / f).parent_path(), e.folder()) << f;
            EXPECT_EQ(stageOfFile(fs::path(f).filename().string()), e.stage) << f;
            listed.insert(fs::path(f).filename().string());
        }
        EXPECT_EQ(onDisk, listed) << "the catalogue's files must be the folder's";
        EXPECT_TRUE(listed.count(e.fileName()));
        EXPECT_LE(listed.size(), e.stage == "sat" ? 2u : 1u);
        int tagged = 0;  // files that say what they model
        for (const auto& f : listed) {
            std::ifstream tin(e.folder() / f);
            std::string line;
            std::getline(tin, line);
            if (line.rfind("// MUTANT: ", 0) == 0 || line.rfind("// ALTERNATIVE: ", 0) == 0)
                ++tagged;
        }
        if (e.mutant()) {
            EXPECT_EQ(tagged, 1) << "a mutant modifies exactly one file";
        }
        std::ifstream in(e.path());
        std::string first;
        std::getline(in, first);
        const std::string tag = e.mutant() ? "// MUTANT: " : "// ALTERNATIVE: ";
        EXPECT_EQ(first.rfind(tag, 0), 0u) << "first line must name what it models: " << first;
        EXPECT_FALSE(e.models.empty());
        EXPECT_FALSE(e.scenes.empty());
        for (const auto& s : e.scenes) EXPECT_TRUE(fs::is_regular_file(test::scenePath(s))) << s;
    }
    EXPECT_GE(mutants, 15);
    EXPECT_GE(alternatives, 5);
    EXPECT_EQ(mutantStages, (std::set<std::string>{"moments", "gaussian", "sat", "msm"}));
}

// ------------------------------------------------------------------ level 1: stage outputs

class CatalogueStageOutput : public testing::TestWithParam<std::string> {};

// τ: how far a correct float32 implementation of `stage` may be from another one (or from the
// exact value) on scene `s`, from the rounding that stage's arithmetic cannot avoid. Stage
// values are moments or G, all in [0, 1].
double roundingTolerance(const std::string& stage, const Scene& s) {
    if (stage == "moments") {
        // relativeDepth: a subtraction and a division, or a reciprocal, two products and a
        // subtraction, of terms up to far / (far - near) (~2 on the public scenes): ~4
        // roundings of values <= 2; z^4 multiplies z's relative error by 4 and adds 3 roundings
        // of its own. 64u (3.8e-6) covers both implementations with room to spare.
        return 64 * u;
    }
    if (stage == "gaussian") {
        // One pass sums 2r + 1 non-negative terms w·x with Σw = 1 and x <= 1; any summation
        // order is within (2r + 1)·u of the exact sum (Wilkinson), so two implementations are
        // within 2·(2r + 1)·u per pass, and the second pass carries the first's difference
        // over unchanged (Σw = 1): 4·(2r + 1)·u overall (2.1e-6 for r = 4). Same weights buffer
        // for both, so the weights' own rounding cancels.
        return 4.0 * (2 * s.shadow.gaussianRadius + 1) * u;
    }
    if (stage == "sat") {
        // A summed-area table's entries grow to W·H·max(moment) = W·H (1e6 for 1024²), where
        // float32's spacing is 2^-4, and the lookup subtracts corners of that size, so the box
        // mean inherits their rounding divided by the box area: a plain float32 table is
        // ~8·u·W·H / area from a float64 oracle. This in-process level only asks alternatives
        // to stay within that (τ = 32·u·W·H / area: 0.041 for contact's 7-texel box, 1.2e-3 for
        // wide_blur's 40.5); the grader level holds them to the SAT precision the handout
        // requires (docs/numerics.md), which a plain table does not meet (tests/submissions/
        // fragile/naive_sat).
        const double k = s.shadow.satKernelTexels;
        return 32.0 * u * double(s.shadow.mapSize) * s.shadow.mapSize / (k * k);
    }
    // msm: G of a nearly singular Hankel matrix (one depth dominates the filter footprint; the
    // bias α = 3e-5 alone keeps it positive definite) is ill-conditioned: its pivots are O(α)
    // differences of O(1) moments, so float32 moves them by ~u / α ≈ 2e-3 relative. Measured
    // on the classic scene's filtered moments (msmOracleError), the reference's own G is up to
    // 5.9e-3 from a float64 oracle (Cramer's rule: 9.1e-3), so two correct solutions can be
    // ~1e-2 apart on a few texels.
    return 1e-2;
}

// Max over samples of |G - float64 oracle G| of `library`'s msm.glsl, at fragment depths just
// in front of and behind the mean depth of every 8th texel of the filtered moment map.
double msmOracleError(const ShaderLibrary& library, const Image& filtered, float momentBias) {
    std::vector<glm::vec4> b;
    std::vector<float> zf;
    for (int y = 0; y < filtered.height; y += 8)
        for (int x = 0; x < filtered.width; x += 8) {
            const glm::vec4 v(filtered.at(x, y, 0), filtered.at(x, y, 1), filtered.at(x, y, 2),
                              filtered.at(x, y, 3));
            for (float dz : {0.02f, -0.002f, -0.01f, -0.05f}) {
                b.push_back(v);
                zf.push_back(v.x + dz);
            }
        }
    const std::vector<float> G = probeMomentShadowIntensity(library, b, zf, momentBias);
    double worst = 0.0;
    for (size_t i = 0; i < b.size(); ++i) {
        const double want = oracle::msm4Hamburger(glm::dvec4(b[i]), zf[i], momentBias);
        worst = std::max(worst, std::isfinite(G[i]) ? std::fabs(G[i] - want) : INFINITY);
    }
    return worst;
}

// Level 1 for one entry (ASSERTs end this entry's check only).
void checkStageOutput(const Entry& e) {
    const std::string base = stageImage(e.stage);
    bool visibleSomewhere = false;
    std::string measured;
    for (const std::string& sceneName : e.scenes) {
        SCOPED_TRACE(sceneName);
        const Scene& s = scene(sceneName);
        const RenderResult& ref = referenceRender(sceneName);
        const double tau = roundingTolerance(e.stage, s);
        const auto start = std::chrono::steady_clock::now();
        const ShaderLibrary library = entryLibrary(e);
        RenderResult got = render(s, library);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto keys = outputKeys(ref, base);
        ASSERT_FALSE(keys.empty()) << "no " << base << " image";
        for (const std::string& key : keys) {
            ASSERT_TRUE(got.images.count(key)) << key;
            const Image& a = got.images.at(key);
            const Image& b = ref.images.at(key);
            const double visibleAt = std::max(kTexelTolerance, 2 * tau);
            const Difference d = compare(a, b, visibleAt);
            measured += sceneName + "/" + key + ": " + d.str() + "; ";
            std::printf("[catalogue] %-31s %-11s %-9s %-16s %s (τ %.2g; render %.2f s)\n",
                        e.name.c_str(), e.kind.c_str(), sceneName.c_str(), key.c_str(),
                        d.str().c_str(), tau, seconds);
            if (e.mutant()) {
                // Visible: well beyond what rounding explains, on a few texels at least.
                if (d.maxAbs >= std::max(kMutantMaxAbs, 4 * tau) &&
                    d.fraction >= kMutantMinFraction)
                    visibleSomewhere = true;
                continue;
            }
            // Alternatives: equal up to rounding.
            EXPECT_EQ(d.nonFinite, 0) << key;
            if (e.stage == "moments" || e.stage == "gaussian") {
                EXPECT_LE(d.maxAbs, tau) << key << ": " << d.str();
            } else if (e.stage == "sat") {
                // Against the exact box mean (float64 SAT of the same raw moments, same box),
                // not against the reference, whose own error is part of the budget.
                const Image& raw = ref.images.at("moments_raw");
                const auto exact = oracle::summedAreaTable(raw.pixels, raw.width, raw.height);
                const double k = s.shadow.satKernelTexels;
                double refMax = 0, altMax = 0;
                for (int y = 0; y < raw.height; ++y)
                    for (int x = 0; x < raw.width; ++x) {
                        const glm::dvec4 want = oracle::satBoxAverage(
                            exact, raw.width, raw.height, glm::dvec2(x + 0.5, y + 0.5),
                            glm::dvec2(k));
                        for (int c = 0; c < 4; ++c) {
                            refMax = std::max(refMax, std::fabs(b.at(x, y, c) - want[c]));
                            altMax = std::max(altMax, std::fabs(a.at(x, y, c) - want[c]));
                        }
                    }
                std::printf("[catalogue] %-31s vs float64 oracle: reference max %.3g, "
                            "alternative max %.3g (τ %.2g)\n",
                            e.name.c_str(), refMax, altMax, tau);
                EXPECT_LE(altMax, tau) << key << ": error against the exact box mean";
            } else {  // msm
                EXPECT_LE(d.maxAbs, tau) << key << ": " << d.str();
                // Differences beyond 1e-3 only where G is ill-conditioned: a few texels.
                EXPECT_LE(compare(a, b, kTexelTolerance).fraction, 1e-2) << key;
            }
        }
        if (!e.mutant() && e.stage == "msm") {
            // And as accurate as the reference against the float64 oracle, on this scene's
            // real filtered moments (up to a factor 2: a different order of operations).
            const Image& filtered = ref.images.at("moments_filtered");
            const double refErr = msmOracleError(test::library("reference"), filtered,
                                                 s.shadow.momentBias);
            const double altErr = msmOracleError(library, filtered, s.shadow.momentBias);
            std::printf("[catalogue] %-31s G vs float64 oracle: reference max %.3g, "
                        "alternative max %.3g\n", e.name.c_str(), refErr, altErr);
            EXPECT_LE(altErr, 2 * refErr + 1e-4);
        }
    }
    if (e.mutant()) {
        EXPECT_TRUE(visibleSomewhere)
            << e.name << " (" << e.models << ") must differ from the reference on its stage's "
            << "output by max |d| >= max(1e-2, 4τ) with >= " << 100 * kMutantMinFraction
            << " % of the texels beyond max(1e-3, 2τ); " << measured;
    }
    testing::Test::RecordProperty(e.name, measured);
}

// One CTest case per stage (one process renders each reference scene once for all entries).
TEST_P(CatalogueStageOutput, MutantsDifferAlternativesAgree) {
    const std::string stage = GetParam();
    int entries = 0;
    for (const Entry& e : catalogue()) {
        if (e.stage != stage) continue;
        ++entries;
        SCOPED_TRACE(e.name + " (" + e.kind + ": " + e.models + ")");
        checkStageOutput(e);
    }
    EXPECT_GT(entries, 0) << "no catalogue entry for stage " << stage;
}

INSTANTIATE_TEST_SUITE_P(Stages, CatalogueStageOutput,
                         testing::Values("moments", "gaussian", "sat", "msm"),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

// ------------------------------------------------------------------ level 2: the grader

bool graderBuilt() {
    static const bool built = [] {
        test::CommandResult r = test::runCommand(test::shadowlabBinary() + " grade --help");
        return r.exitCode == 0 && r.output.find("--submission") != std::string::npos;
    }();
    return built;
}

struct StageScore {
    double score = 0.0, max = 0.0;
    std::string output;
    bool full() const { return score >= max - 1e-9; }
};

// Per stage tag ("stage:<stage>"), the scores of one results.json, summed over its tests.
std::map<std::string, StageScore> stageScores(const json& results) {
    std::map<std::string, StageScore> stages;
    for (const json& t : results["tests"]) {
        std::string stage;
        if (t.contains("tags"))
            for (const json& tag : t["tags"]) {
                const std::string s = tag.get<std::string>();
                if (s.rfind("stage:", 0) == 0) stage = s.substr(6);
            }
        if (stage.empty()) continue;
        stages[stage].score += t.value("score", 0.0);
        stages[stage].max += t.value("max_score", 0.0);
        stages[stage].output += t.value("output", "");
    }
    return stages;
}

// Every entry through `shadowlab grade`. Each entry is a complete submission: the reference's
// five files with the entry's file(s) on top (a folder with the one file alone would, rightly,
// grade the other stages "not submitted"). Graded on its first scene (the catalogue lists
// first a scene where the bug shows), against the live reference, without the HTML report,
// as one --batch per scene: one process for all entries (~40-80 s for the 30 entries on 2
// busy cores, against ~3 min for 30 single `grade --submission` runs). --timeout 120: a busy
// shared machine must not turn a slow render into a "timed out" zero.
TEST(CatalogueGrade, MutantsLoseOnlyOnTheirStageAlternativesScoreFull) {
    if (!graderBuilt()) GTEST_SKIP() << "grader not built yet";
    // Per process: a concurrent run of the suite (several people share build/) must not
    // delete this one's folders.
    const fs::path dir = test::tempDir("catalogue_grade_" + std::to_string(getpid()));
    std::string finalLosses;  // alternatives that lose points on the end-to-end image only
    std::map<std::string, std::vector<const Entry*>> byScene;
    for (const Entry& e : catalogue()) {
        ASSERT_FALSE(e.scenes.empty()) << e.name;
        byScene[e.scenes.front()].push_back(&e);
    }
    for (const auto& [scene, entries] : byScene) {
        const fs::path batch = dir / ("submissions_" + scene), out = dir / ("out_" + scene);
        for (const Entry* e : entries) {
            const fs::path submission = batch / e->name;
            fs::create_directories(submission);
            for (const auto& name : stageFileNames())
                fs::copy_file(repoRoot() / "reference" / name, submission / name,
                              fs::copy_options::overwrite_existing);
            for (const auto& file : e->files)
                fs::copy_file(Entry::submissionsDir() / file,
                              submission / fs::path(file).filename(),
                              fs::copy_options::overwrite_existing);
        }
        const auto start = std::chrono::steady_clock::now();
        const test::CommandResult run = test::runCommand(
            test::shadowlabBinary() + " grade --batch '" + batch.string() + "' --out '" +
            out.string() + "' --scenes " + scene + " --reference live --no-report -j 2 --timeout 120");
        std::printf("[catalogue] grade --batch of %zu entries on %s: %.1f s, exit %d\n",
                    entries.size(), scene.c_str(),
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                        .count(),
                    run.exitCode);

        for (const Entry* e : entries) {
            SCOPED_TRACE(e->name + " (" + e->kind + ", stage " + e->stage + ", scene " + scene +
                         ")");
            std::ifstream in(out / e->name / "results.json");
            if (!in) {
                ADD_FAILURE() << "no results.json; exit " << run.exitCode << "\n" << run.output;
                continue;
            }
            const json results = json::parse(in, nullptr, false);
            if (!results.is_object() || !results.contains("tests")) {
                ADD_FAILURE() << "results.json without tests[]";
                continue;
            }
            const auto stages = stageScores(results);
            EXPECT_TRUE(stages.count(e->stage)) << "no test tagged stage:" << e->stage;
            std::string table;
            for (const auto& [stage, s] : stages) {
                char buf[96];
                std::snprintf(buf, sizeof buf, "%s %.2f/%.2f  ", stage.c_str(), s.score, s.max);
                table += buf;
            }
            std::printf("[catalogue] grade %-31s %-11s %s\n", e->name.c_str(), e->kind.c_str(),
                        table.c_str());
            for (const auto& [stage, s] : stages) {
                SCOPED_TRACE("stage " + stage + ": " + std::to_string(s.score) + " / " +
                             std::to_string(s.max) + "\n" + s.output);
                if (e->mutant()) {
                    // The end-to-end "final" stage may lose points too: not checked. Nor may
                    // "robustness" for an msm mutant: it probes the same msm.glsl.
                    const bool sameFile = e->stage == "msm" && stage == "robustness";
                    if (stage == e->stage) {
                        EXPECT_FALSE(s.full()) << "a mutant must lose points on its own stage";
                    } else if (stage != "final" && !sameFile) {
                        EXPECT_TRUE(s.full()) << "a mutant must not lose points on another stage";
                    }
                } else if (stage == "robustness" && e->stage == "msm") {
                    // Correct on every scene, yet a solve may be less stable on the adversarial
                    // hard cases (msm_cramer: non-monotone on 16 of 289): that is what the
                    // robustness stage is for, so it is reported, not required (catalogue.md).
                    if (!s.full()) std::printf("[catalogue] %s: robustness %.2f / %.2f\n",
                                               e->name.c_str(), s.score, s.max);
                } else if (stage != "final") {
                    EXPECT_TRUE(s.full()) << "an alternative must score full marks";
                } else if (!s.full()) {
                    finalLosses += e->name + ": final " + std::to_string(s.score) + " / " +
                                   std::to_string(s.max) + " on " + scene + "; ";
                }
            }
        }
    }
    if (!HasFailure()) fs::remove_all(dir);  // kept for inspection when something failed
    if (!finalLosses.empty() && !HasFailure()) {
        // Every isolated stage passed. What is left is for the grader to fix: through a SAT,
        // the end-to-end shadow is chaotic in float rounding. Even sat_lookup_fp_order (box
        // means within 2e-5 of the reference's) flips G by up to 0.99 on 1-3 % of the contact
        // and wide_blur pixels, so "final" cannot ask for 99.5 % of the pixels within
        // tolerance of the reference there. (docs/catalogue.md, "Known grader issue".)
        GTEST_SKIP() << "known grader issue: correct alternatives lose points on the end-to-end "
                        "final image only (every isolated stage scores as required): "
                     << finalLosses;
    }
}

}  // namespace
}  // namespace sl
