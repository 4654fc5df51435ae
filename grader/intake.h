// intake.h: takes a submission's stage files into the grader's own folder (see intake.cpp).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sl::grader {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxSubmissionFileBytes = 256 * 1024;

struct IntakeResult {
    fs::path staged;                           // folder holding the accepted copies
    std::map<std::string, std::string> refused;  // file -> reason ("not submitted" for missing)
    std::vector<std::string> accepted;
    std::vector<std::string> ignored;          // other names in the folder (told, not taken)
    bool has(const std::string& file) const { return !refused.count(file); }
};

// Copies the five expected stage files of `submission` into `staging` (created afresh).
// Refuses symlinks, non-regular files, files over 256 KiB and #include paths that leave the
// folder. Never throws for a bad submission: every problem is a reason in `refused`.
IntakeResult takeSubmission(const fs::path& submission, const fs::path& staging);

}  // namespace sl::grader
