// The student kit attacked as a student would (issue 20 §4): pack it, unpack it, and look in
// everything it ships outside student/ for something to hand in as a stage.
//  - Stages: every function whose signature could stand in for a stage function (GLSL files,
//    the code blocks of its Markdown, and C++ translated line by line to GLSL), and every compute
//    shader with a filter stage's bindings, goes into a copy of the stubs as that stage (with the
//    helpers, constants, uniforms and #defines it needs from its file and the files that file
//    includes; extra parameters get zeros, the constants its callers pass, or uMomentBias) and
//    is graded by the kit's own `shadowlab grade --batch` against its goldens: classic for
//    moments, msm (with robustness) and the Gaussian, wide_blur for the SAT pair. It must score
//    no more than the stub on that stage. What the stage needs besides the attacked function
//    comes from the solution, so that the attacked function alone decides: the reference's other
//    moments.glsl function, the reference's relativeDepth for msm (the kit's lighting takes it
//    from the submission), a plain float32 SAT pair (tests/submissions/fragile/naive_sat) for
//    the other half of the SAT stage.
//  - Patterns: no file it ships outside student/ holds the Hankel matrix's Cholesky pivots on
//    moments, a loop over uWeights, a running sum stored with imageStore in its loop, or the
//    moment powers vec4(z, z2, z2 * z, z2 * z2).
// Controls keep the attack honest: the reference's stage functions, the plain SAT pair and the
// float MSM mirror (C++), put through the same extraction, score above the stub, and the
// patterns find the solution's files. This file is not in the student kit (not in
// grader/student_kit.manifest). Time: docs/grading.md, "What the student kit contains".
#include "kit_test_support.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstring>
#include <functional>
#include <map>
#include <set>

// A named namespace: the tests build in unity batches, where another file's anonymous
// namespace shares this one's translation unit.
namespace sl::kit_attack {

// ---------------------------------------------------------------------------------------
// Source text

// `code` with its comments turned into spaces (newlines kept, so offsets stay valid); string
// and character literals are kept.
std::string stripComments(const std::string& code) {
    std::string s = code;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '"' || s[i] == '\'') {
            const char q = s[i];
            for (++i; i < s.size() && s[i] != q && s[i] != '\n'; ++i)
                if (s[i] == '\\') ++i;
        } else if (s.compare(i, 2, "//") == 0) {
            for (; i < s.size() && s[i] != '\n'; ++i) s[i] = ' ';
        } else if (s.compare(i, 2, "/*") == 0) {
            const size_t end = s.find("*/", i + 2);
            const size_t stop = end == std::string::npos ? s.size() : end + 2;
            for (; i < stop; ++i)
                if (s[i] != '\n') s[i] = ' ';
            --i;
        }
    }
    return s;
}

// The index of the bracket closing the one at `open` ('{' or '('), or npos.
size_t matching(const std::string& s, size_t open) {
    const char o = s[open], c = o == '{' ? '}' : ')';
    int depth = 0;
    for (size_t i = open; i < s.size(); ++i) {
        if (s[i] == o)
            ++depth;
        else if (s[i] == c && --depth == 0)
            return i;
    }
    return std::string::npos;
}

std::string squeeze(const std::string& s) {
    static const std::regex space(R"(\s+)"), ends(R"(^ | $)");
    return std::regex_replace(std::regex_replace(s, space, " "), ends, "");
}

bool hasWord(const std::string& text, const std::string& word) {
    return std::regex_search(text, std::regex("\\b" + word + "\\b"));
}

bool isIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

int lineOf(const std::string& text, size_t pos) {
    return 1 + int(std::count(text.begin(), text.begin() + std::min(pos, text.size()), '\n'));
}

// ---------------------------------------------------------------------------------------
// Functions and the globals they need

struct Param {
    std::string type, name;
};

struct Function {
    std::string returnType, name;
    std::vector<Param> params;
    size_t begin = 0, end = 0;  // [begin, end) of the definition in its source
    std::string text;           // the definition, comments removed
};

// The GLSL type a C++ or GLSL parameter type matches: qualifiers, glm::, references dropped,
// double -> float, dvecN -> vecN; an array gets "[]".
std::string normalType(std::string t) {
    static const std::regex prefix(R"(\b(glm|std)::)"), dvec(R"(d(vec|mat)[234])");
    static const std::regex qualifier(
        R"(\b(const|in|out|inout|highp|mediump|lowp|precise|static|inline|constexpr)\b|[&*])");
    t = squeeze(std::regex_replace(std::regex_replace(t, prefix, ""), qualifier, " "));
    if (t == "double") return "float";
    if (std::regex_match(t, dvec)) return t.substr(1);
    return t;
}

