#include "read_common.h"

#include "camera_grid.h"

#include "edgefit/scan/lattice_estimation.h"

#include <string>
#include <utility>

namespace edgefit {
namespace io_internal {

Status FinishScan(const std::string& what, const ReadOptions& options, OrganizedScan* scan) {
  if (scan->size() == 0 || scan->CountValid() == 0) {
    return Status::Error(what + ": no valid points");
  }
  const CameraInfo& camera = options.camera;
  if (options.estimate_lattice && !scan->organized() && !camera.empty()) {
    OrganizedScan grid;
    EDGEFIT_RETURN_IF_ERROR(GridOnCamera(what, camera, *scan, &grid));
    *scan = std::move(grid);
  }
  if (!options.intensity) scan->DropIntensity();
  scan->ShareEmptyChunks();
  if (options.estimate_lattice && scan->organized()) {
    if (!camera.empty()) {
      if (camera.width != scan->cols() || camera.height != scan->rows()) {
        return Status::Error(what + ": the grid is " + std::to_string(scan->cols()) + " x " +
                             std::to_string(scan->rows()) + " cells, the camera (" +
                             camera.source + ") " + std::to_string(camera.width) + " x " +
                             std::to_string(camera.height) + " pixels");
      }
      scan->set_lattice(ScanLattice(scan->rows(), scan->cols(), camera.camera));
      return Status::Ok();
    }
    ScanLattice lattice;
    const Status status = EstimateLattice(*scan, options.lattice, &lattice);
    if (!status.ok()) return Status::Error(what + ": " + status.message());
    scan->set_lattice(std::move(lattice));
  }
  return Status::Ok();
}

}  // namespace io_internal
}  // namespace edgefit
