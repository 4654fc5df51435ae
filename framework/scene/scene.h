// Scene: the in-memory form of a scene JSON file (format: docs/scenes.md).
// Loading and validation live in scene_loader.cpp; geometry in mesh.h.
#pragma once

#include <glm/glm.hpp>

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

// A scene file that does not validate. what() reads
// "<file>: <json path>: expected <what>, found <what>".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Camera {
    std::string name = "main";
    glm::vec3 position{0.0f, 2.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    int width = 512;
    int height = 512;
};

enum class LightType { Spot, Directional };

// How a directional light's cascades cut the camera's view range (cascades.h).
enum class CascadeSplit { Uniform, Logarithmic, Practical };

struct Light {
    LightType type = LightType::Spot;
    glm::vec3 position{0.0f, 5.0f, 0.0f};  // spot: the light; directional: eye of its shadow frustum
    glm::vec3 target{0.0f};                // spot: aimed at; directional: direction = target - position
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float coneDegrees = 60.0f;    // spot: full opening angle of the cone (and of its shadow frustum)
    float extent = 10.0f;         // directional: half-width of the orthographic shadow frustum
    float size = 0.0f;            // world-space size of the emitter, for soft shadows (0: point)
    glm::vec2 rectangle{0.0f};    // "size": [w, h]: a w × h rectangular emitter (size = max);
                                  // else a disk of diameter `size` (truth/, docs/scenes.md)
    bool castsShadows = true;
    // Directional: cascaded shadow maps, one map per slice of the first camera's view range
    // (1 = a single map over `extent`); the slices follow `cascadeSplit` (practical: the
    // blend λ·logarithmic + (1 − λ)·uniform, λ = `cascadeLambda`). See cascades.h.
    int cascades = 1;
    CascadeSplit cascadeSplit = CascadeSplit::Practical;
    float cascadeLambda = 0.5f;
};

enum class ShapeType { Plane, Box, Sphere, Cylinder, Torus, Mesh };

struct Object {
    std::string name;
    ShapeType shape = ShapeType::Box;
    // Shape parameters (which ones apply depends on shape; see docs/scenes.md).
    glm::vec2 planeSize{10.0f, 10.0f};
    glm::vec3 boxSize{1.0f};
    float radius = 0.5f;          // sphere, cylinder
    float height = 1.0f;          // cylinder
    float majorRadius = 0.5f;     // torus
    float minorRadius = 0.2f;     // torus
    std::string meshPath;         // OBJ; the loader has resolved it against the scene file's
                                  // directory, so it opens as is
    // Placement: scale, then rotate (degrees about x, then y, then z), then translate.
    glm::vec3 translate{0.0f};
    glm::vec3 rotateDegrees{0.0f};
    glm::vec3 scale{1.0f};
    // Material: Blinn-Phong.
    glm::vec3 color{0.8f};
    float specular = 0.1f;
    float shininess = 32.0f;
    bool castsShadows = true;
};

// The shadow technique: the index of a row of the technique table (technique.h), which names
// it; techniqueFromName("pcf") finds one. The default is msm4, the student stages' row.
enum class Technique : int {};
// Throws std::invalid_argument listing the names if `name` is not a row.
Technique techniqueFromName(const std::string& name);
enum class FilterKind { None, Gaussian, Sat };

struct ShadowEffect {
    Technique technique = techniqueFromName("msm4");
    int mapSize = 1024;
    std::optional<glm::vec2> depthRange;  // (near, far); empty: derived from the scene bounds
    FilterKind filter = FilterKind::Gaussian;
    int gaussianRadius = 4;               // taps: 2r + 1
    float gaussianSigma = 0.0f;           // 0: radius / 2
    float satKernelTexels = 9.0f;         // box width in texels, fractional allowed
    // "kernel": "per-pixel": each pixel's box from the solution's satKernelTexels (msm4).
    // satKernelTexels is then the search box's largest width (and the filtered-moments image's).
    bool satPerPixel = false;
    float satMaxKernelTexels = 64.0f;     // per-pixel: the largest filter box, texels
    float momentBias = 3.0e-5f;           // α
    float depthBias = 0.0f;               // subtracted from the fragment's relative depth
    // The technique's own parameters as the scene gives them (`shadow.parameters`); the
    // table's defaults fill the rest (techniqueParameter in technique.h).
    std::map<std::string, double> parameters;
};

// A pixel of the shadow image whose intensity the scene's author knows, so that a test can
// check a render without a golden image (Nori's "test scenes carry their expected values").
struct ShadowProbe {
    std::string camera = "main";
    glm::ivec2 pixel{0};  // (x, y), y = 0 is the top row of the PNG
    float shadow = 0.0f;  // expected G
    float tolerance = 0.05f;
    std::string why;      // the author's reasoning
};

struct Scene {
    std::string path;         // file it was loaded from
    std::string name;         // file stem
    std::string description;
    std::vector<Camera> cameras;  // at least one; the first is "main"
    std::vector<Light> lights;
    std::vector<Object> objects;
    ShadowEffect shadow;
    glm::vec3 ambient{0.15f};
    glm::vec3 background{0.05f, 0.06f, 0.08f};
    std::vector<ShadowProbe> probes;
};

// Reads and validates a scene file. Throws SceneError.
Scene loadScene(const std::string& path);
// The same, from JSON text; `path` is used in messages and to resolve mesh files.
Scene parseScene(const std::string& jsonText, const std::string& path);

const char* toString(LightType);
const char* toString(ShapeType);
const char* toString(FilterKind);
const char* toString(Technique);

}  // namespace sl
