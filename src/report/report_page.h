// The report's HTML page: the data (fit_report.cc) and three.js embedded in
// one file that needs nothing else. The page's script draws the 3D view,
// the tables and the residual histograms from the data, and writes what it
// did into the element #status: "ok: N pixels drawn" once the view is drawn,
// "error: ..." on any script error (headless tests read it).
#ifndef EDGEFIT_REPORT_REPORT_PAGE_H_
#define EDGEFIT_REPORT_REPORT_PAGE_H_

#include <string>

namespace edgefit {

// title: the page's title (escaped here); three_js, orbit_controls_js: the
// scripts of Debian's libjs-three (three.min.js and OrbitControls.js);
// data_json: the report's data, a JSON object.
std::string ReportPage(const std::string& title, const std::string& three_js,
                       const std::string& orbit_controls_js, const std::string& data_json);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_REPORT_PAGE_H_
