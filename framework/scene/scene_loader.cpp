// scene_loader: reads a scene JSON file (format: docs/scenes.md) into sl::Scene and validates
// every value on the way. A scene is hand-written by instructors and students, so every
// mistake must come back as one clear line:
//   "<file>: <json pointer>: expected <what>, found <what was there, or nothing>".
// Unknown keys are errors (they are almost always typos), and so is invalid JSON, reported
// as "<file>:<line>:<column>: invalid JSON ...".
#include "scene.h"
#include "scene_json.h"
#include "scene_limits.h"
#include "technique.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace sl {
namespace {

using namespace scene_json;

// The names the file uses for the enums, in the order of their values.
const std::vector<std::string> kLightTypes = {"spot", "directional"};
const std::vector<std::string> kCascadeSplits = {"uniform", "logarithmic", "practical"};
const std::vector<std::string> kShapes = {"plane", "box", "sphere", "cylinder", "torus", "mesh"};
const std::vector<std::string> kFilters = {"none", "gaussian", "sat"};

Camera readCamera(const Reader& R, const Node& n, bool nameRequired) {
    R.object(n, {"name", "position", "target", "up", "fovYDegrees", "near", "far", "width", "height"},
             "a camera");
    Camera c;
    if (nameRequired || n["name"]) c.name = R.string(n["name"], true);
    c.position = R.vec3(n["position"], Range::any());
    c.target = R.vec3(n["target"], Range::any());
    if (auto u = n["up"]) c.up = R.vec3(u, Range::any());
    if (auto f = n["fovYDegrees"]) c.fovYDegrees = float(R.number(f, Range::open(0, 180)));
    if (auto v = n["near"]) c.nearPlane = float(R.number(v, Range::positive()));
    if (auto v = n["far"]) c.farPlane = float(R.number(v, Range{c.nearPlane, kInf, true, false}));
    if (c.farPlane <= c.nearPlane)
        R.fail(n["near"], "a number < far (" + formatNumber(c.farPlane) + ")");
    if (auto v = n["width"]) c.width = R.integer(v, Range::closed(16, 4096));
    if (auto v = n["height"]) c.height = R.integer(v, Range::closed(16, 4096));
    const glm::vec3 forward = c.target - c.position;
    if (glm::length(forward) < 1e-6f)
        R.fail(n["target"], "a point different from the position");
    if (glm::length(glm::cross(glm::normalize(forward), c.up)) < 1e-3f)
        R.fail(n["up"], "an up vector not parallel to the viewing direction (default [0, 1, 0])");
    return c;
}

Light readLight(const Reader& R, const Node& n) {
    if (!n || !n.v->is_object()) R.fail(n, "an object (a light)");
    Light l;
    l.type = LightType(R.choice(n["type"], kLightTypes));
    const bool spot = l.type == LightType::Spot;
    std::vector<std::string> keys = {"type", "position", "target", "color", "intensity", "size",
                                     "castsShadows"};
    if (spot) keys.push_back("coneDegrees");
    else keys.insert(keys.end(), {"extent", "cascades", "cascadeSplit", "cascadeLambda"});
    R.object(n, keys, spot ? "a spot light" : "a directional light");
    l.position = R.vec3(n["position"], Range::any());
    l.target = R.vec3(n["target"], Range::any());
    if (glm::length(l.target - l.position) < 1e-6f)
        R.fail(n["target"], "a point different from the position");
    if (auto v = n["color"]) l.color = R.vec3(v, Range::atLeast(0));
    if (auto v = n["intensity"]) l.intensity = float(R.number(v, Range::atLeast(0)));
    if (auto v = n["size"]; v && v.v->is_array()) {  // [w, h]: a rectangular emitter
        if (v.v->size() != 2) R.fail(v, "a number >= 0 (disk diameter) or [width, height]");
        l.rectangle = {float(R.number(v[size_t(0)], Range::positive())),
                       float(R.number(v[size_t(1)], Range::positive()))};
        l.size = std::max(l.rectangle.x, l.rectangle.y);
    } else if (v) {
        l.size = float(R.number(v, Range::atLeast(0)));
    }
    if (auto v = n["castsShadows"]) l.castsShadows = R.boolean(v);
    if (auto v = n["coneDegrees"]) l.coneDegrees = float(R.number(v, Range::open(0, 170)));
    if (auto v = n["extent"]) l.extent = float(R.number(v, Range::positive()));
    if (auto v = n["cascades"]) l.cascades = R.integer(v, Range::closed(1, kMaxCascades));
    if (auto v = n["cascadeSplit"]) l.cascadeSplit = CascadeSplit(R.choice(v, kCascadeSplits));
    if (auto v = n["cascadeLambda"]) {
        l.cascadeLambda = float(R.number(v, Range::closed(0, 1)));
        if (l.cascadeSplit != CascadeSplit::Practical)
            R.fail(v, "no cascadeLambda unless cascadeSplit is \"practical\" (the default)");
    }
    return l;
}

// "size" of a plane: [width (x), depth (z)] or one number for a square; of a box: [x, y, z]
// or one number for a cube.
glm::vec3 readSize(const Reader& R, const Node& n, int components) {
    const std::string what = components == 2 ? "a number > 0 or an array of 2 numbers > 0"
                                             : "a number > 0 or an array of 3 numbers > 0";
    if (n && n.v->is_number()) return glm::vec3(float(R.number(n, Range::positive())));
    if (!n || !n.v->is_array() || int(n.v->size()) != components) R.fail(n, what);
    glm::vec3 s(0.0f);
    for (int i = 0; i < components; ++i) s[i] = float(R.number(n[size_t(i)], Range::positive()));
    return s;
}

Object readObject(const Reader& R, const Node& n, size_t index) {
    if (!n || !n.v->is_object()) R.fail(n, "an object (a scene object)");
    Object o;
    o.shape = ShapeType(R.choice(n["shape"], kShapes));
    const std::string shape = toString(o.shape);
    std::vector<std::string> keys = {"name", "shape", "translate", "rotateDegrees", "scale",
                                     "color", "specular", "shininess", "castsShadows"};
    switch (o.shape) {
        case ShapeType::Plane:
        case ShapeType::Box: keys.push_back("size"); break;
        case ShapeType::Sphere: keys.push_back("radius"); break;
        case ShapeType::Cylinder: keys.insert(keys.end(), {"radius", "height"}); break;
        case ShapeType::Torus: keys.insert(keys.end(), {"majorRadius", "minorRadius"}); break;
        case ShapeType::Mesh: keys.push_back("path"); break;
    }
    R.object(n, keys, "a " + shape);
    o.name = n["name"] ? R.string(n["name"], true) : shape + std::to_string(index);

    switch (o.shape) {
        case ShapeType::Plane: {
            glm::vec3 s = readSize(R, n["size"], 2);
            o.planeSize = {s.x, s.y};
            break;
        }
        case ShapeType::Box: o.boxSize = readSize(R, n["size"], 3); break;
        case ShapeType::Sphere: o.radius = float(R.number(n["radius"], Range::positive())); break;
        case ShapeType::Cylinder:
            o.radius = float(R.number(n["radius"], Range::positive()));
            o.height = float(R.number(n["height"], Range::positive()));
            break;
        case ShapeType::Torus:
            o.majorRadius = float(R.number(n["majorRadius"], Range::positive()));
            o.minorRadius = float(R.number(n["minorRadius"], Range::positive()));
            if (o.minorRadius >= o.majorRadius)
                R.fail(n["minorRadius"], "a number < majorRadius (" +
                                             formatNumber(o.majorRadius) + ")");
            break;
        case ShapeType::Mesh: {
            const Node p = n["path"];
            const std::string written = R.string(p, true);
            namespace fs = std::filesystem;
            const fs::path full = (fs::path(R.file()).parent_path() / written).lexically_normal();
            std::error_code ec;
            if (!fs::is_regular_file(full, ec))
                R.fail(p.ptr, "the path of an OBJ file relative to the scene file's directory",
                       dumpShort(*p.v) + " (no such file: " + full.string() + ")");
            o.meshPath = full.string();
            break;
        }
    }

    if (auto v = n["translate"]) o.translate = R.vec3(v, Range::any());
    if (auto v = n["rotateDegrees"]) o.rotateDegrees = R.vec3(v, Range::any());
    if (auto v = n["scale"]) {
        // Positive only: a mirroring scale would turn the winding inside out.
        o.scale = v.v->is_number() ? glm::vec3(float(R.number(v, Range::positive())))
                                   : R.vec3(v, Range::positive());
    }
    if (auto v = n["color"]) o.color = R.vec3(v, Range::atLeast(0));
    if (auto v = n["specular"]) o.specular = float(R.number(v, Range::atLeast(0)));
    if (auto v = n["shininess"]) o.shininess = float(R.number(v, Range::closed(1, 10000)));
    if (auto v = n["castsShadows"]) o.castsShadows = R.boolean(v);
    return o;
}

void readFilter(const Reader& R, const Node& n, ShadowEffect& fx) {
    if (!n || !n.v->is_object()) R.fail(n, "an object such as {\"type\": \"gaussian\", \"radius\": 4}");
    fx.filter = FilterKind(R.choice(n["type"], kFilters));
    switch (fx.filter) {
        case FilterKind::None: R.object(n, {"type"}, "filter \"none\""); break;
        case FilterKind::Gaussian:
            R.object(n, {"type", "radius", "sigma"}, "filter \"gaussian\"");
            if (auto v = n["radius"]) fx.gaussianRadius = R.integer(v, Range::closed(0, 64));
            fx.gaussianSigma = 0.5f * float(fx.gaussianRadius);
            if (auto v = n["sigma"]) fx.gaussianSigma = float(R.number(v, Range::positive()));
            break;
        case FilterKind::Sat: {
            // The box may not be wider than the map it averages.
            const Node k = n["kernel"];
            fx.satPerPixel = k && k.v->is_string() && k.v->get<std::string>() == "per-pixel";
            if (!fx.satPerPixel) {
                R.object(n, {"type", "kernel"}, "filter \"sat\" with a fixed kernel");
                if (k && !k.v->is_number())
                    R.fail(k, "a box width in texels in [1, " + std::to_string(fx.mapSize) +
                                  "] or \"per-pixel\"");
                if (k) fx.satKernelTexels = float(R.number(k, Range::closed(1, fx.mapSize)));
                break;
            }
            // Per pixel: the solution's satKernelTexels chooses each box (msm4's lighting).
            R.object(n, {"type", "kernel", "searchTexels", "maxKernelTexels"},
                     "filter \"sat\" with kernel \"per-pixel\"");
            fx.satKernelTexels = 32.0f;
            if (auto v = n["searchTexels"])
                fx.satKernelTexels = float(R.number(v, Range::closed(1, fx.mapSize)));
            if (auto v = n["maxKernelTexels"])
                fx.satMaxKernelTexels = float(R.number(v, Range::closed(1, fx.mapSize)));
            if (!techniqueRow(fx.technique).perPixelSat)
                R.fail(k, "a box width in texels: \"per-pixel\" is the msm4 technique's (its "
                          "lighting asks sat_lookup.glsl's satKernelTexels), not " +
                              std::string(toString(fx.technique)) + "'s");
            break;
        }
    }
}

// `perspective`: a spot light casts shadows, whose projection needs an explicit near > 0.
ShadowEffect readShadow(const Reader& R, const Node& n, bool perspective) {
    R.object(n, {"technique", "mapSize", "depthRange", "filter", "momentBias", "depthBias",
                 "parameters"},
             "the shadow effect");
    ShadowEffect fx;
    if (auto v = n["technique"]) fx.technique = Technique(R.choice(v, techniqueNames()));
    if (auto v = n["mapSize"]) {
        const int size = R.integer(v, Range::closed(64, 4096));
        if (size & (size - 1)) R.fail(v, "a power of two in [64, 4096]");
        fx.mapSize = size;
    }
    if (auto v = n["depthRange"]) {
        const std::string what = "\"auto\" or an array [near, far] with 0 <= near < far";
        if (v.v->is_string() && v.v->get<std::string>() == "auto") {
            fx.depthRange.reset();
        } else {
            if (!v.v->is_array() || v.v->size() != 2) R.fail(v, what);
            const double nearD =
                perspective ? R.number(v[0], Range::positive()) : R.number(v[0], Range::atLeast(0));
            const double farD = R.number(v[1], Range{nearD, kInf, true, false});
            fx.depthRange = glm::vec2(float(nearD), float(farD));
            if (!(fx.depthRange->y > fx.depthRange->x))  // distinct doubles, one float
                R.fail(v[1], "a number > near that stays > near as a 32-bit float");
        }
    }
    if (auto v = n["filter"]) readFilter(R, v, fx);
    if (auto v = n["momentBias"]) fx.momentBias = float(R.number(v, Range::closed(0, 0.1)));
    if (auto v = n["depthBias"]) fx.depthBias = float(R.number(v, Range::closed(0, 0.1)));
    // The technique's row checks its filter and parameters (technique.h).
    validateTechnique(fx, bool(n["filter"]), n["parameters"].v, R.file(), n.ptr);
    return fx;
}

ShadowProbe readProbe(const Reader& R, const Node& n, const std::vector<Camera>& cameras) {
    R.object(n, {"camera", "pixel", "shadow", "tolerance", "why"}, "a probe");
    ShadowProbe p;
    p.camera = cameras.front().name;
    const Camera* camera = &cameras.front();
    if (auto v = n["camera"]) {
        std::vector<std::string> names;
        for (const Camera& c : cameras) names.push_back(c.name);
        camera = &cameras[size_t(R.choice(v, names))];
        p.camera = camera->name;
    }
    const Node px = n["pixel"];
    if (!px || !px.v->is_array() || px.v->size() != 2)
        R.fail(px, "an array [x, y] of 2 integers (y = 0 is the top row)");
    p.pixel.x = R.integer(px[0], Range::closed(0, camera->width - 1));
    p.pixel.y = R.integer(px[1], Range::closed(0, camera->height - 1));
    p.shadow = float(R.number(n["shadow"], Range::closed(0, 1)));
    if (auto v = n["tolerance"]) p.tolerance = float(R.number(v, Range{0, 1, true, false}));
    p.why = R.string(n["why"], true);
    return p;
}

// nlohmann reports the 1-based index of the last character it read; turn it into line:column.
std::string lineColumn(const std::string& text, size_t byte) {
    const size_t at = std::min(byte > 0 ? byte - 1 : 0, text.size());
    size_t line = 1, lineStart = 0;
    for (size_t i = 0; i < at; ++i)
        if (text[i] == '\n') ++line, lineStart = i + 1;
    return std::to_string(line) + ":" + std::to_string(at - lineStart + 1);
}

// nlohmann's message without its "[json.exception.parse_error.101] " tag, nor the
// "parse error at line L, column C: " that we compute ourselves.
std::string parseDetail(std::string what) {
    const size_t tag = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && tag != std::string::npos) what.erase(0, tag + 2);
    const size_t colon = what.find(": ");
    if (what.rfind("parse error", 0) == 0 && colon != std::string::npos) what.erase(0, colon + 2);
    return what;
}

