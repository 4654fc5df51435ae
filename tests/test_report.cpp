// `shadowlab report` (cli_report.cpp, `./kit report`): the assignment's report images. Of the
// reference solution: every PNG, an index.html that links each one by a relative path, moments
// after the blur smoother than before, and a softness ladder that gets softer at every step.
// Of stubs: no crash, magenta images, the page names what is still to implement.
#include "image_io.h"
#include "kit_test_support.h"

namespace sl {
namespace {

// Mean squared difference of neighbouring pixels (all channels): the high-frequency energy
// that a blur removes and a sharp shadow outline adds.
// Over the rectangle [x0, x1) × [y0, y1), default the whole image.
double gradientEnergy(const Image& img, int x0 = 0, int y0 = 0, int x1 = -1, int y1 = -1) {
    if (x1 < 0) x1 = img.width - 1, y1 = img.height - 1;
    double e = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < img.channels; ++c) {
                const double v = img.at(x, y, c);
                e += std::pow(img.at(x + 1, y, c) - v, 2) + std::pow(img.at(x, y + 1, c) - v, 2);
            }
    return e / (double(x1 - x0) * (y1 - y0) * img.channels);
}

bool hasMagenta(const Image& img) {
    if (img.channels < 3) return false;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (img.at(x, y, 0) == 1.0f && img.at(x, y, 1) == 0.0f && img.at(x, y, 2) == 1.0f) return true;
    return false;
}

test::CommandResult report(const std::string& solution, const fs::path& out, int size,
                           const std::string& extra = "") {
    return test::runCommand(test::shadowlabBinary() + " report --solution '" + solution + "' --out '" +
                            out.string() + "' --size " + std::to_string(size) + extra);
}

size_t ladderSteps() {
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(test::root() / "scenes/ladder"))
        n += e.path().filename().string().rfind("softness_", 0) == 0;
    return n;
}

}  // namespace

