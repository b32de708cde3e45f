// three.js for the reports' 3D views: Debian's libjs-three, read when a
// report is written and embedded in it, so that the page opens offline.
#ifndef EDGEFIT_REPORT_THREE_JS_H_
#define EDGEFIT_REPORT_THREE_JS_H_

#include <string>

#include "edgefit/core/status.h"

namespace edgefit {

// Where libjs-three installs three.min.js and
// examples/js/controls/OrbitControls.js.
inline constexpr char kDebianThreeJsDir[] = "/usr/share/javascript/three";

// Whether both scripts are in `dir`; else one line naming the file missing
// and the package that installs it.
Status CheckThreeJs(const std::string& dir);
// Both scripts' text.
Status ReadThreeJs(const std::string& dir, std::string* three_js, std::string* orbit_controls_js);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_THREE_JS_H_