// Arrays and objects nested deeper than this are refused before nlohmann sees them: its
// dump() (used in error messages) recurses once per level, and 100 000 levels overflow the
// stack. A scene needs 4.
constexpr int kMaxJsonDepth = 64;

void checkDepth(const std::string& text, const std::string& path) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) {
                const std::string lc = lineColumn(text, i + 1);
                throw SceneError(path + ":" + lc + ": invalid scene: arrays and objects nested more "
                                 "than " + std::to_string(kMaxJsonDepth) + " deep");
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// The textures lighting samples: per shadowing light, per cascade, the map's layers (and the
// second-depth map). Over kMaxShadowMaps the scene is refused here, not by the renderer.
void checkMapCount(const Reader& R, const Node& lights, const Scene& s) {
    const TechniqueRow& row = techniqueRow(s.shadow.technique);
    const int perSlot = mapLayout(s.shadow).layers + (row.secondDepth ? 1 : 0);
    int maps = 0;
    for (const Light& l : s.lights)
        if (l.castsShadows) maps += perSlot * (l.type == LightType::Directional ? l.cascades : 1);
    if (maps > kMaxShadowMaps)
        R.fail(lights.ptr,
               "at most " + std::to_string(kMaxShadowMaps) + " shadow maps in all (the lighting "
               "pass's limit; technique \"" + row.name + "\" takes " + std::to_string(perSlot) +
               " per light and cascade)",
               std::to_string(maps));
}

}  // namespace

