// glsl_scan: directive lines, #if evaluation and driver log lines, without std::regex (see
// glsl_scan.h for why).
#include "glsl_scan.h"

#include <cctype>
#include <cstdint>

namespace sl::glsl {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r'; }
bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

// `s` with // and /* */ comments replaced by a space (a comment left open runs to the end).
std::string stripComments(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '/') break;
        if (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            const size_t end = s.find("*/", i + 2);
            if (end == std::string_view::npos) break;
            out += ' ';
            i = end + 1;
            continue;
        }
        out += s[i];
    }
    return out;
}

// --- #if expressions -------------------------------------------------------------------------

struct Unknown {};  // thrown inside the evaluator: the answer is "maybe"

struct Token {
    enum Kind { Num, Id, Op, End } kind = End;
    long long value = 0;
    std::string text;
};

constexpr size_t kMaxTokens = 4096;
constexpr int kMaxDepth = 64;
constexpr int kMaxExpansions = 16;

std::vector<Token> tokenize(std::string_view s) {
    std::vector<Token> out;
    size_t i = 0;
    while (i < s.size()) {
        if (out.size() > kMaxTokens) throw Unknown{};
        const char c = s[i];
        if (blank(c)) { ++i; continue; }
        Token t;
        if (digit(c)) {
            size_t j = i;
            while (j < s.size() && identChar(s[j])) ++j;
            std::string lit(s.substr(i, j - i));
            while (!lit.empty() && (lit.back() == 'u' || lit.back() == 'U')) lit.pop_back();
            int base = 10;
            size_t k = 0;
            if (lit.size() > 1 && lit[0] == '0' && (lit[1] == 'x' || lit[1] == 'X')) base = 16, k = 2;
            else if (lit.size() > 1 && lit[0] == '0') base = 8, k = 1;
            if (k >= lit.size() && base == 16) throw Unknown{};
            unsigned long long v = 0;
            for (; k < lit.size(); ++k) {
                const char d = lit[k];
                int x = digit(d) ? d - '0'
                        : (d >= 'a' && d <= 'f') ? d - 'a' + 10
                        : (d >= 'A' && d <= 'F') ? d - 'A' + 10 : 99;
                if (x >= base) throw Unknown{};
                v = v * unsigned(base) + unsigned(x);
                if (v > (1ull << 62)) throw Unknown{};
            }
            t.kind = Token::Num;
            t.value = static_cast<long long>(v);
            i = j;
        } else if (identStart(c)) {
            size_t j = i;
            while (j < s.size() && identChar(s[j])) ++j;
            t.kind = Token::Id;
            t.text = std::string(s.substr(i, j - i));
            i = j;
        } else {
            static const char* two[] = {"||", "&&", "==", "!=", "<=", ">=", "<<", ">>"};
            t.kind = Token::Op;
            for (const char* op : two)
                if (s.substr(i, 2) == op) t.text = op;
            if (t.text.empty()) {
                if (std::string_view("()!~+-*/%<>&|^?:").find(c) == std::string_view::npos)
                    throw Unknown{};
                t.text = std::string(1, c);
            }
            i += t.text.size();
        }
        out.push_back(std::move(t));
    }
    return out;
}

class Evaluator {
public:
    Evaluator(std::vector<Token> tokens) : t_(std::move(tokens)) { t_.push_back({}); }
    long long run() {
        long long v = ternary(0);
        if (t_[pos_].kind != Token::End) throw Unknown{};
        return v;
    }

private:
    bool op(const char* s) {
        if (t_[pos_].kind == Token::Op && t_[pos_].text == s) return ++pos_, true;
        return false;
    }
    void need(const char* s) {
        if (!op(s)) throw Unknown{};
    }
    long long ternary(int depth) {
        if (depth > kMaxDepth) throw Unknown{};
        long long c = binary(0, depth);
        if (!op("?")) return c;
        long long a = ternary(depth + 1);
        need(":");
        long long b = ternary(depth + 1);
        return c ? a : b;
    }
    // Levels from loosest to tightest, as in C.
    long long binary(int level, int depth) {
        static const std::vector<std::vector<std::string>> levels = {
            {"||"}, {"&&"}, {"|"}, {"^"}, {"&"}, {"==", "!="}, {"<", ">", "<=", ">="},
            {"<<", ">>"}, {"+", "-"}, {"*", "/", "%"}};
        if (level == int(levels.size())) return unary(depth);
        long long left = binary(level + 1, depth);
        for (;;) {
            std::string found;
            for (const auto& o : levels[size_t(level)])
                if (t_[pos_].kind == Token::Op && t_[pos_].text == o) found = o;
            if (found.empty()) return left;
            ++pos_;
            const long long r = binary(level + 1, depth);
            if (found == "||") left = left || r;
            else if (found == "&&") left = left && r;
            else if (found == "|") left |= r;
            else if (found == "^") left ^= r;
            else if (found == "&") left &= r;
            else if (found == "==") left = left == r;
            else if (found == "!=") left = left != r;
            else if (found == "<") left = left < r;
            else if (found == ">") left = left > r;
            else if (found == "<=") left = left <= r;
            else if (found == ">=") left = left >= r;
            else if (found == "<<" || found == ">>") {
                if (r < 0 || r > 62) throw Unknown{};
                left = found == "<<" ? (left << r) : (left >> r);
            }
            else if (found == "+") left += r;
            else if (found == "-") left -= r;
            else if (found == "*") left *= r;
            else {
                if (r == 0) throw Unknown{};
                left = found == "/" ? left / r : left % r;
            }
            if (left > (1ll << 62) || left < -(1ll << 62)) throw Unknown{};
        }
    }
    long long unary(int depth) {
        if (depth > kMaxDepth) throw Unknown{};
        if (op("!")) return !unary(depth + 1);
        if (op("~")) return ~unary(depth + 1);
        if (op("-")) return -unary(depth + 1);
        if (op("+")) return unary(depth + 1);
        if (op("(")) {
            long long v = ternary(depth + 1);
            need(")");
            return v;
        }
        const Token& t = t_[pos_];
        if (t.kind == Token::Num) return ++pos_, t.value;
        throw Unknown{};  // an identifier left after expansion: not a constant we know
    }

