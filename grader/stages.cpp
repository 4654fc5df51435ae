// stages: which stage grades which files and images (grader.h).
#include "grader.h"

namespace sl::grader {

const std::vector<std::string>& stageNames() {
    static const std::vector<std::string> names = {"moments", "gaussian", "sat", "msm", "robustness", "final"};
    return names;
}

bool stageApplies(const std::string& stage, const std::string& filter) {
    if (stage == "gaussian") return filter == "gaussian";
    if (stage == "sat") return filter == "sat";
    if (stage == "robustness") return false;  // one test for the submission, not per scene
    return true;
}

std::vector<std::string> stageFiles(const std::string& stage, const std::string& filter) {
    if (stage == "moments") return {"moments.glsl"};
    if (stage == "gaussian") return {"gaussian_blur.comp"};
    if (stage == "sat") return {"sat.comp", "sat_lookup.glsl"};
    if (stage == "msm" || stage == "robustness") return {"msm.glsl"};
    std::vector<std::string> files = {"moments.glsl", "msm.glsl"};
    if (filter == "gaussian") files.push_back("gaussian_blur.comp");
    if (filter == "sat") files.insert(files.end(), {"sat.comp", "sat_lookup.glsl"});
    return files;
}

std::string stageImage(const std::string& stage) {
    if (stage == "moments") return "moments_raw";
    if (stage == "gaussian" || stage == "sat") return "moments_filtered";
    if (stage == "msm") return "shadow";
    return "final";
}

}  // namespace sl::grader