Scene parseScene(const std::string& jsonText, const std::string& path) {
    checkDepth(jsonText, path);
    json root;
    try {
        root = json::parse(jsonText);
    } catch (const json::parse_error& e) {
        const std::string lc = lineColumn(jsonText, e.byte);
        const size_t colon = lc.find(':');
        throw SceneError(path + ":" + lc + ": invalid JSON at line " + lc.substr(0, colon) +
                         ", column " + lc.substr(colon + 1) + ": " + parseDetail(e.what()));
    } catch (const json::exception& e) {  // e.g. a number too large for a double
        throw SceneError(path + ": invalid JSON: " + parseDetail(e.what()));
    }

    const Reader R(path);
    const Node r{&root, ""};
    R.object(r, {"description", "camera", "cameras", "lights", "objects", "shadow", "ambient",
                 "background", "expect"},
             "a scene");
    Scene s;
    s.path = path;
    s.name = std::filesystem::path(path).stem().string();
    if (auto v = r["description"]) s.description = R.string(v);

    // Cameras: "camera" (one, named "main") or "cameras" (named; the first is the main one).
    if (r["camera"] && r["cameras"])
        R.fail(r["cameras"], "nothing when \"camera\" is given (use one or the other)");
    if (auto v = r["cameras"]) {
        const size_t count = R.array(v, 1, "a non-empty array of cameras");
        std::set<std::string> names;
        for (size_t i = 0; i < count; ++i) {
            s.cameras.push_back(readCamera(R, v[i], true));
            if (!names.insert(s.cameras.back().name).second)
                R.fail(v[i]["name"], "a camera name not used before");
        }
    } else {
        if (!r["camera"])
            R.fail(r["camera"], "an object (the camera), or \"cameras\": an array of them");
        s.cameras.push_back(readCamera(R, r["camera"], false));
    }

    if (auto v = r["lights"]) {
        const size_t count = R.array(v, 0, "an array of lights (it may be empty)");
        if (count > size_t(kMaxLights))
            R.fail(v.ptr, "at most " + std::to_string(kMaxLights) + " lights (the lighting pass's limit)",
                   std::to_string(count));
        for (size_t i = 0; i < count; ++i) s.lights.push_back(readLight(R, v[i]));
    }
    const Node objects = r["objects"];
    const size_t count = R.array(objects, 1, "a non-empty array of objects");
    for (size_t i = 0; i < count; ++i) s.objects.push_back(readObject(R, objects[i], i));

    const bool spot = std::any_of(s.lights.begin(), s.lights.end(), [](const Light& l) {
        return l.castsShadows && l.type == LightType::Spot;
    });
    if (auto v = r["shadow"]) s.shadow = readShadow(R, v, spot);
    checkMapCount(R, r["lights"], s);
    if (auto v = r["ambient"]) s.ambient = R.vec3(v, Range::atLeast(0));
    if (auto v = r["background"]) s.background = R.vec3(v, Range::atLeast(0));

    if (auto e = r["expect"]) {
        R.object(e, {"probes"}, "the expectations");
        const Node probes = e["probes"];
        const size_t n = R.array(probes, 0, "an array of probes");
        for (size_t i = 0; i < n; ++i) s.probes.push_back(readProbe(R, probes[i], s.cameras));
    }
    return s;
}

