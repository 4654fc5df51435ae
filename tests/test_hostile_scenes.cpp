// Hostile input (nothing a student submits may crash the grader): scene files. Values that pass the
// double checks but become inf or 0 as floats (translate 1e308, far 1e308, a spot depthRange near
// 1e-300) rendered a blank image with exit 0; a description nested 100 000 arrays deep crashed the
// process that built the error message; a FIFO blocked forever and a directory was "invalid JSON at
// line 1".
#include "scene.h"

#include "gl_test_support.h"

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <future>

namespace sl {
namespace {

// A valid scene (a spot light, an explicit depth range) with `patch` replacing `what`.
std::string scene(const std::string& what = "", const std::string& patch = "") {
    std::string s = R"({
  "camera": {"position": [0, 3, 6], "target": [0, 0, 0], "far": 50},
  "lights": [{"type": "spot", "position": [2, 5, 2], "target": [0, 0, 0], "coneDegrees": 60}],
  "objects": [{"shape": "plane", "size": 10}, {"shape": "box", "size": 1, "translate": [0, 0.5, 0]}],
  "shadow": {"depthRange": [0.5, 20], "filter": {"type": "gaussian", "radius": 2}}
})";
    if (!what.empty()) s.replace(s.find(what), what.size(), patch);
    return s;
}

std::string error(const std::string& json) {
    try {
        parseScene(json, "hostile.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(HostileScenes, NumbersAreCheckedAsTheFloatsTheyBecome) {
    ASSERT_EQ(error(scene()), "");
    const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
        {R"("translate": [0, 0.5, 0])", R"("translate": [1e308, 0.5, 0])", "/objects/1/translate/0"},
        {R"("far": 50)", R"("far": 1e308)", "/camera/far"},
        {R"("depthRange": [0.5, 20])", R"("depthRange": [1e-300, 20])", "/shadow/depthRange/0"},
        {R"("size": 1,)", R"("size": 1e-60,)", "/objects/1/size"},
        {R"("depthRange": [0.5, 20])", R"("depthRange": [1, 1.00000000001])", "/shadow/depthRange/1"}};
    for (const auto& [what, patch, pointer] : cases) {
        const std::string e = error(scene(what, patch));
        EXPECT_EQ(e.rfind("hostile.json: " + pointer + ": expected ", 0), 0u) << patch << "\n" << e;
        EXPECT_NE(e.find("32-bit float"), std::string::npos) << e;
    }
}

TEST(HostileScenes, DeeplyNestedJsonIsAnErrorNotACrash) {
    std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::string e = error(scene(R"("camera")", R"("description": )" + deep + R"(, "camera")"));
    EXPECT_NE(e.find("hostile.json:2:"), std::string::npos) << e.substr(0, 200);
    EXPECT_NE(e.find("nested more than 64 deep"), std::string::npos) << e.substr(0, 200);
    // Brackets inside strings are text, not nesting.
    EXPECT_EQ(error(scene(R"("camera")", R"("description": ")" + std::string(1000, '[') +
                                             R"(", "camera")")), "");
}

TEST(HostileScenes, AFifoOrADirectoryIsNamedWithoutBlocking) {
    const fs::path dir = test::tempDir("hostile_scene_kinds");
    const fs::path fifo = dir / "fifo.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto load = [](const fs::path& p) {
        return std::async(std::launch::async, [p]() -> std::string {
            try {
                loadScene(p.string());
            } catch (const SceneError& e) {
                return e.what();
            }
            return "";
        });
    };
    auto fromFifo = load(fifo);
    if (fromFifo.wait_for(std::chrono::seconds(5)) != std::future_status::ready) {
        // Unblock the reader so that the test process can end, then fail.
        std::ofstream(fifo) << "{}";
        FAIL() << "loading a FIFO blocked";
    }
    EXPECT_EQ(fromFifo.get(), fifo.string() + ": expected a scene file (JSON), found a FIFO");
    auto fromDir = load(dir);
    EXPECT_EQ(fromDir.get(), dir.string() + ": expected a scene file (JSON), found a directory");
}

}  // namespace sl