TEST(Report, ReferenceImagesAreLinkedBlurredAndSofterAlongTheLadder) {
    const fs::path out = test::tempDir("report_reference");
    auto r = report("reference", out, 256);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const size_t steps = ladderSteps();
    ASSERT_GE(steps, 4u);

    std::vector<std::string> pngs = {"moments_before_blur.png", "moments_after_blur.png",
                                     "penumbra.png"};
    for (size_t i = 1; i <= steps; ++i) pngs.push_back("softness_" + std::to_string(i) + ".png");
    const std::string html = test::readFile(out / "index.html");
    for (const auto& p : pngs) {
        ASSERT_TRUE(fs::exists(out / p)) << p;
        EXPECT_NE(html.find("src=\"" + p + "\""), std::string::npos) << "index.html does not show " << p;
    }
    // Every link stays inside the folder (it is zipped and handed in).
    static const std::regex link(R"((src|href)="([^"]*)\")");
    for (std::sregex_iterator it(html.begin(), html.end(), link), end; it != end; ++it) {
        const std::string target = (*it)[2].str();
        EXPECT_TRUE(fs::exists(out / target)) << target;
        EXPECT_EQ(target.find('/'), std::string::npos) << target;
    }
    EXPECT_EQ(html.find("not implemented"), std::string::npos) << "the reference has no stub";

    // The blur removes high frequencies: same window, same grey scale, far smoother.
    const Image before = readImage(out / "moments_before_blur.png");
    const Image after = readImage(out / "moments_after_blur.png");
    ASSERT_EQ(before.width, after.width);
    // Inside the top-left cell (b1) of the 2×2 grid (cells 4 px apart): the grid's frame is the
    // same in both images and would hide the difference.
    const int cell = (before.width - 12) / 2;
    const double eb = gradientEnergy(before, 8, before.height - cell, cell, before.height - 8);
    const double ea = gradientEnergy(after, 8, after.height - cell, cell, after.height - 8);
    EXPECT_GT(eb, 0.0) << "the window before the blur has no edge";
    EXPECT_LT(ea, 0.7 * eb) << "before " << eb << ", after " << ea;
    EXPECT_FALSE(hasMagenta(before) || hasMagenta(after));

    // Each step of the ladder is softer than the one before: the shadow outlines' energy falls
    // (the scene's own edges are the same in every step).
    double previous = 0.0;
    for (size_t i = 1; i <= steps; ++i) {
        const double e = gradientEnergy(readImage(out / ("softness_" + std::to_string(i) + ".png")));
        if (i > 1) EXPECT_LT(e, previous) << "softness_" << i << " is not softer than softness_" << i - 1;
        previous = e;
    }
    const double first = gradientEnergy(readImage(out / "softness_1.png"));
    EXPECT_LT(previous, 0.9 * first) << "the ladder's last step is hardly softer than its first";
}

// The shipped stubs: the report still completes, shows magenta and names each stage to do; and
// a second run writes the same bytes.
TEST(Report, StubsGiveMagentaImagesAndAreNamedNotFatal) {
    const fs::path out = test::tempDir("report_stubs");
    auto r = report("student", out / "a", 64);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("not implemented yet"), std::string::npos) << r.output;
    const std::string html = test::readFile(out / "a/index.html");
    EXPECT_NE(html.find("Stages still to implement"), std::string::npos);
    EXPECT_NE(html.find("momentShadowIntensity"), std::string::npos);
    EXPECT_TRUE(hasMagenta(readImage(out / "a/softness_1.png")));
    EXPECT_TRUE(hasMagenta(readImage(out / "a/moments_before_blur.png")));

    ASSERT_EQ(report("student", out / "b", 64).exitCode, 0);
    for (const auto& e : fs::directory_iterator(out / "a"))
        EXPECT_EQ(test::readFile(e.path()), test::readFile(out / "b" / e.path().filename()))
            << e.path().filename() << " differs between two runs";
}

// The "either" rubric: a solution whose SAT stages are stubs but whose Gaussian works gets its
// ladder through the Gaussian (auto), without a magenta pixel.
TEST(Report, AutoFilterTakesTheGaussianWhenTheSatIsAStub) {
    const fs::path dir = test::tempDir("report_either");
    const fs::path solution = dir / "solution";
    fs::copy(test::root() / "reference", solution, fs::copy_options::recursive);
    for (const char* f : {"sat.comp", "sat_lookup.glsl"})
        fs::copy_file(test::root() / "student" / f, solution / f, fs::copy_options::overwrite_existing);
    auto r = report(solution.string(), dir / "out", 64);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("gaussian filter"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("not implemented"), std::string::npos) << r.output;
    EXPECT_FALSE(hasMagenta(readImage(dir / "out/softness_1.png")));
    // The captions describe the Gaussian that made the images, not the SAT's per-pixel boxes.
    const std::string page = test::readFile(dir / "out/index.html");
    EXPECT_EQ(page.find("stay sharp where a caster meets the ground"), std::string::npos);
    EXPECT_EQ(page.find("sharp at its foot and widens"), std::string::npos);
    EXPECT_NE(page.find("With the Gaussian every pixel is blurred with one kernel"), std::string::npos);
    auto forced = report(solution.string(), dir / "forced", 64, " --filter sat");
    ASSERT_EQ(forced.exitCode, 0) << forced.output;
    EXPECT_NE(forced.output.find("sat.comp"), std::string::npos) << forced.output;
    // A chosen filter says why (it was chosen), never "(..., sat filter: )".
    EXPECT_NE(forced.output.find(", sat filter: chosen with --filter sat)"), std::string::npos) << forced.output;
    const std::string satPage = test::readFile(dir / "forced/index.html");
    EXPECT_NE(satPage.find("Filter: sat (chosen with --filter sat)"), std::string::npos);
    EXPECT_NE(satPage.find("stay sharp where a caster meets the ground"), std::string::npos);
}

}  // namespace sl
