// The study's shared raw shadow maps (raw_map_key.h, raw_map_cache.h): which rows share a map
// (the key), that a shared map changes no image (bit for bit, against a sweep that shares
// nothing), that it is rendered once, that rows whose shadow pass differs do not share, that a
// shared row's shadow-pass time is the rendering row's, and that a resumed sweep still gets it
// right. The key is also checked against the renderer itself: any two settings with the same
// key must give the same raw map, so a shader change that makes the shadow pass read a new
// parameter (without the key following) fails here.
#include "gl_test_support.h"
#include "raw_map_key.h"
#include "study.h"
#include "study_table.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace sl {
namespace {

Scene studyScene(Technique t, FilterKind f, int size,
                 const std::vector<std::pair<std::string, double>>& params = {}) {
    Scene s = loadScene(test::scenePath("classic").string());
    s.cameras.resize(1);
    s.probes.clear();
    s.cameras[0].width = s.cameras[0].height = 32;
    s.shadow.mapSize = size;
    overrideTechnique(s.shadow, t, params);
    s.shadow.filter = f;
    overrideTechnique(s.shadow, t, params);  // the filter falls back to the row's if not allowed
    return s;
}

RawMapKey keyOf(const Scene& s, const ShaderLibrary& lib) {
    PlanOptions po;
    po.resolveSat = false;
    const PassPlan plan = planPasses(s, po);
    return rawMapKey(s, plan, plan.shadowLights.front(), lib, "scene");
}

TEST(StudySharingKey, SameMapSameKeyAndDifferentShadowPassDifferentKey) {
    const ShaderLibrary lib = test::library("reference");
    auto T = [](const char* name) { return techniqueFromName(name); };
    using F = FilterKind;
    const std::string depth = keyOf(studyScene(T("hard"), F::None, 512), lib).digest;
    ASSERT_FALSE(depth.empty());
    // The depth map: hard, pcf with either filter, pcss.
    EXPECT_EQ(keyOf(studyScene(T("pcf"), F::Gaussian, 512), lib).digest, depth);
    EXPECT_EQ(keyOf(studyScene(T("pcf"), F::Sat, 512), lib).digest, depth);
    EXPECT_EQ(keyOf(studyScene(T("pcss"), F::None, 512), lib).digest, depth);
    // Biases are applied at lighting time: they do not split the depth map.
    EXPECT_EQ(keyOf(studyScene(T("pcf"), F::Gaussian, 512, {{"constantBias", 0.01}}), lib).digest, depth);
    // Another size, another format, another store: another map.
    EXPECT_NE(keyOf(studyScene(T("hard"), F::None, 256), lib).digest, depth);
    EXPECT_NE(keyOf(studyScene(T("vsm"), F::Gaussian, 512), lib).digest, depth);
    // The moments map (the solution's computeMoments): msm4, msm4-hausdorff and msm-soft share
    // one; the 16-bit store is another.
    const std::string moments = keyOf(studyScene(T("msm4-hausdorff"), F::Gaussian, 512), lib).digest;
    EXPECT_EQ(keyOf(studyScene(T("msm-soft"), F::Sat, 512), lib).digest, moments);
    EXPECT_EQ(keyOf(studyScene(T("msm4"), F::Gaussian, 512), lib).digest, moments);
    EXPECT_NE(keyOf(studyScene(T("msm4-16bit"), F::Gaussian, 512), lib).digest, moments);
    // Shadow-pass parameters: the EVSM warp exponents and the CSM term count split the map;
    // the lighting-only ones do not.
    const std::string evsm = keyOf(studyScene(T("evsm2"), F::Gaussian, 512), lib).digest;
    EXPECT_NE(keyOf(studyScene(T("evsm2"), F::Gaussian, 512, {{"positiveExponent", 20}}), lib).digest, evsm);
    EXPECT_EQ(keyOf(studyScene(T("evsm2"), F::Sat, 512, {{"bleedReduction", 0.3}}), lib).digest, evsm);
    EXPECT_NE(keyOf(studyScene(T("evsm4"), F::Gaussian, 512, {{"negativeExponent", 5}}), lib).digest,
              keyOf(studyScene(T("evsm4"), F::Gaussian, 512, {{"negativeExponent", 9}}), lib).digest);
    EXPECT_NE(keyOf(studyScene(T("csm"), F::Gaussian, 512, {{"terms", 4}}), lib).digest,
              keyOf(studyScene(T("csm"), F::Gaussian, 512, {{"terms", 8}}), lib).digest);
    // Two shadow passes: never shared.
    EXPECT_FALSE(keyOf(studyScene(T("second-depth"), F::None, 512), lib).shareable());
    // Another solution's moments.glsl is another program.
    EXPECT_NE(keyOf(studyScene(T("msm4"), F::Gaussian, 512), test::library("student")).digest,
              keyOf(studyScene(T("msm4"), F::Gaussian, 512), lib).digest);
}

// Every technique with every filter and with each parameter changed: settings with one key
// render the same raw map, bit for bit (the key is sufficient), and the key does split where
// the map differs (it is not trivially conservative).
TEST(StudySharingKey, EqualKeysRenderEqualRawMaps) {
    test::sharedContext();
    const ShaderLibrary lib = test::library("reference");
    Renderer renderer(lib);
    std::map<std::string, std::pair<std::string, Image>> seen;  // digest -> (setting, raw)
    int compared = 0, split = 0;
    for (const TechniqueRow& row : techniqueTable()) {
        if (row.secondDepth) continue;
        std::vector<std::vector<std::pair<std::string, double>>> variants = {{}};
        for (const TechniqueParameter& p : row.parameters) {
            double v = p.integer ? std::max(p.min, p.defaultValue - 1) : 0.5 * (p.defaultValue + p.max);
            if (v == p.defaultValue) v = p.min;
            variants.push_back({{p.name, v}});
        }
        for (const auto& params : variants)
            for (FilterKind f : row.filters) {
                const Scene s = studyScene(row.id, f, 64, params);
                PlanOptions po;
                po.resolveSat = false;
                const PassPlan plan = planPasses(s, po);
                const int light = plan.shadowLights.front();
                const RawMapKey key = rawMapKey(s, plan, light, lib, "scene");
                RenderInputs in;
                in.keepRawMaps = true;
                const RenderResult r = renderer.render(s, plan, in);
                const Image& raw = r.rawMaps.at(light).raw.front();
                std::string setting = row.name + " " + toString(f);
                for (const auto& [n, v] : params) setting += " " + n + "=" + std::to_string(v);
                auto it = seen.find(key.digest);
                if (it == seen.end()) {
                    for (const auto& [d, other] : seen)
                        if (other.second.pixels == raw.pixels && other.second.width == raw.width &&
                            other.second.channels == raw.channels)
                            ++split;  // the same map under two keys: conservative, allowed
                    seen.emplace(key.digest, std::make_pair(setting, raw));
                    continue;
                }
                ++compared;
                EXPECT_TRUE(it->second.second.pixels == raw.pixels)
                    << setting << " and " << it->second.first << " have one key (" << key.label
                    << ") but different raw maps: the shadow pass reads something the key "
                       "(framework/study/raw_map_key.cpp) does not";
            }
    }
    EXPECT_GT(compared, 20) << "too few settings shared a key to test anything";
    // msm4's stage program vs the framework's moments store: the only expected split.
    EXPECT_LE(split, 2);
}

class StudySharing : public ::testing::Test {
protected:
    static StudyOptions options(const fs::path& dir, bool share) {
        StudyOptions o;
        o.scene = test::scenePath("classic");
        // hard (none) and pcf (r = 1, 3) share the depth map; evsm2 at two exponents must not.
        o.techniques = {"hard", "pcf", "evsm2", "evsm2:positiveExponent=20"};
        o.mapSizes = {128};
        o.radii = {1, 3};
        o.filters = {"gaussian"};
        o.repeats = 2;
        o.imageSize = 64;
        o.out = dir;
        o.progress = false;
        o.report = false;
        o.shareMaps = share;
        return o;
    }
    static StudySummary run(const StudyOptions& o) {
        test::sharedContext();
        std::ostringstream log;
        return runStudy(o, log);
    }
    static std::map<std::string, StudyRow> byKey(const fs::path& csv) {
        std::map<std::string, StudyRow> out;
        for (const StudyRow& r : readStudyCsv(csv)) out[r.key()] = r;
        return out;
    }
    static std::string shadowTime(const StudyRow& r) {  // "shadow@L0=med/min/max"
        const size_t at = r.passTimes.find("shadow@");
        const size_t end = r.passTimes.find_first_of(";(", at);
        return at == std::string::npos ? "" : r.passTimes.substr(at, end - at);
    }
};

TEST_F(StudySharing, RenderedOnceSameBitsAsUnsharedAndResumes) {
    const std::string pid = std::to_string(::getpid());
    const fs::path sharedDir = test::tempDir("study_shared_" + pid);
    const fs::path ownDir = test::tempDir("study_unshared_" + pid);
    const StudySummary s = run(options(sharedDir, true));
    const StudySummary u = run(options(ownDir, false));
    ASSERT_EQ(s.run, 7);
    ASSERT_EQ(u.run, 7);
    // hard renders the depth map once for itself and both pcf rows; each evsm2 renders its own.
    EXPECT_EQ(s.shadowMapsRendered, 3);
    EXPECT_EQ(s.sharedMaps, 4);
    EXPECT_EQ(u.shadowMapsRendered, 7);
    EXPECT_EQ(u.sharedMaps, 0);

    const auto shared = byKey(sharedDir / "study.csv"), own = byKey(ownDir / "study.csv");
    ASSERT_EQ(shared.size(), 7u);
    ASSERT_EQ(own.size(), 7u);
    const std::string hardKey = "classic|reference|hard|none|0|128|light 0";
    ASSERT_TRUE(shared.count(hardKey));
    for (const auto& [key, r] : shared) {
        const StudyRow& o = own.at(key);
        // Sharing changes no bit of the image, hence no error figure.
        EXPECT_EQ(r.imageDigest, o.imageDigest) << key;
        EXPECT_EQ(r.imageDigest.size(), 16u) << key;
        EXPECT_EQ(r.truth.rmse, o.truth.rmse) << key;
        EXPECT_EQ(r.truth.max, o.truth.max) << key;
        EXPECT_EQ(r.filtered.rmse, o.filtered.rmse) << key;
        EXPECT_EQ(r.filtered.p99, o.filtered.p99) << key;
        EXPECT_TRUE(o.mapFrom.empty()) << key;
        if (r.technique == "pcf") {
            // Shared from hard's row, which said it rendered; the shadow time is hard's.
            EXPECT_EQ(r.mapFrom, hardKey) << key;
            EXPECT_EQ(r.mapKey, shared.at(hardKey).mapKey);
            EXPECT_NE(r.reused.find("shared from " + hardKey), std::string::npos) << r.reused;
            EXPECT_NE(r.passTimes.find("(shared)"), std::string::npos) << r.passTimes;
            EXPECT_EQ(shadowTime(r), shadowTime(shared.at(hardKey))) << r.passTimes;
            EXPECT_FALSE(shadowTime(r).empty());
        }
    }
    EXPECT_TRUE(shared.at(hardKey).mapFrom.empty());
    // evsm2 at exponent 20 shares only with itself (its r = 3 row from its r = 1 row).
    const StudyRow& e20 = shared.at("classic|reference|evsm2:positiveExponent=20|gaussian|3|128|light 0");
    EXPECT_EQ(e20.mapFrom, "classic|reference|evsm2:positiveExponent=20|gaussian|1|128|light 0");
    EXPECT_NE(e20.mapKey, shared.at("classic|reference|evsm2|gaussian|3|128|light 0").mapKey);
    EXPECT_EQ(shared.at("classic|reference|evsm2:positiveExponent=20|gaussian|1|128|light 0").mapFrom, "");

    // Resume: drop hard's row (the map's source), one pcf row and one evsm2 row whose source
    // stays. The rerun renders hard's map again and shares it with the pcf row; the evsm2 row
    // renders its own. Every image is the same as before.
    {
        std::ifstream in(sharedDir / "study.csv");
        std::vector<std::string> lines;
        for (std::string l; std::getline(in, l);) lines.push_back(l);
        std::ofstream out(sharedDir / "study.csv", std::ios::trunc);
        for (const std::string& l : lines)
            if (l.rfind("classic,reference,hard,", 0) != 0 &&
                l.find("\"pcf\",gaussian,3,") == std::string::npos &&
                l.find("\"evsm2\",gaussian,3,") == std::string::npos)
                out << l << "\n";
    }
    ASSERT_EQ(readStudyCsv(sharedDir / "study.csv").size(), 4u);
    const StudySummary again = run(options(sharedDir, true));
    EXPECT_EQ(again.skipped, 4);
    EXPECT_EQ(again.run, 3);
    EXPECT_EQ(again.shadowMapsRendered, 2);
    EXPECT_EQ(again.sharedMaps, 1);
    const auto resumed = byKey(sharedDir / "study.csv");
    ASSERT_EQ(resumed.size(), 7u);
    for (const auto& [key, r] : resumed) EXPECT_EQ(r.imageDigest, own.at(key).imageDigest) << key;
    EXPECT_EQ(resumed.at("classic|reference|pcf|gaussian|3|128|light 0").mapFrom, hardKey);
    EXPECT_EQ(resumed.at("classic|reference|evsm2|gaussian|3|128|light 0").mapFrom, "");
}

}  // namespace
}  // namespace sl
