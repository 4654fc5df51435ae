// The rubric is validated like a scene (a typo in the rubric must not grade silently): an unknown
// key, a stage typed "gausian", a visibility Gradescope does not know or a ramp upside down is an
// error naming the file, the JSON path and what was expected, written to results.json, before
// anything renders.
#include "rubric.h"
#include "test_grader_support.h"

#include <cmath>
#include <regex>
#include <set>

namespace sl {
namespace {

// Grades the reference with `rubric` (the file's text); the rubric is read first, so an invalid
// one fails in well under a second.
test::Graded gradeWithRubric(const std::string& name, const std::string& rubric) {
    const fs::path dir = test::tempDir("fairness_rubric_" + name);
    std::ofstream(dir / "rubric.json") << rubric;
    return test::grade("--no-report --scenes classic --rubric " + (dir / "rubric.json").string() +
                           " --submission " + (test::root() / "reference").string(),
                       dir / "out");
}

struct BadRubric {
    const char* name;
    const char* json;
    const char* path;      // the JSON path the message must name
    const char* expected;  // and what it says was expected
};

TEST(FairnessRubric, InvalidRubricsAreRefusedWithTheJsonPath) {
    const BadRubric cases[] = {
        {"stage_typo", R"({"stages": {"gausian": {"weight": 30}}})", "/stages/gausian",
         "unknown key (known: final, gaussian, moments, msm, robustness, sat)"},
        {"visibility", R"({"hidden_scene_visibility": "after_due"})", "/hidden_scene_visibility",
         "expected one of \"visible\", \"hidden\", \"after_due_date\", \"after_published\", got \"after_due\""},
        {"top_key", R"({"totl": 100})", "/totl", "unknown key"},
        {"filters", R"({"filters": "one"})", "/filters", "expected one of \"both\", \"either\""},
        {"weight_type", R"({"stages": {"msm": {"weight": "20"}}})", "/stages/msm/weight",
         "expected a number, got \"20\""},
        {"negative_weight", R"({"stages": {"msm": {"weight": -1}}})", "/stages/msm/weight",
         "expected a number in [0, 1e+06]"},
        {"stage_key", R"({"stages": {"msm": {"wieght": 20}}})", "/stages/msm/wieght", "unknown key"},
        {"ramp", R"({"stages": {"sat": {"pass_fraction": 0.9, "zero_fraction": 0.95}}})",
         "/stages/sat/zero_fraction", "must be below pass_fraction"},
        {"tolerance_key", R"({"tolerances": {"moment_abs": 1e-4}})", "/tolerances/moment_abs",
         "unknown key"},
        {"tolerance_range", R"({"tolerances": {"shadow": 0}})", "/tolerances/shadow",
         "expected a number in (0, 1]"},
        {"not_object", R"([1, 2])", "/", "expected an object"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        auto g = gradeWithRubric(c.name, c.json);
        EXPECT_EQ(g.run.exitCode, 1) << g.run.output;
        ASSERT_TRUE(g.results.is_object()) << g.run.output;
        EXPECT_EQ(g.results["score"], 0);
        const std::string out = g.results["output"].get<std::string>();
        EXPECT_NE(out.find("rubric.json: " + std::string(c.path) + ": "), std::string::npos) << out;
        EXPECT_NE(out.find(c.expected), std::string::npos) << out;
    }
}

TEST(FairnessRubric, CommentsAreAcceptedAndRescaledPointsArePrinted) {
    // "_comment" keys are allowed in every object. classic has no SAT: the sat stage's 20
    // points are rescaled away, and the grade says what each stage is then worth (exact
    // hundredths, adding up to the total): 15, 20, 20, 5, 20 of 80 -> 18.75, 25, 25, 6.25, 25.
    auto g = gradeWithRubric("comment", R"({"_comment": "x", "stages": {"_note": 1, "msm": {"_why": "", "weight": 20}}})");
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), 100.0) << g.run.output;
    const std::string line = "points per stage (weights rescaled to the total 100.00): moments "
                             "18.75, gaussian 25.00, msm 25.00, robustness 6.25, final 25.00";
    EXPECT_NE(g.run.output.find(line), std::string::npos) << g.run.output;
    EXPECT_NE(g.results["output"].get<std::string>().find(line), std::string::npos);
    EXPECT_NE(g.run.output.find("filters: both"), std::string::npos) << g.run.output;
}

// A doc's text with every run of white space one space and no bold markers: a quote reads the
// same wherever its lines break.
std::string flatDoc(const std::string& doc) {
    std::string text = std::regex_replace(test::readFile(test::root() / doc), std::regex(R"(\s+)"), " ");
    return std::regex_replace(text, std::regex(R"(\*\*)"), "");
}

// "10⁻⁴" -> 4.
double superscript(const std::string& s) {
    static const std::vector<std::string> digits = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    double v = 0;
    for (size_t i = 0; i < s.size();) {
        size_t d = 0;
        while (d < digits.size() && s.compare(i, digits[d].size(), digits[d]) != 0) ++d;
        if (d == digits.size()) return -1;
        v = v * 10 + double(d);
        i += digits[d].size();
    }
    return v;
}

// Every match of `pattern` in `text`: the whole match, then its groups.
std::vector<std::vector<std::string>> allMatches(const std::string& text, const std::string& pattern) {
    const std::regex re(pattern);
    std::vector<std::vector<std::string>> out;
    for (std::sregex_iterator it(text.begin(), text.end(), re), end; it != end; ++it) {
        out.emplace_back();
        for (const auto& group : *it) out.back().push_back(group.str());
    }
    return out;
}

// One quote of the rubric in a doc: `pattern` (NUM and SUP stand for a number and for the
// superscript exponent of 10⁻ⁿ) must occur, and at each occurrence its numbers must be `values`.
struct RubricQuote {
    const char* doc;
    std::string pattern;
    std::vector<double> values;
};

}  // namespace

