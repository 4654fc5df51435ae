// The student kit attacked as a student would (the kit must not ship anything that passes as a
// stage): pack it, unpack it, and look in everything it ships outside student/ for something to
// hand in as a stage.
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
#include "kit_attack_pastes.h"
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
        if (key == "satKernelTexels") {  // the reference's table and box averages around it
            f["sat.comp"] = test::readFile(root / "reference/sat.comp");
            f["sat_lookup.glsl"] =
                replaceFunction(test::readFile(root / "reference/sat_lookup.glsl"), "satKernelTexels",
                                definitionOf(f["sat_lookup.glsl"], "satKernelTexels"));
        }
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
    // The reference's satKernelTexels alone (its satBoxAverage reads the reference's table).
    controlSources.push_back(makeSource(
        "reference/sat_lookup.glsl",
        definitionOf(test::readFile(root / "reference/sat_lookup.glsl"), "satKernelTexels"), false,
        root));
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
