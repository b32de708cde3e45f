// edgefit batch --merge: the batch's results gathered from every row's
// output, whichever process or array task wrote them: one table, one
// summary, and the rows missing or failed, to resubmit with --rows.
#ifndef EDGEFIT_TOOLS_BATCH_MERGE_H_
#define EDGEFIT_TOOLS_BATCH_MERGE_H_

#include <string>
#include <vector>

#include "batch_manifest.h"
#include "command_line.h"

namespace edgefit::tools {

// Prints the table and summary; --out_csv, --out_report. Exit 0 when every
// row is done, 1 when one is missing or failed, 2 when an output cannot be
// written.
int MergeBatch(const Command& command, const std::string& manifest, const std::vector<Job>& jobs);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_BATCH_MERGE_H_
