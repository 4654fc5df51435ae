// study: the sweep (see study.h).
#include "study.h"

#include "cost_clock.h"
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
#include "study_combinations.h"
#include "study_cost.h"
#include "study_flicker.h"
#include "study_report.h"
#include "study_shard.h"
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

std::string slug(const std::string& s) {
    std::string out;
    for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
    return out;
}

std::string studyFmt(const char* f, double a, double b = 0, double c = 0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, f, a, b, c);
    return buf;
}

// The SAT box of the same variance as the Gaussian of radius r (σ = r / 2): σ·√12 texels.
double satBoxTexels(int radius) { return 0.5 * radius * std::sqrt(12.0); }

// The scene with every light a disk that wide (< 0: as the file has it). A directional light's
// size is an angle: the same disk at its position, seen from its target (docs/scenes.md).
Scene withLightSize(const Scene& base, double size) {
    Scene s = base;
    if (size < 0) return s;
    for (Light& l : s.lights) {
        l.size = l.type == LightType::Directional
                     ? float(size / double(glm::length(l.position - l.target)))
                     : float(size);
        l.rectangle = glm::vec2(0.0f);  // a disk
    }
    return s;
}

// "truth/light_0.8": where a light size's truth previews go.
std::string truthFolder(double lightSize) { return "truth/light_" + studyFmt("%g", lightSize); }

