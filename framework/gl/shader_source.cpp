// ShaderLibrary: #include resolution, conditional includes and the line table (see
// shader_source.h). Plain scanning only (glsl_scan.h): the text may be a student's.
#include "shader_source.h"

#include "glsl_scan.h"

#include <algorithm>
#include <fstream>

namespace sl {

const std::vector<std::string>& stageFileNames() {
    static const std::vector<std::string> names = {
        "moments.glsl", "gaussian_blur.comp", "sat.comp", "sat_lookup.glsl", "msm.glsl"};
    return names;
}

// The state of one assemble() call.
struct ShaderLibrary::Assembly {
    AssembledShader out;
    glsl::Conditionals conditions;
    std::map<std::string, std::string> defines;  // the framework's, NAME -> value
    std::vector<fs::path> stack;  // the files being expanded, outermost first
    void emit(std::string_view line, int file, int lineNo) {
        out.text.append(line);
        out.text += '\n';
        out.lines.push_back({file, lineNo});
    }
};

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
    std::error_code ec;
    fs::path p = fs::weakly_canonical(path, ec);
    if (ec) p = path.lexically_normal();
    auto rel = p.lexically_relative(displayRoot_);
    if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
    // Outside the root: the folder and the name only (no machine paths in student messages).
    const std::string folder = p.parent_path().filename().generic_string();
    return (folder.empty() ? "" : folder + "/") + p.filename().generic_string();
}

fs::path ShaderLibrary::resolve(const std::string& fileName, const fs::path& includer) const {
    std::error_code ec;
    if (auto it = stageDirs_.find(fileName); it != stageDirs_.end()) {
        fs::path p = it->second / fileName;
        if (!fs::is_regular_file(p, ec))
            throw ShaderError(displayPath(p) + ": not found (stage file not submitted?)",
                              displayPath(p));
        return p;
    }
    std::vector<fs::path> dirs;
    if (!includer.empty()) {
        // A solution's file (student or reference) finds helpers in its own folder and in the
        // framework's folders (shaders/) only: never in another solution's folder.
        const fs::path own = includer.parent_path();
        auto isSolution = [&](const fs::path& d) {
            for (const auto& [name, dir] : stageDirs_)
                if (dir == d) return true;
            return false;
        };
        dirs.push_back(own);
        if (isSolution(own)) {
            for (const auto& d : searchDirs_)
                if (!isSolution(d)) dirs.push_back(d);
            for (const auto& dir : dirs)
                if (fs::is_regular_file(dir / fileName, ec)) return dir / fileName;
            throw ShaderError(fileName + ": not found next to " + includer.filename().string() +
                                  " or in shaders/", "");
        }
    }
    for (const auto& [name, dir] : stageDirs_)
        if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
    dirs.insert(dirs.end(), searchDirs_.begin(), searchDirs_.end());
    for (const auto& dir : dirs)
        if (fs::is_regular_file(dir / fileName, ec)) return dir / fileName;
    throw ShaderError(fileName + ": not found in the solution folders or shaders/", "");
}

AssembledShader ShaderLibrary::assemble(const std::string& fileName,
                                        const std::vector<std::string>& defines) const {
    Assembly a{{}, glsl::Conditionals(defines), {}, {}};
    a.emit("#version 450 core", -1, 0);
    for (const auto& d : defines) {
        auto eq = d.find('=');
        if (eq != std::string::npos) a.defines[d.substr(0, eq)] = d.substr(eq + 1);
        a.emit("#define " + (eq == std::string::npos ? d : d.substr(0, eq) + " " + d.substr(eq + 1)),
               -1, 0);
    }
    append(resolve(fileName), a, 0);
    return std::move(a.out);
}

