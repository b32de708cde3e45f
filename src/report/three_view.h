// What both 3D reports (report_page.cc, world_report.cc) share: the page's
// head with the style of the view, its side panel and the status line; and
// its end: the data (a JSON object in #data), three.js, and a script that
// sets up the status line, `data`, decode(), a three.js renderer, scene and
// lights in the element #view and drawnPixels() before the page's own.
#ifndef EDGEFIT_REPORT_THREE_VIEW_H_
#define EDGEFIT_REPORT_THREE_VIEW_H_

#include <string>

namespace edgefit {

// Up to <body>: `title` (escaped here), the shared style, then `style`.
std::string ThreeViewPageHead(const std::string& title, const char* style);

// From the data to </html>: `script` runs after the shared one.
std::string ThreeViewPageEnd(const std::string& data_json, const std::string& three_js,
                             const std::string& orbit_controls_js, const char* script);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_THREE_VIEW_H_
