// The fit report (`edgefit fit --out_report`): one self-contained HTML file
// that opens offline from any folder and shows a fit so that a person can
// judge it at a glance: the scan around the asset, thinned, each point
// coloured by its distance to the fitted model (points far from it, such as
// accessories, jackets and the surroundings, stand out in grey); the fitted
// meshes, which can be toggled, seen from anywhere or from each station;
// what each station saw as an image (also PNG files); the edge map (paper
// Sec. 4: the points in valid edge regions, which Eq. 6 weights w_high); the
// verdict, and per joint its value, verdict, standard deviation and, with a
// truth, its error; the stage timings and the options. The 3D view is WebGL through three.js, embedded
// from Debian's libjs-three (read when the report is written).
#ifndef EDGEFIT_REPORT_FIT_REPORT_H_
#define EDGEFIT_REPORT_FIT_REPORT_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/report/three_js.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct FitReportOptions {
  // Points shown at most: the valid cells near the model, every k-th
  // (deterministic). 300 000 points keep the page near 10 MB and fluid.
  size_t max_points = 300000;
  // Points within this of the fitted model's bounding box are shown [m].
  double margin = 0.3;
  // Colours: distance 0 green through yellow to red at residual_scale [m];
  // beyond not_modelled grey (the scan there is not the model) [m].
  double residual_scale = 0.005;
  double not_modelled = 0.015;
  // The model's surface samples the distances are measured to [m].
  double sample_spacing = 0.003;
  uint64_t seed = 1;
  // What each station saw (its grid around the model, coloured the same
  // way) at most this many pixels a side; station_pngs: also written as
  // PNG files beside the report (StationImagePath).
  int max_image_size = 1600;
  bool station_pngs = true;
  // The edge map: Sec. 4 run on the scans with these options (the fit's),
  // so the view can colour the points Eq. (6) weights w_high. Scans without
  // a lattice have none (the page says so).
  bool edge_map = true;
  EdgeDetectionOptions edges;
  std::string three_js_dir = kDebianThreeJsDir;  // three.js (three_js.h)

  bool IsValid(std::string* error) const;
};

// Whether three.js is where options.three_js_dir says (check before a fit
// whose report is asked for).
Status CheckFitReportScripts(const FitReportOptions& options);

// The PNG of station k (0-based) beside the report: R.html -> R_station_<k+1>.png.
std::string StationImagePath(const std::string& report_path, size_t station);

// Writes the report of `result` (result.json of the fit) for the model at
// (q, T_world_base) over `scans` to `path`, and the stations' PNG files,
// each atomically; each scan placed by its station's correction
// (station_corrections, scan order, as the fit registered them:
// T_world_scanner = correction * written; empty: as written). *written
// (may be null) gets the files written. Fails (nothing written) on invalid
// options, q or corrections of the wrong size, three.js missing, or a file
// not writable.
Status WriteFitReport(const KinematicModel& model, const std::vector<double>& q,
                      const Pose& T_world_base, const ScanSet& scans,
                      const std::vector<Pose>& station_corrections, const nlohmann::json& result,
                      const std::string& title, const FitReportOptions& options,
                      const std::string& path, std::vector<std::string>* written);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_FIT_REPORT_H_
