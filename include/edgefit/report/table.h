// A table of text cells, written as Markdown (the bench's output,
// BENCHMARK.md) or as HTML (the reports): one table, two renderings, so the
// terminal and the report never disagree.
#ifndef EDGEFIT_REPORT_TABLE_H_
#define EDGEFIT_REPORT_TABLE_H_

#include <string>
#include <vector>

namespace edgefit {

struct Table {
  std::string heading;  // a section heading before the table ("" for none)
  std::string caption;  // a line before the table ("robot (degrees):")
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as wide as header
  std::string note;     // a line after the table ("" for none)
};

// "## heading", the caption, the table with a |---| rule, the note; blank
// lines between. A table without header is only its heading and lines.
std::string MarkdownTable(const Table& table);
// <h2>, <p>, <table> with <th> and <td>, <p>; every text escaped.
std::string HtmlTable(const Table& table);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_TABLE_H_
