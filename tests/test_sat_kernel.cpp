// satKernelTexels (sat_lookup.glsl): each pixel's SAT box from a blocker search over the table
// and the light's size. Probed on maps whose answer is known from the geometry alone, against
// a double oracle on a busy map, through the scene loader, and as a stub.
#include "gl_test_support.h"
#include "oracles/sat_kernel_oracle.h"
#include "probe.h"

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

namespace sl {
namespace {

// A receiver plane at relative depth zs, and blockers at zb over the columns x < edge: each
// texel's moments (z, z², z³, z⁴).
Image twoDepthMap(int n, int edge, float zs, float zb) {
    Image img(n, n, 4);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float z = x < edge ? zb : zs;
            for (int c = 0; c < 4; ++c) img.at(x, y, c) = std::pow(z, float(c + 1));
        }
    return img;
}

SatKernelCase receiverAt(float cx, float zr, float lightTexels, bool perspective) {
    SatKernelCase c;
    c.center = {cx, 32.0f};
    c.searchTexels = 16.0f;
    c.zr = zr;
    c.depthRange = {2.0f, 10.0f};  // z = 0.7 at world depth 7.6, z = 0.25 at 4
    c.lightTexels = lightTexels;
    c.perspective = perspective;
    c.kernelRange = {1.0f, 64.0f};
    return c;
}

}  // namespace

// Receiver at 0.7, blockers at 0.25 (world depths 7.6 and 4): a box holding a share f of
// blockers has mean 0.7 − 0.45 f and variance f (1 − f) 0.45², so Chebyshev's bound is 1 − f
// exactly and the blockers' depth comes out 0.25 whatever f. The penumbra by similar
// triangles: 20 · (7.6 − 4) / 4 = 18 texels (spot), 5 · (7.6 − 4) = 18 (directional). A bug
// that takes the box's mean for the blockers' depth changes with f; one that drops the
// perspective division gives 72, clamped to 64.
TEST(SatKernel, BlockersDepthAndPenumbraFromTheGeometry) {
    test::sharedContext();
    const Image map = twoDepthMap(64, 24, 0.7f, 0.25f);
    std::vector<SatKernelCase> cases;
    for (float cx : {18.0f, 20.0f, 24.0f, 28.0f})  // blocker shares 7/8, 3/4, 1/2, 1/4
        for (bool perspective : {true, false})
            cases.push_back(receiverAt(cx, 0.7f, perspective ? 20.0f : 5.0f, perspective));
    const std::vector<float> w = probeSatKernelTexels(test::library("reference"), map, cases);
    ASSERT_EQ(w.size(), cases.size());
    for (size_t i = 0; i < w.size(); ++i)
        // float32: σ² = b2 − μ² keeps ~1e-6 of its value here; 1e-3 leaves room for the
        // order of operations of any correct solution.
        EXPECT_NEAR(w[i], 18.0, 18.0 * 1e-3) << "case " << i << " at x " << cases[i].center.x;
}

// Nothing in front: the smallest box; a penumbra wider than the largest box: the largest.
TEST(SatKernel, GuardsAndClamp) {
    test::sharedContext();
    const Image map = twoDepthMap(64, 24, 0.7f, 0.25f);
    std::vector<SatKernelCase> cases = {
        receiverAt(24.0f, 0.2f, 20.0f, true),     // in front of every texel
        receiverAt(50.0f, 0.699f, 20.0f, true),   // lit ground, the bias below the surface
        receiverAt(24.0f, 0.7f, 200.0f, true),    // 180 texels wanted
        receiverAt(24.0f, 0.7f, 0.5f, true),      // 0.45 texels wanted
    };
    const std::vector<float> w = probeSatKernelTexels(test::library("reference"), map, cases);
    EXPECT_EQ(w[0], 1.0f);
    EXPECT_EQ(w[1], 1.0f);
    EXPECT_EQ(w[2], 64.0f);
    EXPECT_EQ(w[3], 1.0f);
}

