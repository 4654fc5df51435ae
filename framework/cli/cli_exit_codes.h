// cli_exit_codes: the exit codes of the shadowlab command, on their own so that code which only
// returns one (grader/worker.cpp) does not compile CLI11 (cli_commands.h).
#pragma once

namespace sl::cli {

enum ExitCode { Ok = 0, Failed = 1, BadInput = 2, ShaderFailed = 3, NoBackend = 4 };

}  // namespace sl::cli
