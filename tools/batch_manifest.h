// The batch's manifest (edgefit batch): a CSV of `edgefit fit` and
// `edgefit cell` jobs, which
// rows a process runs (--rows, --shard), and where a failed job leaves its
// record for --merge.
#ifndef EDGEFIT_TOOLS_BATCH_MANIFEST_H_
#define EDGEFIT_TOOLS_BATCH_MANIFEST_H_

#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit::tools {

// A row: `edgefit fit` of one model (column urdf), or `edgefit cell` of
// every instance of several (column models).
struct Job {
  int row = 0;  // data row, from 0
  std::string name;
  bool cell = false;
  std::vector<std::string> args;  // for `edgefit fit` or `edgefit cell`
  std::string out;
};

// Reads the manifest into jobs (all rows), `threads` (> 0) passed on to
// every fit; errors name the file and line.
Status ReadManifest(const std::string& path, int threads, std::vector<Job>* jobs);

// "3,7,10-12": rows (from 0) in the order given, each once; every one must
// be below `rows`. Empty text: every row.
Status ParseRows(const std::string& text, int rows, std::vector<int>* selected);

// The record a failed job leaves beside its output: <out>.failed holds the
// exit code and the fit's error line (removed when the job later succeeds).
std::string FailureRecordPath(const Job& job);

// Trims blanks and carriage returns.
std::string Trim(const std::string& s);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_BATCH_MANIFEST_H_
