// Renderer's read-back: the maps of every shadowing light into RenderResult's images, and the
// stub detection that tells an unimplemented stage (output -1) from a wrong one.
#include "render_internal.h"
#include "image_name.h"

namespace sl::render_detail {
bool stubOutput(const Image& out, const Image* in, bool everywhere) {
    for (std::size_t i = 0, n = std::size_t(out.width) * out.height; i < n; ++i) {
        const bool stub = out.stubTexel(i);
        if (everywhere && !stub) return false;
        if (!everywhere && stub && !(in && in->stubTexel(i))) return true;
    }
    return everywhere;
}

void noteStub(const ShaderLibrary& library, RenderResult& result, StageFunction function) {
    const std::string line =
        stubNoteText(library.displayPath(library.resolve(stageFunction(function).file)), function);
    for (const auto& existing : result.stubNotes)
        if (existing == line) return;
    result.stubNotes.push_back(line);
}

void readBack(const ShaderLibrary& library, const TechniqueRow& row, const ShadowEffect& fx,
              const PassPlan& plan, ShadowMapSet& maps, RenderResult& result) {
    const bool moments = row.store == StoreKind::Moments4 || row.store == StoreKind::Moments4_16bit;
    for (auto& [id, m] : maps) {
        // The first shadowing light's maps carry no light in their names.
        const int light = id.light == plan.shadowLights.front() ? -1 : id.light;
        auto name = [&](ImageKind kind, int layer = 0) {
            return ImageName{.kind = kind, .light = light, .cascade = id.cascade, .layer = layer}.str();
        };
        // Every layer of a role: the first as the map's name, the others with their layer.
        auto readLayers = [&](TextureRole role, ImageKind kind) {
            const auto& layers = m.tex.at(role);
            for (size_t k = 1; k < layers.size(); ++k) result.images[name(kind, int(k))] = layers[k].read();
            return layers.front().read();
        };
        Image raw = readLayers(TextureRole::Raw, ImageKind::MomentsRaw);
        // The stub value in every channel: computeMoments' stub, or a depth map of relativeDepth's.
        if (!m.given && stubOutput(raw, nullptr))
            noteStub(library, result, moments ? StageFunction::ComputeMoments : StageFunction::RelativeDepth);
        if (m.tex.count(TextureRole::Second)) result.images[name(ImageKind::SecondDepth)] = m.one(TextureRole::Second).read();
        if (m.tex.count(TextureRole::Sat)) {
            Image sat = readLayers(TextureRole::Sat, ImageKind::Sat);
            // sat.comp's stub writes -1 to every texel of the table (twice the map's width).
            const bool satStub = stubOutput(sat, nullptr, true);
            if (satStub) noteStub(library, result, StageFunction::SatPass);
            if (m.tex.count(TextureRole::Filtered)) {
                Image filtered = readLayers(TextureRole::Filtered, ImageKind::MomentsFiltered);
                // A stub table makes a correct lookup return -1 at a few border boxes at most,
                // never everywhere.
                if ((!satStub && stubOutput(filtered, nullptr)) || stubOutput(filtered, nullptr, true))
                    noteStub(library, result, StageFunction::SatBoxAverage);
                result.images[name(ImageKind::MomentsFiltered)] = std::move(filtered);
            }
            result.images[name(ImageKind::Sat)] = std::move(sat);
        } else if (m.tex.count(TextureRole::Filtered)) {
            Image filtered = readLayers(TextureRole::Filtered, ImageKind::MomentsFiltered);
            if (fx.filter == FilterKind::Gaussian && stubOutput(filtered, &raw))
                noteStub(library, result, StageFunction::GaussianPass);
            result.images[name(ImageKind::MomentsFiltered)] = std::move(filtered);
        } else {
            result.images[name(ImageKind::MomentsFiltered)] = raw;
        }
        result.images[name(ImageKind::MomentsRaw)] = std::move(raw);
    }
}

void noteLightingStubs(const ShaderLibrary& library, const TechniqueRow& row, const Image& shadow,
                       RenderResult& result) {
    bool msmStub = false, depthStub = false, kernelStub = false;
    for (std::size_t i = 0, n = std::size_t(shadow.width) * shadow.height; i < n; ++i) {
        const float g = shadow.pixels[i * shadow.channels];
        msmStub = msmStub || g == -1.0f || g == -3.0f;
        depthStub = depthStub || g == -2.0f || g == -3.0f;
        kernelStub = kernelStub || g == -4.0f;  // msm4.glsl: satKernelTexels returned -1
    }
    if (depthStub) noteStub(library, result, StageFunction::RelativeDepth);
    if (kernelStub) noteStub(library, result, StageFunction::SatKernelTexels);
    if (msmStub && row.msmStage) noteStub(library, result, StageFunction::MomentShadowIntensity);
}

}  // namespace sl::render_detail
