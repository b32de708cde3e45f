// edgefit batch: many fits from a manifest, one `edgefit fit` process per
// job, split into shards across processes or machines, and their results
// gathered again.
//   edgefit batch --manifest=jobs.csv [--rows=3,7-9] [--shard=i/N] [--threads=N]
//   edgefit batch --manifest=jobs.csv --merge [--out_csv=F.csv] [--out_report=B.html]
// The manifest is CSV with a header row naming its columns:
//   urdf, scan, out   required; several scans separated by ';'
//   name              optional (default: the row number)
//   attach            optional; several separated by ';'
//   options           optional: more `edgefit fit` flags, separated by spaces
//                     (--kind=conveyance --weighting=uniform --truth=T.json ...)
// Relative paths (the columns' and those of --truth and --out_* in options)
// are taken from the manifest's folder; fields are not quoted
// (lists use ';'). The rows run are all data rows (counted from 0) or
// --rows; shard i of N runs the k-th of them with k mod N = i. Each job
// writes its outputs atomically (edgefit fit): a failed job leaves none but a
// record <out>.failed with its error line, is reported, and the batch goes
// on. Exit 0 when every job of the shard succeeded, 1 when one failed, 2 on a
// bad manifest or flags (before any job runs). --merge: batch_merge.h.
#include <fcntl.h>
#include <gflags/gflags.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "batch_manifest.h"
#include "batch_merge.h"
#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/core/atomic_file.h"

extern char** environ;

DEFINE_string(manifest, "", "Batch: CSV of jobs (header: urdf,scan,out[,name,attach,options]).");
DEFINE_string(rows, "",
              "Batch: only these rows of the manifest (from 0; '3,7,10-12'), e.g. those "
              "--merge reports missing or failed.");
DEFINE_bool(merge, false,
            "Batch: run nothing; gather every row's result into one table and summary, list "
            "the rows missing or failed (--out_csv, --out_report).");

namespace edgefit::tools {
namespace {

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
    *error = "cannot start edgefit";
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

// Leaves the record of a failed job beside its output, or removes a stale
// one when the job succeeded; a record that cannot be written is said.
void RecordOutcome(const Job& job, int code, const std::string& error) {
  const std::string record = FailureRecordPath(job);
  if (code == kExitOk) {
    std::remove(record.c_str());
    return;
  }
  const Status status =
      WriteStringAtomically(record, "exit " + std::to_string(code) + ": " + error + "\n");
  if (!status.ok()) std::printf("  (no failure record: %s)\n", status.message().c_str());
}

int RunBatch(const Command& command) {
  if (FLAGS_manifest.empty()) return BadInput(command, "--manifest is required");
  int shard = 0, shards = 1;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseShard(FLAGS_shard, &shard, &shards));
  std::vector<Job> jobs;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadManifest(FLAGS_manifest, FLAGS_threads, &jobs));
  std::vector<int> rows;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                               ParseRows(FLAGS_rows, static_cast<int>(jobs.size()), &rows));
  if (FLAGS_merge) {
    if (!FLAGS_rows.empty() || FLAGS_shard != "0/1") {
      return BadInput(command, "--merge reads every row: no --rows or --shard with it");
    }
    return MergeBatch(command, FLAGS_manifest, jobs);
  }
  if (!FLAGS_out_csv.empty() || !FLAGS_out_report.empty()) {
    return BadInput(command, "--out_csv and --out_report go with --merge");
  }
  // The k-th selected row belongs to shard k mod N.
  std::vector<const Job*> mine;
  for (size_t k = 0; k < rows.size(); ++k) {
    if (static_cast<int>(k % static_cast<size_t>(shards)) == shard) {
      mine.push_back(&jobs[static_cast<size_t>(rows[k])]);
    }
  }
  int failed = 0, not_ok = 0;
  std::vector<std::string> failures;
  const auto start = std::chrono::steady_clock::now();
  ProgressCounter counter(mine.size());
  for (size_t k = 0; k < mine.size(); ++k) {
    const Job& job = *mine[k];
    Progress("batch: job " + counter.Next() + ": row " + std::to_string(job.row) + ", " +
             job.name);
    const auto job_start = std::chrono::steady_clock::now();
    std::string error;
    const int code = RunChild(job.args, &error);
    const double seconds = SecondsSince(job_start);
    std::string verdict;
    if (code != kExitOk) {
      ++failed;
      failures.push_back(job.name);
      verdict = "FAILED (exit " + std::to_string(code) + "): " + error;
    } else {
      const RowResult row = ReadRow(job);
      not_ok += !row.ok;
      verdict = row.ok ? "ok" : "done, quality not ok: " + row.message;
    }
    std::printf("[%zu/%zu] %s: %s (%.1f s) -> %s\n", k + 1, mine.size(), job.name.c_str(),
                verdict.c_str(), seconds, job.out.c_str());
    RecordOutcome(job, code, error);
    std::fflush(stdout);
  }
  const double total = SecondsSince(start);
  std::printf("batch: shard %d/%d, %zu of %zu jobs: %zu done (%d not ok), %d failed in %.1f s\n",
              shard, shards, mine.size(), jobs.size(), mine.size() - failed, not_ok, failed, total);
  for (const std::string& name : failures) std::printf("  failed: %s\n", name.c_str());
  return failed == 0 ? kExitOk : kExitInternal;
}

}  // namespace

Command BatchCommand() {
  return {"batch",
          "many fits and cells from a manifest (CSV), split into shards across processes, "
          "machines or a Slurm array, and merged again",
          "Usage:\n"
          "  edgefit batch --manifest=jobs.csv [--rows=3,7-9] [--shard=i/N] [--threads=N]\n"
          "  edgefit batch --manifest=jobs.csv --merge [--out_csv=F.csv] [--out_report=B.html]\n"
          "Manifest (CSV, header row; relative paths from its folder; lists with ';'):\n"
          "  name,urdf,attach,scan,out,options\n"
          "  cell_3,robot.urdf,gun.urdf@tool0,cell3_a.ptx;cell3_b.ptx,cell3.json,--w_high=5\n"
          "Shard i of N runs the k-th row (of all, or of --rows) with k mod N = i (a Slurm "
          "array: scripts/slurm/batch.sbatch).\n"
          "--merge gathers every row's result (whoever wrote it), prints one table and a "
          "summary, and the --rows to resubmit for the rows missing or failed.\n"
          "Exit 0: every job done; 1: a job failed (reported, the batch goes on), or with "
          "--merge a row missing or failed; 2: bad manifest or flags.",
          {"manifest", "shard", "rows", "merge", "out_csv", "out_report", "threads"},
          RunBatch};
}

}  // namespace edgefit::tools
