// Tests of the scene format (framework/scene/scene_loader.cpp): every public scene loads and
// carries probes, and a malformed scene fails with one line that names the file, the JSON
// path, what was expected and what was found. The shapes themselves: test_mesh.cpp.
#include "gl_test_support.h"
#include "mesh.h"
#include "scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace sl;

std::vector<fs::path> publicScenes() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(test::root() / "scenes"))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A scratch directory of this test process (for OBJ files and scenes that refer to them).
fs::path scratchDir() {
    const char* env = std::getenv("SHADOWLAB_TEST_TMP");
    fs::path dir = (env ? fs::path(env) : fs::temp_directory_path()) /
                   ("test_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// A small valid scene; tests break one thing in it at a time.
json baseScene() {
    return json::parse(R"({
      "description": "test scene",
      "camera": {"position": [0, 3, 6], "target": [0, 0, 0]},
      "lights": [{"type": "spot", "position": [2, 6, 2], "target": [0, 0, 0]}],
      "objects": [
        {"name": "ground", "shape": "plane", "size": [10, 10]},
        {"name": "box", "shape": "box", "size": [1, 1, 1], "translate": [0, 0.5, 0]},
        {"name": "ball", "shape": "sphere", "radius": 0.5, "translate": [1, 1, 0]}
      ],
      "shadow": {"mapSize": 512, "filter": {"type": "gaussian", "radius": 4}},
      "expect": {"probes": [{"pixel": [10, 20], "shadow": 1, "why": "test"}]}
    })");
}

// The SceneError message of parsing `text`, or "" (and a test failure) if it parses.
std::string errorOf(const std::string& text, const std::string& path = "bad.json") {
    try {
        parseScene(text, path);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no SceneError for:\n" << text;
    return "";
}

// ---------------------------------------------------------------- the public scenes

TEST(SceneFiles, EveryPublicSceneLoadsWithDescriptionAndProbes) {
    const auto files = publicScenes();
    std::set<std::string> names;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        Scene scene;
        ASSERT_NO_THROW(scene = loadScene(file.string()));
        names.insert(scene.name);
        EXPECT_FALSE(scene.description.empty());
        EXPECT_GE(scene.probes.size(), 2u);
        EXPECT_LE(scene.probes.size(), 4u);
        for (const ShadowProbe& p : scene.probes) {
            EXPECT_FALSE(p.why.empty());
            EXPECT_TRUE(p.shadow == 0.0f || p.shadow == 1.0f) << "probes are fully lit or shadowed";
            EXPECT_GE(p.tolerance, 0.05f);
            EXPECT_LE(p.tolerance, 0.1f);
        }
    }
    for (const char* expected : {"classic", "contact", "depth_range", "thin", "grazing",
                                 "wide_blur", "unlit_no_shadow"})
        EXPECT_TRUE(names.count(expected)) << "missing scenes/" << expected << ".json";
}

TEST(SceneFiles, EveryObjectTessellates) {
    for (const fs::path& file : publicScenes()) {
        const Scene scene = loadScene(file.string());
        for (const Object& object : scene.objects) {
            SCOPED_TRACE(file.filename().string() + ": " + object.name);
            const Mesh mesh = buildMesh(object, scene);
            EXPECT_GE(mesh.indices.size(), 6u);
            EXPECT_FALSE(worldBounds(mesh, objectToWorld(object)).empty());
        }
    }
}

TEST(SceneFiles, EachSceneExercisesItsCase) {
    auto load = [](const char* name) { return loadScene((test::root() / "scenes" / name).string()); };
    const Scene classic = load("classic.json");
    EXPECT_EQ(classic.shadow.filter, FilterKind::Gaussian);
    EXPECT_EQ(classic.shadow.gaussianRadius, 4);
    EXPECT_EQ(classic.cameras.size(), 2u);
    EXPECT_EQ(classic.cameras[0].name, "main");

    const Scene contact = load("contact.json");
    EXPECT_EQ(contact.shadow.filter, FilterKind::Sat);
    EXPECT_NEAR(contact.shadow.satKernelTexels, 7.0f, 1.0f);

    const Scene depthRange = load("depth_range.json");
    ASSERT_TRUE(depthRange.shadow.depthRange.has_value());
    EXPECT_GT(depthRange.shadow.depthRange->y / depthRange.shadow.depthRange->x, 10.0f);

    const Scene thin = load("thin.json");
    EXPECT_NE(thin.cameras[0].width, thin.cameras[0].height);
    EXPECT_GE(thin.shadow.mapSize, 1024);
    EXPECT_TRUE(std::any_of(thin.objects.begin(), thin.objects.end(),
                            [](const Object& o) { return o.shape == ShapeType::Mesh; }));

    const Scene grazing = load("grazing.json");
    ASSERT_EQ(grazing.lights.size(), 1u);
    EXPECT_EQ(grazing.lights[0].type, LightType::Directional);

    const Scene wide = load("wide_blur.json");
    EXPECT_EQ(wide.shadow.filter, FilterKind::Sat);
    EXPECT_GT(wide.shadow.satKernelTexels, 30.0f);
    EXPECT_NE(wide.shadow.satKernelTexels, std::floor(wide.shadow.satKernelTexels));

    const Scene unlit = load("unlit_no_shadow.json");
    for (const Light& l : unlit.lights) EXPECT_FALSE(l.castsShadows);
}

// ---------------------------------------------------------------- parsing

TEST(SceneParse, DefaultsAndDerivedValues) {
    const Scene s = parseScene(baseScene().dump(), "dir/base.json");
    EXPECT_EQ(s.name, "base");
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_EQ(s.cameras[0].name, "main");
    EXPECT_EQ(s.cameras[0].width, 512);
    EXPECT_EQ(s.objects[2].shape, ShapeType::Sphere);
    EXPECT_FLOAT_EQ(s.objects[2].radius, 0.5f);
    EXPECT_EQ(s.shadow.mapSize, 512);
    EXPECT_FALSE(s.shadow.depthRange.has_value());  // "auto"
    EXPECT_FLOAT_EQ(s.shadow.gaussianSigma, 2.0f);  // radius / 2
    EXPECT_FLOAT_EQ(s.shadow.momentBias, 3.0e-5f);
    ASSERT_EQ(s.probes.size(), 1u);
    EXPECT_EQ(s.probes[0].camera, "main");
    EXPECT_EQ(s.probes[0].pixel, glm::ivec2(10, 20));
}

TEST(SceneParse, CamerasFiltersAndDepthRange) {
    json j = baseScene();
    j.erase("camera");
    j["cameras"] = json::parse(R"([{"name": "front", "position": [0, 1, 5], "target": [0, 0, 0]},
                                   {"name": "top", "position": [0, 9, 0], "target": [0, 0, 0],
                                    "up": [0, 0, -1], "width": 640, "height": 480}])");
    j["expect"]["probes"][0]["camera"] = "top";
    j["shadow"] = json::parse(R"({"mapSize": 2048, "depthRange": [0.5, 20],
                                  "filter": {"type": "sat", "kernel": 40.5}})");
    const Scene s = parseScene(j.dump(), "cams.json");
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_EQ(s.cameras[1].width, 640);
    EXPECT_EQ(s.probes[0].camera, "top");
    EXPECT_EQ(s.shadow.filter, FilterKind::Sat);
    EXPECT_FLOAT_EQ(s.shadow.satKernelTexels, 40.5f);
    ASSERT_TRUE(s.shadow.depthRange.has_value());
    EXPECT_EQ(*s.shadow.depthRange, glm::vec2(0.5f, 20.0f));

    j["shadow"]["filter"] = json::parse(R"({"type": "none"})");
    EXPECT_EQ(parseScene(j.dump(), "none.json").shadow.filter, FilterKind::None);
    j["lights"] = json::array();  // no light at all is a valid scene
    EXPECT_TRUE(parseScene(j.dump(), "dark.json").lights.empty());
}

