// The world report (`edgefit clearance --out_report`): one self-contained
// HTML page that shows a planning world and one machine's way through it:
// the background's surface where the machine goes, every machine with what
// rides on it (attachments in their own colour), the machine checked at
// each waypoint (a slider, and a play button, move it along the trajectory),
// where it collides, and the clearance along the trajectory as plots. The
// 3D view is WebGL through three.js (three_js.h). Its script writes into
// #status "ok: N pixels drawn, P parts" once the view is drawn, or
// "error: ..." (headless tests read it).
#ifndef EDGEFIT_REPORT_WORLD_REPORT_H_
#define EDGEFIT_REPORT_WORLD_REPORT_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/report/chart.h"
#include "edgefit/report/three_js.h"

namespace edgefit {

struct WorldReportPart {
  enum class Kind { kBackground, kMachine, kAttachment };
  Kind kind = Kind::kMachine;
  std::string name;     // a link of cell.urdf, or "background"
  std::string machine;  // its machine's instance name; empty for the background
  TriangleMesh mesh;    // in the part's frame [m]
  // The part's pose: one (it stays where it is), or one per waypoint (it
  // moves with the machine checked).
  std::vector<Pose> T_world_part;
};

struct WorldReport {
  std::string title;
  std::vector<std::string> lines;  // under the title: what ran, what was found
  std::string machine;             // the machine checked (drawn darker)
  std::vector<WorldReportPart> parts;
  // Per waypoint: a line shown with it (its distances and collision), and
  // where it collides [world, m] (NaN: nowhere).
  std::vector<std::string> waypoint_notes;
  std::vector<Eigen::Vector3d> collision_points;
  std::vector<Chart> charts;  // along the trajectory
  std::string three_js_dir = kDebianThreeJsDir;
};

// Writes the page atomically. One line, nothing written, when three.js is
// missing, there are no waypoints, a part has no pose or a moving part's
// poses or the collision points do not match waypoint_notes.
Status WriteWorldReport(const WorldReport& report, const std::string& path);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_WORLD_REPORT_H_
