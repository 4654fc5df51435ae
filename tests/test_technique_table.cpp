// The technique table seen from outside: scenes name techniques and parameters and get clear
// errors; the --technique override keeps or replaces the filter as the row allows; the 16-bit
// moment transform and its inverse are inverses and land in [0, 1] (UNORM16 can store them).
#include "gl_test_support.h"
#include "scene.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace sl {
namespace {

std::string sceneWithShadow(const std::string& shadow) {
    return R"({"camera": {"position": [0, 3, 5], "target": [0, 0, 0]},
               "lights": [{"type": "spot", "position": [0, 6, 0], "target": [0, 0, 0]}],
               "objects": [{"name": "ground", "shape": "plane", "size": [4, 4]}], "shadow": )" +
           shadow + "}";
}

std::string errorOf(const std::string& shadow) {
    try {
        parseScene(sceneWithShadow(shadow), "t.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(TechniqueTable, EveryRowIsNamedAndFindable) {
    const auto names = techniqueNames();
    ASSERT_EQ(names.size(), 12u);
    for (const auto& name : names) EXPECT_EQ(toString(techniqueFromName(name)), name);
    // The rows that reconstruct with Hamburger 4MSM do it through the solution's msm.glsl; the
    // two whose own files solve the msm stage say so (the student kit leaves them out).
    for (const auto& row : techniqueTable()) {
        const bool msm = row.storeDefine.rfind("SL_STORE_MOMENTS4", 0) == 0;
        EXPECT_EQ(row.msmStage, msm) << row.name;
        const bool leftOut = row.id == Technique::Msm4Hausdorff || row.id == Technique::MsmSoft;
        EXPECT_EQ(!row.solvesStage.empty(), leftOut) << row.name;
    }
}

TEST(TechniqueTable, SceneNamesTechniqueAndParameters) {
    Scene s = parseScene(sceneWithShadow(R"({"technique": "vsm", "parameters": {"bleedReduction": 0.3}})"),
                         "t.json");
    EXPECT_EQ(s.shadow.technique, Technique::Vsm);
    EXPECT_DOUBLE_EQ(techniqueParameter(s.shadow, "bleedReduction"), 0.3);
    EXPECT_DOUBLE_EQ(techniqueParameter(s.shadow, "minVariance"), 1e-5);  // the row's default
}

TEST(TechniqueTable, HardWithoutAFilterGetsNone) {
    Scene s = parseScene(sceneWithShadow(R"({"technique": "hard"})"), "t.json");
    EXPECT_EQ(s.shadow.filter, FilterKind::None);
}

TEST(TechniqueTable, BadTechniqueInputGivesClearErrors) {
    EXPECT_NE(errorOf(R"({"technique": "vsn"})").find("/shadow/technique: expected one of \"hard\""),
              std::string::npos)
        << errorOf(R"({"technique": "vsn"})");
    const std::string unknown = errorOf(R"({"technique": "vsm", "parameters": {"bleed": 0.3}})");
    EXPECT_NE(unknown.find("t.json: /shadow/parameters/bleed: expected one of the parameters "
                           "\"minVariance\", \"bleedReduction\" of technique \"vsm\""),
              std::string::npos)
        << unknown;
    const std::string range = errorOf(R"({"technique": "vsm", "parameters": {"bleedReduction": 1.5}})");
    EXPECT_NE(range.find("/shadow/parameters/bleedReduction: expected a number in [0, 0.99], found 1.5"),
              std::string::npos)
        << range;
    const std::string integer = errorOf(R"({"technique": "csm", "parameters": {"terms": 2.5}})");
    EXPECT_NE(integer.find("expected an integer in [1, 8]"), std::string::npos) << integer;
    const std::string filter = errorOf(R"({"technique": "hard", "filter": {"type": "gaussian"}})");
    EXPECT_NE(filter.find("/shadow/filter/type: expected one of \"none\" for technique \"hard\", "
                          "found \"gaussian\""),
              std::string::npos)
        << filter;
    const std::string none = errorOf(R"({"technique": "msm4", "parameters": {"x": 1}})");
    EXPECT_NE(none.find("no parameters"), std::string::npos) << none;
}

TEST(TechniqueTable, OverrideKeepsAnAllowedFilterAndReplacesOthers) {
    ShadowEffect fx;
    fx.filter = FilterKind::Sat;
    overrideTechnique(fx, Technique::Vsm, {{"bleedReduction", 0.0}});
    EXPECT_EQ(fx.filter, FilterKind::Sat);
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "bleedReduction"), 0.0);
    overrideTechnique(fx, Technique::Hard);
    EXPECT_EQ(fx.filter, FilterKind::None);
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "constantBias"), 5e-4);  // parameters reset
    fx.filter = FilterKind::Gaussian;
    overrideTechnique(fx, Technique::MsmSoft);
    EXPECT_EQ(fx.filter, FilterKind::Sat);
    // The same technique keeps its parameters and takes the given ones on top.
    overrideTechnique(fx, Technique::Vsm, {{"bleedReduction", 0.0}});
    overrideTechnique(fx, Technique::Vsm, {{"minVariance", 1e-3}});
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "bleedReduction"), 0.0);
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "minVariance"), 1e-3);
    EXPECT_THROW(overrideTechnique(fx, Technique::Vsm, {{"nope", 1}}), std::invalid_argument);
    EXPECT_THROW(overrideTechnique(fx, Technique::Vsm, {{"minVariance", -1}}), std::invalid_argument);
}

