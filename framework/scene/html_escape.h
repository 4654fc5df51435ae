// html_escape: text made safe for the HTML pages the kit writes (the grade report, the batch's
// gradebook, the study's page, compare and report).
#pragma once

#include <string>

namespace sl {

// `s` with <, >, & and " written as entities: safe as element text and as a quoted attribute.
inline std::string htmlEscape(const std::string& s) {
    std::string out;
    for (char c : s)
        out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
    return out;
}

}  // namespace sl