// The scene a combination renders: the base scene with the row's light, map, filter and
// technique.
Scene rowScene(const Scene& file, const Combination& c) {
    Scene s = withLightSize(file, c.lightSize);
    s.shadow.mapSize = c.size;
    s.shadow.filter = c.filter;
    s.shadow.gaussianRadius = std::max(c.radius, 1);
    s.shadow.gaussianSigma = 0.0f;  // r / 2
    // Filters compared at equal variance: the Gaussian's σ = r / 2, so the SAT's box is
    // σ·√12 = r·√3 texels wide (a box of width w has variance w² / 12; the lookup weighs the
    // partly covered texels at its edges).
    s.shadow.satKernelTexels = float(satBoxTexels(c.radius));
    overrideTechnique(s.shadow, c.technique, c.params);
    s.shadow.filter = c.filter;
    // Per pixel: satKernelTexels picks each box (search up to 48, boxes up to 64 texels, as
    // scenes/penumbra.json), whatever the radius.
    s.shadow.satPerPixel = c.perPixel;
    if (c.perPixel) s.shadow.satKernelTexels = 48.0f, s.shadow.satMaxKernelTexels = 64.0f;
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
    if (!o.mergeFrom.empty())
        summary.notes.push_back("merged " + std::to_string(mergeStudyShards(o.mergeFrom, o.out)) +
                                " row(s) from " + std::to_string(o.mergeFrom.size()) + " folder(s)");
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
    const std::string method = costMethod();

    // The truth, once per light size (and from the disk cache when the scene has not changed),
    // traced when a row first needs it.
    SceneTruthOptions to;
    to.rays.samples = o.samples;
    to.cacheDir = o.cacheDir;
    std::map<double, SceneTruth> truths;
    auto truthFor = [&](double lightSize) -> const SceneTruth& {
        auto it = truths.find(lightSize);
        if (it != truths.end()) return it->second;
        const SceneTruth& t =
            truths.emplace(lightSize, computeSceneTruth(withLightSize(base, lightSize), referenceLib, to))
                .first->second;
        const fs::path dir = o.out / (lightSize < 0 ? std::string("truth") : truthFolder(lightSize));
        writeTruthFiles(t, dir);
        summary.truthFromCache = t.fromCache;
        summary.truthSeconds += t.seconds;
        summary.maxStdError = std::max(summary.maxStdError, t.ray.maxStdError);
        summary.samplesPerPixel = std::max(summary.samplesPerPixel, t.ray.samplesPerPixel);
        summary.notes.push_back(std::string("ray-traced truth") +
                                (lightSize < 0 ? "" : " (light size " + studyFmt("%g", lightSize) + ")") +
                                ": " + (t.fromCache ? "read from the cache" : "traced") + " (" +
                                std::to_string(t.ray.samplesPerPixel) + " rays per pixel, max "
                                "standard error " + studyFmt("%.4f", t.ray.maxStdError) + ", " +
                                studyFmt("%.1f s", t.seconds) + ", key " + t.hash.substr(0, 12) + ")");
        return t;
    };
    SceneTruthOptions hashOnly = to;
    // The turning light's truths, once per light size (study_flicker.h).
    std::map<double, FlickerSequence> flickers;
    auto flickerFor = [&](double lightSize) -> const FlickerSequence& {
        auto it = flickers.find(lightSize);
        if (it != flickers.end()) return it->second;
        const auto t0 = Clock::now();
        FlickerSequence q = flickerSequence(withLightSize(base, lightSize), o.flickerFrames,
                                            o.flickerStep, referenceLib, to);
        summary.notes.push_back("flicker: " + std::to_string(o.flickerFrames) + " frames, light "
                                "turning " + studyFmt("%g", o.flickerStep) + "° a frame; truth's "
                                "mean change " + studyFmt("%.5f", q.truthChange) + " (" +
                                studyFmt("%.1f s", std::chrono::duration<double>(Clock::now() - t0).count()) + ")");
        return flickers.emplace(lightSize, std::move(q)).first->second;
    };
    auto sceneHash = [&](double lightSize) { return sceneTruthHash(withLightSize(base, lightSize), hashOnly); };

    // One depth map per size (the shadow pass of msm4 through the reference stages, b1 = z),
    // shared by every row's filtered truth; one filtered truth per (size, kernel): neither
    // depends on the light's size.
    std::map<int, Image> depthMaps;
    std::map<std::string, Image> filteredTruths;
    auto depthMap = [&](int size) -> const Image& {
        auto it = depthMaps.find(size);
        if (it != depthMaps.end()) return it->second;
        Scene s = base;
        s.shadow.mapSize = size;
        s.shadow.filter = FilterKind::None;
        overrideTechnique(s.shadow, techniqueFromName("msm4"));
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
    const PassPlan basePlan = rowPlan(base);
    if (basePlan.shadowLights.empty()) throw std::runtime_error(base.path + ": no light casts shadows");
    const double ownLightSize = base.lights.at(size_t(basePlan.shadowLights.front())).size;

    // Which rows share a raw shadow map (raw_map_key.h): count every row still to run per key,
    // so that the first renders the map and keeps it for the others, and the last drops it.
    struct Planned {
        StudyRow row;  // the combination's columns, filled in below
        RawMapKey map;
        bool mine = true;  // in this shard
    };
    std::vector<Planned> rows;
    std::vector<std::string> digests;
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
        p.row.lightSize = c.lightSize < 0 ? ownLightSize : c.lightSize;
        const Scene s = rowScene(base, c);
        const PassPlan plan = rowPlan(s);
        p.map = rawMapKey(s, plan, plan.shadowLights.front(), solution.library(), sceneHash(c.lightSize));
        if (!o.shareMaps) p.map.digest.clear();
        digests.push_back(p.map.digest);
        rows.push_back(std::move(p));
    }
    const std::vector<bool> mine = shardRows(digests, o.shard, o.shards);
    for (size_t i = 0; i < rows.size(); ++i) {
        rows[i].mine = mine[i];
        if (mine[i]) ++summary.planned;
        if (mine[i] && !done.count(rows[i].row.key())) shared.expect(rows[i].map.digest);
    }

    // Where the sweep's time goes (wall seconds per phase, said in the summary).
    std::vector<std::pair<std::string, double>> phases;
    auto lapStart = Clock::now();
    auto lap = [&](const std::string& name) {
        const auto now = Clock::now();
        const double sec = std::chrono::duration<double>(now - lapStart).count();
        lapStart = now;
        for (auto& [n, v] : phases)
            if (n == name) { v += sec; return; }
        phases.emplace_back(name, sec);
    };
    std::optional<SharedRawMap> pendingKeep;  // the map this row rendered, kept after its frames
    const auto sweepStart = Clock::now();
    int index = 0;
    for (const Combination& c : combos) {
        StudyRow& row = rows[size_t(index)].row;
        const RawMapKey& mapKey = rows[size_t(index)].map;
        const bool inShard = rows[size_t(index)].mine;
        ++index;
        if (!inShard) continue;
        if (done.count(row.key())) {
            ++summary.skipped;
            continue;
        }
        const std::string what = c.spec + " " + row.filter +
                                 (c.radius ? " r=" + std::to_string(c.radius) : "") + " " +
                                 std::to_string(c.size) + "²" +
                                 (c.lightSize < 0 ? "" : " light " + studyFmt("%g", c.lightSize));
        if (o.progress) {
            const int at = summary.run + summary.skipped;
            const double elapsed = std::chrono::duration<double>(Clock::now() - sweepStart).count();
            const double eta = summary.run ? elapsed / summary.run * (summary.planned - at) : 0;
            progressBar(std::cerr, at, summary.planned, what, eta);
        }
        lap("bookkeeping");
        const SceneTruth& truth = truthFor(c.lightSize);
        lap("ray-traced truth");
        const Image& reached = truth.ray.reached;
        const Scene s = rowScene(base, c);
        const PassPlan plan = rowPlan(s);
        const int light = plan.shadowLights.front();
        const MapLayout layout = mapLayout(s.shadow);
        row.kernelTexels = c.filter == FilterKind::None ? 1.0
                           : c.filter == FilterKind::Sat ? satBoxTexels(c.radius)
                                                         : 2.0 * c.radius + 1.0;
        row.bits = techniqueRow(c.technique).bitsPerChannel;
        row.parameters = "momentBias=" + studyFmt("%g", s.shadow.momentBias);
        for (const auto& [name, value] : resolvedParameters(s.shadow))
            row.parameters += ";" + name + "=" + studyFmt("%g", value);
        row.mapBytes = size_t(c.size) * c.size * size_t(layout.layers) * size_t(layout.bytesPerTexel);
        row.planBytes = plan.bytes(light);

        // The raw map: this row's own shadow pass, or the one an earlier row rendered. A shared
        // row's shadow pass does not run; its cost is the one measured when the map was
        // rendered (frame k takes the rendering row's frame k), so the frame stays whole.
        const SharedRawMap* given = shared.find(mapKey.digest);
        RenderInputs inputs;
        inputs.readMaps = false;  // G only: the maps are not compared (study.h)
        if (given) inputs.rawMaps[light] = given->map;
        auto isShadowPass = [&](size_t p) {
            const PlannedPass& pass = plan.passes[p];
            return pass.light == light &&
                   (pass.kind == PassKind::Shadow || pass.kind == PassKind::ShadowSecond);
        };
        row.mapKey = mapKey.label;
        row.mapFrom = given ? given->sourceRow : "";

        // Cost: a warm-up frame compiles the programs (and keeps the raw map for later rows);
        // then `repeats` frames, each after a copy pass (study_cost.h).
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
        lap("warm-up frame (compiles, renders the shared map)");
        std::vector<std::vector<double>> passMs(plan.passes.size());
        std::vector<double> frames, wallFrames, copies;
        std::vector<std::vector<double>> shadowMs;  // per frame, each of the light's shadow passes
        for (int k = 0; k < std::max(o.repeats, 1); ++k) {
            copies.push_back(copy.measureOnce());
            result = solution.render(s, plan, inputs);
            double frame = 0, wall = 0;
            shadowMs.emplace_back();
            for (size_t p = 0; p < plan.passes.size(); ++p) {
                double ms = result.passCost.at(p);
                double wallMs = result.passMillis.at(p);
                if (isShadowPass(p)) {
                    // The j-th shadow pass (a cascade's, the peel) takes the rendering row's j-th.
                    const size_t j = shadowMs.back().size();
                    if (given && !given->shadowMillis.empty()) {
                        const auto& f = given->shadowMillis[size_t(k) % given->shadowMillis.size()];
                        ms = j < f.size() ? f[j] : 0.0;
                        wallMs = ms;  // its wall time was not kept: the CPU figure stands in
                    }
                    shadowMs.back().push_back(ms);
                }
                passMs[p].push_back(ms);
                frame += ms;
                wall += wallMs;
            }
            frames.push_back(frame);
            wallFrames.push_back(wall);
        }
        lap("timed frames and copy passes");
        if (pendingKeep) {
            pendingKeep->shadowMillis = shadowMs;
            shared.keep(mapKey.digest, std::move(*pendingKeep));
            pendingKeep.reset();
        }
        if (given) ++summary.sharedMaps;
        else ++summary.shadowMapsRendered;
        row.repeats = int(frames.size());
        const CostStats frameCost = costStats(frames);
        row.frameMin = frameCost.min;
        row.frameMedian = frameCost.median;
        row.frameMax = frameCost.max;
        row.frameWallMedian = costStats(wallFrames).median;
        row.copyMillis = costStats(copies).min;
        row.frameRatio = row.copyMillis > 0 ? row.frameMin / row.copyMillis : 0;
        row.costMethod = method;
        std::vector<double> medians;
        for (size_t p = 0; p < plan.passes.size(); ++p) {
            const CostStats st = costStats(passMs[p]);
            medians.push_back(st.median);
            row.passTimes += (p ? ";" : "") + std::string(toString(plan.passes[p].kind)) +
                             (plan.passes[p].light >= 0 ? "@L" + std::to_string(plan.passes[p].light) : "") +
                             "=" + studyFmt("%.3f/%.3f/%.3f", st.min, st.median, st.max) +
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
        lap("depth map and filtered truth");
        row.truth = measureShadowError(shadow, truth.ray.shadow, reached);
        row.filtered = measureShadowError(shadow, filtered, reached);
        lap("error measures");
        if (o.flickerFrames > 1) {
            const FlickerSequence& q = flickerFor(c.lightSize);
            row.flickerFrames = q.frames;
            row.flickerTruth = q.truthChange;
            row.flicker = rowChange(solution, s, q, rowPlan) - q.truthChange;
        }
        lap("flicker (frames and their truths)");
        row.reused = std::string("truth (") + (truth.fromCache ? "disk cache" : "this sweep") +
                     "); depth map " + std::to_string(c.size) + "² " +
                     (haveDepth ? "shared" : "rendered") + "; filtered truth " +
                     (haveFiltered ? "shared" : "computed") + "; technique map " +
                     (given ? "shared from " + given->sourceRow + " (its shadow-pass cost)"
                            : mapKey.shareable() && o.shareMaps ? "rendered (shared with later rows)"
                                                                : "rendered");
        const std::string name = slug(row.spec) + "_" + row.filter +
                                 (c.radius ? "_r" + std::to_string(c.radius) : "") + "_" +
                                 std::to_string(c.size) +
                                 (c.lightSize < 0 ? "" : "_light" + studyFmt("%g", c.lightSize));
        row.image = "rows/" + name + "_shadow.png";
        row.errorMap = "rows/" + name + "_error.png";
        writePngPreview(shadow, o.out / row.image, false);
        writePngPreview(errorHeatMap(shadow, truth.ray.shadow, reached), o.out / row.errorMap, false);
        if (!haveFiltered)
            writePngPreview(filtered, o.out / "truth" / ("filtered_" + slug(kernelKey) + ".png"), false);
        appendStudyRow(csv, row);
        lap("images and the CSV row");
        shared.done(mapKey.digest);  // (after the last use of `given`: this may drop it)
        ++summary.run;
        if (o.explain) {
            if (o.progress) std::cerr << "\n";
            log << "== " << what << "  (map " << row.mapKey << "; reused: " << row.reused << ")\n"
                << explainPlan(s, plan, &medians, costUnit());
        }
    }
    if (o.progress) {
        progressBar(std::cerr, summary.planned, summary.planned, "done", 0);
        std::cerr << "\n";
    }
    // The table in the sweep's order (a resumed or merged run appended rows out of it); rows of
    // other settings stay, after these.
    {
        std::vector<StudyRow> table = readStudyCsv(csv), ordered;
        std::map<std::string, size_t> at;
        for (size_t i = 0; i < table.size(); ++i) at[table[i].key()] = i;
        std::vector<bool> placed(table.size(), false);
        for (const Planned& p : rows) {
            auto it = at.find(p.row.key());
            if (it == at.end() || placed[it->second]) continue;
            ordered.push_back(table[it->second]);
            placed[it->second] = true;
        }
        for (size_t i = 0; i < table.size(); ++i)
            if (!placed[i]) ordered.push_back(table[i]);
        if (!ordered.empty()) writeStudyCsv(csv, ordered);
    }
    summary.notes.push_back(std::to_string(depthMaps.size()) + " depth map(s) and " +
                            std::to_string(filteredTruths.size()) +
                            " filtered truth(s) computed for " + std::to_string(summary.run) +
                            " row(s)");
    summary.notes.push_back(
        "technique maps: " + std::to_string(summary.shadowMapsRendered) + " row(s) rendered their own, " +
        std::to_string(summary.sharedMaps) + " lit with one an earlier row rendered (" +
        std::to_string(shared.kept()) + " map(s) kept for sharing" +
        (o.shareMaps ? "" : "; sharing off") + "); a shared row reports the shadow-pass cost "
        "measured when its map was rendered");
    summary.notes.push_back("cost: " + method);
    std::string where = "where the time went (wall s):";
    for (const auto& [n, v] : phases)
        if (v >= 0.05) where += " " + n + " " + studyFmt("%.1f", v) + ";";
    summary.notes.push_back(where);
    if (o.report && o.shards == 1) writeStudyReport(o.out, readStudyCsv(csv), log, o.headline);
    return summary;
}

}  // namespace sl