std::vector<Param> parseParams(const std::string& list) {
    std::vector<Param> out;
    const std::string l = squeeze(list);
    if (l.empty() || l == "void") return out;
    std::istringstream in(l);
    static const std::regex defaultValue(R"(=.*$)"), arrayEnd(R"(\]\s*$)"), arraySize(R"(\s*\[[^\]]*\]\s*$)");
    for (std::string p; std::getline(in, p, ',');) {
        p = squeeze(std::regex_replace(p, defaultValue, ""));  // a C++ default value
        const bool array = std::regex_search(p, arrayEnd);
        p = std::regex_replace(p, arraySize, "");
        size_t n = p.size();
        while (n > 0 && isIdent(p[n - 1])) --n;
        if (n == 0)
            out.push_back({normalType(p) + (array ? "[]" : ""), ""});  // unnamed
        else
            out.push_back({normalType(p.substr(0, n)) + (array ? "[]" : ""), p.substr(n)});
    }
    return out;
}

const std::set<std::string>& keywords() {
    static const std::set<std::string> k = {
        "if",    "for",      "while",    "switch",  "return",   "else",  "do",        "case",
        "new",   "delete",   "catch",    "sizeof",  "throw",    "using", "namespace", "struct",
        "class", "operator", "decltype", "typedef", "template", "TEST",  "TEST_F"};
    return k;
}

// Every function definition `type name(params) [const] {...}` in the comment-free `code`: in
// GLSL at brace depth 0, in C++ anywhere outside another function's body.
std::vector<Function> functions(const std::string& code, bool cpp) {
    std::vector<Function> out;
    std::vector<int> depth(code.size() + 1, 0);
    for (size_t i = 0, d = 0; i < code.size(); ++i) {
        depth[i] = int(d);
        if (code[i] == '{')
            ++d;
        else if (code[i] == '}' && d > 0)
            --d;
    }
    size_t skipTo = 0;
    for (size_t open = code.find('('); open != std::string::npos; open = code.find('(', open + 1)) {
        if (open < skipTo || (!cpp && depth[open] != 0)) continue;
        size_t n = open;
        while (n > 0 && std::isspace(static_cast<unsigned char>(code[n - 1]))) --n;
        size_t nameBegin = n;
        while (nameBegin > 0 && isIdent(code[nameBegin - 1])) --nameBegin;
        if (nameBegin == n || std::isdigit(static_cast<unsigned char>(code[nameBegin]))) continue;
        const std::string name = code.substr(nameBegin, n - nameBegin);
        size_t t = nameBegin;
        while (t > 0 && (std::isspace(static_cast<unsigned char>(code[t - 1])) || code[t - 1] == '&' ||
                         code[t - 1] == '*'))
            --t;
        if (t == nameBegin) continue;  // `glm::vec4(` or `a.b(`: no type before the name
        size_t typeBegin = t;
        while (typeBegin > 0 && (isIdent(code[typeBegin - 1]) || code[typeBegin - 1] == ':')) --typeBegin;
        if (typeBegin == t) continue;
        const std::string type = code.substr(typeBegin, t - typeBegin);
        if (keywords().count(name) || keywords().count(type) || type == "else" || type == "return") continue;
        const size_t close = matching(code, open);
        if (close == std::string::npos) continue;
        const std::string params = code.substr(open + 1, close - open - 1);
        if (params.find_first_of(";{}") != std::string::npos) continue;
        size_t b = close + 1;
        for (;;) {
            while (b < code.size() && std::isspace(static_cast<unsigned char>(code[b]))) ++b;
            bool more = false;
            for (const char* q : {"const", "noexcept", "override"})
                if (code.compare(b, std::strlen(q), q) == 0 &&
                    (b + std::strlen(q) >= code.size() || !isIdent(code[b + std::strlen(q)]))) {
                    b += std::strlen(q);
                    more = true;
                }
            if (!more) break;
        }
        if (b >= code.size() || code[b] != '{') continue;
        const size_t end = matching(code, b);
        if (end == std::string::npos) continue;
        out.push_back({normalType(type), name, parseParams(params), typeBegin, end + 1,
                       code.substr(typeBegin, end + 1 - typeBegin)});
        skipTo = end + 1;
    }
    return out;
}

// A global a pasted function may need: a #define, a const, a uniform, a struct.
struct Global {
    std::string name, text;
    size_t pos = 0;
};

