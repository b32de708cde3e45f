#include "edgefit/report/tables_report.h"

#include <string>

#include "edgefit/core/atomic_file.h"
#include "html.h"

namespace edgefit {
namespace {

constexpr char kTablesStyle[] = R"css(
body { font: 14px/1.4 sans-serif; margin: 0 16px 24px; color: #222; }
h1 { font-size: 18px; margin: 12px 0 4px; }
h2 { font-size: 15px; margin: 22px 0 6px; }
p { margin: 4px 0; }
.caption { font-weight: bold; margin-top: 12px; }
.note { color: #555; font-size: 12px; }
table { border-collapse: collapse; font-size: 12px; margin: 4px 0; }
td, th { border-bottom: 1px solid #e3e3e3; padding: 2px 8px; text-align: right; white-space: nowrap; }
th { background: #f4f4f4; }
td:first-child, th:first-child { text-align: left; }
.charts { display: flex; flex-wrap: wrap; gap: 12px; }
#status { font-size: 11px; color: #888; margin-top: 16px; }
)css";

constexpr char kTablesScript[] = R"js(
'use strict';
const status = document.getElementById('status');
window.addEventListener('error', e => { status.textContent = 'error: ' + e.message; });
window.addEventListener('load', () => {
  if (status.textContent.startsWith('error')) return;
  status.textContent = 'ok: ' + document.querySelectorAll('table').length + ' tables, ' +
      document.querySelectorAll('svg.chart').length + ' charts';
});
)js";

}  // namespace

std::string TablesReportPage(const TablesReport& report) {
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" +
                     EscapeHtml(report.title) + "</title>\n<style>" + kTablesStyle +
                     "</style></head>\n<body>\n<h1>" + EscapeHtml(report.title) + "</h1>\n";
  for (const std::string& line : report.lines) page += "<p>" + EscapeHtml(line) + "</p>\n";
  if (!report.charts.empty()) {
    page += "<h2>" + EscapeHtml(report.charts_heading) + "</h2>\n<div class=\"charts\">\n";
    for (const Chart& chart : report.charts) page += SvgChart(chart);
    page += "</div>\n";
  }
  for (const Table& table : report.tables) page += HtmlTable(table);
  page += "<div id=\"status\">loading</div>\n<script>" + EscapeScript(kTablesScript) +
          "</script>\n</body></html>\n";
  return page;
}

Status WriteTablesReport(const TablesReport& report, const std::string& path) {
  return WriteStringAtomically(path, TablesReportPage(report));
}

}  // namespace edgefit
