// ShaderSource: assembles a GLSL file and its #includes into one string the driver compiles,
// and maps the driver's "N:line(col)" messages back to real files.
//
// Lookup: a stage file (moments.glsl, msm.glsl, ...) comes from the folder its stage was given
// (student/, reference/ or a submission; the grader mixes them stage by stage); any other name
// is looked up in those folders first and then in shaders/. Every file gets a GLSL source-string
// number through `#line 1 N`, so errors point at the student's own file and line.
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

struct AssembledShader {
    std::string text;                     // what is handed to glShaderSource
    std::vector<std::string> fileNames;   // source-string number -> display path
    // Rewrites "N:L(C): msg" lines of a driver log as "<file>:L:C: msg".
    std::string mapLog(const std::string& driverLog, std::string* firstFile = nullptr) const;
};

class ShaderLibrary {
public:
    // stageDirs: stage file name -> folder holding it. Other files: `searchDirs` in order.
    // Paths under `displayRoot` are shown relative to it (student/msm.glsl).
    ShaderLibrary(std::map<std::string, fs::path> stageDirs, std::vector<fs::path> searchDirs,
                  fs::path displayRoot);

    // All five stages from one solution folder, then shaders/ under the repository root.
    static ShaderLibrary forSolution(const fs::path& solutionDir, const fs::path& repoRoot);
    // The stages of `baseDir`, except the files named in `overrides` (stage file -> folder):
    // how the grader and the tests grade one stage of a submission on reference inputs.
    // Other includes are looked up in the override folders, then `baseDir`, then shaders/.
    static ShaderLibrary mixed(const fs::path& baseDir,
                               const std::map<std::string, fs::path>& overrides,
                               const fs::path& repoRoot, const fs::path& displayRoot = {});

    // `defines` become "#define NAME" or "#define NAME VALUE" lines after #version.
    AssembledShader assemble(const std::string& fileName,
                             const std::vector<std::string>& defines) const;

    fs::path resolve(const std::string& fileName) const;  // throws ShaderError if absent
    std::string displayPath(const fs::path& path) const;
    const std::map<std::string, fs::path>& stageDirs() const { return stageDirs_; }

private:
    void append(const fs::path& file, AssembledShader& out, std::vector<fs::path>& stack) const;

    std::map<std::string, fs::path> stageDirs_;
    std::vector<fs::path> searchDirs_;
    fs::path displayRoot_;
};

}  // namespace sl