// ---------------------------------------------------------------- error messages

struct BadScene {
    const char* what;
    std::function<void(json&)> breakIt;
    std::vector<std::string> words;  // besides the file name, "expected" and "found"
};

TEST(SceneErrors, NameFileJsonPathExpectedAndFound) {
    const std::vector<BadScene> cases = {
        {"bad type", [](json& j) { j["objects"][1]["translate"] = "up"; },
         {"/objects/1/translate", "an array of 3 numbers", "found \"up\""}},
        {"negative radius", [](json& j) { j["objects"][2]["radius"] = -1; },
         {"/objects/2/radius", "a number > 0", "found -1"}},
        {"typo in a key", [](json& j) { j["objects"][2]["raduis"] = 1; },
         {"/objects/2/raduis", "unknown key \"raduis\"", "\"radius\"", "\"translate\""}},
        {"typo at top level", [](json& j) { j["lihgts"] = json::array(); },
         {"/lihgts", "unknown key", "\"lights\""}},
        {"missing camera", [](json& j) { j.erase("camera"); },
         {"/camera", "found nothing"}},
        {"camera and cameras", [](json& j) { j["cameras"] = json::array({j["camera"]}); },
         {"/cameras", "nothing when \"camera\" is given"}},
        {"bad filter type", [](json& j) { j["shadow"]["filter"]["type"] = "box"; },
         {"/shadow/filter/type", "\"gaussian\"", "\"sat\"", "found \"box\""}},
        {"gaussian key on a sat filter",
         [](json& j) { j["shadow"]["filter"] = {{"type", "sat"}, {"radius", 4}}; },
         {"/shadow/filter/radius", "unknown key", "\"kernel\""}},
        {"filter radius too large", [](json& j) { j["shadow"]["filter"]["radius"] = 65; },
         {"/shadow/filter/radius", "[0, 64]", "found 65"}},
        {"map size not a power of two", [](json& j) { j["shadow"]["mapSize"] = 1000; },
         {"/shadow/mapSize", "power of two", "found 1000"}},
        {"map size too small", [](json& j) { j["shadow"]["mapSize"] = 32; },
         {"/shadow/mapSize", "[64, 4096]", "found 32"}},
        {"depth range reversed", [](json& j) { j["shadow"]["depthRange"] = {5, 1}; },
         {"/shadow/depthRange/1", "> 5", "found 1"}},
        {"depth range word", [](json& j) { j["shadow"]["depthRange"] = "automatic"; },
         {"/shadow/depthRange", "\"auto\"", "found \"automatic\""}},
        {"moment bias", [](json& j) { j["shadow"]["momentBias"] = 0.5; },
         {"/shadow/momentBias", "[0, 0.1]", "found 0.5"}},
        {"light type", [](json& j) { j["lights"][0]["type"] = "spotlight"; },
         {"/lights/0/type", "\"spot\"", "\"directional\"", "found \"spotlight\""}},
        {"cone angle", [](json& j) { j["lights"][0]["coneDegrees"] = 180; },
         {"/lights/0/coneDegrees", "(0, 170)", "found 180"}},
        {"extent on a spot light", [](json& j) { j["lights"][0]["extent"] = 5; },
         {"/lights/0/extent", "unknown key", "spot light"}},
        {"negative colour", [](json& j) { j["objects"][0]["color"] = {0.5, -0.1, 0.5}; },
         {"/objects/0/color/1", ">= 0", "found -0.1"}},
        {"camera width", [](json& j) { j["camera"]["width"] = 8; },
         {"/camera/width", "[16, 4096]", "found 8"}},
        {"fov", [](json& j) { j["camera"]["fovYDegrees"] = 180; },
         {"/camera/fovYDegrees", "(0, 180)", "found 180"}},
        {"probe outside the image", [](json& j) { j["expect"]["probes"][0]["pixel"] = {512, 0}; },
         {"/expect/probes/0/pixel/0", "[0, 511]", "found 512"}},
        {"probe camera", [](json& j) { j["expect"]["probes"][0]["camera"] = "side"; },
         {"/expect/probes/0/camera", "\"main\"", "found \"side\""}},
        {"unknown shape", [](json& j) { j["objects"][1]["shape"] = "cube"; },
         {"/objects/1/shape", "\"box\"", "found \"cube\""}},
        {"no objects", [](json& j) { j["objects"] = json::array(); },
         {"/objects", "non-empty array", "found []"}},
        // The lighting pass's limits (framework/scene/scene_limits.h), refused here with the limit.
        {"five lights",
         [](json& j) { for (int i = 0; i < 4; ++i) j["lights"].push_back(j["lights"][0]); },
         {"/lights", "at most 4 lights", "found 5"}},
        {"five cascades",
         [](json& j) {
             j["lights"][0] = {{"type", "directional"}, {"position", {0, 6, 0}},
                               {"target", {0, 0, 0}}, {"cascades", 5}};
         },
         {"/lights/0/cascades", "[1, 4]", "found 5"}},
        // csm's 8 terms take 4 maps per light and cascade: 4 + 4 + 4 + 2 × 4 = 20 > 16.
        {"seventeen maps and more",
         [](json& j) {
             j["shadow"]["technique"] = "csm";
             j["lights"][0] = {{"type", "directional"}, {"position", {0, 6, 0}},
                               {"target", {0, 0, 0}}, {"cascades", 2}};
             for (int i = 0; i < 3; ++i) j["lights"].push_back(j["lights"][0]);
             for (int i = 1; i < 4; ++i) j["lights"][i].erase("cascades");
         },
         {"/lights", "at most 16 shadow maps", "\"csm\" takes 4", "found 20"}},
    };
    for (const BadScene& c : cases) {
        SCOPED_TRACE(c.what);
        json j = baseScene();
        c.breakIt(j);
        const std::string message = errorOf(j.dump(2), "scenes/bad_scene.json");
        EXPECT_EQ(message.rfind("scenes/bad_scene.json: /", 0), 0u) << message;
        EXPECT_NE(message.find(": expected "), std::string::npos) << message;
        EXPECT_NE(message.find(", found "), std::string::npos) << message;
        for (const std::string& word : c.words)
            EXPECT_NE(message.find(word), std::string::npos) << "'" << word << "' not in: " << message;
    }
}

