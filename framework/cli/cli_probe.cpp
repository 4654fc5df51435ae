// cli_probe: `shadowlab probe` (issue 4) — evaluates a stage function on a CSV of inputs.
#include "cli_commands.h"

namespace sl::cli {

void addProbeCommand(CLI::App&, Context&) {}

}  // namespace sl::cli
