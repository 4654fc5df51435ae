// study: the sweep (see study.h).
#include "study.h"

#include "error_metrics.h"
#include "filtered_truth.h"
#include "gpu_resources.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "raw_map_cache.h"
#include "raw_map_key.h"
#include "renderer.h"
#include "scene_truth.h"
#include "study_report.h"
#include "technique.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <iostream>
#include <ostream>
#include <set>
#include <sstream>

namespace sl {
namespace {

using Clock = std::chrono::steady_clock;

struct Combination {
    std::string spec;
    Technique technique;
    std::vector<std::pair<std::string, double>> params;
    double momentBias;  // < 0: the scene's
    FilterKind filter;
    int radius;
    int size;
};

FilterKind filterFromName(const std::string& name) {
    if (name == "none") return FilterKind::None;
    if (name == "gaussian") return FilterKind::Gaussian;
    if (name == "sat") return FilterKind::Sat;
    throw std::invalid_argument("filter \"" + name + "\": expected none, gaussian or sat");
}

std::vector<Combination> combinations(const StudyOptions& o, std::vector<std::string>& notes) {
    std::vector<Combination> out;
    for (const std::string& spec : o.techniques) {
        auto [t, allParams] = parseTechniqueSpec(spec);
        const TechniqueRow& row = techniqueRow(t);
        // "momentBias" (α) is the scene's shadow.momentBias, not a row parameter: the study lets
        // a spec set it (msm4:momentBias=1e-4) so that α can be swept like the rest.
        std::vector<std::pair<std::string, double>> params;
        double momentBias = -1.0;
        for (const auto& [name, value] : allParams)
            if (name == "momentBias") momentBias = value;
            else params.emplace_back(name, value);
        std::vector<FilterKind> filters;
        for (const auto& f : o.filters) {
            const FilterKind k = filterFromName(f);
            if (std::count(row.filters.begin(), row.filters.end(), k)) filters.push_back(k);
        }
        if (filters.empty()) {
            filters.push_back(row.filters.front());
            notes.push_back(spec + ": none of the requested filters applies; its own (" +
                            std::string(toString(row.filters.front())) + ") is used");
        }
        for (int size : o.mapSizes)
            for (FilterKind f : filters) {
                if (f == FilterKind::None) {
                    out.push_back({spec, t, params, momentBias, f, 0, size});
                    continue;
                }
                ShadowEffect fx;
                fx.technique = t;
                fx.filter = f;
                if (!kernelReachesImage(fx) && !o.radii.empty()) {  // every radius, one frame
                    out.push_back({spec, t, params, momentBias, f, o.radii.front(), size});
                    if (size == o.mapSizes.front() && o.radii.size() > 1)
                        notes.push_back(spec + ": its " + toString(f) + " kernel does not reach the "
                                        "image (it picks its box per pixel): one row, radius " +
                                        std::to_string(o.radii.front()));
                    continue;
                }
                for (int r : o.radii) out.push_back({spec, t, params, momentBias, f, r, size});
            }
    }
    return out;
}

std::string slug(const std::string& s) {
    std::string out;
    for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
    return out;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, f, a, b, c);
    return buf;
}

// The copy pass (1024² RGBA32F, the practical floor of a filter pass), median of 5.
class CopyYardstick {
public:
    explicit CopyYardstick(Renderer& r)
        : renderer_(r), src_(Texture::create(1024, 1024, GL_RGBA32F)),
          dst_(Texture::create(1024, 1024, GL_RGBA32F)) {
        renderer_.copyPass(src_, dst_);  // compile
        gl::Finish();
    }
    double measure() {
        std::vector<double> ms;
        for (int i = 0; i < 5; ++i) {
            const auto t0 = Clock::now();
            renderer_.copyPass(src_, dst_);
            gl::Finish();
            ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        }
        return median(ms);
    }

private:
    Renderer& renderer_;
    Texture src_, dst_;
};

// The scene a combination renders: the base scene with the row's map, filter and technique.
Scene rowScene(const Scene& base, const Combination& c) {
    Scene s = base;
    s.shadow.mapSize = c.size;
    s.shadow.filter = c.filter;
    s.shadow.gaussianRadius = std::max(c.radius, 1);
    s.shadow.gaussianSigma = 0.0f;  // r / 2
    s.shadow.satKernelTexels = float(2 * c.radius + 1);
    overrideTechnique(s.shadow, c.technique, c.params);
    s.shadow.filter = c.filter;
    if (c.momentBias >= 0) s.shadow.momentBias = float(c.momentBias);
    return s;
}

PassPlan rowPlan(const Scene& s) {
    // No SAT resolve: it makes msm4's filtered moments for output only, and no frame needs it.
    PlanOptions planOptions;
    planOptions.resolveSat = false;
    return planPasses(s, planOptions);
}

// The first 16 hex digits of the SHA-256 of an image's floats: equal digests, equal images.
std::string imageDigest(const Image& img) {
    const std::string bytes(reinterpret_cast<const char*>(img.pixels.data()),
                            img.pixels.size() * sizeof(float));
    return sha256Hex(std::to_string(img.width) + "x" + std::to_string(img.height) + "x" +
                     std::to_string(img.channels) + "\n" + bytes).substr(0, 16);
}

void progressBar(std::ostream& err, int done, int total, const std::string& what, double eta) {
    const int width = 28, filled = total ? done * width / total : width;
    std::string bar(size_t(filled), '#');
    bar += std::string(size_t(width - filled), '.');
    char line[200];
    std::snprintf(line, sizeof line, "\r[%s] %d/%d  ETA %dm%02ds  %-40.40s", bar.c_str(), done,
                  total, int(eta) / 60, int(eta) % 60, what.c_str());
    err << line << std::flush;
}

}  // namespace