// Every threshold the docs quote is grader/rubric.json's (one source): each quote below is read
// from its doc and compared with the rubric the grader loads, and any score ramp quoted in a
// student-facing doc ("full marks from 99.9 %", "none at 99.0 %", "ramp 0.999 → 0.99") must be
// some stage's. A quote reworded so that this test no longer finds it fails here: update the
// pattern with the text.
TEST(FairnessRubric, DocsQuoteTheRubricsThresholds) {
    const grader::Rubric r = grader::loadRubric(test::root() / "grader/rubric.json");
    // grading.md's "default" column is both the built-in defaults and the shipped file.
    const grader::Rubric d = grader::defaultRubric();
    const std::vector<std::string> stages = {"moments", "gaussian", "sat", "msm", "robustness", "final"};
    for (const auto& st : stages) {
        EXPECT_EQ(r.ramp(st), d.ramp(st)) << st;
        EXPECT_EQ(r.weights.at(st), d.weights.at(st)) << st;
        EXPECT_EQ(r.worstTexelCap.count(st) ? r.worstTexelCap.at(st) : -1.0,
                  d.worstTexelCap.count(st) ? d.worstTexelCap.at(st) : -1.0) << st;
    }
    for (auto [a, b] : std::initializer_list<std::pair<double, double>>{{r.momentsAbs, d.momentsAbs}, {r.momentsRel, d.momentsRel},
                        {r.filterAbs, d.filterAbs}, {r.filterRel, d.filterRel},
                        {r.worstTexelFactor, d.worstTexelFactor}, {r.satRounding, d.satRounding},
                        {r.satKernelAbs, d.satKernelAbs}, {r.satKernelRel, d.satKernelRel},
                        {r.shadowTol, d.shadowTol}, {r.finalTol, d.finalTol}, {r.passFraction, d.passFraction},
                        {r.zeroFraction, d.zeroFraction}})
        EXPECT_EQ(a, b);

    auto pass = [&](const char* st) { return r.ramp(st).first; };
    auto zero = [&](const char* st) { return r.ramp(st).second; };
    auto pct = [](double f) { return 100 * f; };
    auto exponent = [](double tol) { return -std::log10(tol); };  // 1e-4 -> 4
    const std::vector<RubricQuote> quotes = {
        {"docs/handout.md", "full marks from NUM % of texels, none at NUM %", {pct(pass("sat")), pct(zero("sat"))}},
        {"docs/handout.md", "a texel beyond NUM× that tolerance caps a scene at NUM %",
         {r.worstTexelFactor, pct(r.worstTexelCap.at("sat"))}},
        {"docs/handout.md", "≤ 10⁻SUP \\+ 10⁻SUP·\\|reference\\|", {exponent(r.filterAbs), exponent(r.filterRel)}},
        {"docs/numerics.md", "full marks from NUM % of texels, none at NUM %", {pct(pass("sat")), pct(zero("sat"))}},
        {"docs/numerics.md", "\\|s − r\\| ≤ 10⁻SUP \\+ 10⁻SUP·\\|r\\|", {exponent(r.filterAbs), exponent(r.filterRel)}},
        {"docs/numerics.md", "full marks only when every case passes, none at NUM %", {pct(zero("robustness"))}},
        {"docs/grading.md", "full marks (?:only )?at NUM %, none at NUM %", {pct(pass("robustness")), pct(zero("robustness"))}},
        {"docs/grading.md", "full points at `f ≥ pass_fraction` \\(NUM\\), none at `f ≤ zero_fraction` \\(NUM\\)",
         {r.passFraction, r.zeroFraction}},
        {"docs/grading.md", "`msm` and `final` use NUM and NUM", {pass("msm"), zero("msm")}},
        {"docs/grading.md", "`msm` and `final` use NUM and NUM", {pass("final"), zero("final")}},
        {"docs/grading.md", "\\| `moments` \\| .{0,150}?ramp NUM → NUM", {pass("moments"), zero("moments")}},
        {"docs/grading.md", "\\| `gaussian` \\| .{0,150}?ramp NUM → NUM", {pass("gaussian"), zero("gaussian")}},
        {"docs/grading.md", "\\| `msm` \\| .{0,150}?ramp NUM → NUM", {pass("msm"), zero("msm")}},
        {"docs/grading.md", "\\| `final` \\| .{0,150}?ramp NUM → NUM", {pass("final"), zero("final")}},
        {"docs/grading.md", "a texel beyond NUM× the tolerance caps the test at NUM %",
         {r.worstTexelFactor, pct(r.worstTexelCap.at("gaussian"))}},
        {"docs/grading.md", "`pass_fraction`, `zero_fraction` \\| NUM, NUM", {r.passFraction, r.zeroFraction}},
        {"docs/grading.md", "msm and final: NUM, NUM; gaussian and sat: NUM, NUM; robustness: NUM, NUM",
         {pass("msm"), zero("msm"), pass("gaussian"), zero("gaussian"), pass("robustness"), zero("robustness")}},
        {"docs/grading.md", "msm and final: NUM, NUM; gaussian and sat: NUM, NUM",
         {pass("final"), zero("final"), pass("sat"), zero("sat")}},
        {"docs/grading.md", "`stages.<stage>.worst_texel_cap` \\| gaussian and sat: NUM",
         {r.worstTexelCap.at("gaussian")}},
        {"docs/grading.md", "`stages.<stage>.worst_texel_cap` \\| gaussian and sat: NUM", {r.worstTexelCap.at("sat")}},
        {"docs/grading.md",
         "`moments_abs` NUM, `moments_rel` NUM, `filter_abs` NUM, `filter_rel` NUM, `worst_texel_factor` NUM, "
         "`sat_rounding` NUM, `sat_kernel_abs` NUM, `sat_kernel_rel` NUM, `shadow` NUM, `final` NUM",
         {r.momentsAbs, r.momentsRel, r.filterAbs, r.filterRel, r.worstTexelFactor, r.satRounding, r.satKernelAbs,
          r.satKernelRel, r.shadowTol, r.finalTol}},
        {"docs/stage_contract.md", "`grader/rubric.json`: NUM \\+ NUM %", {r.satKernelAbs, pct(r.satKernelRel)}},
        {"docs/grading.md", "\\(NUM texels \\+ NUM %\\)", {r.satKernelAbs, pct(r.satKernelRel)}},
        {"docs/grading.md", "\\(`shadow` NUM in G, `final` NUM in linear colour\\)", {r.shadowTol, r.finalTol}},
        {"docs/grading.md", "moments NUM, gaussian NUM, sat NUM, msm NUM, robustness NUM, final NUM \\|",
         {r.weights.at("moments"), r.weights.at("gaussian"), r.weights.at("sat"), r.weights.at("msm"),
          r.weights.at("robustness"), r.weights.at("final")}},
    };
    const std::string num = R"(([0-9]+(?:\.[0-9]+)?(?:e-?[0-9]+)?))";
    const std::string sup = "((?:⁰|¹|²|³|⁴|⁵|⁶|⁷|⁸|⁹)+)";
    std::map<std::string, std::string> docs;
    for (const auto& q : quotes) {
        if (!docs.count(q.doc)) docs[q.doc] = flatDoc(q.doc);
        const std::string& text = docs[q.doc];
        std::string pattern = std::regex_replace(q.pattern, std::regex("NUM"), num);
        pattern = std::regex_replace(pattern, std::regex("SUP"), sup);
        const auto found = allMatches(text, pattern);
        for (const auto& m : found) {
            ASSERT_EQ(m.size(), q.values.size() + 1) << q.pattern;
            for (size_t i = 0; i < q.values.size(); ++i) {
                const bool sup = q.pattern.find("SUP") != std::string::npos;
                const double quoted = sup ? superscript(m[i + 1]) : std::stod(m[i + 1]);
                EXPECT_NEAR(quoted, q.values[i], 1e-9 * std::max(1.0, std::fabs(q.values[i])))
                    << q.doc << " quotes \"" << m[0] << "\"; number " << i + 1
                    << " is not grader/rubric.json's";
            }
        }
        EXPECT_FALSE(found.empty()) << q.doc << ": no quote matches \"" << q.pattern << "\"";
    }

    // Any ramp quoted in a doc students read is some stage's, and the plain float table's
    // measured share on contact (docs/numerics.md §5) is at or below the sat stage's zero:
    // that table keeps none of contact's SAT points (Grader.PlainFloatSatTable...).
    std::set<double> passes, zeros;
    std::set<std::pair<double, double>> ramps;
    for (const auto& st : stages) {
        passes.insert(std::round(pct(pass(st.c_str())) * 1000) / 1000);
        zeros.insert(std::round(pct(zero(st.c_str())) * 1000) / 1000);
        ramps.insert(r.ramp(st));
    }
    auto rounded = [](double v) { return std::round(v * 1000) / 1000; };
    for (const char* doc : {"README.md", "docs/handout.md", "docs/numerics.md", "docs/grading.md",
                            "docs/stage_contract.md", "docs/scenes.md"}) {
        const std::string text = flatDoc(doc);
        for (const auto& m : allMatches(text, "full marks from " + num + " ?%"))
            EXPECT_TRUE(passes.count(rounded(std::stod(m[1])))) << doc << ": " << m[0];
        for (const auto& m : allMatches(text, "none at " + num + " ?%"))
            EXPECT_TRUE(zeros.count(rounded(std::stod(m[1])))) << doc << ": " << m[0];
        for (const auto& m : allMatches(text, "ramp " + num + " → " + num))
            EXPECT_TRUE(ramps.count({std::stod(m[1]), std::stod(m[2])})) << doc << ": " << m[0];
        for (const auto& m : allMatches(text, "plain (?:float32 )?table (?:reaches|passes on) " + num +
                                                  " % (?:on|of) contact"))
            EXPECT_LE(std::stod(m[1]), pct(zero("sat"))) << doc << ": " << m[0];
    }
}

}  // namespace sl
