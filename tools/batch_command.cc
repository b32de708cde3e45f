// edgefit batch: many fits from a manifest, one `edgefit fit` process per
// job, split into shards across processes or machines.
//   edgefit batch --manifest=jobs.csv [--shard=i/N] [--threads=N]
// The manifest is CSV with a header row naming its columns:
//   urdf, scan, out   required; several scans separated by ';'
//   name              optional (default: the row number)
//   attach            optional; several separated by ';'
//   options           optional: more `edgefit fit` flags, separated by spaces
//                     (--kind=conveyance --weighting=uniform --truth=T.json ...)
// Relative paths (the columns' and those of --truth and --out_* in options)
// are taken from the manifest's folder; fields are not quoted
// (lists use ';'). Shard i of N runs the data rows k with k mod N = i (rows
// counted from 0). Each job writes its outputs atomically (edgefit fit): a
// failed job leaves none, is reported with its error line, and the batch goes
// on. Exit 0 when every job of the shard succeeded, 1 when one failed, 2 on a
// bad manifest or flags (before any job runs).
#include <fcntl.h>
#include <gflags/gflags.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"

extern char** environ;

DEFINE_string(manifest, "", "Batch: CSV of jobs (header: urdf,scan,out[,name,attach,options]).");
DEFINE_string(shard, "0/1", "Batch: i/N runs the rows k with k mod N = i (rows from 0).");

namespace edgefit::tools {
namespace {

struct Job {
  int row = 0;  // data row, from 0
  std::string name;
  std::vector<std::string> args;  // for `edgefit fit`
  std::string out;
};

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

std::string Trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
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

// Reads the manifest into jobs (all rows); errors name the file and line.
Status ReadManifest(const std::string& path, std::vector<Job>* jobs) {
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open the manifest");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  auto resolve = [&folder](const std::string& p) {
    return std::filesystem::path(p).is_absolute() || folder.empty() ? p : (folder / p).string();
  };
  std::string line;
  std::map<std::string, size_t> column;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    if (Trim(line).empty() || Trim(line)[0] == '#') continue;
    if (line.find('"') != std::string::npos) {
      return Status::Error(where + "quoted fields are not supported (lists use ';')");
    }
    std::vector<std::string> fields = Split(line, ',');
    for (std::string& f : fields) f = Trim(f);
    if (column.empty()) {  // the header
      for (size_t k = 0; k < fields.size(); ++k) {
        static const char* kKnown[] = {"name", "urdf", "attach", "scan", "out", "options"};
        if (std::find(std::begin(kKnown), std::end(kKnown), fields[k]) == std::end(kKnown)) {
          return Status::Error(where + "unknown column '" + fields[k] +
                               "' (name, urdf, attach, scan, out, options)");
        }
        column[fields[k]] = k;
      }
      for (const char* required : {"urdf", "scan", "out"}) {
        if (column.count(required) == 0) {
          return Status::Error(where + "the header lacks the column '" + required + "'");
        }
      }
      continue;
    }
    if (fields.size() != column.size()) {
      return Status::Error(where + std::to_string(fields.size()) + " fields, the header has " +
                           std::to_string(column.size()));
    }
    auto field = [&](const char* name) {
      return column.count(name) != 0 ? fields[column[name]] : std::string();
    };
    Job job;
    job.row = static_cast<int>(jobs->size());
    job.name = field("name").empty() ? "row " + std::to_string(job.row) : field("name");
    for (const char* required : {"urdf", "scan", "out"}) {
      if (field(required).empty()) return Status::Error(where + "empty '" + required + "'");
    }
    job.out = resolve(field("out"));
    job.args = {"fit", "--urdf=" + resolve(field("urdf")), "--out=" + job.out};
    std::string scans;
    for (const std::string& scan : Split(field("scan"), ';')) {
      if (!Trim(scan).empty()) scans += (scans.empty() ? "" : ",") + resolve(Trim(scan));
    }
    job.args.push_back("--scan=" + scans);
    std::string attach;
    for (const std::string& a : Split(field("attach"), ';')) {
      if (!Trim(a).empty()) attach += (attach.empty() ? "" : ",") + resolve(Trim(a));
    }
    if (!attach.empty()) job.args.push_back("--attach=" + attach);
    std::istringstream options(field("options"));
    for (std::string option; options >> option;) {
      for (const char* owned : {"--urdf", "--scan", "--out=", "--attach"}) {
        if (option.rfind(owned, 0) == 0) {
          return Status::Error(where + "option '" + option + "' belongs in its own column");
        }
      }
      if (option.rfind("--", 0) != 0) {
        return Status::Error(where + "option '" + option + "' is not a --flag");
      }
      // Path-valued flags follow the manifest's folder too.
      for (const char* path_flag :
           {"--truth=", "--out_joint_states=", "--out_urdf=", "--out_ply=", "--out_background="}) {
        const std::string prefix = path_flag;
        if (option.rfind(prefix, 0) == 0) option = prefix + resolve(option.substr(prefix.size()));
      }
      job.args.push_back(option);
    }
    if (FLAGS_threads > 0) job.args.push_back("--threads=" + std::to_string(FLAGS_threads));
    jobs->push_back(std::move(job));
  }
  if (column.empty()) return Status::Error(path + ": the manifest has no header row");
  return Status::Ok();
}

