// The image codec module (render/image_codec.h): OpenImageIO is loaded only by what reads or
// writes an image file, files round-trip through it, its comparison figures are the textbook
// ones, and a program without the module says which file is missing.
#include "gl_test_support.h"
#include "golden_encoding.h"
#include "image_codec.h"
#include "image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <sstream>

namespace sl::test {
namespace {

TEST(ImageCodec, CommandsThatTouchNoImageFileDoNotLoadOpenImageIO) {
    // LD_DEBUG=files names every shared object the dynamic loader opens.
    const auto info = runCommand("LD_DEBUG=files " + shadowlabBinary() + " info 2>&1");
    EXPECT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("libc.so"), std::string::npos) << "LD_DEBUG gave no file list";
    EXPECT_EQ(info.output.find("libOpenImageIO"), std::string::npos);
    const fs::path out = tempDir("image_codec_render");
    const auto render = runCommand("LD_DEBUG=files " + shadowlabBinary() + " render --scene " +
                                   scenePath("unlit_no_shadow").string() + " --out " +
                                   out.string() + " 2>&1");
    EXPECT_EQ(render.exitCode, 0) << render.output.substr(render.output.size() - 2000);
    EXPECT_NE(render.output.find("libOpenImageIO"), std::string::npos);
}

TEST(ImageCodec, FilesRoundTripUpright) {
    const fs::path dir = tempDir("image_codec_files");
    Image img(3, 2, 2);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = 0.125f * float(i) - 0.3f;
    writeExr(img, dir / "f.exr");
    const Image back = readImage(dir / "f.exr");
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    ASSERT_EQ(back.channels, 2);
    EXPECT_EQ(back.pixels, img.pixels);  // float EXR: exact, rows flipped there and back
    writeExr(img, dir / "h.exr", SampleType::Half);
    const Image half = readImage(dir / "h.exr");
    for (size_t i = 0; i < img.pixels.size(); ++i)
        EXPECT_NEAR(half.pixels[i], img.pixels[i], 1e-3) << i;
    // The file's first row is the image's top row (Image stores the bottom row first).
    const Image raw = imageCodec().read((dir / "f.exr").string(), false);
    EXPECT_EQ(raw.at(0, 0, 0), img.at(0, 1, 0));
}

// Compression::Fast (a render's outputs) trades file size for zlib time, never pixels: both
// levels give back the exact floats, the fast file is really written at another level (its
// bytes differ), and it is the same bytes when written again.
TEST(ImageCodec, FastCompressionKeepsEveryFloatAndIsReproducible) {
    const fs::path dir = tempDir("image_codec_levels");
    Image img(256, 64, 4);
    for (size_t i = 0; i < img.pixels.size(); ++i)  // smooth with noise: compressible, not trivially
        img.pixels[i] = std::sin(0.01f * float(i)) + 1e-3f * float((i * 2654435761u) % 1000);
    writeExr(img, dir / "compact.exr");
    writeExr(img, dir / "fast.exr", SampleType::Float, Compression::Fast);
    writeExr(img, dir / "fast2.exr", SampleType::Float, Compression::Fast);
    EXPECT_EQ(readImage(dir / "compact.exr").pixels, img.pixels);
    EXPECT_EQ(readImage(dir / "fast.exr").pixels, img.pixels);
    EXPECT_NE(sha256File(dir / "fast.exr"), sha256File(dir / "compact.exr"));
    EXPECT_EQ(sha256File(dir / "fast.exr"), sha256File(dir / "fast2.exr"));
}

// Previews: top row first, grey stays one channel, sRGB when asked, magenta for stub (-1) and
// non-finite texels (which turn the whole preview RGB). Expected bytes by hand:
// 0.25 -> 64 linear; sRGB 1.055 · 0.25^(1/2.4) - 0.055 = 0.5371 -> 137.
TEST(ImageCodec, PngPreviewsAreUprightGreyOrMagenta) {
    const fs::path dir = tempDir("image_codec_previews");
    Image grey(2, 2, 1);  // bottom row first: (0, 0) is the file's bottom-left texel
    grey.pixels = {0.25f, 1.5f, 0.0f, -0.5f};
    writePngPreview(grey, dir / "grey.png", false);
    writePngPreview(grey, dir / "grey_srgb.png", true);
    const Image g = imageCodec().read((dir / "grey.png").string(), false);  // rows top first, /255
    ASSERT_EQ(g.channels, 1);
    EXPECT_EQ(std::lround(g.at(0, 1, 0) * 255), 64);   // file row 1 = image row 0
    EXPECT_EQ(std::lround(g.at(1, 1, 0) * 255), 255);  // clamped
    EXPECT_EQ(std::lround(g.at(1, 0, 0) * 255), 0);    // clamped
    EXPECT_EQ(std::lround(imageCodec().read((dir / "grey_srgb.png").string(), false).at(0, 1, 0) * 255), 137);
    Image broken = grey;
    broken.pixels[3] = std::nanf("");
    broken.pixels[2] = -1.0f;
    writePngPreview(broken, dir / "broken.png", false);
    const Image b = imageCodec().read((dir / "broken.png").string(), false);
    ASSERT_EQ(b.channels, 3);
    for (int x : {0, 1}) {  // image row 1 = file row 0: both magenta
        EXPECT_EQ(b.at(x, 0, 0), 1.0f);
        EXPECT_EQ(b.at(x, 0, 1), 0.0f);
        EXPECT_EQ(b.at(x, 0, 2), 1.0f);
    }
    EXPECT_EQ(std::lround(b.at(0, 1, 1) * 255), 64);  // grey spread over RGB
}

TEST(ImageCodec, ComparisonFiguresAreMeanRmsAndMaxOfTheDifference) {
    Image a(2, 2, 1), b(2, 2, 1);
    a.pixels = {0.0f, 0.5f, 1.0f, 0.25f};
    b.pixels = {0.0f, 0.25f, 0.5f, 0.25f};  // differences 0, 0.25, 0.5, 0
    const ImageFigures f = imageCodec().compare(a, b);
    EXPECT_NEAR(f.mean, 0.1875, 1e-6);
    EXPECT_NEAR(f.rms, std::sqrt((0.0625 + 0.25) / 4), 1e-6);
    EXPECT_NEAR(f.max, 0.5, 1e-6);
}

// SHADOWLAB_CODEC=child (codec_child.h, what the exact cost mode runs with): the program itself
// never loads OpenImageIO, a child it starts does, and the files are the same bytes.
TEST(ImageCodec, TheChildCodecKeepsOpenImageIOOutOfTheProgramAndWritesTheSameBytes) {
    const fs::path dir = tempDir("image_codec_child");
    const std::string render = shadowlabBinary() + " render --scene " +
                               scenePath("classic").string() + " --out ";
    const auto own = runCommand(render + (dir / "own").string());
    ASSERT_EQ(own.exitCode, 0) << own.output;
    const auto child = runCommand("SHADOWLAB_CODEC=child LD_DEBUG=files " + render +
                                  (dir / "child").string() + " 2>&1");
    ASSERT_EQ(child.exitCode, 0) << child.output.substr(child.output.size() - 2000);
    // LD_DEBUG's lines start with the process id: the first is the program's.
    std::istringstream lines(child.output);
    std::string line, programPid;
    bool programLoads = false, childLoads = false;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string pid;
        words >> pid;
        if (pid.empty() || pid.back() != ':') continue;
        if (programPid.empty()) programPid = pid;
        if (line.find("libOpenImageIO") == std::string::npos) continue;
        (pid == programPid ? programLoads : childLoads) = true;
    }
    EXPECT_FALSE(programPid.empty()) << "LD_DEBUG gave no file list";
    EXPECT_FALSE(programLoads) << "the program loaded OpenImageIO itself";
    EXPECT_TRUE(childLoads) << "no child loaded OpenImageIO";
    int compared = 0;
    for (const auto& e : fs::directory_iterator(dir / "own")) {
        const std::string ext = e.path().extension().string();
        if (ext != ".exr" && ext != ".png") continue;
        ++compared;
        EXPECT_EQ(sha256File(e.path()), sha256File(dir / "child" / e.path().filename()))
            << e.path().filename();
    }
    EXPECT_GE(compared, 4);
}

