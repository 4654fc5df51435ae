// view_panels: see view_panels.h.
#include "view_panels.h"

#include "technique.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sl {
namespace {

using nlohmann::json;

// A combo over `names`; returns the chosen one when it changed.
bool combo(const char* label, const std::vector<std::string>& names, const std::string& current,
           std::string& chosen) {
    bool changed = false;
    if (ImGui::BeginCombo(label, current.c_str())) {
        for (const auto& name : names) {
            const bool selected = name == current;
            if (ImGui::Selectable(name.c_str(), selected) && !selected) chosen = name, changed = true;
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    return changed;
}

void shadowSettings(const Scene& scene, std::vector<SettingEdit>& edits) {
    const ShadowEffect& fx = scene.shadow;
    const TechniqueRow& row = techniqueRow(fx.technique);
    std::string chosen;
    if (combo("technique", techniqueNames(), row.name, chosen)) edits.push_back({"shadow.technique", chosen});
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", row.summary.c_str());
    std::vector<std::string> filters;  // the ones the technique allows
    for (FilterKind f : row.filters) filters.push_back(toString(f));
    if (combo("filter", filters, toString(fx.filter), chosen))
        edits.push_back({"shadow.filter.type", chosen});
    if (fx.filter == FilterKind::Gaussian) {
        int radius = fx.gaussianRadius;
        if (ImGui::SliderInt("radius", &radius, 0, 64)) edits.push_back({"shadow.filter.radius", radius});
        float sigma = fx.gaussianSigma;
        if (ImGui::SliderFloat("sigma", &sigma, 0.1f, 32.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
            edits.push_back({"shadow.filter.sigma", sigma});
        ImGui::SameLine();
        if (ImGui::SmallButton("r/2")) edits.push_back({"shadow.filter.sigma", nullptr});
    } else if (fx.filter == FilterKind::Sat && fx.satPerPixel) {
        // Each pixel's box is satKernelTexels': only its limits are the scene's.
        float search = fx.satKernelTexels, largest = fx.satMaxKernelTexels;
        if (ImGui::SliderFloat("search", &search, 1.0f, 128.0f, "%.1f texels", ImGuiSliderFlags_Logarithmic))
            edits.push_back({"shadow.filter.searchTexels", search});
        if (ImGui::SliderFloat("largest box", &largest, 1.0f, 128.0f, "%.1f texels", ImGuiSliderFlags_Logarithmic))
            edits.push_back({"shadow.filter.maxKernelTexels", largest});
    } else if (fx.filter == FilterKind::Sat) {
        float kernel = fx.satKernelTexels;
        if (ImGui::SliderFloat("kernel", &kernel, 1.0f, 128.0f, "%.1f texels", ImGuiSliderFlags_Logarithmic))
            edits.push_back({"shadow.filter.kernel", kernel});
    }
    float alpha = fx.momentBias;
    if (ImGui::SliderFloat("alpha", &alpha, 1e-7f, 1e-2f, "%.2e", ImGuiSliderFlags_Logarithmic))
        edits.push_back({"shadow.momentBias", alpha});  // α of the moment bias
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("moment bias (alpha): shadow.momentBias");
    float depthBias = fx.depthBias;
    if (ImGui::SliderFloat("depth bias", &depthBias, 0.0f, 0.05f, "%.4f"))
        edits.push_back({"shadow.depthBias", depthBias});
    const std::vector<std::string> sizes = {"256", "512", "1024", "2048", "4096"};
    if (combo("map size", sizes, std::to_string(fx.mapSize), chosen))
        edits.push_back({"shadow.mapSize", std::stoi(chosen)});
}

// The technique's own parameters (bias modes, bleeding reduction, warp exponents, ...), each
// a slider over the row's range; a value too small for a linear slider gets a logarithmic one.
void techniqueParameters(const ShadowEffect& fx, std::vector<SettingEdit>& edits) {
    const TechniqueRow& row = techniqueRow(fx.technique);
    if (row.parameters.empty()) {
        ImGui::TextDisabled("%s has no parameters", row.name.c_str());
        return;
    }
    for (const TechniqueParameter& p : row.parameters) {
        const std::string key = "shadow.parameters." + p.name;
        const double value = techniqueParameter(fx, p.name);
        if (p.integer) {
            int v = int(std::lround(value));
            if (ImGui::SliderInt(p.name.c_str(), &v, int(p.min), int(p.max))) edits.push_back({key, v});
        } else {
            float v = float(value);
            const bool tiny = p.defaultValue > 0.0 && p.defaultValue < 0.01 * p.max;
            if (ImGui::SliderFloat(p.name.c_str(), &v, float(p.min), float(p.max), tiny ? "%.2e" : "%.3f",
                                   tiny ? ImGuiSliderFlags_Logarithmic : 0))
                edits.push_back({key, v});
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (default %g)", p.meaning.c_str(), p.defaultValue);
    }
    if (ImGui::SmallButton("defaults")) edits.push_back({"shadow.parameters", nullptr});
}

void lightSettings(const Scene& scene, std::vector<SettingEdit>& edits) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        ImGui::PushID(int(i));
        ImGui::Text("light %zu (%s)", i, toString(light.type));
        const std::string key = "lights." + std::to_string(i) + ".size";
        if (light.rectangle.x > 0.0f) {  // a w × h rectangle ("size": [w, h])
            float wh[2] = {light.rectangle.x, light.rectangle.y};
            if (ImGui::SliderFloat2("size", wh, 0.001f, 2.0f, "%.3f"))
                edits.push_back({key, {wh[0], wh[1]}});
        } else {  // a disk of diameter size (0: a point)
            float size = light.size;
            if (ImGui::SliderFloat("size", &size, 0.0f, 2.0f, "%.3f")) edits.push_back({key, size});
        }
        if (light.type == LightType::Directional) {  // cascaded maps (cascades.h)
            const std::string light_ = "lights." + std::to_string(i) + ".";
            int cascades = light.cascades;
            if (ImGui::SliderInt("cascades", &cascades, 1, 4))
                edits.push_back({light_ + "cascades", cascades});
            if (light.cascades > 1 && light.cascadeSplit == CascadeSplit::Practical) {
                float lambda = light.cascadeLambda;
                if (ImGui::SliderFloat("cascade lambda", &lambda, 0.0f, 1.0f, "%.2f"))
                    edits.push_back({light_ + "cascadeLambda", lambda});
            }
        }
        ImGui::PopID();
    }
}

void imageSettings(const RenderResult& result, const ViewOptions& options,
                   std::vector<SettingEdit>& edits) {
    // The usual ones first, in their order; then any other the render made (further lights).
    std::vector<std::string> present;
    for (const auto& name : viewImageNames())
        if (result.images.count(name)) present.push_back(name);
    for (const auto& [name, image] : result.images)
        if (std::find(present.begin(), present.end(), name) == present.end()) present.push_back(name);
    std::string chosen;
    if (combo("image", present, options.image, chosen)) edits.push_back({"view.image", chosen});
    auto it = result.images.find(options.image);
    if (it == result.images.end() || it->second.channels == 1) return;
    const char* labels[] = {"all", "0", "1", "2", "3"};
    for (int c = -1; c < std::min(it->second.channels, 4); ++c) {
        if (c > -1) ImGui::SameLine();
        if (ImGui::RadioButton(labels[c + 1], options.channel == c))
            edits.push_back({"view.channel", labels[c + 1]});
    }
}

void timingTable(const Scene& scene, const PassPlan& plan, const RenderResult& result) {
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg;
    if (!ImGui::BeginTable("passes", 3, flags)) return;
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("for");
    ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, 60.0f);
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < plan.passes.size(); ++i) {
        const PlannedPass& p = plan.passes[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(toString(p.kind));
        ImGui::TableNextColumn();
        if (p.camera >= 0) ImGui::TextUnformatted(scene.cameras[size_t(p.camera)].name.c_str());
        else ImGui::Text("light %d", p.light);
        ImGui::TableNextColumn();
        if (i < result.passMillis.size()) ImGui::Text("%.2f", result.passMillis[i]);
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    ImGui::TableNextColumn();
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", std::accumulate(result.passMillis.begin(), result.passMillis.end(), 0.0));
    ImGui::EndTable();
    ImGui::Text("shadow maps: %.1f MiB", double(plan.bytes()) / (1 << 20));
}

}  // namespace

std::vector<SettingEdit> drawPanels(const Scene& scene, const PassPlan& plan,
                                    const RenderResult& result, const ViewOptions& options,
                                    const std::string& error, float x0, float width, float height) {
    std::vector<SettingEdit> edits;
    ImGui::SetNextWindowPos(ImVec2(x0, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
    ImGui::Begin("shadowlab", nullptr, flags);
    ImGui::PushItemWidth(-110.0f);  // room for the labels
    ImGui::TextUnformatted(scene.name.c_str());
    if (ImGui::CollapsingHeader("shadow", ImGuiTreeNodeFlags_DefaultOpen)) shadowSettings(scene, edits);
    if (ImGui::CollapsingHeader("technique parameters", ImGuiTreeNodeFlags_DefaultOpen))
        techniqueParameters(scene.shadow, edits);
    if (ImGui::CollapsingHeader("lights", ImGuiTreeNodeFlags_DefaultOpen)) lightSettings(scene, edits);
    if (ImGui::CollapsingHeader("image", ImGuiTreeNodeFlags_DefaultOpen))
        imageSettings(result, options, edits);
    if (ImGui::CollapsingHeader("passes", ImGuiTreeNodeFlags_DefaultOpen)) timingTable(scene, plan, result);
    if (!error.empty()) {  // the last rejected edit, with the loader's reason
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", error.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::PopItemWidth();
    ImGui::End();
    return edits;
}

}  // namespace sl
