// The viewer's settings (EditableScene, ViewOptions): a change is accepted exactly when the
// same value in the scene file would be, and a bad one is refused with the file, the key and
// the expectation, leaving the scene as it was. No GL: these are the model under the panels.
#include "editable_scene.h"
#include "gl_test_support.h"
#include "view_options.h"

namespace sl {
namespace {

EditableScene classic() { return EditableScene(test::scenePath("classic").string()); }

}  // namespace

TEST(ViewSettings, AValueReachesTheSceneAsTheLoaderReadsIt) {
    EditableScene s = classic();
    s.set("shadow.filter.radius", std::string("7"));
    s.set("shadow.momentBias", std::string("1e-4"));
    s.set("lights.0.size", std::string("0.25"));
    EXPECT_EQ(s.scene().shadow.gaussianRadius, 7);
    EXPECT_FLOAT_EQ(s.scene().shadow.gaussianSigma, 2.0f);  // classic.json's own sigma stays
    EXPECT_FLOAT_EQ(s.scene().shadow.momentBias, 1e-4f);
    EXPECT_FLOAT_EQ(s.scene().lights[0].size, 0.25f);
    // null removes the key: the loader's default sigma = radius / 2 applies again.
    s.set("shadow.filter.sigma", nlohmann::json(nullptr));
    EXPECT_FLOAT_EQ(s.scene().shadow.gaussianSigma, 3.5f);
}

TEST(ViewSettings, SwitchingTheFilterTypeKeepsEachTypesParameters) {
    EditableScene s = classic();  // gaussian, radius 4, sigma 2
    s.set("shadow.filter.type", std::string("sat"));
    EXPECT_EQ(s.scene().shadow.filter, FilterKind::Sat);
    EXPECT_FLOAT_EQ(s.scene().shadow.satKernelTexels, 9.0f);  // docs/scenes.md default
    s.set("shadow.filter.kernel", std::string("21.5"));
    s.set("shadow.filter.type", std::string("gaussian"));
    EXPECT_EQ(s.scene().shadow.gaussianRadius, 4);
    EXPECT_FLOAT_EQ(s.scene().shadow.gaussianSigma, 2.0f);
    s.set("shadow.filter.type", std::string("sat"));
    EXPECT_FLOAT_EQ(s.scene().shadow.satKernelTexels, 21.5f);
    s.set("shadow.filter.type", std::string("none"));
    EXPECT_EQ(s.scene().shadow.filter, FilterKind::None);
}

TEST(ViewSettings, SwitchingTheTechniqueKeepsEachTechniquesFilterAndParameters) {
    EditableScene s = classic();  // msm4, gaussian radius 4
    s.set("shadow.technique", std::string("vsm"));  // vsm takes a Gaussian: the filter stays
    EXPECT_EQ(s.scene().shadow.technique, techniqueFromName("vsm"));
    EXPECT_EQ(s.scene().shadow.filter, FilterKind::Gaussian);
    EXPECT_EQ(s.scene().shadow.gaussianRadius, 4);
    s.set("shadow.parameters.bleedReduction", std::string("0.3"));
    s.set("shadow.technique", std::string("hard"));  // filter none only: the row's default
    EXPECT_EQ(s.scene().shadow.technique, techniqueFromName("hard"));
    EXPECT_EQ(s.scene().shadow.filter, FilterKind::None);
    EXPECT_TRUE(s.scene().shadow.parameters.empty());  // vsm's parameter is not hard's
    s.set("shadow.parameters.slopeBias", std::string("2.5"));
    EXPECT_DOUBLE_EQ(s.scene().shadow.parameters.at("slopeBias"), 2.5);
    s.set("shadow.technique", std::string("vsm"));
    EXPECT_EQ(s.scene().shadow.filter, FilterKind::Gaussian);
    EXPECT_DOUBLE_EQ(s.scene().shadow.parameters.at("bleedReduction"), 0.3);
    EXPECT_EQ(s.scene().shadow.parameters.count("slopeBias"), 0u);
    s.set("shadow.technique", std::string("hard"));
    EXPECT_DOUBLE_EQ(s.scene().shadow.parameters.at("slopeBias"), 2.5);
    // A name the table does not have: the loader's message, nothing changes.
    try {
        s.set("shadow.technique", std::string("vsmm"));
        ADD_FAILURE() << "vsmm accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("/shadow/technique: expected one of"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(s.scene().shadow.technique, techniqueFromName("hard"));
}

TEST(ViewSettings, ABadValueNamesFileKeyAndExpectationAndChangesNothing) {
    EditableScene s = classic();
    auto message = [&](const std::string& key, const std::string& value) -> std::string {
        try {
            s.set(key, value);
        } catch (const SceneError& e) {
            return e.what();
        }
        return "accepted";
    };
    std::string m = message("shadow.filter.radius", "65");
    EXPECT_NE(m.find("classic.json: /shadow/filter/radius: expected an integer in [0, 64]"),
              std::string::npos) << m;
    m = message("shadow.filtr.type", "sat");
    EXPECT_NE(m.find("unknown key \"filtr\""), std::string::npos) << m;
    m = message("lights.1.size", "1");
    EXPECT_NE(m.find("/lights: expected an index below 1"), std::string::npos) << m;
    m = message("shadow.mapSize.x", "1");
    EXPECT_NE(m.find("/shadow/mapSize: expected nothing below"), std::string::npos) << m;
    m = message("shadow.filter.type", "box");
    EXPECT_NE(m.find("/shadow/filter/type: expected one of"), std::string::npos) << m;
    EXPECT_EQ(s.scene().shadow.filter, FilterKind::Gaussian);
    EXPECT_EQ(s.scene().shadow.gaussianRadius, 4);
    EXPECT_EQ(s.document(), EditableScene(test::scenePath("classic").string()).document());
}

TEST(ViewSettings, ViewKeysPickImageAndChannel) {
    ViewOptions o;
    EXPECT_TRUE(setViewOption(o, "view.image", "moments_raw"));
    EXPECT_TRUE(setViewOption(o, "view.channel", "2"));
    EXPECT_EQ(o.image, "moments_raw");
    EXPECT_EQ(o.channel, 2);
    EXPECT_TRUE(setViewOption(o, "view.channel", "all"));
    EXPECT_EQ(o.channel, -1);
    EXPECT_FALSE(setViewOption(o, "shadow.filter.radius", "3"));  // a scene key: not a view key
    EXPECT_THROW(setViewOption(o, "view.channel", "4"), std::invalid_argument);
    EXPECT_THROW(setViewOption(o, "view.image", "nope"), std::invalid_argument);
    EXPECT_THROW(setViewOption(o, "view.zoom", "2"), std::invalid_argument);
    EXPECT_EQ(o.image, "moments_raw");
}

}  // namespace sl