// For each offset of `code`: whether it lies outside every brace block but namespaces'.
std::vector<bool> namespaceScope(const std::string& code) {
    std::vector<bool> out(code.size() + 1, true);
    std::vector<bool> stack;  // per open brace: a namespace's?
    size_t statement = 0;
    static const std::regex ns(R"(\bnamespace\b|\bextern\s*"C")");
    int others = 0;
    for (size_t i = 0; i < code.size(); ++i) {
        out[i] = others == 0;
        const char c = code[i];
        if (c == '{') {
            const bool isNamespace = std::regex_search(code.substr(statement, i - statement), ns);
            stack.push_back(isNamespace);
            others += !isNamespace;
        } else if (c == '}' && !stack.empty()) {
            others -= !stack.back();
            stack.pop_back();
        }
        if (c == '{' || c == '}' || c == ';') statement = i + 1;
    }
    return out;
}

std::vector<Global> globals(const std::string& code, bool cpp) {
    std::vector<Global> out;
    const std::vector<bool> outside = cpp ? namespaceScope(code) : std::vector<bool>();
    std::istringstream in(code);
    size_t pos = 0;
    int depth = 0;
    static const std::regex define(R"(^\s*#\s*define\s+(\w+))");
    static const std::regex cppConst(
        R"(^\s*(?:static\s+|inline\s+)*(?:constexpr|const)\s+(float|double|int)\s+(\w+)\s*=\s*([^;]+);)");
    static const std::regex glslConst(R"(^\s*const\s+\w+\s+(\w+)\s*(\[[^\]]*\])?\s*=[^;]*;)");
    static const std::regex uniform(R"(^\s*uniform\s+(?:\w+\s+)*?(\w+)\s*(\[[^\]]*\])?\s*(=[^;]*)?;)");
    static const std::regex structure(R"(^\s*struct\s+(\w+)\s*\{?)");
    for (std::string line; std::getline(in, line); pos += line.size() + 1) {
        std::smatch m;
        if (std::regex_search(line, m, define)) {
            if (!cpp) out.push_back({m[1].str(), line, pos});
        } else if (cpp && outside[pos] && std::regex_search(line, m, cppConst)) {
            const std::string name = m[2].str();
            out.push_back(
                {name, "const " + normalType(m[1].str()) + " " + name + " = " + m[3].str() + ";", pos});
        } else if (!cpp && depth == 0 && std::regex_search(line, m, glslConst)) {
            out.push_back({m[1].str(), line, pos});
        } else if (!cpp && depth == 0 && std::regex_search(line, m, uniform)) {
            out.push_back({m[1].str(), line, pos});
        } else if (!cpp && depth == 0 && std::regex_search(line, m, structure)) {
            const size_t open = code.find('{', pos);
            const size_t close = open == std::string::npos ? open : matching(code, open);
            const size_t semi = close == std::string::npos ? close : code.find(';', close);
            if (semi != std::string::npos) out.push_back({m[1].str(), code.substr(pos, semi + 1 - pos), pos});
        }
        for (char c : line) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    }
    return out;
}

// ---------------------------------------------------------------------------------------
// The kit's sources

struct Source {
    std::string path;  // relative to the kit (or to the full kit, for the controls)
    std::string code;  // comments removed
    bool cpp = false;
    std::vector<Function> fns;
    std::vector<Global> globals;
    std::vector<std::string> includes;  // resolved, relative paths
};

const std::set<std::string>& stageFiles() {
    static const std::set<std::string> s = {"moments.glsl", "gaussian_blur.comp", "sat.comp",
                                            "sat_lookup.glsl", "msm.glsl"};
    return s;
}

