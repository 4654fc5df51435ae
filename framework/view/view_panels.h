// view_panels: the viewer's Dear ImGui panels — the shadow settings (technique, filter and its
// radius/kernel, α, depth bias, the technique's own parameters such as its bias modes, light
// sizes), the image shown, and a per-pass timing table.
// The panels change nothing themselves: they return edits, which the viewer applies exactly
// as it applies `--set key=value` (EditableScene for scene keys, ViewOptions for view.*).
#pragma once

#include "pass_plan.h"
#include "renderer.h"
#include "scene.h"
#include "view_options.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace sl {

using SettingEdit = std::pair<std::string, nlohmann::json>;  // key, value (null: remove key)

// Between ImGuiLayer::beginFrame and endFrame. The panel fills the column
// [x0, x0 + width) × [0, height) of the window (in window pixels, from the top left).
// `error`: the message of the last rejected edit, shown in red ("" for none).
std::vector<SettingEdit> drawPanels(const Scene& scene, const PassPlan& plan,
                                    const RenderResult& result, const ViewOptions& options,
                                    const std::string& error, float x0, float width, float height);

}  // namespace sl
