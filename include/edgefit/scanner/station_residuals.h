// Station registration residuals: the poses a multi-station survey writes
// into its files come from a registration (targets, cloud-to-cloud) that is
// good to a few millimetres and hundredths of a degree, not exact. Each
// station's written pose is its true pose moved by a seeded error:
//
//   T_written = [R(a, phi) R_true | t_true + e],
//
// a rotation by phi in [rotation_min, rotation_max] about a random axis a
// through the scanner's origin and a translation e of random direction and
// length in [translation_min, translation_max]. The points stay in the
// scanner frame, so the stations of one scan no longer agree.
#ifndef EDGEFIT_SCANNER_STATION_RESIDUALS_H_
#define EDGEFIT_SCANNER_STATION_RESIDUALS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"

namespace edgefit {

struct StationResidualOptions {
  bool enabled = false;
  double translation_min = 0.001;  // [m]
  double translation_max = 0.003;  // [m]
  double rotation_min = 0.005 * M_PI / 180.0;  // [rad]
  double rotation_max = 0.02 * M_PI / 180.0;   // [rad]
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// The written poses of stations at T_world_true (station i on stream i).
std::vector<Pose> PerturbStationPoses(const std::vector<Pose>& T_world_true,
                                      const StationResidualOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_STATION_RESIDUALS_H_
