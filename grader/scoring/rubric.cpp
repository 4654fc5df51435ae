// rubric: reads and validates grader/rubric.json. The defaults are the same file as built into
// the program (rubric_defaults.cpp.in), so a kit without the file still grades the same way. Every key is
// checked: a typo ("gausian") must not silently fall back to a default weight, and a value
// Gradescope does not know ("after_due") must not reach results.json.
#include "rubric.h"

#include "stages.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <set>
#include <stdexcept>

namespace sl::grader {

extern const char* const kBuiltInRubricJson;  // rubric_defaults.cpp.in

namespace {

using json = nlohmann::json;

// "<file>: /path: expected ..., got ..." (the scene loader's format).
struct Checker {
    std::string file;

    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw std::runtime_error(file + ": " + (path.empty() ? "/" : path) + ": " + what);
    }
    static std::string shown(const json& v) {
        std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
        return s.size() > 60 ? s.substr(0, 57) + "..." : s;
    }
    void keys(const json& obj, const std::string& path, const std::set<std::string>& allowed) const {
        if (!obj.is_object()) fail(path, "expected an object, got " + shown(obj));
        for (const auto& [key, value] : obj.items()) {
            if (key.rfind('_', 0) == 0) continue;  // "_comment" and the like
            if (!allowed.count(key)) {
                std::string known;
                for (const auto& k : allowed) known += (known.empty() ? "" : ", ") + k;
                fail(path + "/" + key, "unknown key (known: " + known + ")");
            }
        }
    }
    // A number in [lo, hi] (strict bounds where `open`).
    double number(const json& obj, const std::string& path, const std::string& key, double dflt,
                  double lo, double hi, bool openLo = false) const {
        if (!obj.contains(key)) return dflt;
        const json& v = obj[key];
        const std::string p = path + "/" + key;
        if (!v.is_number()) fail(p, "expected a number, got " + shown(v));
        const double x = v.get<double>();
        const bool ok = std::isfinite(x) && (openLo ? x > lo : x >= lo) && x <= hi;
        if (!ok) {
            char range[96];
            std::snprintf(range, sizeof range, "expected a number in %s%g, %g], got ",
                          openLo ? "(" : "[", lo, hi);
            fail(p, range + shown(v));
        }
        return x;
    }
    std::string oneOf(const json& obj, const std::string& path, const std::string& key,
                      const std::string& dflt, const std::vector<std::string>& allowed) const {
        if (!obj.contains(key)) return dflt;
        const json& v = obj[key];
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
        if (!v.is_string() || std::find(allowed.begin(), allowed.end(), v.get<std::string>()) == allowed.end())
            fail(path + "/" + key, "expected one of " + list + ", got " + shown(v));
        return v.get<std::string>();
    }
};

}  // namespace

std::pair<double, double> Rubric::ramp(const std::string& stage) const {
    auto it = stageRamp.find(stage);
    return it != stageRamp.end() ? it->second : std::pair{passFraction, zeroFraction};
}

double Rubric::points(const std::string& stage, double fraction, double max) const {
    const auto [pass, zero] = ramp(stage);
    if (fraction >= pass) return max;
    if (fraction <= zero) return 0.0;
    return max * (fraction - zero) / (pass - zero);
}

std::vector<long> splitHundredths(long hundredths, int n) {
    std::vector<long> parts(size_t(std::max(n, 0)), 0);
    if (n <= 0) return parts;
    for (int i = 0; i < n; ++i) parts[size_t(i)] = hundredths / n + (i < hundredths % n ? 1 : 0);
    return parts;
}

std::map<std::string, long> Rubric::stageHundredths(const std::vector<std::string>& stages) const {
    std::map<std::string, long> out;
    double weightSum = 0.0;
    for (const auto& s : stages) weightSum += weights.count(s) ? weights.at(s) : 0.0;
    const long totalHundredths = std::lround(total * 100.0);
    if (weightSum <= 0.0) {
        for (const auto& s : stages) out[s] = 0;
        return out;
    }
    // Largest remainder: floor every share, then hand out what is left.
    std::vector<std::pair<double, size_t>> remainders;
    long given = 0;
    for (size_t i = 0; i < stages.size(); ++i) {
        const double w = weights.count(stages[i]) ? weights.at(stages[i]) : 0.0;
        const double exact = double(totalHundredths) * w / weightSum;
        const long floor = long(std::floor(exact + 1e-9));
        out[stages[i]] = floor;
        given += floor;
        remainders.push_back({exact - double(floor), i});
    }
    std::stable_sort(remainders.begin(), remainders.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first + 1e-12; });
    for (size_t k = 0; given < totalHundredths && k < remainders.size(); ++k, ++given)
        ++out[stages[remainders[k].second]];
    return out;
}

