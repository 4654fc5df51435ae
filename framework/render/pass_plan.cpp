// planPasses: derive the pass list and its textures from the scene and its technique's row
// (see pass_plan.h).
#include "pass_plan.h"

#include "cascades.h"
#include "technique.h"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <utility>

namespace sl {

const char* toString(PassKind kind) {
    switch (kind) {
        case PassKind::Shadow: return "shadow";
        case PassKind::ShadowSecond: return "shadow-second";
        case PassKind::Widen: return "widen";
        case PassKind::GaussianX: return "gaussian-x";
        case PassKind::GaussianY: return "gaussian-y";
        case PassKind::SatRows: return "sat-rows";
        case PassKind::SatColumns: return "sat-columns";
        case PassKind::SatResolve: return "sat-resolve";
        case PassKind::Lighting: return "lighting";
    }
    return "?";
}

const char* toString(TextureRole role) {
    switch (role) {
        case TextureRole::Depth: return "depth";
        case TextureRole::Raw: return "raw";
        case TextureRole::Second: return "second";
        case TextureRole::Wide: return "wide";
        case TextureRole::Scratch: return "scratch";
        case TextureRole::Filtered: return "filtered";
        case TextureRole::Sat: return "sat";
        case TextureRole::Color: return "color";
        case TextureRole::Shadow: return "shadow";
        case TextureRole::CameraDepth: return "camera-depth";
    }
    return "?";
}

PassProgram passProgramFor(PassKind kind, int blurRadius, const std::vector<std::string>& defines) {
    switch (kind) {
        case PassKind::Shadow: return {"scene.vert", "techniques/store.frag", defines};
        case PassKind::ShadowSecond: return {"scene.vert", "techniques/second_depth_peel.frag", defines};
        case PassKind::Widen: return {"widen.comp", "", {}};
        case PassKind::GaussianX:
        case PassKind::GaussianY:
            // The radius is a compile-time constant (one program per radius): llvmpipe then
            // unrolls the taps and keeps the window in registers (docs/performance.md).
            return {"gaussian_blur.comp", "", {"SL_BLUR_RADIUS=" + std::to_string(blurRadius)}};
        case PassKind::SatRows:
        case PassKind::SatColumns: return {"sat.comp", "", {}};
        case PassKind::SatResolve: return {"sat_resolve.comp", "", {}};
        case PassKind::Lighting: return {"scene.vert", "lighting.frag", defines};
    }
    throw std::logic_error("no program for this pass");
}

const PlannedTexture* PassPlan::texture(int light, TextureRole role, int cascade) const {
    for (const auto& t : textures)
        if (t.light == light && t.role == role && t.cascade == cascade) return &t;
    return nullptr;
}

size_t PassPlan::bytes(int light, int cascade) const {
    size_t sum = 0;
    for (const auto& t : textures)
        if (t.light >= 0 && (light < 0 || t.light == light) && (cascade < 0 || t.cascade == cascade))
            sum += t.bytes;
    return sum;
}

int PassPlan::cascadeCount(int light) const {
    int n = 0;
    for (const PlannedCascade& c : cascades) n += c.light == light;
    return std::max(n, 1);
}

namespace {

PlannedTexture tex(int light, int camera, TextureRole role, std::string format, unsigned gl,
                   int w, int h, int layers, int bytesPerTexel) {
    return {light, camera, role, std::move(format), gl, w, h, layers,
            size_t(w) * h * layers * bytesPerTexel};
}

}  // namespace

namespace {

// The maps and passes of light i (its cascade c: every cascade has a full set of its own).
void planLightMaps(PassPlan& plan, int i, int c, const std::string& light,
                   const PlanOptions& options) {
    const ShadowEffect& fx = plan.effect;
    const TechniqueRow& row = *plan.row;
    const MapLayout& map = plan.map;
    const int n = fx.mapSize;
    const bool filterPasses = !row.filterInLighting;
    auto add = [&](PlannedTexture t) {
        t.cascade = c;
        plan.textures.push_back(std::move(t));
    };
    auto pass = [&](PassKind kind, std::string why, TextureRole writes) {
        PlannedPass p;
        p.kind = kind;
        p.light = i;
        p.why = std::move(why);
        p.writes = writes;
        p.cascade = c;
        plan.passes.push_back(std::move(p));
    };
    add(tex(i, -1, TextureRole::Depth, "DEPTH32F", GL_DEPTH_COMPONENT32F, n, n, 1, 4));
    add(tex(i, -1, TextureRole::Raw, map.formatName, map.glFormat, n, n, map.layers, map.bytesPerTexel));
    pass(PassKind::Shadow, light + " casts shadows; stores " + row.stored, TextureRole::Raw);
    if (row.secondDepth) {
        add(tex(i, -1, TextureRole::Second, "R32F", GL_R32F, n, n, 1, 4));
        pass(PassKind::ShadowSecond, "second-depth: peel the first surface, store the midpoint",
             TextureRole::Second);
    }
    if (!filterPasses || fx.filter == FilterKind::None) return;
    // The filter stages take RGBA32F layers (the stage contract): a 16-bit map is widened first.
    auto rgba32f = [&](TextureRole role) {
        add(tex(i, -1, role, "RGBA32F", GL_RGBA32F, n, n, map.layers, 16));
    };
    if (map.glFormat != GL_RGBA32F) {
        rgba32f(TextureRole::Wide);
        pass(PassKind::Widen, map.formatName + " map into RGBA32F for the filter stages",
             TextureRole::Wide);
    }
    if (fx.filter == FilterKind::Gaussian) {
        const std::string why = "gaussian filter, radius " + std::to_string(fx.gaussianRadius);
        rgba32f(TextureRole::Scratch);
        rgba32f(TextureRole::Filtered);
        pass(PassKind::GaussianX, why, TextureRole::Scratch);
        pass(PassKind::GaussianY, why, TextureRole::Filtered);
        return;
    }
    char why[128];
    if (fx.satPerPixel)
        std::snprintf(why, sizeof why,
                      "sat filter, per-pixel kernel (satKernelTexels: search <= %.2f, box 1-%.2f "
                      "texels)", fx.satKernelTexels, fx.satMaxKernelTexels);
    else
        std::snprintf(why, sizeof why, "sat filter, kernel %.2f texels", fx.satKernelTexels);
    // The table has two texels per entry (satTableWidth).
    for (TextureRole role : {TextureRole::Scratch, TextureRole::Sat})
        add(tex(i, -1, role, "RGBA32F", GL_RGBA32F, satTableWidth(n), n, map.layers, 16));
    pass(PassKind::SatRows, why, TextureRole::Scratch);
    pass(PassKind::SatColumns, why, TextureRole::Sat);
    if (options.resolveSat) {
        rgba32f(TextureRole::Filtered);
        pass(PassKind::SatResolve, "filtered map requested as output", TextureRole::Filtered);
    }
}

// Cascades of light i: its own count for a directional light that declares them (and a scene
// with a camera to fit them to), else 1.
int cascadeCount(const Scene& scene, int i) {
    const Light& l = scene.lights[i];
    return l.type == LightType::Directional && !scene.cameras.empty() ? l.cascades : 1;
}

// Why the scene's filter changes no image, or "" if it does: a Gaussian of radius 0 is one
// tap of weight 1, the map itself to the bit. A SAT box of one texel is not left out: it is
// the bilinear read lighting makes without a filter in exact arithmetic, but llvmpipe weighs
// a bilinear read with 8 bits, and 4MSM turns that into G up to 0.9 apart at shadow edges
// (a 1-texel box on the softness ladder's scene: 5 % of its pixels), so the table stays.
std::string identityFilter(const ShadowEffect& fx) {
    if (techniqueRow(fx.technique).filterInLighting) return "";
    if (fx.filter == FilterKind::Gaussian && fx.gaussianRadius == 0)
        return "gaussian filter of radius 0 (one tap of weight 1): no filter passes";
    return "";
}

// Fills each pass's program and the roles it reads, from what the plan allocated: a filter
// reads the widened copy where there is one; lighting samples the filter's output, else the
// raw map (and the second-depth midpoint).
void describePasses(PassPlan& plan) {
    std::set<std::pair<int, int>> slots;  // (light, cascade) with maps, as the renderer keeps them
    for (int light : plan.shadowLights) slots.insert({light, 0});
    for (const PlannedCascade& c : plan.cascades) slots.insert({c.light, c.cascade});
    std::vector<std::string> lightingDefines = plan.defines;
    lightingDefines.push_back("SL_SHADOW_SLOTS=" + std::to_string(slots.size()));
    if (plan.relativeDepth == RelativeDepth::Shown) lightingDefines.push_back("SL_RELATIVE_DEPTH_SHOWN");
    if (plan.relativeDepth == RelativeDepth::Given) lightingDefines.push_back("SL_RELATIVE_DEPTH_GIVEN");
    std::vector<TextureRole> sampled;
    if (!plan.shadowLights.empty()) {
        sampled = {TextureRole::Raw};
        if (plan.row->secondDepth) sampled.push_back(TextureRole::Second);
    }
    for (const PlannedPass& p : plan.passes)
        if (p.kind == PassKind::GaussianY) sampled = {TextureRole::Filtered};
        else if (p.kind == PassKind::SatColumns) sampled = {TextureRole::Sat};
    for (PlannedPass& p : plan.passes) {
        const bool lighting = p.kind == PassKind::Lighting;
        p.program = passProgramFor(p.kind, plan.effect.gaussianRadius,
                                   lighting ? lightingDefines : plan.defines);
        const TextureRole filterInput = plan.texture(p.light, TextureRole::Wide, p.cascade)
                                            ? TextureRole::Wide
                                            : TextureRole::Raw;
        switch (p.kind) {
            case PassKind::Shadow: p.reads = {}, p.depth = TextureRole::Depth; break;
            case PassKind::ShadowSecond:  // peels the first surface, which it reads
                p.reads = {TextureRole::Raw}, p.depth = TextureRole::Depth;
                break;
            case PassKind::Widen: p.reads = {TextureRole::Raw}; break;
            case PassKind::GaussianX:
            case PassKind::SatRows: p.reads = {filterInput}; break;
            case PassKind::GaussianY:
            case PassKind::SatColumns: p.reads = {TextureRole::Scratch}; break;
            case PassKind::SatResolve: p.reads = {TextureRole::Sat}; break;
            case PassKind::Lighting: p.reads = sampled; break;
        }
    }
}

bool anyCaster(const Scene& scene) {
    for (const Object& o : scene.objects)
        if (o.castsShadows) return true;
    return false;
}

}  // namespace

bool kernelReachesImage(const ShadowEffect& fx) {
    return fx.filter != FilterKind::None && !techniqueRow(fx.technique).blockerSearch;
}

PassPlan planPasses(const Scene& scene, const PlanOptions& options) {
    PassPlan plan;
    plan.effect = scene.shadow;
    plan.resolvedSat = options.resolveSat;
    plan.relativeDepth = options.relativeDepth;
    if (std::string why = identityFilter(scene.shadow); !why.empty()) {
        plan.effect.filter = FilterKind::None;
        plan.leftOut.push_back(why);
    }
    const ShadowEffect& fx = plan.effect;
    plan.row = &techniqueRow(fx.technique);
    plan.map = mapLayout(fx);
    const TechniqueRow& row = *plan.row;
    const MapLayout& map = plan.map;
    const bool casters = anyCaster(scene);
    std::vector<Bounds> bounds;  // only when a light has cascades (meshes are built for it)
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        if (!scene.lights[i].castsShadows) continue;
        if (!casters) {  // its map would be empty: G = 0 everywhere, as without a map
            plan.leftOut.push_back("light " + std::to_string(i) +
                                   ": no object casts shadows (every object has castsShadows "
                                   "false): no shadow map, no filter");
            continue;
        }
        plan.shadowLights.push_back(i);
        const int cascades = cascadeCount(scene, i);
        if (cascades == 1) {
            planLightMaps(plan, i, 0, "light " + std::to_string(i), options);
            continue;
        }
        if (bounds.empty()) bounds = sceneBounds(scene);
        const Light& l = scene.lights[i];
        const glm::vec2 range = cascadeRange(scene.cameras.front(), bounds);
        const std::vector<float> d =
            cascadeSplits(range.x, range.y, cascades, l.cascadeSplit, l.cascadeLambda);
        for (int c = 0; c < cascades; ++c) {
            plan.cascades.push_back({i, c, d[c], d[c + 1]});
            planLightMaps(plan, i, c,
                          "light " + std::to_string(i) + " cascade " + std::to_string(c), options);
        }
    }
    if (fx.filter == FilterKind::Sat && !row.filterInLighting && !plan.shadowLights.empty() &&
        !options.resolveSat)
        plan.leftOut.push_back("sat-resolve: the moments_filtered image is not asked for "
                               "(lighting reads the table; render --filtered-moments makes it)");
    if (!plan.shadowLights.empty()) plan.momentChannels = map.usedChannels;
    plan.defines = techniqueDefines(fx);
    for (int c = 0; c < int(scene.cameras.size()); ++c) {
        const Camera& cam = scene.cameras[c];
        std::string why = "camera '" + cam.name + "'";
        if (!plan.shadowLights.empty()) {
            why += ", " + row.name;
            if (row.filterInLighting) why += std::string(" (") + toString(fx.filter) + " kernel)";
            if (row.blockerSearch) why += " + blocker search";
        }
        plan.textures.push_back(tex(-1, c, TextureRole::Color, "RGBA32F", GL_RGBA32F, cam.width, cam.height, 1, 16));
        plan.textures.push_back(tex(-1, c, TextureRole::Shadow, "R32F", GL_R32F, cam.width, cam.height, 1, 4));
        plan.textures.push_back(tex(-1, c, TextureRole::CameraDepth, "DEPTH32F", GL_DEPTH_COMPONENT32F,
                                    cam.width, cam.height, 1, 4));
        PlannedPass lighting;
        lighting.kind = PassKind::Lighting;
        lighting.camera = c;
        lighting.why = why;
        lighting.writes = TextureRole::Color;
        lighting.depth = TextureRole::CameraDepth;
        plan.passes.push_back(std::move(lighting));
    }
    describePasses(plan);
    return plan;
}