Scene loadScene(const std::string& path) {
    // A regular file, checked on the open descriptor: O_NONBLOCK so that a FIFO cannot block
    // the open; a directory or a device is named as what it is, not as "invalid JSON".
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw SceneError(path + ": expected a readable scene file, found nothing (" +
                         std::string(std::strerror(errno)) + ")");
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        const char* what = S_ISDIR(st.st_mode) ? "a directory" : S_ISFIFO(st.st_mode) ? "a FIFO"
                           : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                           : S_ISSOCK(st.st_mode) ? "a socket" : "not a regular file";
        throw SceneError(path + ": expected a scene file (JSON), found " + std::string(what));
    }
    constexpr off_t kMaxSceneBytes = 64 << 20;
    if (st.st_size > kMaxSceneBytes) {
        ::close(fd);
        throw SceneError(path + ": expected a scene file of at most 64 MiB, found " +
                         std::to_string(st.st_size) + " bytes");
    }
    std::string text;
    char buf[65536];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0 && off_t(text.size()) <= kMaxSceneBytes)
        text.append(buf, size_t(n));
    ::close(fd);
    return parseScene(text, path);
}

// Switches, not the tables above: these may be called during other files' static setup.
const char* toString(LightType t) {
    switch (t) {
        case LightType::Spot: return "spot";
        case LightType::Directional: return "directional";
    }
    return "?";
}
const char* toString(ShapeType t) {
    switch (t) {
        case ShapeType::Plane: return "plane";
        case ShapeType::Box: return "box";
        case ShapeType::Sphere: return "sphere";
        case ShapeType::Cylinder: return "cylinder";
        case ShapeType::Torus: return "torus";
        case ShapeType::Mesh: return "mesh";
    }
    return "?";
}
const char* toString(FilterKind f) {
    switch (f) {
        case FilterKind::None: return "none";
        case FilterKind::Gaussian: return "gaussian";
        case FilterKind::Sat: return "sat";
    }
    return "?";
}
// toString(Technique): the technique table's name (technique.cpp).

}  // namespace sl
