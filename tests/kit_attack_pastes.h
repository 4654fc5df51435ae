// kit_attack_pastes.h: the attack test's stage targets (test_kit_attack.cpp), and how a
// shipped function or compute shader is pasted into a stage file: its helpers and globals,
// extra parameters filled, C++ translated to GLSL, a filter shader's bindings checked.
#pragma once

#include "kit_attack_sources.h"

namespace sl::kit_attack {

// ---------------------------------------------------------------------------------------
// Stage targets

struct Target {
    std::string key;   // the stage function, or the compute stage's file
    std::string file;  // the stage file it goes into
    std::string returnType;
    std::vector<std::string> params;
    std::string scene;
    std::vector<std::string> tests;  // results.json test names that grade it
};

inline const std::vector<Target>& targets() {
    static const std::vector<Target> t = {
        {"relativeDepth", "moments.glsl", "float", {"float", "vec2"}, "classic", {"classic: moments"}},
        {"computeMoments", "moments.glsl", "vec4", {"float"}, "classic", {"classic: moments"}},
        {"momentShadowIntensity",
         "msm.glsl",
         "float",
         {"vec4", "float"},
         "classic",
         {"classic: msm", "hard cases: robustness"}},
        {"satBoxAverage",
         "sat_lookup.glsl",
         "vec4",
         {"sampler2D", "vec2", "vec2"},
         "wide_blur",
         {"wide_blur: sat"}},
        {"satKernelTexels",
         "sat_lookup.glsl",
         "float",
         {"sampler2D", "vec2", "float", "float", "vec2", "float", "bool", "vec2"},
         "penumbra",
         {"penumbra: sat"}},
        {"gaussian_blur.comp", "gaussian_blur.comp", "", {}, "classic", {"classic: gaussian"}},
        {"sat.comp", "sat.comp", "", {}, "wide_blur", {"wide_blur: sat"}},
    };
    return t;
}

inline const Target& target(const std::string& key) {
    for (const auto& t : targets())
        if (t.key == key) return t;
    throw std::runtime_error("no target " + key);
}

inline std::string zeroOf(const std::string& type) {
    if (type == "float") return "0.0";
    if (type == "int" || type == "uint") return type + "(0)";
    if (type == "bool") return "false";
    if (std::regex_match(type, std::regex(R"([iub]?vec[234]|mat[234])"))) return type + "(0)";
    return "";  // a parameter no literal fills (a struct, a sampler, an array)
}

// A call's argument that a student could copy as it is: numbers and constructors only.
inline bool constantArgument(const std::string& a) {
    return std::regex_match(a, std::regex(R"(\s*((vec[234]|float|int)\s*\(|[-+*/.,()\s\deEf])*)"));
}

inline std::vector<std::string> splitArguments(const std::string& args) {
    std::vector<std::string> out;
    int depth = 0;
    std::string cur;
    for (char c : args) {
        if (c == ',' && depth == 0) {
            out.push_back(squeeze(cur));
            cur.clear();
            continue;
        }
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        cur += c;
    }
    out.push_back(squeeze(cur));
    return out;
}

// C++ (a function of GLM and <cmath>) line by line in GLSL; "" if it uses what GLSL has not.
inline std::string cppToGlsl(std::string t, const std::string& returnType) {
    for (size_t pos = 0; (pos = t.find("return", pos)) != std::string::npos; pos += 6) {
        size_t b = pos + 6;
        while (b < t.size() && std::isspace(static_cast<unsigned char>(t[b]))) ++b;
        if (b >= t.size() || t[b] != '{') continue;
        const size_t e = matching(t, b);
        if (e == std::string::npos) return "";
        t[e] = ')';
        t.replace(b, 1, returnType + "(");
    }
    t = std::regex_replace(t, std::regex(R"(static_cast<\s*(\w+)\s*>\s*\()"), "$1(");
    t = std::regex_replace(t, std::regex(R"(\bstd::fabs\b)"), "abs");
    t = std::regex_replace(t, std::regex(R"(\bstd::fmod\b)"), "mod");
    t = std::regex_replace(t, std::regex(R"(\b(std|glm)::)"), "");
    t = std::regex_replace(t, std::regex(R"(\[\[\w+\]\]|\b(constexpr|const|inline|static|noexcept)\b)"), " ");
    t = std::regex_replace(t, std::regex(R"(\bdouble\b)"), "float");
    t = std::regex_replace(t, std::regex(R"(\bd(vec|mat)([234])\b)"), "$1$2");
    const size_t brace = std::min(t.find('{'), t.size());
    t = std::regex_replace(t.substr(0, brace), std::regex("&"), " ") +
        t.substr(brace);  // reference parameters
    static const std::regex foreign(
        R"(::|\bauto\b|\bstd\b|\bthrow\b|->|\btemplate\b|\[[&=]|\bnullptr\b|\bsizeof\b|"|\bsize_t\b|\bmemcpy\b|\bu?int\d+_t\b|\blong\b)");
    return std::regex_search(t, foreign) ? "" : t;
}

// One way to hand a function in as a stage function: the text that replaces the stub's
// definition in the stage file.
struct Paste {
    std::string what;  // "file: function(...) as target" for the report
    std::string text;
};

// Pastes of function `f` of `self` as target `t`: the definitions it needs, renamed, and the
// stage function calling it; one paste per way to fill its extra parameters. Helpers come from
// `scope` (the files `self` includes, then `self`), else from the first file of `library` that
// defines them (a student greps the kit). `context`: uniforms declared around the stage file.
std::vector<Paste> pastes(const Function& f, const Source& self, const std::vector<const Source*>& scope,
                          const std::vector<const Source*>& library, const Target& t,
                          const std::set<std::string>& context,
                          const std::vector<std::vector<std::string>>& callSites) {
    // The definitions it needs, transitively: functions called, globals named.
    struct Item {
        size_t rank, pos;
        std::string name, text;
        bool function;
    };
    std::map<std::string, Item> items;
    // Ranks: library files found along the way, before the scope (a helper precedes its use).
    std::vector<const Source*> found;
    auto rankOf = [&](size_t scopeIndex) { return 1000 + scopeIndex; };
    auto findFunction = [&](const std::string& name) -> std::pair<const Function*, size_t> {
        for (size_t r = scope.size(); r-- > 0;)  // self first (it is last), then its includes
            for (const auto& g : scope[r]->fns)
                if (g.name == name) return {&g, rankOf(r)};
        for (const Source* s : library)
            for (const auto& g : s->fns)
                if (g.name == name) {
                    auto at = std::find(found.begin(), found.end(), s);
                    if (at == found.end()) at = found.insert(found.end(), s);
                    return {&g, 999 - size_t(at - found.begin())};  // found later: defined earlier
                }
        return {nullptr, 0};
    };
    auto translate = [&](const std::string& text, const std::string& ret) {
        return self.cpp ? cppToGlsl(text, ret) : text;
    };
    const std::string first = translate(f.text, f.returnType);
    if (first.empty()) return {};
    items[f.name] = {rankOf(scope.size() - 1), f.begin, f.name, first, true};
    for (bool grew = true; grew;) {
        grew = false;
        std::string all;
        for (const auto& [n, it] : items) all += it.text + "\n";
        static const std::regex call(R"(\b([A-Za-z_]\w*)\s*\()");
        for (std::sregex_iterator it(all.begin(), all.end(), call), end; it != end; ++it) {
            const std::string name = (*it)[1].str();
            if (items.count(name)) continue;
            auto [g, rank] = findFunction(name);
            if (!g) continue;
            const std::string text = translate(g->text, g->returnType);
            if (text.empty()) return {};
            items[name] = {rank, g->begin, name, text, true};
            grew = true;
        }
        std::vector<std::pair<const Source*, size_t>> files;
        for (size_t r = 0; r < scope.size(); ++r) files.push_back({scope[r], rankOf(r)});
        for (size_t i = 0; i < found.size(); ++i) files.push_back({found[i], 999 - i});
        for (const auto& [file, rank] : files)
            for (const auto& g : file->globals) {
                if (items.count(g.name) || context.count(g.name) || !hasWord(all, g.name)) continue;
                const std::string text = translate(g.text, "");
                if (text.empty()) return {};
                items[g.name] = {rank, g.pos, g.name, text, false};
                grew = true;
            }
    }
    std::vector<Item> ordered;
    for (const auto& [n, it] : items) ordered.push_back(it);
    std::sort(ordered.begin(), ordered.end(), [](const Item& a, const Item& b) {
        return a.rank != b.rank ? a.rank < b.rank : a.pos < b.pos;
    });
    std::string block;
    for (const auto& it : ordered) block += it.text + "\n";
    for (const auto& it : ordered)
        if (it.function)
            block =
                std::regex_replace(block, std::regex("\\b" + it.name + "\\b(?=\\s*\\()"), "atk_" + it.name);
    // Its extra parameters: zeros; the constants a caller in the kit passes; uMomentBias (msm).
    std::vector<std::vector<std::string>> fills;
    std::vector<std::string> zeros;
    for (size_t i = t.params.size(); i < f.params.size(); ++i) {
        zeros.push_back(zeroOf(f.params[i].type));
        if (zeros.back().empty()) return {};
    }
    fills.push_back(zeros);
    for (const auto& args : callSites) {
        if (args.size() != f.params.size()) continue;
        auto fill = zeros;
        for (size_t i = t.params.size(); i < args.size(); ++i)
            if (constantArgument(args[i])) fill[i - t.params.size()] = args[i];
        fills.push_back(fill);
    }
    if (t.key == "momentShadowIntensity")  // each fill again, its first zero float the bias
        for (size_t n = fills.size(), j = 0; j < n; ++j)
            for (size_t i = 0; i < zeros.size(); ++i)
                if (f.params[t.params.size() + i].type == "float" && fills[j][i] == "0.0") {
                    auto fill = fills[j];
                    fill[i] = "uMomentBias";
                    fills.push_back(fill);
                    break;
                }
    std::vector<Paste> out;
    std::set<std::vector<std::string>> seen;
    for (const auto& fill : fills) {
        if (!seen.insert(fill).second) continue;
        std::string wrapper = t.returnType + " " + t.key + "(";
        std::string args;
        for (size_t i = 0; i < t.params.size(); ++i) {
            wrapper += (i ? ", " : "") + t.params[i] + " a" + std::to_string(i);
            args += (i ? ", " : "") + std::string("a") + std::to_string(i);
        }
        wrapper += ")\n{\n";
        for (size_t i = 0; i < fill.size(); ++i) {
            const std::string var = "x" + std::to_string(i);
            wrapper += "    " + f.params[t.params.size() + i].type + " " + var + " = " + fill[i] + ";\n";
            args += ", " + var;
        }
        wrapper += "    return " + t.returnType + "(atk_" + f.name + "(" + args + "));\n}\n";
        std::string what = self.path + ": " + f.name + "(";
        for (size_t i = 0; i < f.params.size(); ++i) what += (i ? ", " : "") + f.params[i].type;
        what += ")";
        if (!fill.empty()) {
            what += " with";
            for (const auto& v : fill) what += " " + v;
        }
        what += " as " + t.key;
        out.push_back({what, "// KitAttack: " + what + "\n" + block + wrapper});
    }
    return out;
}

// A stage file's text without the attack's header line (duplicates from two files are one).
inline std::string withoutHeader(const std::string& text) {
    return std::regex_replace(text, std::regex("// KitAttack: [^\n]*\n"), "");
}

inline bool matchesTarget(const Function& f, const Target& t) {
    if (t.returnType.empty() || f.returnType != t.returnType || f.params.size() < t.params.size())
        return false;
    for (size_t i = 0; i < t.params.size(); ++i)
        if (f.params[i].type != t.params[i]) return false;
    return true;
}

// The text of `file` with function `name`'s definition replaced by `with`.
inline std::string replaceFunction(const std::string& file, const std::string& name, const std::string& with) {
    const std::string code = stripComments(file);
    for (const auto& f : functions(code, false))
        if (f.name == name) return file.substr(0, f.begin) + with + file.substr(f.end);
    throw std::runtime_error("no function " + name + " to replace");
}

inline std::string definitionOf(const std::string& file, const std::string& name) {
    const std::string code = stripComments(file);
    for (const auto& f : functions(code, false))
        if (f.name == name) return f.text;
    throw std::runtime_error("no function " + name);
}

// A compute shader's image bindings: binding -> (readable, writable, format).
struct ImageBinding {
    bool read = false, write = false;
    std::string format;
};

inline std::map<int, ImageBinding> imageBindings(const std::string& code) {
    std::map<int, ImageBinding> out;
    static const std::regex decl(R"(layout\s*\(([^)]*)\)\s*uniform\s+((?:\w+\s+)*)[iu]?image2D\b)");
    for (std::sregex_iterator it(code.begin(), code.end(), decl), end; it != end; ++it) {
        const std::string layout = (*it)[1].str(), quals = (*it)[2].str();
        std::smatch m;
        if (!std::regex_search(layout, m, std::regex(R"(binding\s*=\s*(\d+))"))) continue;
        ImageBinding img;
        img.read = quals.find("writeonly") == std::string::npos;
        img.write = quals.find("readonly") == std::string::npos;
        for (const auto& part : splitArguments(layout))
            if (part.find("binding") == std::string::npos) img.format = part;
        out[std::stoi(m[1].str())] = img;
    }
    return out;
}

inline bool weightsBuffer(const std::string& code) {
    static const std::regex block(R"(layout\s*\(([^)]*)\)\s*(?:\w+\s+)*buffer\b)");
    for (std::sregex_iterator it(code.begin(), code.end(), block), end; it != end; ++it)
        if (std::regex_search((*it)[1].str(), std::regex(R"(binding\s*=\s*0\b)"))) return true;
    return false;
}

// A compute shader as a filter stage: its includes inlined (not the stage files), and a
// #define rgba32f for a format that is a macro of the framework's.
inline std::string computeStage(const fs::path& root, const std::string& path, const std::string& text) {
    std::string out;
    for (const auto& [binding, img] : imageBindings(stripComments(text)))
        if (std::regex_match(img.format, std::regex(R"([A-Z_][A-Z0-9_]*)")))
            out += "#define " + img.format + " rgba32f\n";
    std::set<std::string> done;
    std::function<std::string(const std::string&, const std::string&)> inline_ = [&](const std::string& p,
                                                                                     const std::string& t) {
        std::string r;
        std::istringstream in(t);
        for (std::string line; std::getline(in, line);) {
            std::smatch m;
            if (std::regex_search(line, m, std::regex(R"re(^\s*#\s*include\s+"([^"]+)")re")) &&
                !stageFiles().count(m[1].str())) {
                for (const fs::path& q :
                     {fs::path("shaders") / m[1].str(), fs::path(p).parent_path() / m[1].str()})
                    if (fs::is_regular_file(root / q)) {
                        const std::string key = q.lexically_normal().generic_string();
                        if (done.insert(key).second) r += inline_(key, test::readFile(root / q));
                        break;
                    }
                continue;
            }
            r += line + "\n";
        }
        return r;
    };
    return out + inline_(path, text);
}

}  // namespace sl::kit_attack
