// The technique table seen from outside: scenes name techniques and parameters and get clear
// errors; the --technique override keeps or replaces the filter as the row allows; the 16-bit
// moment transform and its inverse are inverses and land in [0, 1] (UNORM16 can store them).
#include "gl_test_support.h"
#include "scene.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
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
    ASSERT_GE(names.size(), 13u);  // the twelve of the ladder and esm
    for (const auto& name : names) EXPECT_EQ(toString(techniqueFromName(name)), name);
    // Each row's define, file and name are its own (a copied row that kept one would clash).
    std::set<std::string> defines, files;
    for (const auto& row : techniqueTable()) {
        EXPECT_TRUE(defines.insert(techniqueDefine(row)).second) << row.name;
        EXPECT_TRUE(files.insert(row.file).second) << row.name;
        EXPECT_TRUE(fs::exists(test::root() / "shaders" / row.file)) << row.file;
    }
    // The rows that reconstruct with Hamburger 4MSM do it through the solution's msm.glsl; the
    // two whose own files solve the msm stage say so (the student kit leaves them out).
    for (const auto& row : techniqueTable()) {
        const bool msm = row.store == StoreKind::Moments4 || row.store == StoreKind::Moments4_16bit;
        EXPECT_EQ(row.msmStage, msm) << row.name;
        const bool leftOut = row.id == techniqueFromName("msm4-hausdorff") || row.id == techniqueFromName("msm-soft");
        EXPECT_EQ(!row.solvesStage.empty(), leftOut) << row.name;
    }
}

TEST(TechniqueTable, SceneNamesTechniqueAndParameters) {
    Scene s = parseScene(sceneWithShadow(R"({"technique": "vsm", "parameters": {"bleedReduction": 0.3}})"),
                         "t.json");
    EXPECT_EQ(s.shadow.technique, techniqueFromName("vsm"));
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
    overrideTechnique(fx, techniqueFromName("vsm"), {{"bleedReduction", 0.0}});
    EXPECT_EQ(fx.filter, FilterKind::Sat);
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "bleedReduction"), 0.0);
    overrideTechnique(fx, techniqueFromName("hard"));
    EXPECT_EQ(fx.filter, FilterKind::None);
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "constantBias"), 5e-4);  // parameters reset
    fx.filter = FilterKind::Gaussian;
    overrideTechnique(fx, techniqueFromName("msm-soft"));
    EXPECT_EQ(fx.filter, FilterKind::Sat);
    // The same technique keeps its parameters and takes the given ones on top.
    overrideTechnique(fx, techniqueFromName("vsm"), {{"bleedReduction", 0.0}});
    overrideTechnique(fx, techniqueFromName("vsm"), {{"minVariance", 1e-3}});
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "bleedReduction"), 0.0);
    EXPECT_DOUBLE_EQ(techniqueParameter(fx, "minVariance"), 1e-3);
    EXPECT_THROW(overrideTechnique(fx, techniqueFromName("vsm"), {{"nope", 1}}), std::invalid_argument);
    EXPECT_THROW(overrideTechnique(fx, techniqueFromName("vsm"), {{"minVariance", -1}}), std::invalid_argument);
}

TEST(TechniqueTable, SpecParsing) {
    auto [t, p] = parseTechniqueSpec("evsm4:positiveExponent=30:negativeExponent=8");
    EXPECT_EQ(t, techniqueFromName("evsm4"));
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
    fx.technique = techniqueFromName("evsm4");
    fx.parameters = {{"positiveExponent", 80.0}, {"negativeExponent", 5.0}};
    const auto c = shadowClearValues(fx);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_FLOAT_EQ(c[0].x, float(std::exp(42.0)));  // clamped: e^{2c} must stay finite
    EXPECT_TRUE(std::isfinite(c[0].y));
    EXPECT_FLOAT_EQ(c[0].z, float(-std::exp(-5.0)));
    fx.technique = techniqueFromName("csm");
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
    const TechniqueRow& soft = techniqueRow(techniqueFromName("msm-soft"));
    EXPECT_FALSE(techniqueInKit(soft, shaders.string()));
    test::writeFile(shaders / soft.file, "// present\n");
    EXPECT_TRUE(techniqueInKit(soft, shaders.string()));
    EXPECT_FALSE(techniqueInKit(techniqueRow(techniqueFromName("msm4")), shaders.string()));
}

}  // namespace sl

namespace sl {

// The lighting program of a row includes that row's file and no other row's (the file is the
// row's, handed over as SL_TECHNIQUE_FILE); a row that stores through its own file has it in
// the shadow pass's program too.
TEST(TechniqueTable, EachRowsProgramsIncludeItsFileAndNoOtherRows) {
    const ShaderLibrary lib = test::library("reference");
    auto includes = [](const AssembledShader& a, const TechniqueRow& row) {
        return std::any_of(a.fileNames.begin(), a.fileNames.end(),
                           [&](const std::string& f) { return f == "shaders/" + row.file; });
    };
    for (const TechniqueRow& row : techniqueTable()) {
        if (!row.solvesStage.empty()) continue;  // their files need the msm stage's solution
        ShadowEffect fx;
        overrideTechnique(fx, row.id);
        const std::vector<std::string> defines = techniqueDefines(fx);
        const AssembledShader lighting = lib.assemble("lighting.frag", defines);
        for (const TechniqueRow& other : techniqueTable())
            EXPECT_EQ(includes(lighting, other), other.id == row.id) << row.name << " " << other.name;
        if (row.store == StoreKind::File)
            EXPECT_TRUE(includes(lib.assemble("techniques/store.frag", defines), row)) << row.name;
    }
}

// `#include NAME` takes its file from a framework define only; any other name is refused.
TEST(TechniqueTable, AnIncludeByNameNeedsTheFrameworksDefine) {
    const fs::path dir = test::tempDir("include_by_name");
    test::writeFile(dir / "a.glsl", "#include SL_SOME_FILE\nfloat a;\n");
    test::writeFile(dir / "b.glsl", "float b;\n");
    ShaderLibrary lib({}, {dir}, dir);
    const AssembledShader ok = lib.assemble("a.glsl", {"SL_SOME_FILE=b.glsl"});
    EXPECT_NE(ok.text.find("float b;"), std::string::npos);
    try {
        lib.assemble("a.glsl", {});
        ADD_FAILURE() << "an undefined name was included";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("a.glsl:1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("a name the framework defines"), std::string::npos) << e.what();
    }
}

}  // namespace sl
