// kit_attack_sources.h: reading the student kit's sources as the attack test does
// (test_kit_attack.cpp): comments stripped, function definitions of GLSL and C++ with their
// parameters, the globals a pasted function may need, one source per shipped file.
#pragma once

#include "kit_test_support.h"

#include <cctype>
#include <cstring>
#include <functional>
#include <map>
#include <set>

namespace sl::kit_attack {

// ---------------------------------------------------------------------------------------
// Source text

// `code` with its comments turned into spaces (newlines kept, so offsets stay valid); string
// and character literals are kept.
inline std::string stripComments(const std::string& code) {
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
inline size_t matching(const std::string& s, size_t open) {
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

inline std::string squeeze(const std::string& s) {
    static const std::regex space(R"(\s+)"), ends(R"(^ | $)");
    return std::regex_replace(std::regex_replace(s, space, " "), ends, "");
}

inline bool hasWord(const std::string& text, const std::string& word) {
    return std::regex_search(text, std::regex("\\b" + word + "\\b"));
}

bool isIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

inline int lineOf(const std::string& text, size_t pos) {
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
inline std::string normalType(std::string t) {
    static const std::regex prefix(R"(\b(glm|std)::)"), dvec(R"(d(vec|mat)[234])");
    static const std::regex qualifier(
        R"(\b(const|in|out|inout|highp|mediump|lowp|precise|static|inline|constexpr)\b|[&*])");
    t = squeeze(std::regex_replace(std::regex_replace(t, prefix, ""), qualifier, " "));
    if (t == "double") return "float";
    if (std::regex_match(t, dvec)) return t.substr(1);
    return t;
}

inline std::vector<Param> parseParams(const std::string& list) {
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

inline const std::set<std::string>& keywords() {
    static const std::set<std::string> k = {
        "if",    "for",      "while",    "switch",  "return",   "else",  "do",        "case",
        "new",   "delete",   "catch",    "sizeof",  "throw",    "using", "namespace", "struct",
        "class", "operator", "decltype", "typedef", "template", "TEST",  "TEST_F"};
    return k;
}

// Every function definition `type name(params) [const] {...}` in the comment-free `code`: in
// GLSL at brace depth 0, in C++ anywhere outside another function's body.
inline std::vector<Function> functions(const std::string& code, bool cpp) {
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
inline std::vector<bool> namespaceScope(const std::string& code) {
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

inline std::vector<Global> globals(const std::string& code, bool cpp) {
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

inline const std::set<std::string>& stageFiles() {
    static const std::set<std::string> s = {"moments.glsl", "gaussian_blur.comp", "sat.comp",
                                            "sat_lookup.glsl", "msm.glsl"};
    return s;
}

inline Source makeSource(const std::string& path, const std::string& text, bool cpp, const fs::path& root) {
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

}  // namespace sl::kit_attack
