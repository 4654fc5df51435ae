// scene_json: the vocabulary scene_loader.cpp validates JSON with. A Node is a value and its
// JSON pointer (or a missing key's would-be pointer); a Reader turns a wrong or missing value
// into the one-line SceneError "<file>: <pointer>: expected <what>, found <value or nothing>".
// Private to scene_loader.cpp; a header only to keep that file about the format itself.
#pragma once

#include "scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace sl::scene_json {

using json = nlohmann::json;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline std::string formatNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The value as it appears in the file, shortened so that a whole object stays one line.
inline std::string dumpShort(const json& v) {
    std::string s = v.dump();
    return s.size() > 72 ? s.substr(0, 69) + "..." : s;
}

inline std::string quotedList(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ", \"" : "\"") + items[i] + "\"";
    return out;
}

// An allowed interval of numbers; describes itself for the "expected ..." part of a message.
struct Range {
    double lo = -kInf, hi = kInf;
    bool loOpen = false, hiOpen = false;

    static Range any() { return {}; }
    static Range positive() { return {0.0, kInf, true, false}; }
    static Range atLeast(double lo) { return {lo, kInf, false, false}; }
    static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
    static Range open(double lo, double hi) { return {lo, hi, true, true}; }

    bool contains(double v) const {
        return std::isfinite(v) && (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    std::string describe(bool integer) const {
        std::string kind = integer ? "an integer" : "a number";
        if (lo == -kInf && hi == kInf) return kind;
        if (hi == kInf) return kind + (loOpen ? " > " : " >= ") + formatNumber(lo);
        if (lo == -kInf) return kind + (hiOpen ? " < " : " <= ") + formatNumber(hi);
        return kind + " in " + (loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) +
               (hiOpen ? ")" : "]");
    }
};

// A value in the document and its JSON pointer; `v` is null when the key is absent, so that
// "missing" and "wrong" go through the same checks ("found nothing").
struct Node {
    const json* v = nullptr;
    std::string ptr;

    explicit operator bool() const { return v != nullptr; }
    Node operator[](const std::string& key) const {
        std::string escaped;  // RFC 6901: '~' -> "~0", '/' -> "~1"
        for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
        const json* child = nullptr;
        if (v && v->is_object()) {
            auto it = v->find(key);
            if (it != v->end()) child = &*it;
        }
        return {child, ptr + "/" + escaped};
    }
    Node operator[](size_t i) const {
        return {v && v->is_array() && i < v->size() ? &(*v)[i] : nullptr,
                ptr + "/" + std::to_string(i)};
    }
};

class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const Node& n, const std::string& expected) const {
        fail(n.ptr, expected, n ? dumpShort(*n.v) : "nothing");
    }
    [[noreturn]] void fail(const std::string& ptr, const std::string& expected,
                           const std::string& found) const {
        throw SceneError(file_ + ": " + (ptr.empty() ? "/" : ptr) + ": expected " + expected +
                         ", found " + found);
    }

    // An object whose keys are all in `allowed`; `what` names it ("a light", "a sphere").
    void object(const Node& n, const std::vector<std::string>& allowed,
                const std::string& what) const {
        if (!n || !n.v->is_object()) fail(n, "an object (" + what + ")");
        for (const auto& item : n.v->items())
            if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
                fail(n[item.key()].ptr, "one of the keys " + quotedList(allowed) + " for " + what,
                     "unknown key \"" + item.key() + "\"");
    }
    size_t array(const Node& n, size_t minSize, const std::string& what) const {
        if (!n || !n.v->is_array() || n.v->size() < minSize) fail(n, what);
        return n.v->size();
    }
    // Every number of a scene becomes a float: the range is checked on the float too, so that
    // 1e308 (inf as a float) or 1e-300 (0 as a float, where > 0 is required) is an error.
    double number(const Node& n, const Range& r) const {
        if (!n || !n.v->is_number() || !r.contains(n.v->get<double>())) fail(n, r.describe(false));
        const double d = n.v->get<double>();
        if (!r.contains(double(float(d))))
            fail(n, r.describe(false) + " that a 32-bit float holds (|x| <= 3.4e38, and not so "
                                        "close to 0 that it rounds to " +
                                        formatNumber(double(float(d))) + ")");
        return d;
    }
    int integer(const Node& n, const Range& r) const {
        if (!n || !n.v->is_number_integer() || !r.contains(n.v->get<double>()))
            fail(n, r.describe(true));
        return n.v->get<int>();
    }
    glm::vec3 vec3(const Node& n, const Range& r) const {
        std::string what = "an array of 3 numbers";
        if (r.lo != -kInf || r.hi != kInf) what += " (each " + r.describe(false) + ")";
        if (!n || !n.v->is_array() || n.v->size() != 3) fail(n, what);
        return {float(number(n[0], r)), float(number(n[1], r)), float(number(n[2], r))};
    }
    std::string string(const Node& n, bool nonEmpty = false) const {
        if (!n || !n.v->is_string() || (nonEmpty && n.v->get<std::string>().empty()))
            fail(n, nonEmpty ? "a non-empty string" : "a string");
        return n.v->get<std::string>();
    }
    bool boolean(const Node& n) const {
        if (!n || !n.v->is_boolean()) fail(n, "true or false");
        return n.v->get<bool>();
    }
    // One of a fixed set of strings; returns its index.
    int choice(const Node& n, const std::vector<std::string>& options) const {
        if (n && n.v->is_string()) {
            auto it = std::find(options.begin(), options.end(), n.v->get<std::string>());
            if (it != options.end()) return int(it - options.begin());
        }
        fail(n, "one of " + quotedList(options));
    }

    const std::string& file() const { return file_; }

private:
    std::string file_;
};

}  // namespace sl::scene_json
