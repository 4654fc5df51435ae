// Exponential shadow maps (techniques/esm.glsl, the `esm` row):
//  - its G on given filtered values matches a double-precision mirror of Annen et al.'s test,
//    with the exponent clamped to 80;
//  - its shadow pass stores e^{c (z − 1)} of the very depths the hard technique stores;
//  - rendered, it shadows where hard shadows do and lights where hard lights.
#include "gl_test_support.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

// The mirror: lit fraction m · e^{−c (z_f − 1)} clamped to [0, 1], c = min(exponent, 80).
double esmMirror(double m, double zf, double exponent) {
    const double c = std::min(exponent, 80.0);
    return 1.0 - std::clamp(m * std::exp(-c * (zf - 1.0)), 0.0, 1.0);
}

Scene boxScene(const std::vector<std::pair<std::string, double>>& params, Technique t) {
    Scene s = loadScene((test::root() / "scenes" / "ladder" / "box_on_plane.json").string());
    s.shadow.mapSize = 256;
    s.cameras[0].width = s.cameras[0].height = 160;
    overrideTechnique(s.shadow, t, params);
    s.shadow.filter = FilterKind::None;
    return s;
}

}  // namespace

TEST(TechniqueEsm, ShadowIntensityMatchesTheMirror) {
    struct Case { float m, zf, c; };
    std::vector<Case> cases;
    // Filtered values from occluders at z_occ in front of, at and behind the receiver, over
    // several exponents (100: clamped to 80).
    for (float c : {5.0f, 20.0f, 80.0f, 100.0f})
        for (float zOcc : {0.1f, 0.45f, 0.5f, 0.52f, 0.9f})
            for (float zf : {0.2f, 0.5f, 0.55f, 0.99f})
                cases.push_back({std::exp(std::min(c, 80.0f) * (zOcc - 1.0f)), zf, c});
    cases.push_back({0.5f * std::exp(20.0f * (0.3f - 1.0f)) + 0.5f, 0.6f, 20.0f});  // half covered
    test::sharedContext();
    ShaderLibrary lib({}, {test::root() / "tests" / "shaders", test::root() / "shaders"}, test::root());
    GlProgram p = GlProgram::compute(lib, "esm_probe.comp", {});
    std::vector<glm::vec4> in;
    for (const Case& k : cases) in.push_back({k.m, k.zf, k.c, 0.0f});
    BufferHandle inBuf = createBuffer(in.data(), GLsizeiptr(in.size() * sizeof(glm::vec4)));
    BufferHandle outBuf = createBuffer(nullptr, GLsizeiptr(in.size() * sizeof(float)));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, inBuf.id());
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, outBuf.id());
    p.use();
    p.set("uCount", int(in.size()));
    gl::DispatchCompute(GLuint((in.size() + 63) / 64), 1, 1);
    gl::MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> out(in.size());
    gl::GetNamedBufferSubData(outBuf.id(), 0, GLsizeiptr(out.size() * sizeof(float)), out.data());
    int shadowed = 0, lit = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& k = cases[i];
        const double want = esmMirror(k.m, k.zf, k.c);
        // float32 exp of an argument up to ~80: a relative error of a few ulp of the argument.
        EXPECT_NEAR(out[i], want, 2e-4 + 1e-5 * std::abs(k.c)) << "m " << k.m << " z_f " << k.zf << " c " << k.c;
        shadowed += want > 0.99;
        lit += want == 0.0;
    }
    EXPECT_GT(shadowed, 10);  // the cases reach both ends
    EXPECT_GT(lit, 10);
}

TEST(TechniqueEsm, StoresTheExponentialOfTheHardDepths) {
    const Technique esm = techniqueFromName("esm");
    // Not the default: a store that ignored the parameter would fail.
    const Image e = test::renderScene(boxScene({{"exponent", 60.0}}, esm)).images.at("moments_raw");
    const Image z = test::renderScene(boxScene({}, techniqueFromName("hard"))).images.at("moments_raw");
    ASSERT_EQ(e.width, z.width);
    ASSERT_EQ(e.channels, 1);  // R32F without a filter
    int below = 0;
    for (int y = 0; y < z.height; ++y)
        for (int x = 0; x < z.width; ++x) {
            const double d = z.at(x, y, 0);
            const double want = std::exp(60.0 * (d - 1.0));
            ASSERT_NEAR(e.at(x, y, 0), want, 1e-5 * want + 1e-37) << "texel " << x << ", " << y << " z " << d;
            below += d < 0.99;
        }
    EXPECT_GT(below, 1000) << "the map must hold geometry, not only the clear value";
}

TEST(TechniqueEsm, ShadowsWhereHardShadowsAndLightsWhereItLights) {
    const Image hard = test::renderScene(boxScene({}, techniqueFromName("hard"))).images.at("shadow");
    const Image esm = test::renderScene(boxScene({}, techniqueFromName("esm"))).images.at("shadow");
    int hardShadow = 0, agreeShadow = 0, hardLit = 0, wrongLit = 0;
    for (size_t i = 0; i < hard.pixels.size(); ++i) {
        const float g = esm.pixels[i];
        ASSERT_TRUE(g >= 0.0f && g <= 1.0f) << "pixel " << i << ": G " << g;
        if (hard.pixels[i] == 1.0f) {
            ++hardShadow;
            agreeShadow += g > 0.5f;
        } else if (hard.pixels[i] == 0.0f) {
            ++hardLit;
            wrongLit += g > 0.5f;
        }
    }
    ASSERT_GT(hardShadow, 300) << "the box's shadow must be in view";
    // ESM leaks light only where the receiver is within ~1/c of its occluder (at the box's foot).
    EXPECT_GT(agreeShadow, 0.9 * hardShadow);
    EXPECT_EQ(wrongLit, 0) << "of " << hardLit << " lit pixels";
}

}  // namespace sl
