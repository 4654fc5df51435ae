// The exact filtered visibility (CPU, double) against a brute-force GPU PCF with the same
// kernel (tests/shaders/pcf_bruteforce.comp, float), on a random depth map at random samples;
// and the error metrics and the Pareto front on hand-computed cases.
#include "error_metrics.h"
#include "filtered_truth.h"
#include "gl_program.h"
#include "gl_test_support.h"
#include "gpu_resources.h"
#include "study_report.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace sl {
namespace {

std::vector<float> gpuPcf(const Image& depth, const std::vector<glm::vec4>& samples,
                          const FilterKernel& k) {
    test::sharedContext();
    ShaderLibrary lib({}, {test::root() / "tests" / "shaders", test::root() / "shaders"}, test::root());
    GlProgram p = GlProgram::compute(lib, "pcf_bruteforce.comp", {});
    Texture map = Texture::create(depth.width, depth.height, GL_R32F);
    map.upload(depth);
    const std::vector<float> w = k.kind == FilterKind::Gaussian
                                     ? Renderer::gaussianWeights(k.radius, k.sigma)
                                     : std::vector<float>{1.0f};
    BufferHandle in = createBuffer(samples.data(), GLsizeiptr(samples.size() * sizeof(glm::vec4)));
    BufferHandle weights = createBuffer(w.data(), GLsizeiptr(w.size() * sizeof(float)));
    std::vector<float> out(samples.size(), -7.0f);
    BufferHandle result = createBuffer(out.data(), GLsizeiptr(out.size() * sizeof(float)));
    p.use();
    p.set("uDepth", 0);
    p.set("uCount", int(samples.size()));
    p.set("uRadius", k.kind == FilterKind::Gaussian ? k.radius : -1);
    p.set("uBox", k.boxTexels);
    gl::BindTextureUnit(0, map.id());
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, weights.id());
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, result.id());
    gl::DispatchCompute(GLuint((samples.size() + 63) / 64), 1, 1);
    gl::MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl::GetNamedBufferSubData(result.id(), 0, GLsizeiptr(out.size() * sizeof(float)), out.data());
    return out;
}

// A depth map with large smooth features and texel noise, so that every kernel straddles edges.
Image randomDepth(int n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Image d(n, n, 1);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            d.at(x, y, 0) = 0.5f + 0.3f * std::sin(x * 0.21f) * std::cos(y * 0.13f) + 0.2f * (u(rng) - 0.5f);
    return d;
}

void compareWithGpu(const FilterKernel& k, int n) {
    const Image depth = randomDepth(n, 7u + unsigned(n));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec4> samples;
    for (int i = 0; i < 3000; ++i)  // the edges of the map too: clamping and clipping
        samples.push_back({u(rng) * 1.1f - 0.05f, u(rng) * 1.1f - 0.05f, 0.3f + 0.4f * u(rng), 0});
    for (auto& s : samples) s.x = std::clamp(s.x, 0.0f, 1.0f), s.y = std::clamp(s.y, 0.0f, 1.0f);
    const std::vector<float> gpu = gpuPcf(depth, samples, k);
    double maxDiff = 0, spread = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
        const double cpu = filteredShadow(depth, {samples[i].x, samples[i].y}, samples[i].z, k);
        maxDiff = std::max(maxDiff, std::abs(cpu - double(gpu[i])));
        spread += cpu > 0.05 && cpu < 0.95;
    }
    EXPECT_LE(maxDiff, 1e-6);
    EXPECT_GT(spread, 300) << "too few samples with partial visibility to test the kernel";
}

TEST(FilteredTruth, GaussianPcfMatchesBruteForceGpu) {
    FilterKernel k;
    k.kind = FilterKind::Gaussian;
    k.radius = 4;
    compareWithGpu(k, 128);
    k.radius = 1;
    k.sigma = 0.8f;
    compareWithGpu(k, 64);
}

TEST(FilteredTruth, SatBoxMatchesBruteForceGpu) {
    FilterKernel k;
    k.kind = FilterKind::Sat;
    k.boxTexels = 7.5f;
    compareWithGpu(k, 128);
    k.boxTexels = 2.0f;
    compareWithGpu(k, 64);
}

TEST(FilteredTruth, BoxOfOneTexelIsTheTexelsOwnComparison) {
    Image depth(4, 4, 1, 0.5f);
    depth.at(2, 1, 0) = 0.2f;
    FilterKernel k;
    k.kind = FilterKind::Sat;
    k.boxTexels = 1.0f;
    EXPECT_DOUBLE_EQ(filteredShadow(depth, {2.5 / 4, 1.5 / 4}, 0.3, k), 1.0);
    EXPECT_DOUBLE_EQ(filteredShadow(depth, {1.5 / 4, 1.5 / 4}, 0.3, k), 0.0);
    // Half a texel each of (1, 1) and (2, 1): half shadowed.
    EXPECT_DOUBLE_EQ(filteredShadow(depth, {2.0 / 4, 1.5 / 4}, 0.3, k), 0.5);
}

