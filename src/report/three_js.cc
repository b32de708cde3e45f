#include "edgefit/report/three_js.h"

#include <fstream>
#include <string>

#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace {

std::string ThreePath(const std::string& dir) { return dir + "/three.min.js"; }
std::string OrbitControlsPath(const std::string& dir) {
  return dir + "/examples/js/controls/OrbitControls.js";
}

}  // namespace

Status CheckThreeJs(const std::string& dir) {
  for (const std::string& script : {ThreePath(dir), OrbitControlsPath(dir)}) {
    if (!std::ifstream(script).good()) {
      return Status::Error("report: three.js not found: " + script +
                           " (Debian's libjs-three; ./scripts/install-deps.sh installs it)");
    }
  }
  return Status::Ok();
}

Status ReadThreeJs(const std::string& dir, std::string* three_js, std::string* orbit_controls_js) {
  EDGEFIT_RETURN_IF_ERROR(CheckThreeJs(dir));
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(ThreePath(dir), three_js));
  return ReadFileToString(OrbitControlsPath(dir), orbit_controls_js);
}

}  // namespace edgefit
