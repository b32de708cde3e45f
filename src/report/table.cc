#include "edgefit/report/table.h"

#include <string>

#include "html.h"

namespace edgefit {

std::string MarkdownTable(const Table& table) {
  std::string out;
  if (!table.heading.empty()) out += "\n## " + table.heading + "\n";
  if (!table.caption.empty()) out += "\n" + table.caption + "\n";
  if (!table.header.empty()) {
    out += "\n|";
    for (const std::string& h : table.header) out += " " + h + " |";
    out += "\n|";
    for (size_t k = 0; k < table.header.size(); ++k) out += "---|";
    out += "\n";
    for (const std::vector<std::string>& row : table.rows) {
      out += "|";
      for (const std::string& cell : row) out += " " + cell + " |";
      out += "\n";
    }
  }
  if (!table.note.empty()) out += "\n" + table.note + "\n";
  return out;
}

std::string HtmlTable(const Table& table) {
  std::string out;
  if (!table.heading.empty()) out += "<h2>" + EscapeHtml(table.heading) + "</h2>\n";
  if (!table.caption.empty()) out += "<p class=\"caption\">" + EscapeHtml(table.caption) + "</p>\n";
  if (!table.header.empty()) {
    out += "<table>\n<tr>";
    for (const std::string& h : table.header) out += "<th>" + EscapeHtml(h) + "</th>";
    out += "</tr>\n";
    for (const std::vector<std::string>& row : table.rows) {
      out += "<tr>";
      for (const std::string& cell : row) out += "<td>" + EscapeHtml(cell) + "</td>";
      out += "</tr>\n";
    }
    out += "</table>\n";
  }
  if (!table.note.empty()) out += "<p class=\"note\">" + EscapeHtml(table.note) + "</p>\n";
  return out;
}

}  // namespace edgefit
