// stub_scouts: see stub_scouts.h.
#include "stub_scouts.h"

#include <algorithm>
#include <sstream>

namespace sl::grader {

std::string scoutStubNote(const StageRow& row, bool robustness, const WorkerResult& w) {
    if (robustness ? w.stubNotes.empty() : !w.stubEverywhere) return "";
    std::string note;
    for (const auto& f : row.files) note += (note.empty() ? "submission/" : " + ") + f;
    note += ": not implemented yet (its output is the stub value -1)";
    std::string named;
    for (const auto& n : w.stubNotes)
        if (std::find(row.files.begin(), row.files.end(), n.file) != row.files.end())
            named += (named.empty() ? "" : "\n") + n.text;
    return named.empty() ? note : named;
}

bool scoutSpeaksFor(Stage stage, bool scoutPerPixelSat, bool renderPerPixelSat) {
    return !(stage == Stage::Sat && renderPerPixelSat && !scoutPerPixelSat);
}

std::string spareReason(const std::string& note, Stage stage, bool renderPerPixelSat,
                        bool scoutIsRobustness, const GradedScene& scoutScene) {
    std::string kept = note;
    if (stage == Stage::Sat && !renderPerPixelSat) {
        std::istringstream in(note);
        kept.clear();
        for (std::string line; std::getline(in, line);)
            if (line.find(": satKernelTexels:") == std::string::npos) kept += (kept.empty() ? "" : "\n") + line;
    }
    const std::string where = scoutIsRobustness ? std::string("on every hard case")
                              : scoutScene.hidden ? std::string("everywhere in another scene's render")
                                                  : "everywhere in the render of " + scoutScene.name;
    return kept + "; " + where + "\n";
}

}  // namespace sl::grader
