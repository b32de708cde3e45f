// edgefit batch --merge: the batch's results gathered from every row's
// output, whichever process or array task wrote them: one table, one
// summary, and the rows missing or failed, to resubmit with --rows.
#ifndef EDGEFIT_TOOLS_BATCH_MERGE_H_
#define EDGEFIT_TOOLS_BATCH_MERGE_H_

#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch_manifest.h"
#include "command_line.h"

namespace edgefit::tools {

enum class RowState { kDone, kFailed, kMissing };

// What a row's output says: done (its result.json of edgefit fit, or the
// output of edgefit cell), failed (its failure record, or an output that is
// neither) or missing.
struct RowResult {
  const Job* job = nullptr;
  RowState state = RowState::kMissing;
  bool ok = false;       // a fit's quality.ok; a cell's counts met and every instance ok
  std::string message;   // the fit's quality message, the cell's instances, or the failure
  double seconds = std::numeric_limits<double>::quiet_NaN();
  nlohmann::json result;  // the output when done
};

RowResult ReadRow(const Job& job);

// Prints the table and summary; --out_csv, --out_report. Exit 0 when every
// row is done, 1 when one is missing or failed, 2 when an output cannot be
// written.
int MergeBatch(const Command& command, const std::string& manifest, const std::vector<Job>& jobs);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_BATCH_MERGE_H_
