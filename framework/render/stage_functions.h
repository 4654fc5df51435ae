// stage_functions: the seven functions the students write, each with its stage file and the
// name every message uses for it (render notes, the demo's to-do list, the grader). A .comp
// file's function is its main(): one pass of its filter.
#pragma once

#include <array>
#include <string>

namespace sl {

enum class StageFunction {
    RelativeDepth, ComputeMoments, GaussianPass, SatPass, SatBoxAverage, SatKernelTexels,
    MomentShadowIntensity
};

struct StageFunctionName {
    StageFunction function;
    const char* file;  // the stage file, as in student/
    const char* name;  // as messages name it
};

// In the order a frame runs them: a to-do list in this order is the assignment's.
inline constexpr std::array<StageFunctionName, 7> kStageFunctions = {{
    {StageFunction::RelativeDepth, "moments.glsl", "relativeDepth"},
    {StageFunction::ComputeMoments, "moments.glsl", "computeMoments"},
    {StageFunction::GaussianPass, "gaussian_blur.comp", "main (one Gaussian pass)"},
    {StageFunction::SatPass, "sat.comp", "main (one prefix-sum pass)"},
    {StageFunction::SatBoxAverage, "sat_lookup.glsl", "satBoxAverage"},
    {StageFunction::SatKernelTexels, "sat_lookup.glsl", "satKernelTexels"},
    {StageFunction::MomentShadowIntensity, "msm.glsl", "momentShadowIntensity"},
}};

inline const StageFunctionName& stageFunction(StageFunction f) {
    return kStageFunctions[size_t(f)];
}

// "FILE: FUNCTION: not implemented yet (its output is the stub value -1)", FILE as shown.
inline std::string stubNoteText(const std::string& shownFile, StageFunction f) {
    return shownFile + ": " + stageFunction(f).name +
           ": not implemented yet (its output is the stub value -1)";
}

}  // namespace sl