std::vector<std::string> allTechniqueSpecs() { return techniqueNames(); }

StudySummary runStudy(const StudyOptions& o, std::ostream& log) {
    StudySummary summary;
    Scene base = loadScene(o.scene.string());
    // One camera, the main one: the truth is its view, and a frame times what a row compares.
    base.cameras.resize(1);
    base.probes.clear();
    if (o.imageSize > 0) base.cameras.at(0).width = base.cameras.at(0).height = o.imageSize;
    fs::create_directories(o.out / "rows");
    fs::create_directories(o.out / "truth");
    const fs::path csv = o.out / "study.csv";
    std::set<std::string> done;
    for (const StudyRow& r : readStudyCsv(csv)) done.insert(r.key());

    // The truths are the scene's, not the solution's: the visible points are the framework's
    // pass, the filtered truth's depth map comes from relativeDepth, which every correct
    // solution computes alike (the kit without reference/ uses the student's).
    const ShaderLibrary referenceLib =
        ShaderLibrary::forSolution(resolveSolution(defaultSolution()), repoRoot());
    Renderer reference(referenceLib);
    Renderer solution(ShaderLibrary::forSolution(resolveSolution(o.solution), repoRoot()));
    CopyYardstick copy(solution);

    // The truth, once per scene (and from the disk cache when the scene has not changed).
    SceneTruthOptions to;
    to.rays.samples = o.samples;
    to.cacheDir = o.cacheDir;
    const SceneTruth truth = computeSceneTruth(base, referenceLib, to);
    writeTruthFiles(truth, o.out / "truth");
    summary.truthFromCache = truth.fromCache;
    summary.truthSeconds = truth.seconds;
    summary.maxStdError = truth.ray.maxStdError;
    summary.samplesPerPixel = truth.ray.samplesPerPixel;
    const Image& reached = truth.ray.reached;
    summary.notes.push_back(std::string("ray-traced truth: ") +
                            (truth.fromCache ? "read from the cache" : "traced") + " (" +
                            std::to_string(truth.ray.samplesPerPixel) + " rays per pixel, max "
                            "standard error " + fmt("%.4f", truth.ray.maxStdError) + ", key " +
                            truth.hash.substr(0, 12) + ")");

    // One depth map per size (the shadow pass of msm4 through the reference stages, b1 = z),
    // shared by every row's filtered truth; one filtered truth per (size, kernel).
    std::map<int, Image> depthMaps;
    std::map<std::string, Image> filteredTruths;
    auto depthMap = [&](int size) -> const Image& {
        auto it = depthMaps.find(size);
        if (it != depthMaps.end()) return it->second;
        Scene s = base;
        s.shadow.mapSize = size;
        s.shadow.filter = FilterKind::None;
        overrideTechnique(s.shadow, Technique::Msm4);
        s.shadow.filter = FilterKind::None;
        RenderResult r = reference.render(s, planPasses(s));
        Image z(size, size, 1);
        const Image& m = r.images.at("moments_raw");
        for (size_t i = 0, n = size_t(size) * size; i < n; ++i) z.pixels[i] = m.pixels[i * m.channels];
        return depthMaps.emplace(size, std::move(z)).first->second;
    };

    std::vector<std::string> notes;
    const std::vector<Combination> combos = combinations(o, notes);
    summary.notes.insert(summary.notes.end(), notes.begin(), notes.end());
    summary.planned = int(combos.size());

    // Which rows share a raw shadow map (raw_map_key.h): count every row still to run per key,
    // so that the first renders the map and keeps it for the others, and the last drops it.
    struct Planned {
        StudyRow row;  // the combination's columns, filled in below
        RawMapKey map;
    };
    std::vector<Planned> rows;
    RawMapCache shared;
    for (const Combination& c : combos) {
        Planned p;
        p.row.scene = base.name;
        p.row.solution = o.solution;
        p.row.spec = c.spec;
        p.row.technique = techniqueRow(c.technique).name;
        p.row.filter = toString(c.filter);
        p.row.radius = c.radius;
        p.row.mapSize = c.size;
        if (!done.count(p.row.key())) {
            const Scene s = rowScene(base, c);
            const PassPlan plan = rowPlan(s);
            if (plan.shadowLights.empty()) throw std::runtime_error(base.path + ": no light casts shadows");
            p.map = rawMapKey(s, plan, plan.shadowLights.front(), solution.library(), truth.hash);
            if (!o.shareMaps) p.map.digest.clear();
            shared.expect(p.map.digest);
        }
        rows.push_back(std::move(p));
    }

    std::optional<SharedRawMap> pendingKeep;  // the map this row rendered, kept after its frames
    const auto sweepStart = Clock::now();
    int index = 0;
    for (const Combination& c : combos) {
        StudyRow& row = rows[size_t(index)].row;
        const RawMapKey& mapKey = rows[size_t(index)].map;
        ++index;
        if (done.count(row.key())) {
            ++summary.skipped;
            continue;
        }
        const std::string what = c.spec + " " + row.filter +
                                 (c.radius ? " r=" + std::to_string(c.radius) : "") + " " +
                                 std::to_string(c.size) + "²";
        if (o.progress) {
            const double elapsed = std::chrono::duration<double>(Clock::now() - sweepStart).count();
            const double eta = summary.run ? elapsed / summary.run * (summary.planned - index + 1) : 0;
            progressBar(std::cerr, index - 1, summary.planned, what, eta);
        }
        const Scene s = rowScene(base, c);
        const PassPlan plan = rowPlan(s);
        const int light = plan.shadowLights.front();
        const MapLayout layout = mapLayout(s.shadow);
        row.kernelTexels = c.filter == FilterKind::None ? 1.0 : 2.0 * c.radius + 1.0;
        row.bits = techniqueRow(c.technique).bitsPerChannel;
        row.parameters = "momentBias=" + fmt("%g", s.shadow.momentBias);
        for (const auto& [name, value] : resolvedParameters(s.shadow))
            row.parameters += ";" + name + "=" + fmt("%g", value);
        row.mapBytes = size_t(c.size) * c.size * size_t(layout.layers) * size_t(layout.bytesPerTexel);
        row.planBytes = plan.bytes(light);

        // The raw map: this row's own shadow pass, or the one an earlier row rendered. A shared
        // row's shadow pass does not run; its time is the one measured when the map was
        // rendered (frame k takes the rendering row's frame k), so the frame stays whole.
        const SharedRawMap* given = shared.find(mapKey.digest);
        RenderInputs inputs;
        if (given) inputs.rawMaps[light] = given->map;
        auto isShadowPass = [&](size_t p) {
            const PlannedPass& pass = plan.passes[p];
            return pass.light == light &&
                   (pass.kind == PassKind::Shadow || pass.kind == PassKind::ShadowSecond);
        };
        row.mapKey = mapKey.label;
        row.mapFrom = given ? given->sourceRow : "";

        // Time: a warm-up frame compiles the programs (and keeps the raw map for later rows);
        // then `repeats` frames.
        row.copyMillis = copy.measure();
        RenderResult result;
        {
            RenderInputs first = inputs;
            first.keepRawMaps = !given && mapKey.shareable();
            result = solution.render(s, plan, first);
            if (first.keepRawMaps) {
                SharedRawMap keep;
                keep.map = std::move(result.rawMaps.at(light));
                keep.sourceRow = row.key();
                pendingKeep = std::move(keep);
            }
        }
        std::vector<std::vector<double>> passMs(plan.passes.size());
        std::vector<double> frames;
        std::vector<std::vector<double>> shadowMs;  // per frame, each of the light's shadow passes
        for (int k = 0; k < std::max(o.repeats, 1); ++k) {
            result = solution.render(s, plan, inputs);
            double frame = 0;
            shadowMs.emplace_back();
            for (size_t p = 0; p < plan.passes.size(); ++p) {
                double ms = result.passMillis.at(p);
                if (isShadowPass(p)) {
                    // The j-th shadow pass (a cascade's, the peel) takes the rendering row's j-th.
                    const size_t j = shadowMs.back().size();
                    if (given && !given->shadowMillis.empty()) {
                        const auto& f = given->shadowMillis[size_t(k) % given->shadowMillis.size()];
                        ms = j < f.size() ? f[j] : 0.0;
                    }
                    shadowMs.back().push_back(ms);
                }
                passMs[p].push_back(ms);
                frame += ms;
            }
            frames.push_back(frame);
        }
        if (pendingKeep) {
            pendingKeep->shadowMillis = shadowMs;
            shared.keep(mapKey.digest, std::move(*pendingKeep));
            pendingKeep.reset();
        }
        if (given) ++summary.sharedMaps;
        else ++summary.shadowMapsRendered;
        row.repeats = int(frames.size());
        row.frameMedian = median(frames);
        row.frameMin = *std::min_element(frames.begin(), frames.end());
        row.frameMax = *std::max_element(frames.begin(), frames.end());
        row.frameRatio = row.copyMillis > 0 ? row.frameMedian / row.copyMillis : 0;
        std::vector<double> medians;
        for (size_t p = 0; p < plan.passes.size(); ++p) {
            const auto& v = passMs[p];
            medians.push_back(median(v));
            row.passTimes += (p ? ";" : "") + std::string(toString(plan.passes[p].kind)) +
                             (plan.passes[p].light >= 0 ? "@L" + std::to_string(plan.passes[p].light) : "") +
                             "=" + fmt("%.3f/%.3f/%.3f", medians.back(),
                                       *std::min_element(v.begin(), v.end()),
                                       *std::max_element(v.begin(), v.end())) +
                             (given && isShadowPass(p) ? "(shared)" : "");
        }

        // Errors against both truths.
        const Image& shadow = result.images.at("shadow");
        row.imageDigest = imageDigest(shadow);
        const bool haveDepth = depthMaps.count(c.size) > 0;
        const FilterKernel kernel = kernelOf(s.shadow);
        const std::string kernelKey = std::to_string(c.size) + "|" + row.filter + "|" +
                                      std::to_string(c.radius);
        const bool haveFiltered = filteredTruths.count(kernelKey) > 0;
        if (!haveFiltered)
            filteredTruths[kernelKey] =
                filteredTruth(s, truth.points, reached, light, depthMap(c.size), kernel);
        const Image& filtered = filteredTruths.at(kernelKey);
        row.truth = measureShadowError(shadow, truth.ray.shadow, reached);
        row.filtered = measureShadowError(shadow, filtered, reached);
        row.reused = std::string("truth (") + (truth.fromCache ? "disk cache" : "this sweep") +
                     "); depth map " + std::to_string(c.size) + "² " +
                     (haveDepth ? "shared" : "rendered") + "; filtered truth " +
                     (haveFiltered ? "shared" : "computed") + "; technique map " +
                     (given ? "shared from " + given->sourceRow + " (its shadow-pass time)"
                            : mapKey.shareable() && o.shareMaps ? "rendered (shared with later rows)"
                                                                : "rendered");
        const std::string name = slug(row.spec) + "_" + row.filter +
                                 (c.radius ? "_r" + std::to_string(c.radius) : "") + "_" +
                                 std::to_string(c.size);
        row.image = "rows/" + name + "_shadow.png";
        row.errorMap = "rows/" + name + "_error.png";
        writePngPreview(shadow, o.out / row.image, false);
        writePngPreview(errorHeatMap(shadow, truth.ray.shadow, reached), o.out / row.errorMap, false);
        if (!haveFiltered)
            writePngPreview(filtered, o.out / "truth" / ("filtered_" + slug(kernelKey) + ".png"), false);
        appendStudyRow(csv, row);
        shared.done(mapKey.digest);  // (after the last use of `given`: this may drop it)
        ++summary.run;
        if (o.explain) {
            if (o.progress) std::cerr << "\n";
            log << "== " << what << "  (map " << row.mapKey << "; reused: " << row.reused << ")\n"
                << explainPlan(s, plan, &medians);
        }
    }
    if (o.progress) {
        progressBar(std::cerr, summary.planned, summary.planned, "done", 0);
        std::cerr << "\n";
    }
    summary.notes.push_back(std::to_string(depthMaps.size()) + " depth map(s) and " +
                            std::to_string(filteredTruths.size()) +
                            " filtered truth(s) computed for " + std::to_string(summary.run) +
                            " row(s)");
    summary.notes.push_back(
        "technique maps: " + std::to_string(summary.shadowMapsRendered) + " row(s) rendered their own, " +
        std::to_string(summary.sharedMaps) + " lit with one an earlier row rendered (" +
        std::to_string(shared.kept()) + " map(s) kept for sharing" +
        (o.shareMaps ? "" : "; sharing off") + "); a shared row reports the shadow-pass time "
        "measured when its map was rendered");
    if (o.report) writeStudyReport(o.out, readStudyCsv(csv), log, o.headline);
    return summary;
}

}  // namespace sl
