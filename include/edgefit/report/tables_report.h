// A report of tables and charts (the bench's tables and ablation plots,
// the batch's jobs): one self-contained HTML page that opens offline, the
// charts inline SVG. Its one script writes into #status "ok: T tables, C
// charts" once the page has loaded, or "error: ..." on a script error
// (headless tests read it).
#ifndef EDGEFIT_REPORT_TABLES_REPORT_H_
#define EDGEFIT_REPORT_TABLES_REPORT_H_

#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/report/chart.h"
#include "edgefit/report/table.h"

namespace edgefit {

struct TablesReport {
  std::string title;
  std::vector<std::string> lines;  // under the title: what ran, the command
  std::string charts_heading = "Plots";
  std::vector<Chart> charts;       // first: they are what one sees at a glance
  std::vector<Table> tables;
};

std::string TablesReportPage(const TablesReport& report);
// The page, written atomically.
Status WriteTablesReport(const TablesReport& report, const std::string& path);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_TABLES_REPORT_H_