TEST(TechniqueTable, SpecParsing) {
    auto [t, p] = parseTechniqueSpec("evsm4:positiveExponent=30:negativeExponent=8");
    EXPECT_EQ(t, Technique::Evsm4);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].first, "positiveExponent");
    EXPECT_DOUBLE_EQ(p[1].second, 8.0);
    EXPECT_THROW(parseTechniqueSpec("evsm4:positiveExponent"), std::invalid_argument);
    EXPECT_THROW(parseTechniqueSpec("evsm4:positiveExponent=x"), std::invalid_argument);
    EXPECT_THROW(parseTechniqueSpec("nope"), std::invalid_argument);
}

TEST(TechniqueTable, QuantisedMomentsInvertAndFitUnorm16) {
    for (int i = 0; i <= 1000; ++i) {
        const double z = i / 1000.0;
        const glm::dvec4 b(z, z * z, z * z * z, z * z * z * z);
        const glm::dvec4 q = quantizeMoments16(b);
        for (int c = 0; c < 4; ++c) {
            EXPECT_GE(q[c], -1e-6) << z;
            EXPECT_LE(q[c], 1.0 + 1e-6) << z;
        }
        const glm::dvec4 back = dequantizeMoments16(q);
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(back[c], b[c], 2e-7) << "z " << z << " channel " << c;
    }
}

TEST(TechniqueTable, ClearValuesAreTheStoreOfDepthOne) {
    ShadowEffect fx;
    fx.technique = Technique::Evsm4;
    fx.parameters = {{"positiveExponent", 80.0}, {"negativeExponent", 5.0}};
    const auto c = shadowClearValues(fx);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_FLOAT_EQ(c[0].x, float(std::exp(42.0)));  // clamped: e^{2c} must stay finite
    EXPECT_TRUE(std::isfinite(c[0].y));
    EXPECT_FLOAT_EQ(c[0].z, float(-std::exp(-5.0)));
    fx.technique = Technique::Csm;
    fx.parameters = {{"terms", 3.0}};
    const auto csm = shadowClearValues(fx);
    ASSERT_EQ(csm.size(), 2u);
    EXPECT_FLOAT_EQ(csm[0].x, -1.0f);  // cos(π), cos(3π), cos(5π)
    EXPECT_FLOAT_EQ(csm[0].z, -1.0f);
    EXPECT_FLOAT_EQ(csm[1].x, -1.0f);
    EXPECT_EQ(csm[1].z, 0.0f);  // the unused half of the last map
}

}  // namespace sl

namespace sl {

// A row is in a kit when its lighting file is: the student kit leaves out the rows whose files
// solve a stage, and `render --technique all` and `compare` skip or stand in for them.
TEST(TechniqueTable, ARowIsInTheKitWhenItsLightingFileIs) {
    const fs::path shaders = test::tempDir("technique_in_kit") / "shaders";
    fs::create_directories(shaders / "techniques");
    const TechniqueRow& soft = techniqueRow(Technique::MsmSoft);
    EXPECT_FALSE(techniqueInKit(soft, shaders.string()));
    test::writeFile(shaders / soft.lightingFile, "// present\n");
    EXPECT_TRUE(techniqueInKit(soft, shaders.string()));
    EXPECT_FALSE(techniqueInKit(techniqueRow(Technique::Msm4), shaders.string()));
}

}  // namespace sl