namespace {

// "      program scene.vert + techniques/store.frag [SL_TECH_MSM4]; reads -; writes raw, depth"
std::string programAndRoles(const PlannedPass& p) {
    std::string out = "        program " + p.program.vertexOrCompute;
    if (!p.program.fragment.empty()) out += " + " + p.program.fragment;
    if (!p.program.defines.empty()) {
        out += " [";
        for (size_t i = 0; i < p.program.defines.size(); ++i) out += (i ? " " : "") + p.program.defines[i];
        out += "]";
    }
    out += "; reads ";
    if (p.reads.empty()) out += "-";
    for (size_t i = 0; i < p.reads.size(); ++i) out += std::string(i ? ", " : "") + toString(p.reads[i]);
    out += std::string("; writes ") + toString(p.writes);
    if (p.kind == PassKind::Lighting) out += std::string(", ") + toString(TextureRole::Shadow);
    if (p.depth) out += std::string(", ") + toString(*p.depth);
    return out + "\n";
}

}  // namespace

std::string explainPlan(const Scene& scene, const PassPlan& plan,
                        const std::vector<double>* millis, const std::string& unit) {
    std::string out = "plan for " + scene.name + " (" + std::to_string(plan.passes.size()) +
                      " passes, technique " + toString(plan.effect.technique) + ", filter " +
                      toString(plan.effect.filter) + ", moments " +
                      std::to_string(plan.momentChannels) + " channels):\n";
    const auto params = resolvedParameters(plan.effect);
    if (!params.empty()) {
        out += "  parameters:";
        for (const auto& [name, value] : params) {
            char buf[96];
            std::snprintf(buf, sizeof buf, " %s=%g", name.c_str(), value);
            out += buf;
        }
        out += "\n";
    }
    for (const PlannedCascade& c : plan.cascades) {
        const PlannedTexture* raw = plan.texture(c.light, TextureRole::Raw, c.cascade);
        char buf[192];
        std::snprintf(buf, sizeof buf,
                      "  light %d cascade %d: camera depth %.3g to %.3g, map %d² %s, %.2f MiB\n",
                      c.light, c.cascade, c.nearDepth, c.farDepth, raw ? raw->width : 0,
                      raw ? raw->format.c_str() : "?", plan.bytes(c.light, c.cascade) / 1048576.0);
        out += buf;
    }
    double total = 0.0;
    for (size_t i = 0; i < plan.passes.size(); ++i) {
        const PlannedPass& p = plan.passes[i];
        const PlannedTexture* t = nullptr;
        for (const auto& candidate : plan.textures)
            if (candidate.role == p.writes &&
                (p.light >= 0 ? candidate.light == p.light && candidate.cascade == p.cascade
                              : candidate.camera == p.camera))
                t = &candidate;
        char fmt[48] = "";
        if (t)
            std::snprintf(fmt, sizeof fmt, "%s%s %7.2f MiB", t->format.c_str(),
                          t->layers > 1 ? ("×" + std::to_string(t->layers)).c_str() : "",
                          t->bytes / 1048576.0);
        char line[384];
        std::snprintf(line, sizeof line, "  %2zu. %-13s %-22s %-40s", i + 1, toString(p.kind), fmt,
                      p.why.c_str());
        out += line;
        if (millis && i < millis->size()) {
            std::snprintf(line, sizeof line, " %9.2f %s", (*millis)[i], unit.c_str());
            out += line;
            total += (*millis)[i];
        }
        out += "\n" + programAndRoles(p);
    }
    for (const std::string& why : plan.leftOut) out += "  left out: " + why + "\n";
    char line[96];
    std::snprintf(line, sizeof line, "  shadow-map memory %.2f MiB\n", plan.bytes() / 1048576.0);
    out += line;
    if (millis) {
        std::snprintf(line, sizeof line, "  total %44.2f %s\n", total, unit.c_str());
        out += line;
    }
    return out;
}

}  // namespace sl
