// PassPlan: the passes a scene's declared effects need, in execution order — and no others —
// with every texture they allocate. The technique's row (technique.h) decides the shadow map's
// format and channels, the filter passes (none for hard, PCF, PCSS), the SAT, the second-depth
// pass and the lighting permutation. A scene with no shadowing light has no shadow pass and no
// map; a filter of `none` dispatches nothing; a light's map is rendered once for all cameras.
// Each pass carries its program (files and permutation) and the texture roles it reads and
// writes: the renderer compiles and binds what the pass names, it does not re-decide.
#pragma once

#include "scene.h"
#include "technique.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sl {

enum class PassKind {
    Shadow,        // light view: stores the technique's map (relativeDepth, computeMoments)
    ShadowSecond,  // second-depth: peels the first surface, stores the midpoint depth
    Widen,         // a 16-bit map copied into RGBA32F, the filter stages' format
    GaussianX,     // Gaussian along rows (the solution's gaussian_blur.comp), per layer
    GaussianY,     // Gaussian along columns
    SatRows,       // prefix sums along rows (the solution's sat.comp), per layer
    SatColumns,    // prefix sums along columns
    SatResolve,    // satBoxAverage at every texel: the filtered map, for output only
    Lighting,      // camera view: the technique's shadowIntensity... shades the image
};

const char* toString(PassKind);

// What a texture is for. Per light: its shadow pass's depth buffer, the technique's map (Raw),
// the second-depth midpoint, a 16-bit map widened to RGBA32F for the filters, the filters'
// first pass, the filtered map (Gaussian, or the SAT resolve), the summed-area table; per
// camera: the colour, G and depth targets.
enum class TextureRole { Depth, Raw, Second, Wide, Scratch, Filtered, Sat, Color, Shadow, CameraDepth };
// "depth", "raw", "second", "wide", "scratch", "filtered", "sat", "color", "shadow",
// "camera-depth" (--explain, render.json).
const char* toString(TextureRole);
// Width of sat.comp's table for a map `mapWidth` texels wide: two texels per entry, so that an
// entry can hold a sum exactly enough for any box (docs/stage_contract.md).
inline int satTableWidth(int mapWidth) { return 2 * mapWidth; }

struct PlannedTexture {
    int light = -1;
    int camera = -1;
    TextureRole role = TextureRole::Raw;
    std::string format;      // "RGBA32F", "R32F", "RGBA16", "DEPTH32F", ...
    unsigned glFormat = 0;
    int width = 0, height = 0;
    int layers = 1;          // textures of this role (CSM: several RGBA32F maps)
    size_t bytes = 0;        // all layers
    int cascade = 0;         // which of the light's cascades (each has its own set of maps)
};

// The program a pass runs: a compute shader alone (fragment ""), or vertex + fragment, with
// its permutation. The renderer compiles one program per description (its cache's key).
struct PassProgram {
    std::string vertexOrCompute, fragment;
    std::vector<std::string> defines;
};

// The one place that names a pass kind's files and permutation. `blurRadius`: the Gaussians'
// (a compile-time constant); `defines`: the technique's, for shadow and lighting passes (the
// lighting's with SL_SHADOW_SLOTS, planPasses adds it).
PassProgram passProgramFor(PassKind kind, int blurRadius, const std::vector<std::string>& defines);

struct PlannedPass {
    PassKind kind = PassKind::Shadow;
    int light = -1;   // index into Scene::lights (shadow and filter passes)
    int camera = -1;  // index into Scene::cameras (lighting passes)
    std::string why;  // which declared effect calls for it
    TextureRole writes = TextureRole::Raw;
    int cascade = 0;     // shadow and filter passes: which of the light's cascades
    // The light's textures the pass reads, in order (lighting: what it samples of every
    // light's maps, in unit order; a map given by the caller stands in for them).
    std::vector<TextureRole> reads;
    // The depth buffer it draws with: the light's Depth for the shadow passes, the camera's
    // for lighting (which writes G, the Shadow role, beside its colour); none for a compute pass.
    std::optional<TextureRole> depth;
    PassProgram program;  // what it runs (passProgramFor)
};

