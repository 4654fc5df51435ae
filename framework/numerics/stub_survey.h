// stub_survey: which stage functions a render runs are still the stub. A render sees a stub
// only through its output, and one stub hides the next (a stub table gives satBoxAverage
// nothing to return, a stub relativeDepth keeps the lighting from calling satKernelTexels):
// so each function is probed alone, on a small fixed input, and is a stub when it returns
// the stub value -1 there, which no correct stage does.
#pragma once

#include "pass_plan.h"
#include "renderer.h"
#include "shader_source.h"
#include "stage_functions.h"

#include <vector>

namespace sl {

// The stage functions a plan's passes call, in kStageFunctions' order.
std::vector<StageFunction> functionsRun(const PassPlan& plan);

// Those of `functions` that `library`'s files leave as the stub (a probe dispatch each).
std::vector<StageFunction> stubFunctions(const ShaderLibrary& library,
                                         const std::vector<StageFunction>& functions);

// When a render noted a stub, the full list: every function the plan runs that is a stub,
// in the order a frame runs them, as stubNoteText lines; notes it had of other kinds are kept
// after them. A render with no stub note is left as it is (no probe runs).
void completeStubNotes(const ShaderLibrary& library, const PassPlan& plan, RenderResult& result);

}  // namespace sl
