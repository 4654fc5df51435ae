// The Gaussian under stress (docs/numerics.md, "Gaussian"): weights that sum to 1 at radii up
// to 64, and the reference's two passes against the double oracle on odd, non-square and
// non-power-of-two maps, including maps narrower than the kernel (clamp to edge repeats the
// border texel many times over).
#include "gl_test_support.h"
#include "oracles/moment_oracles.h"
#include "technique.h"

#include <cmath>
#include <random>
#include <string>

namespace sl {
namespace {
using oracle::u;  // float32's unit roundoff (moment_oracles.h)
}  // namespace

TEST(NumericsGaussian, WeightsSumToOneAtEveryRadiusUpTo64) {
    for (int r = 1; r <= 64; ++r)
        for (float sigma : {0.0f, 0.5f, float(r) / 3, float(r), 4.0f * r}) {
            const auto w = Renderer::gaussianWeights(r, sigma);
            ASSERT_EQ(w.size(), size_t(r) + 1);
            double sum = w[0];
            for (int k = 1; k <= r; ++k) {
                sum += 2.0 * w[k];
                ASSERT_LE(w[k], w[k - 1]) << "r " << r << " sigma " << sigma;  // bell-shaped
            }
            // r + 1 float weights, each rounded: |sum - 1| <= (2r + 1)·u.
            EXPECT_NEAR(sum, 1.0, (2 * r + 1) * u) << "r " << r << " sigma " << sigma;
        }
}

TEST(NumericsGaussian, EdgesAndOddSizesAtRadii32And64) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    std::mt19937 rng(64);
    std::uniform_real_distribution<float> d(0.0f, 1.0f);
    for (auto [w, h, radius] : {std::tuple{33, 129, 32}, {127, 65, 32}, {97, 31, 64}, {129, 129, 64},
                                {17, 200, 64}, {1, 45, 32}, {250, 3, 64}}) {
        Image src(w, h, 4);
        for (auto& v : src.pixels) v = d(rng);
        // A bright border column / row, so that clamp-to-edge errors cannot hide.
        for (int y = 0; y < h; ++y) src.at(w - 1, y, 0) = 1.0f;
        for (int x = 0; x < w; ++x) src.at(x, 0, 1) = 1.0f;
        Texture a = Texture::create(w, h, GL_RGBA32F), b = Texture::create(w, h, GL_RGBA32F),
                c = Texture::create(w, h, GL_RGBA32F);
        a.upload(src);
        renderer.gaussianPass(a, b, radius, 0.0f, {1, 0});
        renderer.gaussianPass(b, c, radius, 0.0f, {0, 1});
        const Image gpu = c.read();
        const auto want = oracle::gaussianBlur2D(src.pixels, w, h, radius, 0.0);
        const double tol = 2 * (2 * radius + 3) * u;  // as in test_pipeline_oracles.cpp
        double worst = 0;
        for (size_t i = 0; i < want.size(); ++i) {
            ASSERT_NEAR(gpu.pixels[i], want[i], tol) << w << "x" << h << " r" << radius << " @" << i;
            worst = std::max(worst, std::abs(gpu.pixels[i] - want[i]));
        }
        std::printf("gaussian %dx%d r=%d: max error %.2e (tolerance %.2e)\n", w, h, radius, worst, tol);
    }
}

TEST(NumericsGaussian, ConstantMapStaysConstantAtRadius64) {
    // Weights summing to 1 and clamp to edge: a constant map is a fixed point, at the border too.
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    const int w = 75, h = 41;
    Image src(w, h, 4, 0.7f);
    Texture a = Texture::create(w, h, GL_RGBA32F), b = Texture::create(w, h, GL_RGBA32F),
            c = Texture::create(w, h, GL_RGBA32F);
    a.upload(src);
    renderer.gaussianPass(a, b, 64, 0.0f, {1, 0});
    renderer.gaussianPass(b, c, 64, 0.0f, {0, 1});
    for (float v : c.read().pixels) ASSERT_NEAR(v, 0.7f, 2 * (2 * 64 + 3) * u);
}

}  // namespace sl

namespace sl {

// Every technique's map is filtered by the solution's own gaussian_blur.comp (one RGBA32F layer
// at a time; msm4-16bit's RGBA16 map widened first): a render's moments_filtered equals the
// reference's two passes run here on the raw map, bit for bit, in every map format.
TEST(NumericsGaussian, EveryTechniqueFiltersThroughTheSolutionsGaussian) {
    test::sharedContext();
    Renderer reference(test::library("reference"));
    for (const char* name : {"vsm", "evsm4", "msm4-16bit"})
        for (int radius : {3, 8, 16}) {
            // An odd map size: partial work groups and T-texel runs at both edges, and in the y
            // pass 6 groups of 64 walked as a band of 4 and a narrower one of 2.
            Scene s = loadScene((test::root() / "scenes" / "ladder" / "light_bleeding.json").string());
            overrideTechnique(s.shadow, techniqueFromName(name), {});
            s.shadow.mapSize = 331;
            s.shadow.filter = FilterKind::Gaussian;
            s.shadow.gaussianRadius = radius;
            s.shadow.gaussianSigma = 0.0f;
            s.cameras[0].width = s.cameras[0].height = 32;
            const RenderResult r = test::renderScene(s);
            const Image& raw = r.images.at("moments_raw");
            const Image& got = r.images.at("moments_filtered");
            ASSERT_EQ(raw.width, 331);
            const int w = raw.width, h = raw.height, ch = raw.channels;
            Image wide(w, h, 4);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (int c = 0; c < ch; ++c) wide.at(x, y, c) = raw.at(x, y, c);
            Texture a = Texture::create(w, h, GL_RGBA32F), b = Texture::create(w, h, GL_RGBA32F),
                    c = Texture::create(w, h, GL_RGBA32F);
            a.upload(wide);
            reference.gaussianPass(a, b, radius, 0.0f, {1, 0});
            reference.gaussianPass(b, c, radius, 0.0f, {0, 1});
            const Image want = c.read();
            const double tol = 0.0;
            double worst = 0, spread = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (int k = 0; k < ch; ++k) {
                        const double d = std::abs(double(got.at(x, y, k)) - want.at(x, y, k));
                        worst = std::max(worst, d);
                        spread = std::max(spread, std::abs(double(want.at(x, y, k)) - raw.at(x, y, k)));
                        ASSERT_LE(d, tol) << name << " r" << radius << " (" << x << ", " << y
                                          << ") channel " << k;
                    }
            // The blur did something: a filter that copied its input would not pass unnoticed.
            EXPECT_GT(spread, 1e-3) << name << " r" << radius;
            std::printf("%s r=%d: max difference to the reference %.2e\n", name, radius, worst);
        }
}

}  // namespace sl
