// Hostile input (a grade writes only under its output folder): what a grade leaves behind and
// shows. Workers share a Mesa shader cache in the grade's own work folder,
// OUT/.work-<pid>/shader-cache (never the user's cache: that was the only write outside OUT, and
// would share programs between grades), and no student-visible message holds the grader's absolute
// paths (the kit, OUT, the staging folder).
#include "test_grader_support.h"

namespace sl {

TEST(HostileGradeHygiene, NoShaderCacheAndNoAbsolutePathsInMessages) {
    std::string moments = test::readFile(test::root() / "reference" / "moments.glsl");
    moments += "float hostileHelper() { return undeclaredThing; }\n";
    auto sub = test::makeSubmission("hygiene", {{"moments.glsl", moments}});
    const fs::path cache = test::tempDir("hygiene_cache");
    const fs::path out = test::tempDir("hygiene_out");
    // A scene error in a worker names the scene file: a hidden scene by path (outside scenes/).
    const fs::path hidden = test::tempDir("hygiene_hidden") / "hidden_classic.json";
    fs::copy_file(test::scenePath("classic"), hidden);
    auto g = test::grade("--scenes " + hidden.string() + " --no-report --keep-work --submission " + sub.string(), out,
                         "XDG_CACHE_HOME=" + cache.string() + " MESA_SHADER_CACHE_DIR=" +
                             (cache / "mesa").string());
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_TRUE(fs::is_empty(cache)) << "Mesa wrote its shader cache under " << cache;
    // The workers' cache: in this grade's work folder (kept here by --keep-work), and used.
    int caches = 0;
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().filename().string().rfind(".work-", 0) == 0) {
            const fs::path grade = e.path() / "shader-cache";
            ASSERT_TRUE(fs::is_directory(grade)) << grade;
            EXPECT_FALSE(fs::is_empty(grade)) << "the workers compiled without a shared cache";
            ++caches;
        }
    EXPECT_EQ(caches, 1);
    const std::string moment = g.output("hidden_classic", "moments");
    EXPECT_NE(moment.find("submission/moments.glsl:"), std::string::npos) << moment;
    for (const auto& t : g.results["tests"]) {
        const std::string text = t["output"].get<std::string>();
        SCOPED_TRACE(t["name"].get<std::string>());
        for (const fs::path& p : {test::root(), out, sub, hidden.parent_path()})
            EXPECT_EQ(text.find(p.string()), std::string::npos) << p << " in\n" << text;
    }
}

}  // namespace sl
