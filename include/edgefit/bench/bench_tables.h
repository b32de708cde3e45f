// The bench's tables and ablation plots (paper Sec. 7.3-7.4), made from its
// runs: the JSON array `edgefit bench --out_json` writes, one object per fit
// (docs/commands.md). The same tables print as Markdown and go into the
// bench's HTML report, so a saved run can be reported again later.
#ifndef EDGEFIT_BENCH_BENCH_TABLES_H_
#define EDGEFIT_BENCH_BENCH_TABLES_H_

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "edgefit/core/status.h"
#include "edgefit/report/table.h"
#include "edgefit/report/tables_report.h"

namespace edgefit {

// Whether `runs` is an array of the bench's run objects with every field
// the tables read; the error names the run and the field.
Status CheckBenchRuns(const nlohmann::json& runs);

// Table 1 (rotation error per joint, degrees) and Table 2 (translation
// error per joint, mm), a table per asset each; base, tool tip and time per
// stage, a row per run; and, when a setting varies (an ablation axis or
// repeats), the summary per setting: mean, p95 and max per joint kind, tool
// tip, base, failure and not-ok rates, mean time.
std::vector<Table> BenchTables(const nlohmann::json& runs);

// The bench's report: what ran (`command`), the plots, the tables.
TablesReport BenchReport(const nlohmann::json& runs, const std::string& command);

}  // namespace edgefit

#endif  // EDGEFIT_BENCH_BENCH_TABLES_H_
