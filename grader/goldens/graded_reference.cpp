// graded_reference: see graded_reference.h.
#include "graded_reference.h"

#include "golden_encoding.h"
#include "image_io.h"
#include "image_name.h"
#include "pass_plan.h"
#include "raw_image.h"
#include "sat_kernel_ladder.h"

namespace sl::grader {

RenderResult renderFromMoments(Renderer& renderer, Scene scene, const Image& filtered,
                               const std::map<int, Image>& relativeDepth) {
    scene.shadow.filter = FilterKind::None;
    const PassPlan plan = planPasses(scene, {.relativeDepth = RelativeDepth::Given});
    RenderInputs inputs;
    if (!plan.shadowLights.empty()) inputs.filteredMoments[plan.shadowLights.front()] = filtered;
    inputs.relativeDepth = relativeDepth;
    return renderer.render(scene, plan, inputs);
}

namespace {

std::string cameraImage(ImageKind kind, const Scene& scene, int camera) {
    return ImageName{.kind = kind, .camera = camera == 0 ? "" : scene.cameras[camera].name}.str();
}

}  // namespace

std::map<int, Image> relativeDepthBeside(const Scene& scene, const std::filesystem::path& input) {
    std::map<int, Image> images;
    for (int c = 0; c < int(scene.cameras.size()); ++c) {
        std::filesystem::path file = input;
        file.replace_filename(cameraImage(ImageKind::RelativeDepth, scene, c) + input.extension().string());
        images[c] = readAnyImage(file);
    }
    return images;
}

RenderResult gradedReferenceImages(Renderer& renderer, const Scene& scene, RenderResult* full) {
    RenderResult result = renderer.render(scene, planPasses(scene, {.resolveSat = true}));
    if (scene.shadow.filter == FilterKind::Sat && scene.shadow.satPerPixel)  // the sat stage's
        result.images[kSatKernelImage] =
            satKernelLadder(renderer.library(), scene, result.images.at("moments_raw"));
    if (full) *full = result;
    result.images.erase(toString(ImageKind::Sat));  // the table itself is never compared
    const bool shadowed = result.images.count("moments_filtered") > 0;
    if (shadowed) {
        // zf of each camera's fragments, as the reference's relativeDepth gives it.
        Scene unfiltered = scene;
        unfiltered.shadow.filter = FilterKind::None;
        const PassPlan shown = planPasses(unfiltered, {.relativeDepth = RelativeDepth::Shown});
        RenderInputs inputs;
        inputs.readMaps = false;  // only the cameras' images: the relative_depth ones
        if (!shown.shadowLights.empty())
            inputs.filteredMoments[shown.shadowLights.front()] = result.images.at("moments_filtered");
        for (auto& [name, image] : renderer.render(unfiltered, shown, inputs).images)
            if (isImage(name, ImageKind::RelativeDepth)) result.images[name] = std::move(image);
    }
    for (auto& [name, image] : result.images) roundAsGolden(name, image);
    if (shadowed) {
        // What the msm stage is compared with: lit from exactly its inputs, as rounded.
        std::map<int, Image> zf;
        for (int c = 0; c < int(scene.cameras.size()); ++c)
            zf[c] = result.images.at(cameraImage(ImageKind::RelativeDepth, scene, c));
        RenderResult isolated =
            renderFromMoments(renderer, scene, result.images.at("moments_filtered"), zf);
        for (auto& [name, image] : isolated.images)
            if (auto n = ImageName::parse(name); n && n->kind == ImageKind::Shadow) {
                n->msmIsolated = true;
                roundAsGolden(n->str(), image);
                result.images[n->str()] = std::move(image);
            }
    }
    return result;
}

}  // namespace sl::grader
