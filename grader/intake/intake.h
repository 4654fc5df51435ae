// intake.h: takes a submission's stage files into the grader's own folder (see intake.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sl::grader {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxSubmissionFileBytes = 256 * 1024;
constexpr size_t kMaxIncludeFiles = 8;                      // .glsl helpers besides the stages
constexpr std::uintmax_t kMaxIncludeBytes = 512 * 1024;     // all helpers together

struct IntakeResult {
    fs::path staged;                           // folder holding the accepted copies
    std::map<std::string, std::string> refused;  // file -> reason ("not submitted" for missing)
    std::vector<std::string> accepted;         // stage files taken
    std::vector<std::string> includes;         // helper .glsl files taken (for #include)
    std::vector<std::string> ignored;          // other names in the folder (told, not taken)
    std::string nested;                        // the one subfolder the files were in, if so
    bool has(const std::string& file) const { return !refused.count(file); }
};

// Copies the five expected stage files of `submission`, and up to kMaxIncludeFiles other
// `.glsl` files they may #include, into `staging` (created afresh). If the folder holds no
// stage file but exactly one subfolder that does (an upload that kept its folder), that
// subfolder is taken instead. Refuses symlinks, non-regular files, files over 256 KiB, NUL
// bytes, #include paths that leave the folder, and #line / #extension. Never throws for a
// bad submission: every problem is a reason in `refused` (or, for helpers, in `ignored`).
IntakeResult takeSubmission(const fs::path& submission, const fs::path& staging);

// The check applied to every accepted file's text: "" or "refused: ..." (tests use it).
std::string checkSource(const std::string& content);

}  // namespace sl::grader
