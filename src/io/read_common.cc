#include "read_common.h"

#include "edgefit/scan/lattice_estimation.h"

namespace edgefit {
namespace io_internal {

Status FinishScan(const std::string& what, const ReadOptions& options, OrganizedScan* scan) {
  if (scan->size() == 0 || scan->CountValid() == 0) {
    return Status::Error(what + ": no valid points");
  }
  if (options.estimate_lattice && scan->organized()) {
    AngularLattice lattice;
    const Status status = EstimateLattice(*scan, options.lattice, &lattice);
    if (!status.ok()) return Status::Error(what + ": " + status.message());
    scan->set_lattice(std::move(lattice));
  }
  return Status::Ok();
}

}  // namespace io_internal
}  // namespace edgefit
