// study_pick: "which technique for which scene", answered from the table, not by hand. For one
// scene and light size: the most accurate configuration, the cheapest frame within 10 % and
// within 50 % of that error, and the fewest map bytes within 10 %. The page shows it; each
// study folder also gets pick.md, whose lines docs/accuracy.md gathers across scenes.
#pragma once

#include "study_table.h"

#include <string>
#include <vector>

namespace sl {

struct Pick {
    std::string question;  // "most accurate", "cheapest within 10 % of it", ...
    const StudyRow* row = nullptr;
};

// The answers for rows of one light size (rows of other sizes must be left out by the caller).
std::vector<Pick> pickConfigurations(const std::vector<const StudyRow*>& rows);

// "msm4 sat r4 512²": technique, kernel and map size.
std::string pickConfiguration(const StudyRow& row);

// Markdown table lines (no header): | scene | light | question | configuration | RMSE | frame/copy | map bytes |
std::string pickMarkdown(const std::vector<Pick>& picks);
// The header of those lines.
std::string pickMarkdownHeader();

}  // namespace sl