Source makeSource(const std::string& path, const std::string& text, bool cpp, const fs::path& root) {
    Source s{path, stripComments(text), cpp, {}, {}, {}};
    s.fns = functions(s.code, cpp);
    for (auto& g : globals(s.code, cpp)) {  // not a function's locals
        bool local = false;
        for (const auto& f : s.fns) local = local || (g.pos > f.begin && g.pos < f.end);
        if (!local) s.globals.push_back(g);
    }
    if (!cpp) {
        static const std::regex include(R"re(#\s*include\s+"([^"]+)")re");
        for (std::sregex_iterator it(s.code.begin(), s.code.end(), include), end; it != end; ++it) {
            const std::string inc = (*it)[1].str();
            if (stageFiles().count(inc)) continue;  // the student's, not the kit's
            for (const fs::path& p : {fs::path("shaders") / inc, fs::path(path).parent_path() / inc})
                if (fs::is_regular_file(root / p)) {
                    s.includes.push_back(p.lexically_normal().generic_string());
                    break;
                }
        }
    }
    return s;
}

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

const std::vector<Target>& targets() {
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
        {"gaussian_blur.comp", "gaussian_blur.comp", "", {}, "classic", {"classic: gaussian"}},
        {"sat.comp", "sat.comp", "", {}, "wide_blur", {"wide_blur: sat"}},
    };
    return t;
}

const Target& target(const std::string& key) {
    for (const auto& t : targets())
        if (t.key == key) return t;
    throw std::runtime_error("no target " + key);
}

std::string zeroOf(const std::string& type) {
    if (type == "float") return "0.0";
    if (type == "int" || type == "uint") return type + "(0)";
    if (type == "bool") return "false";
    if (std::regex_match(type, std::regex(R"([iub]?vec[234]|mat[234])"))) return type + "(0)";
    return "";  // a parameter no literal fills (a struct, a sampler, an array)
}

// A call's argument that a student could copy as it is: numbers and constructors only.
bool constantArgument(const std::string& a) {
    return std::regex_match(a, std::regex(R"(\s*((vec[234]|float|int)\s*\(|[-+*/.,()\s\deEf])*)"));
}

std::vector<std::string> splitArguments(const std::string& args) {
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
std::string cppToGlsl(std::string t, const std::string& returnType) {
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
std::string withoutHeader(const std::string& text) {
    return std::regex_replace(text, std::regex("// KitAttack: [^\n]*\n"), "");
}

bool matchesTarget(const Function& f, const Target& t) {
    if (t.returnType.empty() || f.returnType != t.returnType || f.params.size() < t.params.size())
        return false;
    for (size_t i = 0; i < t.params.size(); ++i)
        if (f.params[i].type != t.params[i]) return false;
    return true;
}

// The text of `file` with function `name`'s definition replaced by `with`.
std::string replaceFunction(const std::string& file, const std::string& name, const std::string& with) {
    const std::string code = stripComments(file);
    for (const auto& f : functions(code, false))
        if (f.name == name) return file.substr(0, f.begin) + with + file.substr(f.end);
    throw std::runtime_error("no function " + name + " to replace");
}

std::string definitionOf(const std::string& file, const std::string& name) {
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

std::map<int, ImageBinding> imageBindings(const std::string& code) {
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

bool weightsBuffer(const std::string& code) {
    static const std::regex block(R"(layout\s*\(([^)]*)\)\s*(?:\w+\s+)*buffer\b)");
    for (std::sregex_iterator it(code.begin(), code.end(), block), end; it != end; ++it)
        if (std::regex_search((*it)[1].str(), std::regex(R"(binding\s*=\s*0\b)"))) return true;
    return false;
}

// A compute shader as a filter stage: its includes inlined (not the stage files), and a
// #define rgba32f for a format that is a macro of the framework's.
std::string computeStage(const fs::path& root, const std::string& path, const std::string& text) {
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

// ---------------------------------------------------------------------------------------
// Patterns

struct Hit {
    std::string pattern;
    int line;
    std::string excerpt;
};

// `cpp`: the moment powers are not looked for (the framework's C++ builds moment vectors of its
// hard cases; the formula is the stage contract's own).
std::vector<Hit> patternHits(const std::string& text, bool cpp = false) {
    std::vector<Hit> hits;
    auto excerpt = [&](size_t pos) {
        const size_t b = text.rfind('\n', pos), e = text.find('\n', pos);
        return squeeze(text.substr(
            b == std::string::npos ? 0 : b + 1,
            e == std::string::npos ? std::string::npos : e - (b == std::string::npos ? 0 : b + 1)));
    };
    // The two Cholesky pivots of the Hankel matrix: b2 - b1², then b4 - b2² (..., within 1000
    // characters), in .xyzw, [0..3] or b1..b4 spelling.
    const std::vector<std::pair<std::string, std::string>> pivots = {
        {R"(\b(\w+)\s*\.\s*y\s*-\s*\1\s*\.\s*x\s*\*\s*\1\s*\.\s*x\b)",
         R"(\b@\s*\.\s*w\s*-\s*@\s*\.\s*y\s*\*\s*@\s*\.\s*y\b)"},
        {R"(\b(\w+)\s*\[\s*1\s*\]\s*-\s*\1\s*\[\s*0\s*\]\s*\*\s*\1\s*\[\s*0\s*\])",
         R"(\b@\s*\[\s*3\s*\]\s*-\s*@\s*\[\s*1\s*\]\s*\*\s*@\s*\[\s*1\s*\])"},
        {R"(\b([A-Za-z_]*)2\s*-\s*(?:\1)1\s*\*\s*(?:\1)1\b)", R"(\b@4\s*-\s*@2\s*\*\s*@2\b)"},
    };
    for (const auto& [first, second] : pivots) {
        const std::regex firstPivot(first);
        for (std::sregex_iterator it(text.begin(), text.end(), firstPivot), end; it != end; ++it) {
            const std::string var = (*it)[1].str();
            const std::string window = text.substr(it->position(0), 1000);
            if (std::regex_search(window, std::regex(std::regex_replace(second, std::regex("@"), var)))) {
                hits.push_back({"Cholesky pivots of the moments' Hankel matrix",
                                lineOf(text, it->position(0)), excerpt(it->position(0))});
                break;
            }
        }
    }
    // Loops: over uWeights (a Gaussian's taps), or a running sum stored in the loop (a prefix sum).
    static const std::regex loop(R"(\bfor\s*\()");
    static const std::regex weights(R"(\buWeights\s*\[)");
    static const std::regex store(R"(\bimageStore\s*\()");
    static const std::regex running(R"(\b(\w+)\s*(\+=|=\s*\1\s*\+))");
    for (std::sregex_iterator it(text.begin(), text.end(), loop), end; it != end; ++it) {
        const size_t open = it->position(0) + it->length(0) - 1, close = matching(text, open);
        if (close == std::string::npos) continue;
        size_t b = close + 1;
        while (b < text.size() && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
        const size_t e = b < text.size() && text[b] == '{' ? matching(text, b) : text.find(';', b);
        if (e == std::string::npos) continue;
        const std::string header = text.substr(open, close - open), body = text.substr(b, e - b);
        if (std::regex_search(header + body, weights))
            hits.push_back({"a loop over uWeights", lineOf(text, it->position(0)), excerpt(it->position(0))});
        std::smatch m;
        if (std::regex_search(body, store) && std::regex_search(body, m, running) && m[1].str() != "i")
            hits.push_back({"a running sum stored with imageStore in its loop", lineOf(text, it->position(0)),
                            excerpt(it->position(0))});
    }
    // The moment powers (z, z², z³, z⁴) as a vector, in GLSL.
    if (cpp) return hits;
    static const std::regex powers(
        R"(vec4\s*\(\s*(\w+)\s*,\s*(\w+|\1\s*\*\s*\1)\s*,\s*(?:\2|\1)\s*\*\s*(?:\2|\1)(?:\s*\*\s*\1)?\s*,\s*(?:\2|\1)\s*\*\s*(?:\2|\1)(?:\s*\*\s*(?:\2|\1)){0,2}\s*\)|vec4\s*\(\s*(\w+)\s*,\s*pow\s*\(\s*\3\s*,\s*2)");
    for (std::sregex_iterator it(text.begin(), text.end(), powers), end; it != end; ++it)
        hits.push_back({"the moment powers", lineOf(text, it->position(0)), excerpt(it->position(0))});
    return hits;
}

bool textFile(const fs::path& p) {
    static const std::set<std::string> binary = {".exr", ".png", ".jpg", ".obj", ".gz"};
    return !binary.count(p.extension().string());
}

// Every file of the unpacked kit outside student/ and build/ (relative paths, sorted).
std::vector<std::string> shippedFiles(const fs::path& kit) {
    std::vector<std::string> out;
    for (auto it = fs::recursive_directory_iterator(kit); it != fs::recursive_directory_iterator(); ++it) {
        const std::string rel = fs::relative(it->path(), kit).generic_string();
        if (it->is_directory() && (rel == "student" || rel == "build" || rel == "out")) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) out.push_back(rel);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// ---------------------------------------------------------------------------------------
// Grading

using Files = std::map<std::string, std::string>;

struct Attempt {
    std::string name, what, target;
    bool control = false;
    Files files;
};

// Grades every attempt through the kit's `shadowlab grade --batch` on `scene`; name -> results.
std::map<std::string, nlohmann::json> gradeAll(const fs::path& kit, const fs::path& work,
                                               const std::string& scene, const std::vector<Attempt>& attempts,
                                               std::string* log) {
    const fs::path batch = work / ("batch_" + scene), out = work / ("out_" + scene);
    fs::create_directories(batch);
    for (const auto& a : attempts)
        for (const auto& [file, text] : a.files) test::writeFile(batch / a.name / file, text);
    const auto run = test::runIn(kit,
                                 "build/shadowlab grade --batch '" + batch.string() + "' -j 2 --scenes " +
                                     scene + " --no-report --out '" + out.string() + "'",
                                 900, "env -u SHADOWLAB_ROOT -u SHADOWLAB_BUILD");
    *log += run.output;
    std::map<std::string, nlohmann::json> results;
    for (const auto& a : attempts) {
        std::ifstream in(out / a.name / "results.json");
        results[a.name] = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    }
    return results;
}

double score(const nlohmann::json& r, const std::string& test) {
    if (r.is_object() && r.contains("tests"))
        for (const auto& t : r["tests"])
            if (t["name"] == test) return t["score"].get<double>();
    return -1.0;
}

std::string output(const nlohmann::json& r, const std::string& test) {
    if (r.is_object() && r.contains("tests"))
        for (const auto& t : r["tests"])
            if (t["name"] == test) return t["output"].get<std::string>();
    return "no results.json test " + test;
}

// The patterns find what they look for: in the solution's files, and not in the stubs' hints
// or in VSM's one-pivot variance.
TEST(KitAttack, PatternsRecogniseTheSolution) {
    const fs::path root = test::root();
    auto named = [&](const std::string& rel) {
        std::set<std::string> out;
        for (const auto& h : patternHits(test::readFile(root / rel))) out.insert(h.pattern);
        return out;
    };
    EXPECT_TRUE(named("reference/msm.glsl").count("Cholesky pivots of the moments' Hankel matrix"));
    EXPECT_TRUE(
        named("tests/oracles/msm_float_mirror.h").count("Cholesky pivots of the moments' Hankel matrix"));
    EXPECT_TRUE(named("reference/moments.glsl").count("the moment powers"));
    EXPECT_TRUE(named("reference/gaussian_blur.comp").count("a loop over uWeights"));
    EXPECT_TRUE(named("tests/submissions/fragile/naive_sat/sat.comp")
                    .count("a running sum stored with imageStore in its loop"));
    EXPECT_EQ(patternHits("vec4 m(float z) { return vec4(z, z * z, z * z * z, z * z * z * z); }").size(), 1u);
    EXPECT_EQ(patternHits("float D = b[1] - b[0] * b[0];\nfloat E = b[3] - b[1] * b[1] - L * L;").size(), 1u);
    for (const char* stub : {"student/moments.glsl", "student/msm.glsl", "student/gaussian_blur.comp",
                             "student/sat.comp", "student/sat_lookup.glsl"})
        EXPECT_TRUE(named(stub).empty()) << stub << ": " << testing::PrintToString(named(stub));
    EXPECT_TRUE(patternHits("float variance = max(m.y - m.x * m.x, minVariance);").empty());
}

// No file the student kit ships outside student/ holds the core of a stage, in any language.
TEST(KitAttack, NoShippedFileHoldsTheCoreOfAStage) {
    const auto unpacked = test::unpackStudentKit(test::tempDir("kit_attack_patterns"));
    ASSERT_EQ(unpacked.error, "");
    int scanned = 0;
    std::string found;
    for (const auto& rel : shippedFiles(unpacked.root)) {
        if (!textFile(rel)) continue;
        ++scanned;
        const std::string ext = fs::path(rel).extension().string();
        for (const auto& h : patternHits(test::readFile(unpacked.root / rel), ext == ".cpp" || ext == ".h"))
            found += rel + ":" + std::to_string(h.line) + ": " + h.pattern + ": " + h.excerpt + "\n";
    }
    EXPECT_GT(scanned, 100);
    EXPECT_EQ(found, "") << "files of the student kit that hold a stage's core (leave them out of "
                            "grader/student_kit.manifest, or make them use the student's stages)";
}

// Every function and filter shader the student kit ships, handed in as a stage, scores no more
// than the stub there.
TEST(KitAttack, NoShippedFunctionOrShaderScoresAsAStage) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const fs::path work = test::tempDir("kit_attack");
    const auto unpacked = test::unpackStudentKit(work);
    ASSERT_EQ(unpacked.error, "");
    const fs::path kit = unpacked.root, root = test::root();
    const auto build = test::buildKitProgram(kit);
    ASSERT_EQ(build.exitCode, 0) << build.output;

    // What a submission starts from for each target (the baseline: the stub there).
    Files stubs;
    for (const auto& f : stageFiles()) stubs[f] = test::readFile(kit / "student" / f);
    const std::string refMoments = test::readFile(root / "reference/moments.glsl");
    const fs::path naive = root / "tests/submissions/fragile/naive_sat";
    auto base = [&](const std::string& key) {
        Files f = stubs;
        if (key == "relativeDepth")
            f["moments.glsl"] = replaceFunction(f["moments.glsl"], "computeMoments",
                                                definitionOf(refMoments, "computeMoments"));
        if (key == "computeMoments")
            f["moments.glsl"] = replaceFunction(f["moments.glsl"], "relativeDepth",
                                                definitionOf(refMoments, "relativeDepth"));
        if (key == "momentShadowIntensity") f["moments.glsl"] = refMoments;
        if (key == "satBoxAverage") f["sat.comp"] = test::readFile(naive / "sat.comp");
        if (key == "sat.comp") f["sat_lookup.glsl"] = test::readFile(naive / "sat_lookup.glsl");
        return f;
    };

    // Uniforms the framework's drivers declare around the stage files: never pasted again.
    std::set<std::string> context;
    for (const auto& e : fs::directory_iterator(kit / "shaders"))
        if (e.is_regular_file())
            for (const auto& g : globals(stripComments(test::readFile(e.path())), false))
                context.insert(g.name);

    // The kit's sources: GLSL files, Markdown code blocks, C++.
    std::map<std::string, Source> sources;
    for (const auto& rel : shippedFiles(kit)) {
        const std::string ext = fs::path(rel).extension().string();
        const std::string text = test::readFile(kit / rel);
        if (ext == ".glsl" || ext == ".comp" || ext == ".frag" || ext == ".vert") {
            sources[rel] = makeSource(rel, text, false, kit);
        } else if (ext == ".cpp" || ext == ".h" || ext == ".hpp") {
            sources[rel] = makeSource(rel, text, true, kit);
        } else if (ext == ".md") {  // its fenced code blocks (not the shell's or JSON's)
            std::istringstream in(text);
            std::string lang, block;
            bool inBlock = false;
            int n = 0;
            for (std::string line; std::getline(in, line);) {
                if (line.rfind("```", 0) != 0) {
                    if (inBlock) block += line + "\n";
                    continue;
                }
                if (inBlock && lang != "sh" && lang != "json") {
                    const std::string name = rel + " (code block " + std::to_string(++n) + ")";
                    sources[name] = makeSource(name, block, lang == "cpp" || lang == "c++", kit);
                }
                inBlock = !inBlock;
                lang = squeeze(line.substr(3));
                block.clear();
            }
        }
    }
    // Calls in the kit's GLSL: name -> argument lists (their constants fill extra parameters).
    std::map<std::string, std::vector<std::vector<std::string>>> calls;
    for (const auto& [path, s] : sources) {
        if (s.cpp) continue;
        static const std::regex call(R"(\b([A-Za-z_]\w*)\s*\()");
        for (std::sregex_iterator it(s.code.begin(), s.code.end(), call), end; it != end; ++it) {
            const size_t open = it->position(0) + it->length(0) - 1, close = matching(s.code, open);
            if (close != std::string::npos)
                calls[(*it)[1].str()].push_back(splitArguments(s.code.substr(open + 1, close - open - 1)));
        }
    }
    auto scopeOf = [&](const Source& s) {
        std::vector<const Source*> scope;
        std::set<std::string> seen;
        std::function<void(const Source&)> add = [&](const Source& x) {
            if (!seen.insert(x.path).second) return;
            for (const auto& inc : x.includes)
                if (sources.count(inc)) add(sources.at(inc));
            scope.push_back(&x);
        };
        add(s);
        return scope;  // includes first, `s` last
    };

    std::vector<Attempt> attempts;
    std::set<std::string> seenTexts;
    std::vector<const Source*> library;  // the kit's GLSL files, for helpers found by name
    for (const auto& [path, s] : sources)
        if (!s.cpp && path.find(" (code block") == std::string::npos) library.push_back(&s);
    auto addFunctionAttempts = [&](const Source& s, const std::vector<const Source*>& scope, bool control) {
        for (const auto& f : s.fns)
            for (const auto& t : targets()) {
                if (!matchesTarget(f, t)) continue;
                for (const auto& p :
                     pastes(f, s, scope, s.cpp || control ? std::vector<const Source*>{} : library, t,
                            context, calls[f.name])) {
                    Files files = base(t.key);
                    files[t.file] = replaceFunction(files[t.file], t.key, p.text);
                    if (!seenTexts.insert(t.key + "\n" + squeeze(withoutHeader(files[t.file]))).second)
                        continue;
                    attempts.push_back({"", p.what, t.key, control, files});
                }
            }
    };
    auto addComputeAttempt = [&](const std::string& path, const std::string& text, bool control) {
        const std::string code = stripComments(text);
        const auto images = imageBindings(code);
        if (!images.count(0) || !images.count(1) || !images.at(0).read || !images.at(1).write) return;
        const std::string key = weightsBuffer(code) ? "gaussian_blur.comp" : "sat.comp";
        Files files = base(key);
        files[key] =
            "// KitAttack: " + path + " as " + key + "\n" + computeStage(control ? root : kit, path, text);
        if (!seenTexts.insert(key + "\n" + squeeze(withoutHeader(files[key]))).second) return;
        attempts.push_back({"", path + " as " + key, key, control, files});
    };
    // Controls: the solution's own stage functions and filters, through the same extraction.
    std::vector<Source> controlSources;
    for (const char* rel : {"reference/moments.glsl", "reference/msm.glsl",
                            "tests/submissions/fragile/naive_sat/sat_lookup.glsl"})
        controlSources.push_back(makeSource(rel, test::readFile(root / rel), false, root));
    controlSources.push_back(makeSource("tests/oracles/msm_float_mirror.h",
                                        test::readFile(root / "tests/oracles/msm_float_mirror.h"), true,
                                        root));
    for (const auto& s : controlSources) addFunctionAttempts(s, {&s}, true);
    for (const char* rel : {"reference/gaussian_blur.comp", "tests/submissions/fragile/naive_sat/sat.comp"})
        addComputeAttempt(rel, test::readFile(root / rel), true);
    const size_t controls = attempts.size();
    // The attack.
    int scannedGlsl = 0, scannedCpp = 0;
    for (const auto& [path, s] : sources) {
        (s.cpp ? scannedCpp : scannedGlsl)++;
        addFunctionAttempts(s, scopeOf(s), false);
        if (fs::path(path).extension() == ".comp") addComputeAttempt(path, test::readFile(kit / path), false);
    }
    // Baselines: the stub, with the same counterparts.
    for (const auto& t : targets()) attempts.push_back({"", "the stub", t.key, false, base(t.key)});
    for (size_t i = 0; i < attempts.size(); ++i)
        attempts[i].name = (i < controls                     ? "control"
                            : attempts[i].what == "the stub" ? "stub"
                                                             : "attack") +
                           std::to_string(i) + "_" +
                           std::regex_replace(attempts[i].target, std::regex("\\."), "_");

    std::map<std::string, std::vector<Attempt>> byScene;
    for (const auto& a : attempts) byScene[target(a.target).scene].push_back(a);
    std::string log;
    std::map<std::string, nlohmann::json> results;
    for (const auto& [scene, list] : byScene) results.merge(gradeAll(kit, work, scene, list, &log));

    std::map<std::string, const Attempt*> stubOf;
    for (const auto& a : attempts)
        if (a.what == "the stub") stubOf[a.target] = &a;
    std::ostringstream table;
    int attacked = 0;
    for (const auto& a : attempts) {
        if (a.what == "the stub") continue;
        attacked += !a.control;
        const Target& t = target(a.target);
        const auto& r = results[a.name];
        const auto& s = results[stubOf.at(a.target)->name];
        std::string scores;
        bool above = false;
        for (const auto& test : t.tests) {
            const double got = score(r, test), stub = score(s, test);
            ASSERT_GE(stub, 0.0) << "the stub has no test " << test << "\n" << log;
            scores += " " + test + " " + std::to_string(got) + " (stub " + std::to_string(stub) + ")";
            above = above || got > stub;
        }
        const std::string first = output(r, t.tests[0]);
        const bool failed = first.find("compile or link error") != std::string::npos;
        table << (a.control ? "control  " : "attack   ") << a.what << ":" << scores
              << (failed ? "  [does not compile]" : "") << "\n";
        if (a.control)
            EXPECT_TRUE(above) << "control " << a.what << " should score above the stub:" << scores << "\n"
                               << first << "\n"
                               << a.files.at(t.file);
        else
            EXPECT_FALSE(above) << "the student kit leaks " << t.key << ": " << a.what
                                << " scores above the stub:" << scores << "\n"
                                << a.files.at(t.file);
    }
    std::cout << "KitAttack: " << scannedGlsl << " GLSL sources, " << scannedCpp << " C++ files; " << attacked
              << " attacks, " << controls << " controls, graded in "
              << std::chrono::duration<double>(Clock::now() - t0).count() << " s (pack and build included)\n"
              << table.str();
    EXPECT_GE(controls, 6u);
}

}  // namespace sl::kit_attack
