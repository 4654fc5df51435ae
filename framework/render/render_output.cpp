// render_output: files and sidecar of one render (see render_output.h).
#include "render_output.h"
#include "image_name.h"

#include "image_io.h"
#include "technique.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace sl {

nlohmann::json writeRenderOutputs(const Scene& scene, const PassPlan& plan,
                                  const RenderResult& result, const RenderMetadata& meta,
                                  const std::filesystem::path& outDir) {
    std::filesystem::create_directories(outDir);
    nlohmann::json files = nlohmann::json::object();
    auto record = [&](const std::string& file) {
        files[file] = sha256File(outDir / file);
    };
    for (const auto& [name, image] : result.images) {
        writeExr(image, outDir / (name + ".exr"), SampleType::Float, Compression::Fast);
        record(name + ".exr");
        if (isImage(name, ImageKind::Sat)) continue;  // sums, not viewable values
        writePngPreview(image, outDir / (name + ".png"), isImage(name, ImageKind::Final));
        record(name + ".png");
    }
    nlohmann::json passes = nlohmann::json::array();
    for (size_t i = 0; i < plan.passes.size(); ++i)
        passes.push_back({{"pass", toString(plan.passes[i].kind)},
                          {"why", plan.passes[i].why},
                          {"milliseconds", i < result.passMillis.size() ? result.passMillis[i]
                                                                        : 0.0}});
    nlohmann::json parameters = nlohmann::json::object();
    for (const auto& [name, value] : resolvedParameters(scene.shadow)) parameters[name] = value;
    nlohmann::json maps = nlohmann::json::array();
    for (const PlannedTexture& t : plan.textures)
        if (t.light >= 0) {
            maps.push_back({{"light", t.light}, {"role", toString(t.role)}, {"format", t.format},
                            {"width", t.width}, {"height", t.height}, {"layers", t.layers},
                            {"bytes", t.bytes}});
            if (!plan.cascades.empty()) maps.back()["cascade"] = t.cascade;
        }
    nlohmann::json technique = {
        {"name", toString(scene.shadow.technique)},
        {"filter", toString(scene.shadow.filter)},
        {"parameters", parameters},
        {"channels", plan.momentChannels},
        {"maps", maps},
        {"shadowMapBytes", plan.bytes()},
    };
    // Only with cascades, so that other scenes' render.json stay as they were.
    for (const PlannedCascade& c : plan.cascades)
        technique["cascades"].push_back({{"light", c.light}, {"cascade", c.cascade},
                                         {"near", c.nearDepth}, {"far", c.farDepth},
                                         {"bytes", plan.bytes(c.light, c.cascade)}});
    nlohmann::json sidecar = {
        {"scene", scene.path},
        {"solution", meta.solution},
        {"backend", meta.context.backend},
        {"renderer", meta.context.renderer},
        {"glVersion", meta.context.version},
        {"mesaVersion", meta.context.mesaVersion},
        {"technique", technique},
        {"passes", passes},
        {"notImplemented", result.stubNotes},
        {"sha256", files},
    };
    std::ofstream(outDir / "render.json") << sidecar.dump(2) << "\n";
    return sidecar;
}

}  // namespace sl
