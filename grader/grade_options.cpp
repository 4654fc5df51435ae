// grade_options: GradeOptions and BatchRow as JSON, their one encoding across a process
// boundary (a batch hands each submission's child its options, the child hands back its row).
#include "grader.h"

#include <stdexcept>

namespace sl::grader {
namespace {

using json = nlohmann::json;

template <class T>
T field(const json& j, const char* key) {
    if (!j.is_object() || !j.contains(key))
        throw std::invalid_argument(std::string("grade options: no \"") + key + "\"");
    try {
        return j.at(key).get<T>();
    } catch (const json::exception&) {
        throw std::invalid_argument(std::string("grade options: \"") + key + "\" has the wrong type");
    }
}

}  // namespace

json GradeOptions::toJson() const {
    return {{"submission", submission.string()}, {"out", out.string()},
            {"scenes", scenes},                  {"reference", reference},
            {"timeoutSeconds", timeoutSeconds},  {"memoryMb", memoryMb},
            {"jobs", jobs},                      {"goldens", goldens.string()},
            {"rubric", rubric.string()},         {"report", report},
            {"backend", backend},                {"keepWork", keepWork},
            {"referenceImages", referenceImages.string()}, {"rowFile", rowFile.string()}};
}

GradeOptions GradeOptions::fromJson(const json& j) {
    GradeOptions o;
    o.submission = field<std::string>(j, "submission");
    o.out = field<std::string>(j, "out");
    o.scenes = field<std::vector<std::string>>(j, "scenes");
    o.reference = field<std::string>(j, "reference");
    o.timeoutSeconds = field<double>(j, "timeoutSeconds");
    o.memoryMb = field<long>(j, "memoryMb");
    o.jobs = field<int>(j, "jobs");
    o.goldens = field<std::string>(j, "goldens");
    o.rubric = field<std::string>(j, "rubric");
    o.report = field<bool>(j, "report");
    o.backend = field<std::string>(j, "backend");
    o.keepWork = field<bool>(j, "keepWork");
    o.referenceImages = field<std::string>(j, "referenceImages");
    o.rowFile = field<std::string>(j, "rowFile");
    return o;
}

json BatchRow::toJson() const {
    return {{"failed", failed}, {"score", score},       {"maxScore", maxScore},
            {"stagePoints", stagePoints},               {"stageMax", stageMax},
            {"lost", lost},     {"notes", notes},       {"report", report},
            {"digest", digest}};
}

BatchRow BatchRow::fromJson(const json& j) {
    BatchRow r;
    r.failed = field<bool>(j, "failed");
    r.score = field<double>(j, "score");
    r.maxScore = field<double>(j, "maxScore");
    r.stagePoints = field<std::map<std::string, double>>(j, "stagePoints");
    r.stageMax = field<std::map<std::string, double>>(j, "stageMax");
    r.lost = field<std::vector<std::string>>(j, "lost");
    r.notes = field<std::vector<std::string>>(j, "notes");
    r.report = field<bool>(j, "report");
    r.digest = field<std::string>(j, "digest");
    return r;
}

}  // namespace sl::grader
