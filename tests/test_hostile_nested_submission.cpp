// Hostile input (intake: a correct submission must get its points): uploads often keep their
// folder, so the stage files sit in submission/<folder>/*.glsl. That scored 0 ("ignored (not stage
// files): <folder>"); one level of nesting is accepted now, when the top holds no stage file and
// exactly one folder.
#include "test_grader_support.h"

namespace sl {

TEST(HostileNestedSubmission, OneNestedFolderIsGradedAsTheSubmission) {
    auto files = test::makeSubmission("nested_files");
    const fs::path sub = test::tempDir("nested_upload");
    fs::create_directories(sub / "__MACOSX");  // archive tools' leftovers do not count
    std::ofstream(sub / ".DS_Store") << "x";
    fs::copy(files, sub / "my_solution");
    auto g = test::grade("--scenes classic --no-report --submission " + sub.string(),
                         test::tempDir("nested_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    for (const char* stage : {"moments", "gaussian", "msm", "final"})
        EXPECT_TRUE(g.full("classic", stage)) << stage << ": " << g.output("classic", stage);
}

}  // namespace sl
