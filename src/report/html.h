// Text made safe for the reports' HTML pages.
#ifndef EDGEFIT_REPORT_HTML_H_
#define EDGEFIT_REPORT_HTML_H_

#include <string>

namespace edgefit {

// Text safe inside an HTML element or attribute value (also SVG).
inline std::string EscapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A script's text safe inside <script>: no "</" that could close it.
inline std::string EscapeScript(const std::string& script) {
  std::string out;
  out.reserve(script.size());
  for (size_t i = 0; i < script.size(); ++i) {
    out += script[i];
    if (script[i] == '<' && i + 1 < script.size() && script[i + 1] == '/') out += "\\";
  }
  return out;
}

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_HTML_H_
