// cli_grade: `shadowlab grade`, `golden` and `package` (issue 3).
#include "cli_commands.h"

namespace sl::cli {

void addGraderCommands(CLI::App&, Context&) {}

}  // namespace sl::cli
