// edgefit: one executable, subcommands with gflags options (DESIGN.md).
#include <gflags/gflags.h>
#include <glog/logging.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstring>
#include <iostream>

#include "command_line.h"
#include "commands.h"

namespace edgefit::tools {

const std::vector<Command>& AllCommands() {
  static const std::vector<Command> kCommands = {
      InfoCommand(),
      ScanCommand(),
      EdgesCommand(),
      FitCommand(),
      ReportCommand(),
      CellCommand(),
      WorldCommand(),
      ClearanceCommand(),
      BatchCommand(),
      BenchCommand(),
  };
  return kCommands;
}

namespace {

// The fits copy scans of tens of millions of cells and drop them again
// (a cell's instances, their per-cell masks); glibc serves such blocks
// with mmap and returns them to the system on free, so every copy
// page-faults afresh. Kept in the heap instead they are reused: the demo
// cell (36.7 M points) 59.3 -> 51.9 s, system time 9.3 -> 1.2 s, the same
// peak (BENCHMARK.md, "Cells").
void KeepFreedMemoryForReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);  // never trimmed
#endif
}

int Main(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "help") == 0 || std::strcmp(argv[1], "--help") == 0 ||
      std::strcmp(argv[1], "-h") == 0) {
    if (argc >= 3) {  // edgefit help <cmd>
      for (const Command& c : AllCommands()) {
        if (c.name == std::string(argv[2])) {
          PrintCommandHelp(c);
          return kExitOk;
        }
      }
    }
    PrintOverview();
    return argc < 2 ? kExitBadInput : kExitOk;
  }
  const Command* command = nullptr;
  for (const Command& c : AllCommands()) {
    if (c.name == std::string(argv[1])) command = &c;
  }
  if (command == nullptr) {
    std::cerr << "edgefit: error: unknown command '" << argv[1]
              << "' (edgefit help lists the commands)" << std::endl;
    return kExitBadInput;
  }
  // Drop the command word so that gflags sees only flags.
  std::vector<char*> args(argv, argv + argc);
  args.erase(args.begin() + 1);
  int n = static_cast<int>(args.size());
  for (int i = 1; i < n; ++i) {
    if (std::strcmp(args[i], "--help") == 0 || std::strcmp(args[i], "-h") == 0 ||
        std::strcmp(args[i], "-help") == 0) {
      PrintCommandHelp(*command);
      return kExitOk;
    }
  }
  const Status parsed = ParseFlags(*command, n, args.data());
  if (!parsed.ok()) return BadInput(*command, parsed);

  FLAGS_logtostderr = true;
  google::InitGoogleLogging(argv[0]);
  KeepFreedMemoryForReuse();
  return command->run(*command);
}

}  // namespace
}  // namespace edgefit::tools

int main(int argc, char** argv) {
  gflags::SetUsageMessage("edgefit <command> [--flags]; `edgefit help` lists the commands");
  gflags::SetVersionString("0.1.0");
  return edgefit::tools::Main(argc, argv);
}
