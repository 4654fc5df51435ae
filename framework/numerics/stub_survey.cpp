// stub_survey: see stub_survey.h.
#include "stub_survey.h"

#include "probe.h"

#include <algorithm>

namespace sl {
namespace {

// A smooth 8 × 8 moment map, (z, z², z³, z⁴) of depths in (0.2, 0.6): any correct table and
// lookup give box averages in (0, 1).
Image smallMomentMap() {
    Image m(8, 8, 4);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const float z = 0.2f + 0.05f * float(x) + 0.02f * float(y);
            for (int k = 0; k < 4; ++k) m.at(x, y, k) = std::pow(z, float(k + 1));
        }
    return m;
}

bool allStub(const std::vector<float>& v) {
    return !v.empty() && std::all_of(v.begin(), v.end(), [](float x) { return x == -1.0f; });
}

bool isStub(const ShaderLibrary& library, StageFunction f) {
    switch (f) {
        case StageFunction::RelativeDepth:
            return allStub(probeRelativeDepth(library, {{2.0f, 1.0f, 3.0f}}));
        case StageFunction::ComputeMoments: {
            const glm::vec4 b = probeMoments(library, {{2.0f, 1.0f, 3.0f}}).front();
            return allStub({b.x, b.y, b.z, b.w});
        }
        case StageFunction::GaussianPass:
            return probeGaussianBlur(library, smallMomentMap(), 1, 1.0f, true, false).allStub();
        case StageFunction::SatPass: return probeSatTableImage(library, smallMomentMap()).allStub();
        case StageFunction::SatBoxAverage: {
            // Interior boxes: over a stub table a correct lookup returns 0 there, not -1.
            std::vector<float> v;
            for (const glm::vec4& b : probeSatBoxAverage(library, smallMomentMap(),
                                                         {{4.0f, 4.0f, 2.0f, 2.0f}, {5.0f, 3.5f, 3.0f, 1.0f}}))
                v.insert(v.end(), {b.x, b.y, b.z, b.w});
            return allStub(v);
        }
        case StageFunction::SatKernelTexels: {
            SatKernelCase c;
            c.center = {4.0f, 4.0f}, c.searchTexels = 4.0f, c.zr = 0.9f, c.depthRange = {1.0f, 3.0f};
            c.lightTexels = 2.0f;
            return allStub(probeSatKernelTexels(library, smallMomentMap(), {c}));
        }
        case StageFunction::MomentShadowIntensity:
            return allStub(probeMomentShadowIntensity(library, {{0.4f, 0.2f, 0.11f, 0.065f}}, {0.6f}, 3e-5f));
    }
    return false;
}

}  // namespace

std::vector<StageFunction> functionsRun(const PassPlan& plan) {
    std::vector<StageFunction> run;
    auto has = [&](PassKind k) {
        return std::any_of(plan.passes.begin(), plan.passes.end(), [&](const PlannedPass& p) { return p.kind == k; });
    };
    if (plan.shadowLights.empty() || !plan.row) return run;
    const bool moments = plan.row->store == StoreKind::Moments4 || plan.row->store == StoreKind::Moments4_16bit;
    const bool lighting = has(PassKind::Lighting);
    const bool sat = has(PassKind::SatRows);
    for (const StageFunctionName& f : kStageFunctions) {
        bool runs = false;
        switch (f.function) {
            case StageFunction::RelativeDepth: runs = true; break;  // the shadow pass's store
            case StageFunction::ComputeMoments: runs = moments; break;
            case StageFunction::GaussianPass: runs = has(PassKind::GaussianX); break;
            case StageFunction::SatPass: runs = sat; break;
            case StageFunction::SatBoxAverage: runs = sat && (lighting || has(PassKind::SatResolve)); break;
            case StageFunction::SatKernelTexels: runs = sat && lighting && plan.effect.satPerPixel; break;
            case StageFunction::MomentShadowIntensity: runs = lighting && plan.row->msmStage; break;
        }
        if (runs) run.push_back(f.function);
    }
    return run;
}

std::vector<StageFunction> stubFunctions(const ShaderLibrary& library,
                                         const std::vector<StageFunction>& functions) {
    std::vector<StageFunction> stubs;
    for (StageFunction f : functions)
        if (isStub(library, f)) stubs.push_back(f);
    return stubs;
}

void completeStubNotes(const ShaderLibrary& library, const PassPlan& plan, RenderResult& result) {
    if (result.stubNotes.empty()) return;
    std::vector<std::string> notes;
    std::vector<std::string> others = result.stubNotes;
    const std::vector<StageFunction> stubs = stubFunctions(library, functionsRun(plan));
    for (const StageFunctionName& f : kStageFunctions) {
        const std::string line = stubNoteText(library.displayPath(library.resolve(f.file)), f.function);
        const auto seen = std::find(others.begin(), others.end(), line);
        const bool stub = std::find(stubs.begin(), stubs.end(), f.function) != stubs.end();
        if (stub || seen != others.end()) notes.push_back(line);
        if (seen != others.end()) others.erase(seen);
    }
    notes.insert(notes.end(), others.begin(), others.end());
    result.stubNotes = std::move(notes);
}

}  // namespace sl
