// score_render: one finished stage render turned into its test (score_render.h).
#include "score_render.h"

#include "depth_ladder.h"
#include "sat_kernel_ladder.h"
#include "image_io.h"
#include "metrics.h"
#include "raw_image.h"
#include "results.h"
#include "scene.h"
#include "shader_source.h"
#include "stage_functions.h"
#include "worker.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace sl::grader {
namespace fs = std::filesystem;
namespace {

// Stub notes ("FILE: FUNCTION: not implemented yet ...", one a line) as one line that names
// every function: "FILE: F1, F2; FILE2: F3".
std::string stubFunctionsText(const std::string& notes) {
    std::vector<std::pair<std::string, std::string>> byFile;  // file -> "F1, F2"
    std::istringstream lines(notes);
    for (std::string line; std::getline(lines, line);) {
        const size_t end = line.find(": not implemented yet");
        const size_t colon = line.find(": ");
        if (end == std::string::npos || colon == std::string::npos || colon >= end) continue;
        const std::string file = line.substr(0, colon), function = line.substr(colon + 2, end - colon - 2);
        auto it = std::find_if(byFile.begin(), byFile.end(), [&](const auto& f) { return f.first == file; });
        if (it == byFile.end()) byFile.push_back({file, function});
        else if (("_, " + it->second + ",").find(", " + function + ",") == std::string::npos)
            it->second += ", " + function;
    }
    std::string text;
    for (const auto& [file, functions] : byFile) text += (text.empty() ? "" : "; ") + file + ": " + functions;
    return text.empty() ? "the stub value -1" : text;
}

// The kernel image's receivers, by channel (sat_kernel_ladder.h).
const char* kernelReceiver(int channel) {
    return channel == 0 ? "the lit surface's" : "the far receiver's";
}

// satKernelTexels' widths in its own words: how many of each receiver's are off.
std::string kernelWidthsText(const Image& mine, const Image& ref, const Rubric& rubric) {
    long off[2] = {0, 0};
    const size_t n = size_t(ref.width) * ref.height;
    for (size_t i = 0; i < n && mine.pixels.size() == ref.pixels.size(); ++i)
        for (int c = 0; c < 2; ++c) {
            const double m = mine.pixels[i * 2 + c], r = ref.pixels[i * 2 + c];
            off[c] += !(std::fabs(m - r) <= rubric.satKernelAbs + rubric.satKernelRel * std::fabs(r));
        }
    std::ostringstream o;
    o << "satKernelTexels' box widths: " << off[0] << " of " << n << " for the lit surface and "
      << off[1] << " of " << n << " for the far receiver (behind every caster) are off by more than "
      << rubric.satKernelAbs << " texels + " << 100.0 * rubric.satKernelRel << " %";
    return o.str();
}

// Whether the worst texel lies in the band along the map's border where a border rule acts.
bool worstAtBorder(const Comparison& c, const Image& ref) {
    const int band = std::max(4, std::max(ref.width, ref.height) / 32);
    const int edge = std::min(std::min(c.worstX, ref.width - 1 - c.worstX),
                              std::min(c.worstY, ref.height - 1 - c.worstY));
    return c.worstX >= 0 && edge < band;
}

// Where the worst texel is and what it holds, so that a student can reproduce it (probe).
std::string worstTexelText(const std::string& image, const Comparison& c, int mapSize, int cells) {
    std::ostringstream o;
    o.precision(7);
    if (image == kSatKernelImage) {
        const glm::ivec2 t = satKernelCellTexel(c.worstX, c.worstY, cells, mapSize);
        o << "  worst: " << kernelReceiver(c.worstChannel) << " box at map texel (" << t.x << ", "
          << t.y << ") (from the bottom-left; centre (" << t.x + 0.5 << ", " << t.y + 0.5
          << ")): " << c.worstValue << " texels wide, expected " << c.worstExpected << " ("
          << fixedDigits(std::min(c.worst, 1e6), 1) << "x the tolerance)";
        return o.str();
    }
    if (image == kDepthLadderImage) {
        const glm::vec3 in = relativeDepthLadder().at(size_t(c.worstX));
        o << "  worst: ladder row " << c.worstX << " (lightDepth " << in.x << ", near " << in.y
          << ", far " << in.z << "): b" << c.worstChannel + 1 << " = " << c.worstValue
          << ", expected " << c.worstExpected
          << " (shadowlab probe moments --generate depth-ladder writes these rows)";
        return o.str();
    }
    o << "  worst texel: x " << c.worstX << ", y " << c.worstY
      << " (from the bottom-left; its centre is (" << c.worstX + 0.5 << ", " << c.worstY + 0.5
      << ")), channel b" << c.worstChannel + 1 << ": " << c.worstValue << ", expected "
      << c.worstExpected << " (" << fixedDigits(std::min(c.worst, 1e6), 1) << "x the tolerance)";
    return o.str();
}

// The stage's comparison under the rubric's tolerances: moments and filtered moments per
// channel (the SAT with an allowance for its table's rounding), msm's G and final's colour.
Comparison compareStage(const RenderToScore& job, const Rubric& rubric, const Image& mine,
                        const Image& ref, const std::string& image) {
    const CompareBy by = job.stage.compareBy;
    if (by == CompareBy::Shadow) return compareImages(mine, ref, rubric.shadowTol);
    if (image == kSatKernelImage)  // box widths in texels (sat_kernel_ladder.h)
        return compareMoments(mine, ref, rubric.satKernelAbs, rubric.satKernelRel);
    if (by == CompareBy::Colour) return compareImages(mine, ref, rubric.finalTol);
    std::vector<double> extra;
    if (job.stage.stage == Stage::Sat && rubric.satRounding > 0) {
        // A float32 table's rounding grows with its entries (up to the sum of the whole
        // map), and a correct table summed in another order rounds differently: allow
        // satRounding ulps of the total, spread over the box.
        const Scene& scene = *job.scene.scene;
        const double area = double(scene.shadow.satKernelTexels) * scene.shadow.satKernelTexels;
        extra.assign(ref.channels, 0.0);
        for (size_t i = 0; i < ref.pixels.size(); ++i)
            extra[i % ref.channels] += std::fabs(ref.pixels[i]);
        for (double& e : extra) e = rubric.satRounding * std::ldexp(e, -24) / area;
    }
    if (by == CompareBy::Moments)
        return compareMoments(mine, ref, rubric.momentsAbs, rubric.momentsRel);
    return compareMoments(mine, ref, rubric.filterAbs, rubric.filterRel, extra);
}

// The hard-case catalogue: the fraction of cases with no NaN, Inf, out-of-range,
// non-monotone or off-bound G (docs/numerics.md), and the failing cases with their inputs.
TestResult scoreRobustness(TestResult t, const WorkerResult& worker, const Rubric& rubric) {
    const auto& r = worker.robustness;
    const double fraction = r.value("score", 0.0);
    std::vector<std::string> notes;
    for (const auto& n : worker.stubNotes) notes.push_back(n.text);
    t.fraction = notes.empty() ? rubric.points("robustness", fraction, 1.0) : 0.0;
    t.metrics["robustness"] = r;
    const auto [pass, zero] = rubric.ramp("robustness");
    std::string all;
    for (const auto& n : notes) all += n + "\n";
    std::string head = !notes.empty() ? "not implemented: " + stubFunctionsText(all) + "\n" + all
                       : t.fraction >= 1.0 ? std::string("full marks\n")
                       : fixedDigits(100.0 * fraction, 2) + "% of the hard cases pass (full marks from " +
                             fixedDigits(100.0 * pass, 1) + "%, none at " + fixedDigits(100.0 * zero, 1) + "%)\n";
    t.output = head + r.value("summary", std::string());
    return t;
}

}  // namespace

