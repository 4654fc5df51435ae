// The architecture picture (docs/architecture.svg) is the build's own graph: CMake's targets,
// one library per folder, drawn by tools/architecture_graph.sh. A library that gains or loses a
// dependency without the picture being redrawn fails here.
#include "gl_test_support.h"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace sl;

TEST(ArchitectureGraph, TheDocsPictureIsTheBuildsTargetGraph) {
    const auto r = test::runCommand("'" + (test::root() / "tools" / "architecture_graph.sh").string() + "' --check");
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

// The layers as docs/architecture.md states them: the framework's folders build on one another
// downwards only (gl at the bottom), the grader on the numerics and never on the study, the
// truth or the viewer.
TEST(ArchitectureGraph, TheLayersRunDownwardsOnly) {
    std::ifstream in(test::root() / "docs" / "architecture.dot");
    std::stringstream text;
    text << in.rdbuf();
    const std::string dot = text.str();
    for (const char* edge : {"\"framework/scene/\" -> \"framework/gl/\"", "\"framework/render/\" -> \"framework/scene/\"",
                             "\"framework/study/\" -> \"framework/truth/\"", "\"grader/\" -> \"framework/numerics/\""})
        EXPECT_NE(dot.find(edge), std::string::npos) << edge << "\n" << dot;
    for (const char* edge : {"\"framework/gl/\" ->", "\"grader/\" -> \"framework/study/\"",
                             "\"grader/\" -> \"framework/truth/\"", "\"grader/\" -> \"framework/view/\"",
                             "\"framework/truth/\" -> \"framework/study/\"", "\"framework/render/\" -> \"framework/numerics/\""})
        EXPECT_EQ(dot.find(edge), std::string::npos) << edge << "\n" << dot;
}