TEST(ImageCodec, AProgramWithoutTheModuleNamesIt) {
    const fs::path dir = tempDir("image_codec_missing");
    fs::copy_file(shadowlabBinary(), dir / "shadowlab");
    const auto r = runCommand("cd '" + root().string() + "' && '" + (dir / "shadowlab").string() +
                              "' render --scene " + scenePath("unlit_no_shadow").string() +
                              " --out " + (dir / "out").string() + " 2>&1");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("libshadowlab_oiio.so"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sl::test

namespace sl {

// A live grade rounds the reference's images as the goldens store them (golden_encoding.h):
// for half images that must be exactly what OpenEXR's half keeps, or a live grade and a grade
// against goldens of the same render would compare different values. Checked on values across
// half's range: normals, subnormals, ties, beyond 65504 (Inf), negative, zero.
TEST(ImageCodec, TheLiveRoundingToHalfIsWhatAHalfExrStores) {
    Image img(64, 64, 1);
    std::uint32_t state = 12345;
    auto next = [&] { return state = state * 1664525u + 1013904223u; };
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        const float mantissa = float(next() % 1000000) / 1000000.0f;
        const int exponent = int(next() % 44) - 28;  // 2^-28 (below half's subnormals) .. 2^15
        img.pixels[i] = std::ldexp(1.0f + mantissa, exponent) * ((next() & 1) ? -1.0f : 1.0f);
    }
    const float edges[] = {0.0f, -0.0f, 65504.0f, 65519.0f, 65520.0f, 1e9f, 6.1035156e-5f,
                           5.9604645e-8f, 2.9802322e-8f, 1.0f + 1.0f / 2048.0f, 1.0f + 3.0f / 2048.0f};
    for (size_t i = 0; i < std::size(edges); ++i) img.pixels[i] = edges[i];
    const fs::path file = test::tempDir("half_rounding") / "half.exr";
    writeExr(img, file, SampleType::Half);
    const Image stored = readImage(file);
    ASSERT_EQ(stored.pixels.size(), img.pixels.size());
    int wrong = 0;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        const float mine = grader::roundToHalf(img.pixels[i]);
        if (std::memcmp(&mine, &stored.pixels[i], sizeof mine) != 0 && ++wrong <= 5)
            ADD_FAILURE() << img.pixels[i] << ": rounded to " << mine << ", stored as " << stored.pixels[i];
    }
    EXPECT_EQ(wrong, 0);
}

}  // namespace sl