void ShaderLibrary::append(const fs::path& file, Assembly& a, int depth) const {
    const std::string shown = displayPath(file);
    std::error_code ec;
    for (const auto& open : a.stack)
        if (fs::equivalent(open, file, ec))
            throw ShaderError(shown + ":1: error: #include cycle", shown);
    // Each file is included once (like #pragma once): drivers share helpers between stages.
    for (const auto& seen : a.out.fileNames)
        if (seen == shown) return;
    if (depth >= kMaxIncludeDepth)
        throw ShaderError(shown + ":1: error: #include nested more than " +
                              std::to_string(kMaxIncludeDepth) + " deep", shown);
    if (a.out.fileNames.size() >= kMaxIncludedFiles)
        throw ShaderError(shown + ":1: error: more than " + std::to_string(kMaxIncludedFiles) +
                              " files included", shown);
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ShaderError(shown + ": cannot be read", shown);
    std::string content;
    {
        char buf[65536];
        while (in.read(buf, sizeof buf) || in.gcount() > 0) {
            content.append(buf, size_t(in.gcount()));
            if (content.size() + a.out.text.size() > kMaxAssembledBytes)
                throw ShaderError(shown + ": error: the program's source grows over " +
                                      std::to_string(kMaxAssembledBytes >> 20) + " MiB", shown);
        }
    }
    const int id = static_cast<int>(a.out.fileNames.size());
    a.out.fileNames.push_back(shown);
    a.stack.push_back(file);

    glsl::LineScanner scanner;
    int lineNo = 0;
    for (std::string_view line : glsl::splitLines(content)) {
        ++lineNo;
        const auto d = scanner.scan(line);
        auto fail = [&](const std::string& what) {
            throw ShaderError(shown + ":" + std::to_string(lineNo) + ": error: " + what, shown);
        };
        if (!d) {
            a.emit(line, id, lineNo);
            continue;
        }
        a.conditions.apply(*d);
        const bool compiled = a.conditions.active() != glsl::Conditionals::No;
        if (d->name == "include") {
            a.emit("", id, lineNo);  // the include line itself becomes blank
            if (!compiled) continue;  // a branch this permutation does not compile
            auto name = glsl::includeName(d->argument);
            // `#include NAME`: the file the framework's define NAME names (the technique's
            // file, SL_TECHNIQUE_FILE); a file's own #define cannot name one.
            if (!name) {
                const std::string macro(d->argument);  // trimmed, comments removed
                if (auto it = a.defines.find(macro); it != a.defines.end()) name = it->second;
            }
            if (!name || name->empty())
                fail("#include takes a file name in double quotes (#include \"file.glsl\") or "
                     "a name the framework defines as one");
            fs::path target;
            try {
                target = resolve(*name, file);
            } catch (const ShaderError& e) {
                fail(e.what());
            }
            append(target, a, depth + 1);
        } else if (d->name == "version") {
            a.emit("", id, lineNo);  // the framework owns #version
        } else if (d->name == "line") {
            fail("#line is not allowed (it would change where errors are reported)");
        } else if (d->name == "extension") {
            fail("#extension is not allowed (the framework compiles GLSL 4.50 core; "
                 "extensions must come before any code)");
        } else {
            a.emit(line, id, lineNo);
        }
    }
    a.stack.pop_back();
}

std::string AssembledShader::mapLog(const std::string& driverLog, std::string* firstFile) const {
    std::string mapped;
    for (std::string_view line : glsl::splitLines(driverLog)) {
        const auto l = glsl::parseLogLine(line);
        if (!l) continue;
        // By line of the assembled text; past the end (an error at EOF): its last line.
        std::string where = "<framework>";
        long fileLine = l->line;
        if (!lines.empty() && l->line >= 1) {
            const Origin& o = lines[size_t(std::min<long>(l->line, long(lines.size()))) - 1];
            if (o.file >= 0 && size_t(o.file) < fileNames.size()) {
                where = fileNames[size_t(o.file)];
                fileLine = o.line;
            }
        }
        if (firstFile && firstFile->empty()) *firstFile = where;
        mapped += where + ":" + std::to_string(fileLine) +
                  (l->column > 0 ? ":" + std::to_string(l->column) : "") + ": " + l->message + "\n";
    }
    return mapped;
}

}  // namespace sl