    std::vector<Token> t_;
    size_t pos_ = 0;
};

}  // namespace

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

std::optional<Directive> LineScanner::scan(std::string_view line) {
    // Is this line a directive? Only if it starts (outside a comment) with '#'.
    size_t i = 0;
    bool directive = false;
    if (!inBlock_) {
        while (i < line.size() && blank(line[i])) ++i;
        directive = i < line.size() && line[i] == '#';
    }
    // The comment state after this line.
    for (size_t k = 0; k < line.size(); ++k) {
        if (inBlock_) {
            if (line[k] == '*' && k + 1 < line.size() && line[k + 1] == '/') inBlock_ = false, ++k;
        } else if (line[k] == '/' && k + 1 < line.size()) {
            if (line[k + 1] == '/') break;
            if (line[k + 1] == '*') inBlock_ = true, ++k;
        }
    }
    if (!directive) return std::nullopt;
    ++i;
    while (i < line.size() && blank(line[i])) ++i;
    size_t j = i;
    while (j < line.size() && identChar(line[j])) ++j;
    Directive d;
    d.name = std::string(line.substr(i, j - i));
    d.argument = std::string(trim(stripComments(line.substr(j))));
    return d;
}

std::optional<std::string> includeName(std::string_view argument) {
    argument = trim(argument);
    if (argument.size() < 2 || argument.front() != '"') return std::nullopt;
    const size_t close = argument.find('"', 1);
    if (close == std::string_view::npos || !trim(argument.substr(close + 1)).empty())
        return std::nullopt;
    return std::string(argument.substr(1, close - 1));
}

Conditionals::Conditionals(const std::vector<std::string>& defines) {
    macros_["GL_core_profile"] = "1";
    macros_["__VERSION__"] = "450";
    for (const auto& d : defines) {
        const size_t eq = d.find('=');
        if (eq == std::string::npos) macros_[d] = "";
        else macros_[d.substr(0, eq)] = d.substr(eq + 1);
    }
}

Conditionals::State Conditionals::active() const {
    return frames_.empty() ? Yes : frames_.back().current;
}

void Conditionals::open(State condition) {
    const State parent = active();
    State cur = parent == No || condition == No ? No
                : parent == Maybe || condition == Maybe ? Maybe : Yes;
    Frame f{parent, cur};
    f.taken = condition == Yes;
    f.maybeTaken = condition == Maybe;
    frames_.push_back(f);
}

void Conditionals::branch(State condition) {
    if (frames_.empty()) return;  // unbalanced: the driver reports it
    Frame& f = frames_.back();
    if (f.taken) {
        f.current = No;
        return;
    }
    if (f.maybeTaken && condition != No) condition = Maybe;
    f.current = f.parent == No || condition == No ? No
                : f.parent == Maybe || condition == Maybe ? Maybe : Yes;
    f.taken = condition == Yes;
    f.maybeTaken = f.maybeTaken || condition == Maybe;
}

