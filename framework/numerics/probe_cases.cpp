// probe_cases: the hard-case catalogue of momentShadowIntensity (see the header and
// docs/numerics.md for the math of each set).
#include "probe_cases.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>

namespace sl {
namespace {

using Mass = std::pair<double, double>;  // (depth, weight)

glm::dvec4 momentsOf(const std::vector<Mass>& masses) {
    glm::dvec4 b(0.0);
    for (auto [z, w] : masses) b += w * glm::dvec4(z, z * z, z * z * z, z * z * z * z);
    return b;
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

struct Builder {
    std::string set;
    float alpha;
    std::vector<MsmCase> cases;
    void add(const std::string& label, glm::vec4 b, float zf, const std::string& note) {
        MsmCase c;
        c.set = set;
        c.name = set + "/" + label + "/zf" + fmt("%.9g", zf);
        c.b = b;
        c.zf = zf;
        c.expected = exactMomentShadowIntensity(glm::dvec4(b), zf, alpha);
        c.bound = kMsmAbsoluteBound + 4.0 * msmFloatSensitivity(b, zf, alpha);
        c.note = note;
        cases.push_back(std::move(c));
    }
    void addMasses(const std::string& label, const std::vector<Mass>& masses,
                   std::initializer_list<double> zfs, const std::string& note) {
        for (double zf : zfs) add(label, glm::vec4(momentsOf(masses)), float(zf), note);
    }
};

void constantDepth(Builder& s) {
    const char* note = "one depth z: Hankel rank 1 before the bias; the biased support {0, z, 1} "
                       "does not pin the distribution down, so G rises over a short range behind z";
    for (double z : {0.1, 0.25, 0.5, 0.731, 0.9, 0.999})
        s.addMasses(fmt("z%g", z), {{z, 1.0}}, {z - 0.05, z - 1e-3, z, z + 1e-3, z + 0.05}, note);
}

void twoPoint(Builder& s) {
    const char* note = "two depths: Hankel rank 2 before the bias (singular), support of b' = "
                       "{0, z1, z2, 1}";
    for (auto [z1, z2, w] : {std::tuple{0.2, 0.8, 0.5}, {0.3, 0.31, 0.5}, {0.5, 0.9, 0.1},
                             {0.1, 0.6, 0.99}, {0.45, 0.4501, 0.5}})
        s.addMasses(fmt("z%g_%g_w%g", z1, z2, w), {{z1, w}, {z2, 1 - w}},
                    {0.05, z1, 0.5 * (z1 + z2), z2, 0.95}, note);
}

void threePoint(Builder& s) {
    const char* note = "three depths: B regular but nearly singular when a weight or a gap is small";
    s.addMasses("thirds", {{0.2, 1 / 3.0}, {0.5, 1 / 3.0}, {0.8, 1 / 3.0}}, {0.1, 0.35, 0.5, 0.65, 0.9}, note);
    s.addMasses("clustered", {{0.4, 0.3}, {0.41, 0.4}, {0.42, 0.3}}, {0.39, 0.405, 0.415, 0.43}, note);
    s.addMasses("tiny-third", {{0.3, 0.5 - 5e-7}, {0.7, 0.5 - 5e-7}, {0.5, 1e-6}}, {0.2, 0.4, 0.5, 0.6, 0.8}, note);
    s.addMasses("tiny-outer", {{0.1, 0.001}, {0.5, 0.998}, {0.9, 0.001}}, {0.3, 0.5, 0.7, 0.95}, note);
}

void depthZeroOne(Builder& s) {
    const char* note = "depth only at 0 and 1: the bias adds no new support point, B' stays "
                       "singular (D33 = 0); G = w0'*[zf>0] + w1'*[zf>1]";
    for (double w : {0.0, 0.01, 0.5, 0.99, 1.0})
        s.addMasses(fmt("w1=%g", w), {{0.0, 1 - w}, {1.0, w}}, {-0.1, 0.0, 1e-6, 0.5, 1 - 1e-6, 1.0, 1.1}, note);
    s.addMasses("0_0.5_1", {{0.0, 0.25}, {0.5, 0.5}, {1.0, 0.25}}, {0.0, 0.25, 0.5, 0.75, 1.0}, note);
}

void zfPosition(Builder& s) {
    const char* note = "zf at an occluder depth (a support point, where G jumps), in front of all, "
                       "behind all, or outside [0, 1]";
    for (auto masses : {std::vector<Mass>{{0.3, 0.4}, {0.6, 0.6}}, std::vector<Mass>{{0.2, 0.2}, {0.5, 0.3}, {0.7, 0.5}}}) {
        std::string label = "support";
        for (auto [z, w] : masses) label += fmt("-%g", z);
        s.addMasses(label, masses, {-10.0, -1.0, -1e-3, 0.0, 0.1, 0.3, 0.5, 0.6, 0.7, 0.99, 1.0, 1.5, 10.0}, note);
    }
}

// zf where c3 = 0 in exact arithmetic: the roots of A13 + A23*zf + A33*zf² (adjugate entries
// of B'); there the quadratic degenerates to a line and one root runs off to infinity.
void cThreeZero(Builder& s) {
    const char* note = "c3 = 0: zf at a root of z^2 - L32*z + (b1*L32 - b2); one support point at infinity";
    for (auto masses : {std::vector<Mass>{{0.3, 0.5}, {0.7, 0.5}}, std::vector<Mass>{{0.2, 0.3}, {0.5, 0.4}, {0.9, 0.3}},
                        std::vector<Mass>{{0.6, 1.0}}}) {
        const glm::vec4 bf(momentsOf(masses));
        const long double a = s.alpha;
        long double b[4];
        for (int k = 0; k < 4; ++k) b[k] = (1 - a) * (long double)bf[k] + a / 2;
        const long double A13 = b[0] * b[2] - b[1] * b[1], A23 = b[0] * b[1] - b[2],
                          A33 = b[1] - b[0] * b[0];
        const long double disc = A23 * A23 - 4 * A33 * A13;
        std::string label = "c3zero";
        for (auto [z, w] : masses) label += fmt("-%g", z);
        for (int sign : {-1, 1}) {
            const float root = float((-A23 + sign * std::sqrt(std::max(disc, 0.0L))) / (2 * A33));
            for (float zf : {std::nextafter(root, -1e9f), root, std::nextafter(root, 1e9f)})
                s.add(label, bf, zf, note);
        }
    }
}

void discriminant(Builder& s) {
    const char* note = "disc = c2^2 - 4*c1*c3 ~ 0 (nearly a double root): a narrow depth cluster; "
                       "float32 rounding can make it negative";
    for (double z : {0.25, 0.5, 0.8})
        for (double gap : {1e-3, 1e-4, 1e-5}) {
            // A uniform interval [z, z + gap]: variance gap²/12, all pivots tiny.
            glm::dvec4 b(0.0);
            for (int k = 1; k <= 4; ++k)
                b[k - 1] = (std::pow(z + gap, k + 1) - std::pow(z, k + 1)) / ((k + 1) * gap);
            for (double zf : {z - gap, z + 0.5 * gap, z + 2 * gap, z + 0.01})
                s.add(fmt("uniform%g+%g", z, gap), glm::vec4(b), float(zf), note);
        }
    // Float32 powers of one depth: rounding pushes b just outside the moment space.
    for (float z : {0.123457f, 0.654321f, 0.987654f})
        for (float dz : {-1e-4f, 1e-4f, 1e-2f})
            s.add(fmt("float-powers%g", z), glm::vec4(z, z * z, z * z * z, z * z * z * z), z + dz, note);
}

void quantized16(Builder& s) {
    const char* note = "moments rounded to 16-bit unorm (step 1.5e-5): can leave the moment space; "
                       "the bias must absorb it";
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int i = 0; i < 12; ++i) {
        std::vector<Mass> m;
        const int n = 1 + i % 3;
        for (int k = 0; k < n; ++k) m.push_back({U(rng), 1.0 / n});
        glm::dvec4 b = momentsOf(m);
        for (int c = 0; c < 4; ++c) b[c] = std::round(b[c] * 65535.0) / 65535.0;
        for (double zf : {0.1, 0.4, 0.7, 0.95}) s.add(fmt("q%g", i), glm::vec4(b), float(zf), note);
    }
}

void hugeKernel(Builder& s) {
    const char* note = "float32 box mean of 1024^2 nearly equal depths (a separable huge kernel: "
                       "1024-term row sums, then their sum): rounding ~1e-4 relative, larger than "
                       "the variance, so b leaves the moment space (no expected value)";
    std::mt19937 rng(4096);
    for (double z0 : {0.3, 0.7, 0.95}) {
        std::uniform_real_distribution<float> jitter(0.0f, 1e-3f);
        glm::vec4 total(0.0f);
        for (int row = 0; row < 1024; ++row) {
            glm::vec4 rowSum(0.0f);
            for (int i = 0; i < 1024; ++i) {
                const float z = float(z0) + jitter(rng);
                rowSum += glm::vec4(z, z * z, z * z * z, z * z * z * z);
            }
            total += rowSum / 1024.0f;
        }
        const glm::vec4 b = total / 1024.0f;
        for (double zf : {z0 - 0.01, z0 + 5e-4, z0 + 0.01, z0 + 0.1}) s.add(fmt("z%g", z0), b, float(zf), note);
    }
}

void denormals(Builder& s) {
    const char* note = "moments or zf below 1.2e-38 (denormal; llvmpipe may flush them to 0)";
    const float tiny = std::numeric_limits<float>::denorm_min();
    for (float z : {1e-10f, 1e-20f, 1e-38f}) {
        const glm::vec4 b(z, z * z, z * z * z, z * z * z * z);
        for (float zf : {0.0f, tiny, z, 2 * z, 0.5f}) s.add(fmt("z%g", z), b, zf, note);
    }
    for (glm::vec4 b : {glm::vec4(1e-39f, 1e-40f, 0, 0), glm::vec4(tiny, tiny, tiny, tiny),
                        glm::vec4(0.5f, 0.5f, 0.5f, 0.5f - 1e-39f)})
        for (float zf : {0.0f, 1e-39f, 0.5f, 1.0f}) s.add(fmt("b%g", b.x), b, zf, note);
}

const std::vector<std::pair<std::string, std::function<void(Builder&)>>>& registry() {
    static const std::vector<std::pair<std::string, std::function<void(Builder&)>>> sets = {
        {"constant-depth", constantDepth}, {"two-point", twoPoint},   {"three-point", threePoint},
        {"depth-0-1", depthZeroOne},       {"zf-position", zfPosition}, {"c3-zero", cThreeZero},
        {"discriminant", discriminant},    {"quantized-16bit", quantized16},
        {"huge-kernel", hugeKernel},       {"denormals", denormals}};
    return sets;
}

}  // namespace

const std::vector<std::string>& msmCaseSetNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& [name, make] : registry()) n.push_back(name);
        return n;
    }();
    return names;
}

std::vector<MsmCase> msmCaseSet(const std::string& set, float alpha) {
    for (const auto& [name, make] : registry())
        if (name == set) {
            Builder b{name, alpha, {}};
            make(b);
            return std::move(b.cases);
        }
    std::string known;
    for (const auto& n : msmCaseSetNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown case set '" + set + "' (known: " + known + ", catalogue)");
}

std::vector<MsmCase> msmHardCaseCatalogue(float alpha) {
    std::vector<MsmCase> all;
    for (const auto& name : msmCaseSetNames()) {
        auto set = msmCaseSet(name, alpha);
        all.insert(all.end(), set.begin(), set.end());
    }
    return all;
}

}  // namespace sl