std::string testScene(const StageRow* stage, const GradedScene& scene) {
    return stage && !stage->perScene ? "hard cases" : scene.name;
}

// What the child's failure means for the student.
std::string failureText(const ChildResult& c, const GradeOptions& o) {
    switch (c.kind) {
        case ChildResult::TimedOut: {
            const std::string limit = "timed out after " + fixedDigits(c.limitSeconds, 0) + " s" + c.limitNote;
            if (!c.skipped) return limit + ": the render was stopped (look for a loop that never ends)";
            // Not run: another render of the same files ran out of time.
            return (c.skippedAfter.empty() ? "not run here: this stage " + limit + " on another scene"
                                           : "not run here: the " + c.skippedAfter + " stage " + limit +
                                                 ", and this render runs its files too") +
                   " (look for a loop that never ends)";
        }
        case ChildResult::Signalled: return "crashed: " + signalName(c.signal);
        case ChildResult::StartFailed: return "the grader could not start its worker";
        case ChildResult::Exited: break;
    }
    std::string log = c.log;
    if (c.exitCode == 3) {  // ShaderError: file:line lines, then the driver's log
        const std::string head = "shader error:\n";
        if (auto p = log.find(head); p != std::string::npos) log = log.substr(p + head.size());
        if (log.size() > 4000) log = log.substr(0, 4000) + "\n...";
        // The first line is what the score table and the report's list of tests show: the
        // first error mapped to the submission's file and line, when there is one.
        if (log.rfind("---", 0) != 0) return "compile or link error: " + log;
        std::istringstream lines(log);
        std::string first;
        while (std::getline(lines, first) && (first.empty() || first.rfind("---", 0) == 0)) {}
        return "compile or link error: " + first + "\n" + log;
    }
    if (log.size() > 2000) log = "..." + log.substr(log.size() - 2000);
    std::string text = "render failed (exit " + std::to_string(c.exitCode) + "): " + log;
    if (log.find("alloc") != std::string::npos || log.find("memory") != std::string::npos ||
        log.find("map") != std::string::npos)
        text += "\n(the memory limit is " + std::to_string(o.memoryMb) + " MB)";
    return text;
}

