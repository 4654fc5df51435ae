// ShaderLibrary: #include resolution and #line bookkeeping (see shader_source.h).
#include "shader_source.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace sl {

const std::vector<std::string>& stageFileNames() {
    static const std::vector<std::string> names = {
        "moments.glsl", "gaussian_blur.comp", "sat.comp", "sat_lookup.glsl", "msm.glsl"};
    return names;
}

ShaderLibrary::ShaderLibrary(std::map<std::string, fs::path> stageDirs,
                             std::vector<fs::path> searchDirs, fs::path displayRoot)
    : stageDirs_(std::move(stageDirs)),
      searchDirs_(std::move(searchDirs)),
      displayRoot_(fs::weakly_canonical(displayRoot)) {}

ShaderLibrary ShaderLibrary::forSolution(const fs::path& solutionDir, const fs::path& repoRoot) {
    return mixed(solutionDir, {}, repoRoot);
}

ShaderLibrary ShaderLibrary::mixed(const fs::path& baseDir,
                                   const std::map<std::string, fs::path>& overrides,
                                   const fs::path& repoRoot, const fs::path& displayRoot) {
    std::map<std::string, fs::path> stages;
    for (const auto& name : stageFileNames()) stages[name] = baseDir;
    std::vector<fs::path> search;
    for (const auto& [name, dir] : overrides) {
        stages[name] = dir;
        if (std::find(search.begin(), search.end(), dir) == search.end()) search.push_back(dir);
    }
    search.push_back(baseDir);
    search.push_back(repoRoot / "shaders");
    return ShaderLibrary(stages, search, displayRoot.empty() ? repoRoot : displayRoot);
}

std::string ShaderLibrary::displayPath(const fs::path& path) const {
    fs::path p = fs::weakly_canonical(path);
    auto rel = p.lexically_relative(displayRoot_);
    if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
    return p.generic_string();
}

fs::path ShaderLibrary::resolve(const std::string& fileName) const {
    if (auto it = stageDirs_.find(fileName); it != stageDirs_.end()) {
        fs::path p = it->second / fileName;
        if (!fs::is_regular_file(p))
            throw ShaderError(displayPath(p) + ": not found (stage file not submitted?)",
                              displayPath(p));
        return p;
    }
    std::vector<fs::path> dirs;
    for (const auto& [name, dir] : stageDirs_) dirs.push_back(dir);
    dirs.insert(dirs.end(), searchDirs_.begin(), searchDirs_.end());
    for (const auto& dir : dirs)
        if (fs::is_regular_file(dir / fileName)) return dir / fileName;
    throw ShaderError(fileName + ": not found in the solution folders or shaders/", "");
}

AssembledShader ShaderLibrary::assemble(const std::string& fileName,
                                        const std::vector<std::string>& defines) const {
    AssembledShader out;
    out.text = "#version 450 core\n";
    for (const auto& d : defines) {
        auto eq = d.find('=');
        out.text += "#define " + (eq == std::string::npos ? d : d.substr(0, eq) + " " +
                                                                     d.substr(eq + 1)) + "\n";
    }
    std::vector<fs::path> stack;
    append(resolve(fileName), out, stack);
    return out;
}

void ShaderLibrary::append(const fs::path& file, AssembledShader& out,
                           std::vector<fs::path>& stack) const {
    const std::string shown = displayPath(file);
    for (const auto& open : stack)
        if (fs::equivalent(open, file))
            throw ShaderError(shown + ":1: error: #include cycle", shown);
    // Each file is included once (like #pragma once): drivers share helpers between stages.
    for (const auto& seen : out.fileNames)
        if (seen == shown) return;
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ShaderError(shown + ": cannot be read", shown);
    const int id = static_cast<int>(out.fileNames.size());
    out.fileNames.push_back(shown);
    stack.push_back(file);

    static const std::regex includeRe(R"re(^\s*#\s*include\s*"([^"]+)"\s*(//.*)?$)re");
    static const std::regex versionRe(R"(^\s*#\s*version\b.*)");
    out.text += "#line 1 " + std::to_string(id) + "\n";
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch m;
        if (std::regex_match(line, m, includeRe)) {
            fs::path target;
            try {
                target = resolve(m[1]);
            } catch (const ShaderError& e) {
                throw ShaderError(shown + ":" + std::to_string(lineNo) + ": error: " + e.what(),
                                  shown);
            }
            append(target, out, stack);
            out.text += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(id) + "\n";
        } else if (std::regex_match(line, versionRe)) {
            // The framework owns #version; keep line numbers by leaving an empty line.
            out.text += "\n";
        } else {
            out.text += line + "\n";
        }
    }
    stack.pop_back();
}

std::string AssembledShader::mapLog(const std::string& driverLog, std::string* firstFile) const {
    // Mesa: "0:12(5): error: ..."; others: "ERROR: 0:12: ..." — both carry N:L.
    static const std::regex mesaRe(R"(^(\d+):(\d+)\((\d+)\): (.*)$)");
    static const std::regex otherRe(R"(^(?:ERROR|WARNING): (\d+):(\d+): (.*)$)");
    std::istringstream in(driverLog);
    std::string line, mapped;
    while (std::getline(in, line)) {
        std::smatch m;
        auto name = [&](const std::string& n) {
            size_t i = std::stoul(n);
            std::string f = i < fileNames.size() ? fileNames[i] : "<source " + n + ">";
            if (firstFile && firstFile->empty()) *firstFile = f;
            return f;
        };
        if (std::regex_match(line, m, mesaRe))
            mapped += name(m[1]) + ":" + m[2].str() + ":" + m[3].str() + ": " + m[4].str() + "\n";
        else if (std::regex_match(line, m, otherRe))
            mapped += name(m[1]) + ":" + m[2].str() + ": " + m[3].str() + "\n";
    }
    return mapped;
}

}  // namespace sl
