#include "command_line.h"

#include <gflags/gflags.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "edgefit/core/atomic_file.h"

DEFINE_string(progress, "auto",
              "Progress lines on stderr: auto (when stderr is a terminal), always (logs, batch "
              "jobs), never.");
DEFINE_bool(quiet, false, "No progress lines on stderr (the same as --progress=never).");

namespace edgefit::tools {
namespace {

// Flags every command accepts (gflags' own and glog's).
bool IsGlobalFlag(const std::string& name) {
  static const char* kGlobal[] = {
      "help",        "helpfull",        "helpshort",   "version",         "v",
      "logtostderr", "alsologtostderr", "minloglevel", "stderrthreshold", "vmodule",
      "flagfile",    "fromenv",         "progress",    "quiet"};
  for (const char* g : kGlobal) {
    if (name == g) return true;
  }
  return false;
}

}  // namespace

int BadInput(const Command& command, const std::string& message) {
  std::cerr << "edgefit " << command.name << ": error: " << message << std::endl;
  return kExitBadInput;
}

int BadInput(const Command& command, const Status& status) {
  return BadInput(command, status.message());
}

Status ParseFlags(const Command& command, int argc, char** argv) {
  auto reads = [&command](const std::string& flag) {
    if (IsGlobalFlag(flag)) return true;
    for (const std::string& f : command.flags) {
      if (f == flag) return true;
    }
    return false;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.size() < 2 || arg[0] != '-') {
      return Status::Error("unexpected argument '" + arg + "' (flags take the form --name=value)");
    }
    const std::string body = arg.substr(arg[1] == '-' ? 2 : 1);
    const size_t eq = body.find('=');
    std::string name = body.substr(0, eq);
    std::string value;
    bool has_value = eq != std::string::npos;
    if (has_value) value = body.substr(eq + 1);
    // "--nojson" negates the boolean flag "json".
    if (!reads(name) && name.rfind("no", 0) == 0 && reads(name.substr(2)) && !has_value) {
      name = name.substr(2);
      value = "false";
      has_value = true;
    }
    google::CommandLineFlagInfo info;
    if (!reads(name) || !google::GetCommandLineFlagInfo(name.c_str(), &info)) {
      return Status::Error("unknown flag --" + name + " (see: edgefit " + command.name +
                           " --help)");
    }
    if (!has_value) {
      if (info.type == "bool") {
        value = "true";
      } else if (i + 1 < argc) {
        value = argv[++i];  // "--name value"
      } else {
        return Status::Error("flag --" + name + " needs a value");
      }
    }
    if (google::SetCommandLineOption(name.c_str(), value.c_str()).empty()) {
      return Status::Error("flag --" + name + ": '" + value + "' is not a valid " + info.type);
    }
  }
  if (FLAGS_progress != "auto" && FLAGS_progress != "always" && FLAGS_progress != "never") {
    return Status::Error("flag --progress: '" + FLAGS_progress +
                         "' is not one of auto, always, never");
  }
  return Status::Ok();
}

void PrintCommandHelp(const Command& command) {
  std::cout << "edgefit " << command.name << ": " << command.summary << "\n\n"
            << command.usage << "\n\nFlags:\n";
  for (const std::string& name : command.flags) {
    google::CommandLineFlagInfo info;
    if (!google::GetCommandLineFlagInfo(name.c_str(), &info)) continue;
    std::cout << "  --" << info.name << " (" << info.type << ", default \"" << info.default_value
              << "\")\n      " << info.description << "\n";
  }
}

void PrintOverview() {
  std::cout << "edgefit: fit kinematic CAD models (URDF) to terrestrial laser scans.\n\n"
               "Usage: edgefit <command> [--flags]\n\nCommands:\n";
  for (const Command& c : AllCommands()) {
    std::printf("  %-8s %s\n", c.name, c.summary);
  }
  std::cout << "  help     this overview\n\n"
               "`edgefit <command> --help` lists a command's flags; every command takes\n"
               "--progress=auto|always|never (progress lines on stderr; auto: on a terminal)\n"
               "and --quiet (--progress=never).\n"
               "Exit codes: 0 success, 2 bad input (one line on stderr says what and where),\n"
               "1 internal failure.\n";
}