// A busy map (tilted ground with a ripple, square blockers, as SatPrecision's), receivers at
// random places and depths: the reference against the double oracle, away from the guards
// (where a rounding flips a branch). Measured worst: printed.
TEST(SatKernel, ReferenceMatchesTheDoubleOracle) {
    test::sharedContext();
    const int n = 256;
    Image map(n, n, 4);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            float z = 0.6f + 0.3f * float(x + 2 * y) / float(3 * n) +
                      0.02f * std::sin(x / 7.0f) * std::cos(y / 11.0f);
            if ((x / 32) % 3 == 1 && (y / 32) % 3 == 1) z = 0.3f;
            for (int c = 0; c < 4; ++c) map.at(x, y, c) = std::pow(z, float(c + 1));
        }
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> pos(0.0f, float(n)), depth(0.3f, 1.0f),
        search(2.0f, 48.0f), light(1.0f, 40.0f);
    std::vector<SatKernelCase> cases;
    for (int i = 0; i < 2000; ++i) {
        SatKernelCase c;
        c.center = {pos(rng), pos(rng)};
        c.searchTexels = search(rng);
        c.zr = depth(rng);
        c.depthRange = {1.0f, 9.0f};
        c.lightTexels = light(rng);
        c.perspective = i % 2 == 0;
        c.kernelRange = {1.0f, 256.0f};
        cases.push_back(c);
    }
    const std::vector<float> w = probeSatKernelTexels(test::library("reference"), map, cases);
    const auto sat = oracle::summedAreaTable(map.pixels, n, n);
    double worst = 0.0;
    int compared = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const SatKernelCase& c = cases[i];
        const oracle::SatKernelInput in{glm::dvec2(c.center), c.searchTexels, c.zr,
                                        glm::dvec2(c.depthRange), c.lightTexels, c.perspective,
                                        glm::dvec2(c.kernelRange)};
        const glm::dvec4 b = oracle::satBoxAverage(sat, n, n, in.center, glm::dvec2(in.searchTexels));
        const double var = b.y - b.x * b.x, d = in.zr - b.x;
        // Away from the guards: a blocker share of 1 % or more, variance well above the floor.
        if (d <= 1e-3 || var < 1e-5 || 1.0 - var / (var + d * d) < 1e-2) continue;
        const double want = oracle::satKernelTexels(sat, n, n, in);
        worst = std::max(worst, std::fabs(w[i] - want) / want);
        ++compared;
    }
    std::printf("[sat-kernel] %d cases compared, worst relative error %.3g\n", compared, worst);
    EXPECT_GT(compared, 200);
    EXPECT_LE(worst, 1e-2);
}

// "kernel": "per-pixel" is msm4's; anything else is named with the file and key.
TEST(SatKernel, LoaderNamesTheKernelKey) {
    const std::string base =
        R"({"camera": {"position": [0, 4, 6], "target": [0, 0, 0]},
            "lights": [{"type": "spot", "position": [0, 6, 0], "target": [0, 0, 0], "size": 0.5}],
            "objects": [{"shape": "plane", "size": [4, 4]}], "shadow": )";
    auto error = [&](const std::string& shadow) {
        try {
            parseScene(base + shadow + "}", "scenes/x.json");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error(R"({"filter": {"type": "sat", "kernel": "per-pixel", "maxKernelTexels": 32}})"), "");
    const std::string word = error(R"({"filter": {"type": "sat", "kernel": "wide"}})");
    EXPECT_NE(word.find("scenes/x.json"), std::string::npos) << word;
    EXPECT_NE(word.find("/shadow/filter/kernel"), std::string::npos) << word;
    EXPECT_NE(word.find("\"per-pixel\""), std::string::npos) << word;
    const std::string vsm =
        error(R"({"technique": "vsm", "filter": {"type": "sat", "kernel": "per-pixel"}})");
    EXPECT_NE(vsm.find("msm4"), std::string::npos) << vsm;
    const std::string fixedKey =
        error(R"({"filter": {"type": "sat", "kernel": 7, "maxKernelTexels": 32}})");
    EXPECT_NE(fixedKey.find("maxKernelTexels"), std::string::npos) << fixedKey;
}

// A per-pixel scene with satBoxAverage solved and satKernelTexels still the stub: the
// renderer names the function, and the shadow is hatched, never lit as if correct.
TEST(SatKernel, StubIsNamedOnAPerPixelScene) {
    test::sharedContext();
    auto read = [](const fs::path& p) {
        std::ifstream in(p);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    const std::string ref = read(test::root() / "reference" / "sat_lookup.glsl");
    const std::string stub = read(test::root() / "student" / "sat_lookup.glsl");
    const size_t cut = ref.find("// The box each pixel filters with");
    const size_t stubAt = stub.rfind("float satKernelTexels(");  // not the comment
    ASSERT_NE(cut, std::string::npos);
    ASSERT_NE(stubAt, std::string::npos);
    const fs::path dir = test::tempDir("sat_kernel_stub");
    test::writeFile(dir / "sat_lookup.glsl", ref.substr(0, cut) + stub.substr(stubAt));
    Renderer renderer(ShaderLibrary::mixed(test::root() / "reference",
                                           {{"sat_lookup.glsl", dir}}, test::root()));
    Scene scene = loadScene(test::scenePath("penumbra"));
    RenderResult r = renderer.render(scene, planPasses(scene));
    bool named = false;
    for (const auto& note : r.stubNotes)
        named = named || (note.find("satKernelTexels") != std::string::npos &&
                          note.find("not implemented yet") != std::string::npos);
    EXPECT_TRUE(named) << testing::PrintToString(r.stubNotes);
}

}  // namespace sl