// One cascade of a directional light that declares `cascades` > 1 (cascades.h): the slice of
// the first camera's view depth it covers. Its maps are the light's textures with this
// `cascade`; the renderer fits its light view around the slice.
struct PlannedCascade {
    int light = 0;
    int cascade = 0;
    float nearDepth = 0.0f, farDepth = 0.0f;  // camera view depth, world units
};

// The msm stage's isolation (docs/grading.md): its lighting-only render must not run the
// submission's relativeDepth (moments.glsl), so it takes each fragment's zf from an image of
// the reference's.
enum class RelativeDepth {
    Computed,  // relativeDepth of the solution's moments.glsl, as every frame does
    Shown,     // computed, and written in G's place: the image "relative_depth" (no "final")
    Given,     // read from RenderInputs::relativeDepth: lighting compiles no moments.glsl
};

struct PlanOptions {
    // Make the filtered map of a SAT scene, the `moments_filtered` image (the table itself is
    // not a moment map): a SatResolve pass evaluates the solution's satBoxAverage at every
    // texel centre, with the scene's kernel. No frame needs it (lighting reads the table), and
    // it costs more than the lighting pass, so only a caller that shows or grades that image
    // asks for it: the goldens, the grader's reference render, `render --filtered-moments`,
    // the viewer while it shows that image.
    bool resolveSat = false;
    // Where lighting takes zf, each fragment's relative depth toward the first shadowing light.
    RelativeDepth relativeDepth = RelativeDepth::Computed;
};

struct PassPlan {
    // The effect the passes run: the scene's, with the filter dropped where it would change
    // nothing (a Gaussian of radius 0, a SAT box of one texel). Everything after planning
    // reads this, not the scene's.
    ShadowEffect effect;
    const TechniqueRow* row = nullptr;  // the effect's row of the technique table
    MapLayout map;                      // the effect's shadow map (mapLayout)
    std::vector<PlannedPass> passes;
    std::vector<int> shadowLights;  // lights that get a shadow map, in order
    int momentChannels = 0;         // channels the map stores in all (MSM: 4; CSM: 2M; none: 0)
    std::vector<PlannedTexture> textures;  // everything the renderer allocates, nothing else
    std::vector<std::string> defines;      // the permutation of the shadow/lighting programs
    std::vector<PlannedCascade> cascades;  // lights with cascades > 1 only, light by light
    std::vector<std::string> leftOut;      // what the scene declares but cannot see, and why
    bool resolvedSat = false;              // planned with PlanOptions::resolveSat
    RelativeDepth relativeDepth = RelativeDepth::Computed;  // PlanOptions::relativeDepth

    const PlannedTexture* texture(int light, TextureRole role, int cascade = 0) const;
    // Of one light's textures (one cascade's, or all with -1); light -1: all shadow textures.
    size_t bytes(int light = -1, int cascade = -1) const;
    int cascadeCount(int light) const;     // 1 for a light without cascades
};

PassPlan planPasses(const Scene& scene, const PlanOptions& options = {});

// Whether the filter's kernel (Gaussian radius and sigma, SAT box) reaches the lit image: not
// with the filter `none`, nor for a row that chooses its box per pixel (msm-soft). Renders
// that differ only in a kernel that does not reach the image are the same frame (the study
// renders one of them).
bool kernelReachesImage(const ShadowEffect& fx);

// The plan as text: technique and parameters, then one numbered line per pass with the format
// and memory it writes and why it runs, and under it the program it runs (files and defines)
// and the roles it reads and writes; then what it left out and why; with `millis` (one per
// pass) the cost of each, in `unit` (wall ms for a render; the cost clock's unit in a study).
std::string explainPlan(const Scene& scene, const PassPlan& plan,
                        const std::vector<double>* millis = nullptr, const std::string& unit = "ms");

}  // namespace sl
