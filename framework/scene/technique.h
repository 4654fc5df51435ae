// Technique table: every shadow technique of the kit as one row (technique_table.cpp) — what its
// shadow map stores (format, channels, layers), which filters it allows, its GLSL file, and its
// parameters with their defaults. Everything else follows from the row: the lighting and shadow
// programs include the row's file (SL_TECHNIQUE_FILE), the clear values, the map's layers, the
// permutation defines, --explain and the viewer's list. planPasses reads the row; the renderer
// never branches on a technique's name. Every row runs on the solution's stage files
// (relativeDepth, the filters, satBoxAverage, momentShadowIntensity where it reconstructs with
// Hamburger 4MSM); the assignment itself is the `msm4` row. It lives with the scene (the loader
// checks a scene's technique against its row); docs/techniques.md explains each row.
#pragma once

#include "scene.h"

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sl {

struct TechniqueParameter {
    std::string name{};       // key in shadow.parameters; the uniform is u<Name> (both passes)
    double defaultValue = 0.0;
    double min = 0.0, max = 0.0;
    bool integer = false;
    bool compileTime = false; // a #define of the permutation (SL_PARAM_<name>, e.g. CSM's terms)
    std::string meaning{};
};

// What the shadow pass (shaders/techniques/store.frag) writes per texel: one of its built-in
// stores (SL_STORE_<KIND>), or `File`: the row's own GLSL file defines techniqueStore(z)
// (compiled with SL_STORE_PASS), so that a technique with a store of its own is one file.
enum class StoreKind { Depth, Vsm, Evsm2, Evsm4, Csm, Moments4, Moments4_16bit, File };
// "DEPTH", "VSM", "EVSM2", "EVSM4", "CSM", "MOMENTS4", "MOMENTS4_16BIT", "FILE".
const char* toString(StoreKind);

// A map whose channels grow with a parameter (csm: two per Fourier term): `channels` of it
// per unit of `parameter`, packed into layers of the row's `channels`.
struct ChannelsPerParameter {
    const char* parameter = "";  // a literal (a std::string here trips GCC 12's maybe-uninitialized)
    int channels = 0;
};

using ClearValuesFn = std::vector<glm::vec4> (*)(const ShadowEffect&);
// The store of relative depth 1 on every channel (depth 1; moments (1, 1, 1, 1)): one layer.
std::vector<glm::vec4> clearToOne(const ShadowEffect&);

// Every member has a default member initializer: a row written with designated initializers
// leaves out what it does not need, and GCC's -Wmissing-field-initializers stays quiet.
struct TechniqueRow {
    Technique id{};               // its index in the table (set by techniqueTable, not written)
    std::string name{};           // the scene's shadow.technique
    std::string summary{};        // one line, for --explain and the contact sheet
    std::string stored{};         // what a texel of the map holds, in words
    int channels = 1;             // per layer
    int bitsPerChannel = 32;      // 16: UNORM16, 32: float
    ChannelsPerParameter grows{};   // empty parameter: one layer of `channels`
    std::vector<FilterKind> filters{};  // allowed; the first is the default
    bool filterInLighting = false;    // the kernel is evaluated by the lighting pass (PCF)
    bool msmStage = false;            // G comes from the solution's msm.glsl (SL_STAGE_MSM)
    bool secondDepth = false;         // a second (peeling) shadow pass stores the midpoint
    bool blockerSearch = false;       // the lighting pass searches blockers first (PCSS, msm-soft)
    // Its lighting can take a per-pixel SAT box (sat_lookup.glsl's satKernelTexels, a scene's
    // "kernel": "per-pixel", SL_SAT_PER_PIXEL); other rows keep the scene's fixed box.
    bool perPixelSat = false;
    // Under shaders/: defines shadowIntensity<X>(ShadowQuery) as SL_SHADOW_INTENSITY, and
    // techniqueStore(z) when `store` is File. The programs include it as SL_TECHNIQUE_FILE.
    std::string file{};
    StoreKind store = StoreKind::Depth;
    // What the shadow pass clears each layer to: the store of relative depth 1 ("nothing in
    // front"), the CPU mirror of the store.
    ClearValuesFn clear = clearToOne;
    std::vector<TechniqueParameter> parameters{};
    // Not empty: the row's own files solve a stage (why, in words), so the student kit leaves
    // them out and shows the row's reference image instead of rendering it.
    std::string solvesStage{};
};

// Whether this kit has the row's lighting file under `shaders` (the student kit leaves out the
// rows that solve a stage: TechniqueRow::solvesStage).
bool techniqueInKit(const TechniqueRow& row, const std::string& shaders);

// All rows; Technique is an index into it (scene.h).
const std::vector<TechniqueRow>& techniqueTable();
const TechniqueRow& techniqueRow(Technique);
std::vector<std::string> techniqueNames();
// SL_TECHNIQUE_<NAME>: the row's name in capitals, '-' as '_' (msm4-16bit: SL_TECHNIQUE_MSM4_16BIT).
std::string techniqueDefine(const TechniqueRow&);
// SL_STORE_<KIND> (toString(StoreKind)).
std::string storeDefine(const TechniqueRow&);

// The value of a parameter of the effect's technique: the scene's, else the row's default.
// Throws std::invalid_argument for a name the row does not have.
double techniqueParameter(const ShadowEffect& fx, const std::string& name);
// Every parameter of the row with its value, in the row's order.
std::vector<std::pair<std::string, double>> resolvedParameters(const ShadowEffect& fx);

// The shadow map of one light under this effect. A map that a filter stage reads is RGBA32F,
// the stage contract's format (VSM's and EVSM2's two channels then fill half of it); a 16-bit
// map stays RGBA16 and is widened to RGBA32F for its filter (pass_plan.h, PassKind::Widen).
struct MapLayout {
    unsigned glFormat = 0;      // GL internal format of one layer (GL_R32F, GL_RGBA16, ...)
    std::string formatName;     // "R32F", "RG32F", "RGBA32F", "RGBA16"
    int channels = 0;           // per layer, that the technique uses
    int layers = 0;             // textures (CSM: ceil(M / 2); others 1)
    int usedChannels = 0;       // over all layers (CSM: 2M; others `channels`)
    int bytesPerTexel = 0;      // per layer
};
MapLayout mapLayout(const ShadowEffect& fx);

// What the shadow pass clears each layer to: the row's `clear` (msm4: (1, 1, 1, 1)).
std::vector<glm::vec4> shadowClearValues(const ShadowEffect& fx);
// msm4-16bit: Peters et al.'s optimised quantisation, b -> q = Θ b + (0.0359558848, 0, 0, 0),
// and its inverse; the CPU mirror of shaders/techniques/msm4_16bit.glsl.
glm::dvec4 quantizeMoments16(const glm::dvec4& b);
glm::dvec4 dequantizeMoments16(const glm::dvec4& q);
// evsm: the warp exponents as the shaders clamp them (e^{2c} stays finite in float32).
double clampedWarpExponent(double c);

// The permutation defines of the shadow and lighting programs: the row's technique, file and
// store defines, the map's layers, compile-time parameters, SL_STAGE_MSM and the filter's.
std::vector<std::string> techniqueDefines(const ShadowEffect& fx);

// Scene loading: checks the technique against its filter and parameters, fills the row's
// default filter when the scene names none (or one the row does not allow and `filterDeclared`
// is false). `parameters` is shadow.parameters or null. Throws SceneError
// "<file>: <pointer>: expected ..., found ...".
void validateTechnique(ShadowEffect& fx, bool filterDeclared, const nlohmann::json* parameters,
                       const std::string& file, const std::string& pointer);

// Switches the effect to technique `t` (the `--technique` override): keeps the scene's filter
// if the row allows it, else takes the row's default. The scene's own technique keeps the
// scene's parameters; another starts from its row's defaults; `parameters` (checked against the
// row) are set on top. Throws std::invalid_argument with a clear message.
void overrideTechnique(ShadowEffect& fx, Technique t,
                       const std::vector<std::pair<std::string, double>>& parameters = {});
// "vsm" or "vsm:bleedReduction=0.3:minVariance=1e-4" -> technique and parameters.
std::pair<Technique, std::vector<std::pair<std::string, double>>> parseTechniqueSpec(
    const std::string& spec);

}  // namespace sl
