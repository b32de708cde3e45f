// A trajectory as CSV, as planners export one: a header row of joint names,
// then one row of joint values per waypoint, in radians (revolute,
// continuous) or metres (prismatic). Fields are separated by commas (spaces
// around them ignored); blank lines and lines starting with '#' are skipped.
//   a1,a2,a3
//   0,0.1,-0.5
//   0.2,0.1,-0.4
#ifndef EDGEFIT_IO_TRAJECTORY_CSV_H_
#define EDGEFIT_IO_TRAJECTORY_CSV_H_

#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

struct Trajectory {
  std::vector<std::string> joints;             // the header's names
  std::vector<std::vector<double>> waypoints;  // one value per joint each
};

// Reads `path`. One line naming the file (and its line) on a missing file,
// no header or no waypoint, an empty or repeated name, a row of another
// length, or a value that is not a finite number.
Status ReadTrajectoryCsv(const std::string& path, Trajectory* trajectory);

}  // namespace edgefit

#endif  // EDGEFIT_IO_TRAJECTORY_CSV_H_
