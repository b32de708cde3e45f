// Private: steps every reader shares after a scan is loaded.
#ifndef EDGEFIT_SRC_IO_READ_COMMON_H_
#define EDGEFIT_SRC_IO_READ_COMMON_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {
namespace io_internal {

// Fails for a scan without valid points; estimates the lattice of an
// organized scan when asked (a point list read with a camera's intrinsics
// first put on its pixel grid: camera_grid.h); drops the intensities
// unless ReadOptions::intensity. `what` names the scan, e.g.
// "f.ptx: scan 2".
Status FinishScan(const std::string& what, const ReadOptions& options, OrganizedScan* scan);

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_READ_COMMON_H_