namespace {

// Sets every key `j` holds, checked; `r` keeps its values for the keys it lacks.
void applyRubric(Rubric& r, const json& j, const std::string& file) {
    const Checker c{file};
    c.keys(j, "", {"total", "filters", "stages", "pass_fraction", "zero_fraction", "tolerances",
                   "visibility", "hidden_scene_visibility"});
    r.total = c.number(j, "", "total", r.total, 0.0, 1e6, true);
    r.filters = c.oneOf(j, "", "filters", r.filters, {"both", "either"});
    r.passFraction = c.number(j, "", "pass_fraction", r.passFraction, 0.0, 1.0);
    r.zeroFraction = c.number(j, "", "zero_fraction", r.zeroFraction, 0.0, 1.0);
    if (!(r.zeroFraction < r.passFraction))
        c.fail("/zero_fraction", "must be below pass_fraction (" + std::to_string(r.passFraction) + ")");
    if (j.contains("stages")) {
        const std::vector<std::string>& names = stageNames();
        c.keys(j["stages"], "/stages", std::set<std::string>(names.begin(), names.end()));
        for (const auto& [stage, v] : j["stages"].items()) {
            if (stage.rfind('_', 0) == 0) continue;
            const std::string p = "/stages/" + stage;
            c.keys(v, p, {"weight", "pass_fraction", "zero_fraction", "worst_texel_cap"});
            if (v.contains("worst_texel_cap")) {
                const CompareBy by = stageRow(stage).compareBy;
                if (by != CompareBy::Moments && by != CompareBy::Filtered)
                    c.fail(p + "/worst_texel_cap", "only the moment-map stages (moments, gaussian, sat) have one");
                r.worstTexelCap[stage] = c.number(v, p, "worst_texel_cap", 1.0, 0.0, 1.0);
            }
            r.weights[stage] = c.number(v, p, "weight", r.weights[stage], 0.0, 1e6);
            // A stage without a ramp of its own follows the global one, whichever file sets it.
            if (!v.contains("pass_fraction") && !v.contains("zero_fraction")) continue;
            const auto [pass0, zero0] = r.ramp(stage);
            const double pass = c.number(v, p, "pass_fraction", pass0, 0.0, 1.0);
            const double zero = c.number(v, p, "zero_fraction", zero0, 0.0, 1.0);
            if (!(zero < pass)) c.fail(p + "/zero_fraction", "must be below pass_fraction (" + std::to_string(pass) + ")");
            r.stageRamp[stage] = {pass, zero};
        }
    }
    if (j.contains("tolerances")) {
        const json& t = j["tolerances"];
        c.keys(t, "/tolerances", {"moments_abs", "moments_rel", "filter_abs", "filter_rel",
                                  "sat_rounding", "sat_kernel_abs", "sat_kernel_rel", "shadow", "final",
                                  "worst_texel_factor"});
        r.worstTexelFactor = c.number(t, "/tolerances", "worst_texel_factor", r.worstTexelFactor, 1.0, 1e12);
        r.momentsAbs = c.number(t, "/tolerances", "moments_abs", r.momentsAbs, 0.0, 1.0, true);
        r.momentsRel = c.number(t, "/tolerances", "moments_rel", r.momentsRel, 0.0, 1.0);
        r.filterAbs = c.number(t, "/tolerances", "filter_abs", r.filterAbs, 0.0, 1.0, true);
        r.filterRel = c.number(t, "/tolerances", "filter_rel", r.filterRel, 0.0, 1.0);
        r.satRounding = c.number(t, "/tolerances", "sat_rounding", r.satRounding, 0.0, 1e6);
        r.satKernelAbs = c.number(t, "/tolerances", "sat_kernel_abs", r.satKernelAbs, 0.0, 1e3, true);
        r.satKernelRel = c.number(t, "/tolerances", "sat_kernel_rel", r.satKernelRel, 0.0, 1.0);
        r.shadowTol = c.number(t, "/tolerances", "shadow", r.shadowTol, 0.0, 1.0, true);
        r.finalTol = c.number(t, "/tolerances", "final", r.finalTol, 0.0, 1.0, true);
    }
    // Gradescope's visibility values (anything else is rejected by Gradescope or ignored).
    const std::vector<std::string> visibility = {"visible", "hidden", "after_due_date", "after_published"};
    r.visibility = c.oneOf(j, "", "visibility", r.visibility, visibility);
    r.hiddenVisibility = c.oneOf(j, "", "hidden_scene_visibility", r.hiddenVisibility, visibility);
    double weightSum = 0.0;
    for (const auto& [stage, w] : r.weights) weightSum += w;
    if (weightSum <= 0.0) c.fail("/stages", "expected at least one stage with a positive weight");
}

}  // namespace

Rubric defaultRubric() {
    static const Rubric built = [] {
        Rubric r;
        applyRubric(r, json::parse(kBuiltInRubricJson), "grader/rubric.json (built in)");
        return r;
    }();
    return built;
}

Rubric loadRubric(const std::filesystem::path& path) {
    Rubric r = defaultRubric();
    std::ifstream in(path);
    if (!in) return r;
    json j;
    try {
        j = json::parse(in);
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": invalid JSON: " + e.what());
    }
    applyRubric(r, j, path.string());
    return r;
}

}  // namespace sl::grader
