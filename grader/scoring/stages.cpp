// stages: the stage table (stages.h).
#include "stages.h"

#include <algorithm>
#include <stdexcept>

namespace sl::grader {

const std::vector<StageRow>& stageTable() {
    static const std::vector<StageRow> rows = {
        {.stage = Stage::Moments, .name = "moments", .files = {"moments.glsl"}, .images = {ImageKind::MomentsRaw, ImageKind::DepthLadder},
         .compareBy = CompareBy::Moments, .scoutedBy = Stage::Moments},
        {.stage = Stage::Gaussian, .name = "gaussian", .files = {"gaussian_blur.comp"},
         .images = {ImageKind::MomentsFiltered, ImageKind::SatKernel}, .input = "moments_raw", .filter = "gaussian",
         .compareBy = CompareBy::Filtered, .scoutedBy = Stage::Gaussian},
        {.stage = Stage::Sat, .name = "sat", .files = {"sat.comp", "sat_lookup.glsl"},
         .images = {ImageKind::MomentsFiltered, ImageKind::SatKernel}, .input = "moments_raw", .filter = "sat",
         .compareBy = CompareBy::Filtered, .scoutedBy = Stage::Sat},
        // msm's stub is seen on the hard cases (robustness), which speak for it.
        {.stage = Stage::Msm, .name = "msm", .files = {"msm.glsl"}, .images = {ImageKind::Shadow},
         .input = "moments_filtered", .compareBy = CompareBy::Shadow, .scoutedBy = Stage::Robustness},
        {.stage = Stage::Robustness, .name = "robustness", .files = {"msm.glsl"}, .images = {},
         .compareBy = CompareBy::HardCases, .perScene = false, .scoutedBy = Stage::Robustness},
        {.stage = Stage::Final, .name = "final", .files = {}, .images = {ImageKind::Final},
         .compareBy = CompareBy::Colour, .scoutedBy = std::nullopt},
    };
    return rows;
}

bool stageImage(const StageRow& row, const std::string& name) {
    const auto n = ImageName::parse(name);
    return n && !n->msmIsolated && std::find(row.images.begin(), row.images.end(), n->kind) != row.images.end();
}

bool gradedImage(const StageRow& row, const std::string& name) {
    if (!stageImage(row, name)) return false;
    const ImageName n = *ImageName::parse(name);
    return n.kind != ImageKind::MomentsFiltered || (n.light < 0 && n.cascade == 0 && n.layer == 0);
}

const StageRow& stageRow(Stage stage) {
    for (const auto& row : stageTable())
        if (row.stage == stage) return row;
    throw std::logic_error("a stage without a row");
}

const StageRow& stageRow(const std::string& name) {
    for (const auto& row : stageTable())
        if (row.name == name) return row;
    throw std::invalid_argument("unknown stage \"" + name + "\"");
}

const std::vector<std::string>& stageNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& row : stageTable()) n.push_back(row.name);
        return n;
    }();
    return names;
}

std::vector<const StageRow*> stagesRun(const StageRow& row, const std::string& filter) {
    if (row.stage != Stage::Final) return {&row};
    std::vector<const StageRow*> run = {&stageRow(Stage::Moments)};
    for (const auto& r : stageTable())
        if (*r.filter && r.filter == filter) run.push_back(&r);
    run.push_back(&stageRow(Stage::Msm));
    return run;
}

std::vector<std::string> stageFiles(const StageRow& row, const std::string& filter) {
    if (row.stage != Stage::Final) return row.files;
    // moments, msm, then the filter's: the first of them missing is the one a final reports.
    std::vector<std::string> files = stageRow(Stage::Moments).files;
    const auto& msm = stageRow(Stage::Msm).files;
    files.insert(files.end(), msm.begin(), msm.end());
    for (const auto& r : stageTable())
        if (*r.filter && r.filter == filter) files.insert(files.end(), r.files.begin(), r.files.end());
    return files;
}

}  // namespace sl::grader
