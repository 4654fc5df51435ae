// ShaderSource: assembles a GLSL file and its #includes into one string the driver compiles,
// and maps the driver's "N:line(col)" messages back to real files.
//
// Lookup: a stage file (moments.glsl, msm.glsl, ...) comes from the folder its stage was given
// (student/, reference/ or a submission; the grader mixes them stage by stage); any other name
// is looked up next to the file that includes it, then in those folders, then in shaders/.
//
// The assembled text is one source string without #line directives; a table maps each of its
// lines to (file, line). Errors are mapped through that table, never through the driver's
// source-string number (Mesa 22.3 reports semantic errors with source 0 whatever #line said),
// so they point at the student's own file and line. `#line` and `#extension` in a file are
// errors: one would spoof where errors are reported, the other cannot follow other code.
//
// `#include NAME` includes the file a framework define names (SL_TECHNIQUE_FILE=techniques/x.glsl,
// the technique's row); a name a file #defines itself is refused.
// #include lines inside #if/#ifdef branches the program's defines turn off are not expanded
// (glsl_scan.h evaluates the conditions), so a file a permutation does not use is not read.
// The text is scanned by hand, never with std::regex (a long line would overflow the stack).
#pragma once

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

// The five files students edit.
const std::vector<std::string>& stageFileNames();

// A shader that fails to compile or link, or a file that cannot be assembled. what() starts
// with "<file>:<line>: ..." lines and ends with the driver's full, unmodified log.
class ShaderError : public std::runtime_error {
public:
    ShaderError(const std::string& message, std::string firstFile)
        : std::runtime_error(message), file(std::move(firstFile)) {}
    std::string file;  // display path of the first file blamed ("" if none)
};

// Bounds on what one program may include (untrusted submissions go through here).
constexpr int kMaxIncludeDepth = 32;
constexpr size_t kMaxIncludedFiles = 256;
constexpr size_t kMaxAssembledBytes = 16u << 20;

struct AssembledShader {
    struct Origin {
        int file = -1;  // index into fileNames; -1: the framework's #version/#define lines
        int line = 0;   // 1-based line in that file
    };
    std::string text;                     // what is handed to glShaderSource (one string)
    std::vector<std::string> fileNames;   // display paths, the compiled file first
    std::vector<Origin> lines;            // line L of `text` (1-based) is lines[L - 1]
    // Rewrites "N:L(C): msg" lines of a driver log as "<file>:L:C: msg" (by line L of `text`).
    std::string mapLog(const std::string& driverLog, std::string* firstFile = nullptr) const;
};

class ShaderLibrary {
public:
    // stageDirs: stage file name -> folder holding it. Other files: `searchDirs` in order.
    // Paths under `displayRoot` are shown relative to it (student/msm.glsl); others as
    // "<folder>/<file>", never as absolute paths.
    ShaderLibrary(std::map<std::string, fs::path> stageDirs, std::vector<fs::path> searchDirs,
                  fs::path displayRoot);

    // All five stages from one solution folder, then shaders/ under the repository root.
    static ShaderLibrary forSolution(const fs::path& solutionDir, const fs::path& repoRoot);
    // The stages of `baseDir`, except the files named in `overrides` (stage file -> folder):
    // how the grader and the tests grade one stage of a submission on reference inputs.
    // Other includes are looked up next to the including file, then in the override folders,
    // then `baseDir`, then shaders/.
    static ShaderLibrary mixed(const fs::path& baseDir,
                               const std::map<std::string, fs::path>& overrides,
                               const fs::path& repoRoot, const fs::path& displayRoot = {});

    // `defines` become "#define NAME" or "#define NAME VALUE" lines after #version.
    AssembledShader assemble(const std::string& fileName,
                             const std::vector<std::string>& defines) const;

    // A file by name, as a top-level file (throws ShaderError if absent); with `includer`,
    // as that file's #include: its own folder first; a solution's file (in a stage folder)
    // looks only there and in the search folders that hold no stage (shaders/).
    fs::path resolve(const std::string& fileName, const fs::path& includer = {}) const;
    std::string displayPath(const fs::path& path) const;
    const std::map<std::string, fs::path>& stageDirs() const { return stageDirs_; }

private:
    struct Assembly;
    void append(const fs::path& file, Assembly& a, int depth) const;

    std::map<std::string, fs::path> stageDirs_;
    std::vector<fs::path> searchDirs_;
    fs::path displayRoot_;
};

}  // namespace sl
