// The edgefit command's subcommand table, flag validation and exit codes
// (DESIGN.md, command-line contract): 0 success, 2 bad input with one clear
// line on stderr, 1 internal failure.
#ifndef EDGEFIT_TOOLS_COMMAND_LINE_H_
#define EDGEFIT_TOOLS_COMMAND_LINE_H_

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit::tools {

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

struct Command {
  const char* name;
  const char* summary;  // one line for `edgefit help`
  const char* usage;    // synopsis and examples for `edgefit <cmd> --help`
  std::vector<std::string> flags;  // the gflags this command reads
  int (*run)(const Command& self);  // runs after the flags are parsed
};

// Every subcommand; defined next to main().
const std::vector<Command>& AllCommands();

// Prints "edgefit <cmd>: error: <message>" as one line on stderr and returns
// kExitBadInput.
int BadInput(const Command& command, const std::string& message);
int BadInput(const Command& command, const Status& status);

// Sets the flags in argv[1..argc) ("--name=value", "--name value", "--bool",
// "--nobool"). Fails, without exiting, on a flag `command` does not read, a
// missing value or a value of the wrong type; the message names the flag.
Status ParseFlags(const Command& command, int argc, char** argv);

// `edgefit <cmd> --help`.
void PrintCommandHelp(const Command& command);
// `edgefit help`.
void PrintOverview();

// Seconds from `start` to now (steady clock).
inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A progress line on stderr for long steps, only when stderr is a terminal
// (so scripts and logs get exactly one line on failure) or --progress=always,
// never with --quiet; each line starts with the seconds since the command
// started ("[   12.3 s] ").
void Progress(const std::string& message);

// How far a command is through `total` items of similar cost (the bench's
// fits, the batch's jobs, the cell's assets): Next(), as an item starts,
// gives "3/16, about 5:10 left" (the time left from the mean time of the
// items done; none before the first is done).
class ProgressCounter {
 public:
  explicit ProgressCounter(size_t total);
  std::string Next();

 private:
  size_t total_ = 0, started_ = 0;
  std::chrono::steady_clock::time_point start_;
};

// "edgefit <cmd>" and the flags given (those not at their defaults), to
// say in a report what made it.
std::string CommandText(const Command& command);

// Splits "a,b,,c" into {"a", "b", "c"}.
std::vector<std::string> SplitList(const std::string& list);

// A comma list of numbers ("1,10,100") for --flag; an empty list gives
// {fallback}.
Status ParseNumberList(const std::string& flag, const std::string& list, double fallback,
                       std::vector<double>* out);

// "i/N" (--shard): share i of N, 0 <= i < N.
Status ParseShard(const std::string& text, int* index, int* count);

// Parses a level pose on the floor, "x,y,yaw_deg" (metres, degrees), into x,
// y [m] and yaw [rad]; errors name `flag`.
Status ParseXyYawDeg(const std::string& flag, const std::string& text, double* x, double* y,
                     double* yaw);

// Every output file of a command (empty: not asked for) can be written
// (CheckOutputPath): checked before any work, so that a wrong path fails
// at once and not after a long fit.
Status CheckOutputPaths(const std::vector<std::string>& paths);

}  // namespace edgefit::tools

// In a command's run function: on a failed Status, print it as bad input
// (one line) and return exit code 2.
#define EDGEFIT_RETURN_IF_ERROR_EXIT(command, expr)                           \
  do {                                                                         \
    const ::edgefit::Status edgefit_status_ = (expr);                          \
    if (!edgefit_status_.ok()) return ::edgefit::tools::BadInput(command, edgefit_status_); \
  } while (0)

#endif  // EDGEFIT_TOOLS_COMMAND_LINE_H_