namespace {

const auto kStart = std::chrono::steady_clock::now();

double SecondsSinceStart() { return SecondsSince(kStart); }

// "42 s", "3:05", "1:02:09".
std::string Duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s < 60) {
    std::snprintf(text, sizeof(text), "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof(text), "%ld:%02ld", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  }
  return text;
}

}  // namespace

void Progress(const std::string& message) {
  static const bool enabled =
      !FLAGS_quiet && (FLAGS_progress == "always" ||
                       (FLAGS_progress == "auto" && ::isatty(STDERR_FILENO) != 0));
  if (!enabled) return;
  char stamp[32];
  std::snprintf(stamp, sizeof(stamp), "[%7.1f s] ", SecondsSinceStart());
  std::cerr << stamp << message << std::endl;
}

ProgressCounter::ProgressCounter(size_t total)
    : total_(total), start_(std::chrono::steady_clock::now()) {}

std::string ProgressCounter::Next() {
  const double elapsed = SecondsSince(start_);
  std::string text = std::to_string(++started_) + "/" + std::to_string(total_);
  if (started_ > 1 && started_ <= total_) {
    const double per_item = elapsed / static_cast<double>(started_ - 1);
    text += ", about " + Duration(per_item * static_cast<double>(total_ - started_ + 1)) + " left";
  }
  return text;
}

std::vector<std::string> SplitList(const std::string& list) {
  std::vector<std::string> items;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = list.find(',', start);
    const std::string item =
        list.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!item.empty()) items.push_back(item);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return items;
}

Status CheckOutputPaths(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    if (!path.empty()) EDGEFIT_RETURN_IF_ERROR(CheckOutputPath(path));
  }
  return Status::Ok();
}

Status ParseNumberList(const std::string& flag, const std::string& list, double fallback,
                       std::vector<double>* out) {
  out->clear();
  for (const std::string& item : SplitList(list)) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !std::isfinite(value)) {
      return Status::Error("--" + flag + ": '" + item + "' is not a number");
    }
    out->push_back(value);
  }
  if (out->empty()) out->push_back(fallback);
  return Status::Ok();
}

std::string CommandText(const Command& command) {
  std::string text = std::string("edgefit ") + command.name;
  for (const std::string& flag : command.flags) {
    gflags::CommandLineFlagInfo info;
    if (gflags::GetCommandLineFlagInfo(flag.c_str(), &info) && !info.is_default) {
      text += " --" + flag + "=" + info.current_value;
    }
  }
  return text;
}

Status ParseShard(const std::string& text, int* index, int* count) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const long i = std::strtol(begin, &end, 10);
  const bool slash = end != begin && *end == '/';
  const char* rest = slash ? end + 1 : end;
  const long n = slash ? std::strtol(rest, &end, 10) : 0;
  if (!slash || end == rest || *end != '\0') {
    return Status::Error("--shard must be i/N (two integers), not '" + text + "'");
  }
  if (n < 1 || i < 0 || i >= n || n > 1000000) {
    return Status::Error("--shard=" + text + ": need N >= 1 and 0 <= i < N");
  }
  *index = static_cast<int>(i);
  *count = static_cast<int>(n);
  return Status::Ok();
}

Status ParseXyYawDeg(const std::string& flag, const std::string& text, double* x, double* y,
                     double* yaw) {
  const std::vector<std::string> parts = SplitList(text);
  if (parts.size() != 3) return Status::Error(flag + ": expected x,y,yaw_deg, got '" + text + "'");
  double v[3];
  for (size_t i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(parts[i].c_str(), &end);
    if (*end != '\0' || !std::isfinite(v[i])) {
      return Status::Error(flag + ": '" + parts[i] + "' is not a number");
    }
  }
  *x = v[0];
  *y = v[1];
  *yaw = v[2] * M_PI / 180.0;
  return Status::Ok();
}

}  // namespace edgefit::tools