// Runs `edgefit <args>` (this executable); *error gets the child's last
// stderr line. Returns its exit code (kExitInternal when it could not run).
int RunChild(const std::vector<std::string>& args, std::string* error) {
  std::vector<char*> argv;
  static char self[] = "/proc/self/exe";
  argv.push_back(self);
  std::vector<std::string> copies = args;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) {
    *error = "cannot create a pipe";
    return kExitInternal;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, self, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  std::string output;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof(buffer))) > 0;) output.append(buffer, n);
  close(pipe_fds[0]);
  if (spawned != 0) {
    *error = "cannot start edgefit fit";
    return kExitInternal;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (!Trim(line).empty()) *error = Trim(line);
  }
  if (WIFSIGNALED(status)) {
    *error = "killed by signal " + std::to_string(WTERMSIG(status));
    return kExitInternal;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
}

int RunBatch(const Command& command) {
  if (FLAGS_manifest.empty()) return BadInput(command, "--manifest is required");
  int shard = 0, shards = 1;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseShard(FLAGS_shard, &shard, &shards));
  std::vector<Job> jobs;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadManifest(FLAGS_manifest, &jobs));
  std::vector<const Job*> mine;
  for (const Job& job : jobs) {
    if (job.row % shards == shard) mine.push_back(&job);
  }
  int failed = 0, not_ok = 0;
  std::vector<std::string> failures;
  const auto start = std::chrono::steady_clock::now();
  ProgressCounter counter(mine.size());
  for (size_t k = 0; k < mine.size(); ++k) {
    const Job& job = *mine[k];
    Progress("batch: job " + counter.Next() + ": " + job.name);
    const auto job_start = std::chrono::steady_clock::now();
    std::string error;
    const int code = RunChild(job.args, &error);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - job_start).count();
    std::string verdict;
    if (code != kExitOk) {
      ++failed;
      failures.push_back(job.name);
      verdict = "FAILED (exit " + std::to_string(code) + "): " + error;
    } else {
      std::ifstream result(job.out);
      const nlohmann::json json = nlohmann::json::parse(result, nullptr, false);
      const nlohmann::json quality =
          json.is_object() ? json.value("quality", nlohmann::json::object()) : nlohmann::json();
      const bool ok = quality.is_object() && quality.value("ok", false);
      not_ok += !ok;
      verdict = ok ? "ok"
                   : "done, quality not ok: " + (quality.is_object()
                                                     ? quality.value("message", std::string())
                                                     : std::string("unreadable result"));
    }
    std::printf("[%zu/%zu] %s: %s (%.1f s) -> %s\n", k + 1, mine.size(), job.name.c_str(),
                verdict.c_str(), seconds, job.out.c_str());
    std::fflush(stdout);
  }
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("batch: shard %d/%d, %zu of %zu jobs: %zu done (%d not ok), %d failed in %.1f s\n",
              shard, shards, mine.size(), jobs.size(), mine.size() - failed, not_ok, failed, total);
  for (const std::string& name : failures) std::printf("  failed: %s\n", name.c_str());
  return failed == 0 ? kExitOk : kExitInternal;
}

}  // namespace

Command BatchCommand() {
  return {"batch",
          "many fits from a manifest (CSV), split into shards across processes or machines",
          "Usage:\n"
          "  edgefit batch --manifest=jobs.csv [--shard=i/N] [--threads=N]\n"
          "Manifest (CSV, header row; relative paths from its folder; lists with ';'):\n"
          "  name,urdf,attach,scan,out,options\n"
          "  cell_3,robot.urdf,gun.urdf@tool0,cell3_a.ptx;cell3_b.ptx,cell3.json,--w_high=5\n"
          "Shard i of N runs the rows k with k mod N = i (a Slurm array: "
          "--shard=$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT).\n"
          "Exit 0: every job done; 1: a job failed (reported, the batch goes on); 2: bad "
          "manifest.",
          {"manifest", "shard", "threads"},
          RunBatch};
}

}  // namespace edgefit::tools
