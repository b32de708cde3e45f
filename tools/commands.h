// The subcommands, each defined in its own <name>_command.cc with its flags
// at the top of the file.
#ifndef EDGEFIT_TOOLS_COMMANDS_H_
#define EDGEFIT_TOOLS_COMMANDS_H_

#include "command_line.h"

namespace edgefit::tools {

Command InfoCommand();
Command ScanCommand();
Command EdgesCommand();
Command FitCommand();
Command BatchCommand();
Command BenchCommand();
Command CellCommand();
Command ReportCommand();
Command WorldCommand();
Command ClearanceCommand();

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_COMMANDS_H_
