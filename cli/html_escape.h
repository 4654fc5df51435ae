// html_escape: text made safe for the HTML pages the command line writes (compare, report).
#pragma once

#include <string>

namespace sl::cli {

inline std::string htmlEscape(const std::string& s) {
    std::string out;
    for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return out;
}

}  // namespace sl::cli
