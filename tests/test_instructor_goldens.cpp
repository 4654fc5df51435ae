// Hidden goldens (hidden scenes never reach students): `golden --scenes <hidden scene>` writes into
// goldens/ next to the hidden scene's file, never into the public folder (which ships to students);
// a manifest is merged, never silently cut down to the scenes of one run; grade finds a hidden
// scene's goldens; `golden --check` checks the scenes it is given and its advice names them.
#include "test_grader_support.h"

#include <functional>
#include <set>

namespace sl {
namespace {

// A public golden folder like the committed one: its manifest and its images.
fs::path copyOfPublicGoldens(const fs::path& dir) {
    fs::copy(test::root() / "scenes" / "goldens", dir, fs::copy_options::recursive);
    return dir;
}

std::set<std::string> manifestScenes(const fs::path& folder) {
    std::set<std::string> names;
    auto j = nlohmann::json::parse(std::ifstream(folder / "manifest.json"));
    for (const auto& [name, entry] : j["scenes"].items()) names.insert(name);
    return names;
}

}  // namespace

TEST(InstructorGoldens, HiddenGoldensGoNextToTheirSceneAndThePublicManifestKeepsItsEntries) {
    const fs::path dir = test::tempDir("instructor_goldens");
    const fs::path pub = copyOfPublicGoldens(dir / "public");
    const auto before = manifestScenes(pub);
    ASSERT_GE(before.size(), 6u);
    fs::create_directories(dir / "private");
    const fs::path hidden = dir / "private" / "secret_shelf.json";
    fs::copy_file(test::scenePath("contact"), hidden);

    auto r = test::runCommand(test::shadowlabBinary() + " golden --scenes classic," + hidden.string() +
                              " --out " + pub.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The public folder: the same scenes as before (classic remade, the rest kept, and said
    // so), and nothing of the hidden scene.
    EXPECT_EQ(manifestScenes(pub), before);
    EXPECT_FALSE(fs::exists(pub / "secret_shelf"));
    EXPECT_NE(r.output.find("kept from before: contact"), std::string::npos) << r.output;
    // The hidden scene's goldens: their own folder and manifest, next to the scene file.
    const fs::path own = dir / "private" / "goldens";
    EXPECT_EQ(manifestScenes(own), std::set<std::string>{"secret_shelf"});
    EXPECT_TRUE(fs::exists(own / "secret_shelf" / "moments_raw.exr"));
    EXPECT_TRUE(fs::exists(own / "secret_shelf" / "msm_shadow.exr"));

    // grade finds the hidden scene's goldens in its own folder: the reference scores full.
    auto g = test::grade("--reference golden --no-report --goldens " + pub.string() +
                             " --scenes " + hidden.string() + " --submission " +
                             (test::root() / "reference").string(),
                         dir / "graded");
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), 100.0) << g.results.dump(1);

    // --check on the hidden scene: up to date; then stale after an edit of the scene, with
    // advice that remakes exactly that scene.
    auto ok = test::runCommand(test::shadowlabBinary() + " golden --check --scenes " +
                               hidden.string() + " --out " + pub.string());
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
    auto j = nlohmann::json::parse(std::ifstream(hidden));
    j["description"] = "edited after its goldens were made";
    std::ofstream(hidden) << j.dump(2);
    auto stale = test::runCommand(test::shadowlabBinary() + " golden --check --scenes " +
                                  hidden.string() + " --out " + pub.string());
    EXPECT_EQ(stale.exitCode, 1) << stale.output;
    EXPECT_NE(stale.output.find("secret_shelf: the scene file changed"), std::string::npos) << stale.output;
    EXPECT_NE(stale.output.find("--scenes " + hidden.string()), std::string::npos) << stale.output;
    // A hidden scene's goldens go beside its file whatever --out says: the advice leaves it out.
    EXPECT_EQ(stale.output.find("--out"), std::string::npos) << stale.output;
}

// Every golden EXR has its PNG preview beside it (written by `golden` with the EXR), listed in
// the manifest with the SHA-256 of its file and of its pixels.
TEST(InstructorGoldens, EveryGoldenHasAPngPreviewInTheManifest) {
    const fs::path committed = test::root() / "scenes" / "goldens";
    const auto manifest = nlohmann::json::parse(std::ifstream(committed / "manifest.json"));
    int previews = 0;
    for (const auto& [scene, entry] : manifest["scenes"].items()) {
        ASSERT_TRUE(entry.contains("previews")) << scene;
        for (const auto& [image, e] : entry["images"].items()) {
            EXPECT_EQ(e["pixels_sha256"], sha256Pixels(readImage(committed / scene / (image + ".exr"))))
                << scene << "/" << image;
            ASSERT_TRUE(entry["previews"].contains(image)) << scene << "/" << image;
            const auto& p = entry["previews"][image];
            EXPECT_EQ(p["file"], scene + "/" + image + ".png");
            ASSERT_TRUE(fs::exists(committed / scene / (image + ".png"))) << scene << "/" << image;
            EXPECT_EQ(p["sha256"], sha256File(committed / scene / (image + ".png"))) << scene << "/" << image;
            ++previews;
        }
        for (const auto& f : fs::directory_iterator(committed / scene))  // no preview without its EXR
            if (f.path().extension() == ".png")
                EXPECT_TRUE(fs::exists(fs::path(f.path()).replace_extension(".exr"))) << f.path();
    }
    EXPECT_GE(previews, 30);
    for (const char* key : {"mesa_version", "renderer", "image_library"})
        EXPECT_TRUE(manifest.contains(key) && !manifest[key].get<std::string>().empty()) << key;
}

// `golden --check` compares pixels, not file bytes: on the goldens' renderer they must be
// identical (another encoder's bytes for the same pixels pass); on another renderer (Mesa,
// LLVM) each image must earn full marks under its stage's grading rule. Goldens are made here
// first, so that the test holds on any Mesa.
TEST(InstructorGoldens, CheckComparesPixelsExactlyHereAndWithinTheToleranceElsewhere) {
    const fs::path pub = test::tempDir("instructor_goldens_pixels") / "public";
    auto made = test::runCommand(test::shadowlabBinary() + " golden --scenes classic --out " + pub.string());
    ASSERT_EQ(made.exitCode, 0) << made.output;
    const std::string check = test::shadowlabBinary() + " golden --check --scenes classic --out " + pub.string();
    auto manifest = nlohmann::json::parse(std::ifstream(pub / "manifest.json"));
    // Rewrites a golden with `edit` applied to its pixels, and lists the new pixels' hash.
    auto rewrite = [&](const std::string& image, const std::function<void(Image&)>& edit,
                       Compression compression) {
        Image img = readImage(pub / "classic" / (image + ".exr"));
        edit(img);
        writeExr(img, pub / "classic" / (image + ".exr"), SampleType::Float, compression);
        manifest["scenes"]["classic"]["images"][image]["pixels_sha256"] = sha256Pixels(img);
        std::ofstream(pub / "manifest.json") << manifest.dump(2);
    };
    // The same pixels in other bytes (float instead of half, another zlib level): up to date.
    rewrite("final", [](Image&) {}, Compression::Fast);
    auto same = test::runCommand(check);
    EXPECT_EQ(same.exitCode, 0) << same.output;
    // One pixel 0.001 off: stale here, within the final tolerance (0.02) elsewhere.
    rewrite("final", [](Image& img) { img.at(10, 10, 0) += 0.001f; }, Compression::Compact);
    auto here = test::runCommand(check);
    EXPECT_EQ(here.exitCode, 1) << here.output;
    EXPECT_NE(here.output.find("stale: classic/final\n"), std::string::npos) << here.output;
    manifest["mesa_version"] = "99.0.0";
    manifest["renderer"] = "llvmpipe (LLVM 99.0.0, 256 bits)";
    std::ofstream(pub / "manifest.json") << manifest.dump(2);
    auto elsewhere = test::runCommand(check);
    EXPECT_EQ(elsewhere.exitCode, 0) << elsewhere.output;
    EXPECT_NE(elsewhere.output.find("within tolerance: classic/final: other pixels"), std::string::npos)
        << elsewhere.output;
    // A shadow image half a unit off everywhere: stale on any renderer, with the figure.
    rewrite("shadow", [](Image& img) { for (float& v : img.pixels) v = 0.5f * v + 0.25f; },
            Compression::Compact);
    auto off = test::runCommand(check);
    EXPECT_EQ(off.exitCode, 1) << off.output;
    EXPECT_NE(off.output.find("stale: classic/shadow: "), std::string::npos) << off.output;
    EXPECT_NE(off.output.find("within the msm tolerance (full marks need"), std::string::npos) << off.output;
}

TEST(InstructorGoldens, CheckFlagsAHiddenSceneLeftInThePublicFolder) {
    // What the old instructions produced: a hidden scene's goldens in the public folder.
    const fs::path dir = test::tempDir("instructor_goldens_leak");
    const fs::path pub = copyOfPublicGoldens(dir / "public");
    auto j = nlohmann::json::parse(std::ifstream(pub / "manifest.json"));
    j["scenes"]["secret_shelf"] = j["scenes"]["contact"];
    std::ofstream(pub / "manifest.json") << j.dump(2);
    fs::copy(pub / "contact", pub / "secret_shelf");
    auto r = test::runCommand(test::shadowlabBinary() + " golden --check --scenes classic --out " +
                              pub.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("not a public scene"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find((pub / "secret_shelf").string()), std::string::npos) << r.output;
}

}  // namespace sl