TEST(SceneErrors, DuplicateCameraNames) {
    json j = baseScene();
    j.erase("camera");
    j["cameras"] = {{{"name", "a"}, {"position", {0, 1, 5}}, {"target", {0, 0, 0}}},
                    {{"name", "a"}, {"position", {0, 9, 5}}, {"target", {0, 0, 0}}}};
    const std::string message = errorOf(j.dump());
    EXPECT_NE(message.find("/cameras/1/name"), std::string::npos) << message;
}

TEST(SceneErrors, InvalidJsonGivesLineAndColumn) {
    const std::string text = "{\n  \"camera\": {\n    \"position\": [0, 3, 6],,\n  }\n}\n";
    const std::string message = errorOf(text, "syntax.json");
    EXPECT_EQ(message.rfind("syntax.json:3:", 0), 0u) << message;
    EXPECT_NE(message.find("line 3"), std::string::npos) << message;
    EXPECT_NE(message.find("invalid JSON"), std::string::npos) << message;
}

TEST(SceneErrors, MissingObjFileIsNamed) {
    json j = baseScene();
    j["objects"].push_back({{"name", "statue"}, {"shape", "mesh"}, {"path", "meshes/nope.obj"}});
    const std::string file = (scratchDir() / "missing_obj.json").string();
    const std::string message = errorOf(j.dump(), file);
    EXPECT_EQ(message.rfind(file + ": /objects/3/path: expected ", 0), 0u) << message;
    EXPECT_NE(message.find("found \"meshes/nope.obj\""), std::string::npos) << message;
}

TEST(SceneErrors, UnreadableSceneFile) {
    try {
        loadScene("no/such/scene.json");
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("no/such/scene.json"), std::string::npos);
    }
}

}  // namespace