TestResult scoreRender(const RenderToScore& job, const GradeOptions& options, const Rubric& rubric,
                       const std::function<fs::path(const std::string& image)>& referenceFile,
                       ReportWriter* report, std::vector<ImageFindings>* findings) {
    const bool robustness = job.stage.compareBy == CompareBy::HardCases;
    TestResult t;
    t.scene = testScene(&job.stage, job.scene);  // one name, pass or fail
    t.stage = job.stage.name;
    t.hidden = !robustness && job.scene.hidden;
    if (!job.missing.empty()) {
        t.output = job.missing;
        return t;
    }
    if (job.child.notRun) {
        t.output = "not implemented: " + stubFunctionsText(job.notRunReason) + "\n" + job.notRunReason;
        return t;
    }
    if (!(job.child.kind == ChildResult::Exited && job.child.exitCode == 0)) {
        t.output = failureText(job.child, options);
        // A final runs every file of its scene: its own timeout cannot tell which one loops.
        if (job.stage.stage == Stage::Final && job.child.kind == ChildResult::TimedOut && !job.child.skipped) {
            std::string files;
            for (const auto& f : stageFiles(job.stage, job.scene.filter))
                files += (files.empty() ? "" : ", ") + std::string("submission/") + f;
            t.output += "; this render runs " + files + ": each stage's own test says which one loops";
        }
        return t;
    }
    const std::optional<WorkerResult> worker = readWorkerResult(job.out);
    if (!worker) {
        t.output = "the render left no result";
        return t;
    }
    if (robustness) return scoreRobustness(t, *worker, rubric);
    // Stub notes naming the submission's files of this stage: not implemented.
    std::string notes;
    const auto files = stageFiles(job.stage, job.scene.filter);
    for (const auto& n : worker->stubNotes)
        if (std::find(files.begin(), files.end(), n.file) != files.end()) notes += n.text + "\n";

    std::vector<std::string> images;
    for (const auto& name : worker->images)
        if (gradedImage(job.stage, name)) images.push_back(name);
    if (images.empty()) images.push_back(toString(job.stage.images.front()));
    double fraction = 1.0, worstCap = 1.0;
    double mapsFraction = 1.0, ladderFraction = 1.0;  // the moment maps', the depth ladder's
    std::string worstWhere;  // the first image's texel beyond the worst-texel factor, in words
    ImageFindings ladderFindings;
    std::ostringstream detail;
    for (const auto& name : images) {
        Image ref, mine;
        const bool ladder = name == kDepthLadderImage;
        try {
            // msm is compared with the reference lit from the same moments (msm_<image>);
            // the relativeDepth ladder with its exact moments.
            ref = ladder ? depthLadderExpected()
                         : readAnyImage(referenceFile(job.stage.stage == Stage::Msm ? "msm_" + name : name));
        } catch (const std::exception& e) {
            t.output = "no reference image " + name + " to compare with (" + e.what() + ")";
            return t;
        }
        try {
            mine = readRaw(job.out / (name + ".raw"));
        } catch (const std::exception&) {
            fraction = 0.0;
            detail << name << ": no image was produced\n";
            continue;
        }
        if (ladder && depthLadderStub(mine)) {
            if (notes.find(": relativeDepth: ") == std::string::npos)
                notes += stubNoteText("submission/moments.glsl", StageFunction::RelativeDepth) + "\n";
            continue;
        }
        Comparison c = compareStage(job, rubric, mine, ref, name);
        fraction = std::min(fraction, c.error.empty() ? c.fraction : 0.0);
        if (auto cap = rubric.worstTexelCap.find(job.stage.name);
            cap != rubric.worstTexelCap.end() && c.worst > rubric.worstTexelFactor)
            worstCap = std::min(worstCap, cap->second);
        t.metrics[name] = c.toJson();
        t.images.push_back(name);
        detail << name << ": " << fixedDigits(100.0 * c.fraction, 2) << "% within tolerance"
               << "; OIIO mean " << fixedDigits(c.mean, 6) << ", RMS " << fixedDigits(c.rms, 6) << ", max "
               << fixedDigits(c.max, 6) << ", PSNR " << fixedDigits(c.psnr, 1) << " dB";
        if (!c.error.empty()) detail << "; " << c.error;
        if (c.worstX >= 0) detail << "; worst texel at " << fixedDigits(std::min(c.worst, 1e6), 4) << "x the tolerance";
        if (c.nonFinite) detail << "; " << c.nonFinite << " NaN/Inf values (counted wrong)";
        if (c.stubTexels) detail << "; " << c.stubTexels << " texels hold the stub value -1";
        detail << "\n";
        if (name == kSatKernelImage) detail << "  " << kernelWidthsText(mine, ref, rubric) << "\n";
        if (c.worstX >= 0 && c.worst > 1.0)
            detail << worstTexelText(name, c, job.scene.scene->shadow.mapSize, ref.width) << "\n";
        if (c.worst > rubric.worstTexelFactor && worstWhere.empty())
            worstWhere = name == kSatKernelImage ? std::string("a box width (satKernelTexels, from the table)")
                       : worstAtBorder(c, ref) ? std::string("a texel at the map's border (look at the border rule)")
                       : "a texel inside the map, at (" + std::to_string(c.worstX) + ", " +
                             std::to_string(c.worstY) + "), away from the border";
        ImageFindings f = findImageProblems(c.errorMap, c.nonFinite, name);
        f.scene = t.scene, f.stage = t.stage, f.image = name, f.hidden = t.hidden;
        if (ladder && mine.width == ref.width && mine.channels == ref.channels) {
            // Which failing rungs have b1 = z off too (the moments' tolerance).
            f.failingDepth = 0;
            for (int x = 0; x < ref.width; ++x) {
                const double z = ref.at(x, 0, 0), d = std::abs(double(mine.at(x, 0, 0)) - z);
                if (!(c.errorMap.at(x, 0, 0) <= 1.0f) && !(d <= rubric.momentsAbs + rubric.momentsRel * std::abs(z)))
                    ++f.failingDepth;
            }
        }
        if (report) report->add(t, name, ref, mine, c, f);
        (ladder ? ladderFraction : mapsFraction) =
            std::min(ladder ? ladderFraction : mapsFraction, c.error.empty() ? c.fraction : 0.0);
        if (ladder) ladderFindings = f;
        if (findings && notes.empty()) findings->push_back(f);  // a stub is no bug to diagnose
    }
    t.fraction = notes.empty() ? std::min(rubric.points(job.stage.name, fraction, 1.0), worstCap) : 0.0;
    const auto [pass, zero] = rubric.ramp(job.stage.name);
    std::string head;
    if (!notes.empty()) head = "not implemented: " + stubFunctionsText(notes) + "\n" + notes;
    else if (t.fraction >= 1.0) head = "full marks\n";
    else if (worstCap < 1.0 && t.fraction == worstCap)
        head = "worst-texel rule: " + worstWhere + " is off by more than " + fixedDigits(rubric.worstTexelFactor, 0) +
               "x the tolerance, at most " +
               fixedDigits(100.0 * worstCap, 0) + "% of the points; " + fixedDigits(100.0 * fraction, 3) +
               "% within tolerance\n";
    else if (ladderFindings.depthLadder && ladderFraction < 1.0 && ladderFraction <= mapsFraction)
        // The ladder decides the points: say so, not "52% within tolerance" of the stage,
        // whose moment maps may all be right.
        head = depthLadderText(ladderFindings) + "; " + fixedDigits(100.0 * ladderFraction, 2) +
               "% within tolerance (full marks from " + fixedDigits(100.0 * pass, 1) + "%, none at " +
               fixedDigits(100.0 * zero, 1) + "%); " +
               (mapsFraction >= 1.0 ? std::string("every moment map within tolerance")
                                    : "the moment maps " + fixedDigits(100.0 * mapsFraction, 2) + "%") +
               "\n";
    else head = fixedDigits(100.0 * fraction, 2) + "% within tolerance (full marks from " +
                fixedDigits(100.0 * pass, 1) + "%, none at " + fixedDigits(100.0 * zero, 1) + "%)\n";
    if (notes.empty() && fraction == 0.0 && detail.str().find("stub value") != std::string::npos)
        head = "not implemented (the output is the stub value -1)\n";
    t.output = head + detail.str();
    return t;
}

}  // namespace sl::grader