TEST(FilteredTruth, ReceiverPlaneRemovesSelfShadowingOfAFlatReceiver) {
    // A directional light looking straight down at the plane y = 0 tilted by 30°: the map holds
    // the tilted plane's own depths. A point on the plane, filtered with a wide kernel: against
    // its one depth, half the kernel is nearer (acne); against its plane, nothing is.
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 10, 0), glm::dvec3(0, 0, 0), glm::dvec3(0, 0, -1));
    const glm::dmat4 proj = glm::ortho(-5.0, 5.0, -5.0, 5.0, 1.0, 20.0);
    const glm::dmat4 vp = proj * view;
    const glm::dvec3 n = glm::normalize(glm::dvec3(std::sin(0.5236), std::cos(0.5236), 0.0));
    const int size = 64;
    Image depth(size, size, 1);
    ReceiverPlane plane;
    plane.inverseViewProjection = glm::inverse(vp);
    plane.point = {0, 0, 0};
    plane.normal = n;
    plane.eye = {0, 10, 0};
    plane.forward = {0, -1, 0};
    plane.range = {1.0, 20.0};
    for (int y = 0; y < size; ++y)  // each texel: the plane's depth at its centre, as rasterised
        for (int x = 0; x < size; ++x)
            depth.at(x, y, 0) = float(plane.depthAt({(x + 0.5) / size, (y + 0.5) / size}));
    FilterKernel k;
    k.kind = FilterKind::Gaussian;
    k.radius = 4;
    const glm::dvec2 uv(0.5 + 0.13 / size, 0.5 - 0.21 / size);
    const double zf = plane.depthAt(uv);
    plane.depthBias = 1e-6;  // float storage of the map's depths
    EXPECT_GT(filteredShadow(depth, uv, zf - 1e-6, k), 0.3) << "the constant depth should acne";
    EXPECT_EQ(filteredShadow(depth, uv, zf - 1e-6, k, &plane), 0.0);
    // An occluder over part of the kernel is still seen through the plane comparison.
    for (int y = 0; y < size; ++y)
        for (int x = size / 2; x < size; ++x) depth.at(x, y, 0) = 0.01f;
    const double g = filteredShadow(depth, uv, zf - 1e-6, k, &plane);
    EXPECT_GT(g, 0.3);
    EXPECT_LT(g, 0.7);
}

TEST(ErrorMetrics, HandComputedCase) {
    // 10 reached pixels; reference 0; errors -0.2 (a leak), 0.3 (too dark), 0.04, and zeros.
    Image ref(5, 3, 1, 0.0f), g(5, 3, 1, 0.0f), reached(5, 3, 1, 0.0f);
    for (int i = 0; i < 10; ++i) reached.pixels[size_t(i)] = 1.0f;
    ref.pixels[0] = 0.5f, g.pixels[0] = 0.3f;
    g.pixels[1] = 0.3f;
    g.pixels[2] = 0.04f;
    g.pixels[12] = 1.0f;  // not reached: ignored
    const ShadowError e = measureShadowError(g, ref, reached);
    EXPECT_EQ(e.pixels, 10u);
    EXPECT_NEAR(e.rmse, std::sqrt((0.04 + 0.09 + 0.0016) / 10), 1e-7);
    EXPECT_NEAR(e.max, 0.3, 1e-7);
    EXPECT_NEAR(e.p99, 0.3, 1e-7);  // nearest rank: the 10th of 10
    EXPECT_DOUBLE_EQ(e.over005, 0.2);
    EXPECT_DOUBLE_EQ(e.leakArea, 0.1);
    EXPECT_DOUBLE_EQ(e.darkArea, 0.1);
    g.pixels[3] = NAN;  // a NaN is an error of 1, never a silent pass
    EXPECT_NEAR(measureShadowError(g, ref, reached).max, 1.0, 1e-12);
}

TEST(ErrorMetrics, ParetoFrontKeepsOnlyUndominatedPoints) {
    const std::vector<double> x = {1, 2, 2, 3, 4, 0.5}, y = {0.5, 0.4, 0.6, 0.45, 0.1, 0.9};
    EXPECT_EQ(paretoFront(x, y), (std::vector<size_t>{5, 0, 1, 4}));
}

}  // namespace
}  // namespace sl
