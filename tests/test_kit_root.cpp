// The kit's root (paths.h): a copied kit grades from the copy, not from the checkout the
// program was built from (a kit copied elsewhere must grade from where it is); `info` and `grade`
// say which root they use, and warn when the program's build and the kit in use differ;
// $SHADOWLAB_ROOT still wins.
#include "kit_test_support.h"

#include <unistd.h>

namespace sl {
namespace {

// A copy of the kit's data folders and `kit` with this build's program in its build/: what an
// instructor gets by copying a checkout together with its build folder.
fs::path copiedKit(const std::string& name) {
    const fs::path dir = test::tempDir(name);
    for (const char* entry : {"kit", "scenes", "shaders", "student", "reference", "grader"})
        fs::copy(test::root() / entry, dir / entry, fs::copy_options::recursive);
    fs::create_directories(dir / "build");
    fs::copy_file(test::shadowlabBinary(), dir / "build/shadowlab");
    return dir;
}

}  // namespace

TEST(KitRoot, InfoNamesTheRootAndItsOrigin) {
    auto r = test::runCommand("cd / && " + test::shadowlabBinary() + " info");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string expected = "kit root: " + fs::weakly_canonical(test::root()).string() +
                                 " (from the program's location)";
    EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
}

TEST(KitRoot, ACopiedKitUsesItsOwnFoldersAndWarns) {
    const fs::path kit = copiedKit("kit_root_copy");
    // The copy's student/ differs: a render from there must read the copy's files.
    std::ofstream(kit / "student/msm.glsl", std::ios::app) << "\n#error copied-kit-student\n";
    auto info = test::runCommand("cd / && " + (kit / "build/shadowlab").string() + " info");
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("kit root: " + fs::weakly_canonical(kit).string()), std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("warning: this shadowlab was built from"), std::string::npos) << info.output;

    auto render = test::runCommand((kit / "build/shadowlab").string() + " render --scene " +
                                   (kit / "scenes/classic.json").string() + " --solution student --out " +
                                   (kit / "out").string());
    EXPECT_NE(render.exitCode, 0);
    EXPECT_NE(render.output.find("copied-kit-student"), std::string::npos) << render.output;

    // $SHADOWLAB_ROOT wins over the program's location.
    auto env = test::runCommand("SHADOWLAB_ROOT='" + test::root().string() + "' " +
                                (kit / "build/shadowlab").string() + " info");
    EXPECT_NE(env.output.find("(from $SHADOWLAB_ROOT)"), std::string::npos) << env.output;
}

TEST(KitRoot, AProgramOutsideAnyKitFindsTheKitOfTheCurrentFolder) {
    const fs::path kit = copiedKit("kit_root_cwd");
    // Outside every kit (the tests' scratch folder may lie inside the checkout).
    const fs::path elsewhere = fs::temp_directory_path() / ("shadowlab-kit-root-" + std::to_string(::getpid()));
    fs::remove_all(elsewhere);
    fs::create_directories(elsewhere);
    fs::copy_file(test::shadowlabBinary(), elsewhere / "shadowlab");
    auto r = test::runCommand("cd '" + (kit / "scenes").string() + "' && " +
                              (elsewhere / "shadowlab").string() + " info");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("kit root: " + fs::weakly_canonical(kit).string() + " (from the current folder)"),
              std::string::npos) << r.output;
    fs::remove_all(elsewhere);
}

TEST(KitRoot, GradeSaysWhichRootItUses) {
    const fs::path kit = copiedKit("kit_root_grade");
    auto r = test::runCommand((kit / "build/shadowlab").string() + " grade --submission " +
                              (kit / "reference").string() + " --out " + (kit / "out").string() +
                              " --scenes classic --no-report");
    EXPECT_NE(r.output.find("kit root: " + fs::weakly_canonical(kit).string()), std::string::npos)
        << r.output;
}

}  // namespace sl