Conditionals::State Conditionals::evaluate(const std::string& expression) const {
    try {
        std::vector<Token> tokens = tokenize(expression);
        // `defined X` / `defined(X)` first, then object-like macros, a bounded number of times.
        for (int round = 0;; ++round) {
            bool changed = false;
            std::vector<Token> next;
            for (size_t i = 0; i < tokens.size(); ++i) {
                const Token& t = tokens[i];
                if (t.kind == Token::Id && t.text == "defined") {
                    size_t k = i + 1;
                    const bool paren = k < tokens.size() && tokens[k].kind == Token::Op &&
                                       tokens[k].text == "(";
                    if (paren) ++k;
                    if (k >= tokens.size() || tokens[k].kind != Token::Id) throw Unknown{};
                    if (uncertain_.count(tokens[k].text)) throw Unknown{};
                    Token n;
                    n.kind = Token::Num;
                    n.value = macros_.count(tokens[k].text) ? 1 : 0;
                    next.push_back(n);
                    if (paren) {
                        ++k;
                        if (k >= tokens.size() || tokens[k].text != ")") throw Unknown{};
                    }
                    i = k;
                    changed = true;
                } else if (t.kind == Token::Id) {
                    if (uncertain_.count(t.text)) throw Unknown{};
                    auto it = macros_.find(t.text);
                    if (it == macros_.end()) {  // an undefined name is 0 in #if
                        Token n;
                        n.kind = Token::Num;
                        next.push_back(n);
                    } else {
                        if (!it->second.empty() && it->second[0] == '(' &&
                            it->second.find(')') == std::string::npos)
                            throw Unknown{};
                        auto body = tokenize(it->second);
                        next.push_back({Token::Op, 0, "("});
                        next.insert(next.end(), body.begin(), body.end());
                        next.push_back({Token::Op, 0, ")"});
                    }
                    changed = true;
                } else {
                    next.push_back(t);
                }
                if (next.size() > kMaxTokens) throw Unknown{};
            }
            tokens = std::move(next);
            if (!changed) break;
            if (round >= kMaxExpansions) throw Unknown{};
        }
        return Evaluator(std::move(tokens)).run() ? Yes : No;
    } catch (const Unknown&) {
        return Maybe;
    }
}

bool Conditionals::apply(const Directive& d) {
    const std::string& n = d.name;
    if (n == "ifdef" || n == "ifndef") {
        std::string_view name = trim(d.argument);
        State c = uncertain_.count(std::string(name)) ? Maybe
                  : macros_.count(std::string(name)) ? Yes : No;
        if (n == "ifndef" && c != Maybe) c = c == Yes ? No : Yes;
        open(c);
    } else if (n == "if") {
        open(active() == No ? No : evaluate(d.argument));
    } else if (n == "elif") {
        branch(frames_.empty() || frames_.back().parent == No ? No : evaluate(d.argument));
    } else if (n == "else") {
        branch(Yes);
    } else if (n == "endif") {
        if (!frames_.empty()) frames_.pop_back();
    } else if (n == "define" || n == "undef") {
        const State a = active();
        if (a == No) return true;
        const std::string& arg = d.argument;
        size_t j = 0;
        while (j < arg.size() && identChar(arg[j])) ++j;
        const std::string name = arg.substr(0, j);
        if (name.empty()) return true;
        if (a == Maybe) {
            uncertain_.insert(name);
        } else if (n == "undef") {
            macros_.erase(name);
            uncertain_.erase(name);
        } else {
            // A function-like macro keeps its "(": evaluate() treats its uses as unknown.
            macros_[name] = j < arg.size() && arg[j] == '(' ? "(" : std::string(trim(arg.substr(j)));
            uncertain_.erase(name);
        }
    } else {
        return false;
    }
    return true;
}

std::optional<LogLine> parseLogLine(std::string_view s) {
    LogLine r;
    auto number = [&](size_t& i, long& out) {
        const size_t start = i;
        out = 0;
        while (i < s.size() && digit(s[i]) && i - start < 9) out = out * 10 + (s[i++] - '0');
        return i > start && !(i < s.size() && digit(s[i]));
    };
    size_t i = 0;
    bool mesa = true;
    for (const char* prefix : {"ERROR: ", "WARNING: "})
        if (s.substr(0, std::string_view(prefix).size()) == prefix) {
            i = std::string_view(prefix).size();
            mesa = false;
        }
    if (!number(i, r.source) || i >= s.size() || s[i] != ':') return std::nullopt;
    ++i;
    if (!number(i, r.line)) return std::nullopt;
    if (mesa) {  // "(col): "
        if (i >= s.size() || s[i] != '(') return std::nullopt;
        ++i;
        if (!number(i, r.column) || i + 2 >= s.size() + 0 || s.substr(i, 3) != "): ")
            return std::nullopt;
        i += 3;
    } else {
        if (s.substr(i, 2) != ": ") return std::nullopt;
        i += 2;
    }
    r.message = std::string(s.substr(i));
    return r;
}

}  // namespace sl::glsl
