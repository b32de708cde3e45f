#include "edgefit/edges/grid_cloud.h"

#include <glog/logging.h>

#include <limits>

namespace edgefit {

GridCloud GridCloud::FromScan(const OrganizedScan& scan) {
  CHECK(scan.organized() && scan.lattice().valid()) << "GridCloud needs an organized scan with lattice";
  GridCloud cloud;
  cloud.rows = scan.rows();
  cloud.cols = scan.cols();
  cloud.wrap_cols = scan.lattice().full_circle();
  cloud.row_step = static_cast<float>(std::abs(scan.lattice().row_step()));
  cloud.col_step = static_cast<float>(std::abs(scan.lattice().col_step()));
  const size_t n = scan.size();
  cloud.x.resize(n);
  cloud.y.resize(n);
  cloud.z.resize(n);
  cloud.range.resize(n);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = scan.point_scanner(i);
    const bool valid = std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
    cloud.x[i] = valid ? p.x() : nan;
    cloud.y[i] = valid ? p.y() : nan;
    cloud.z[i] = valid ? p.z() : nan;
    cloud.range[i] = valid ? p.norm() : nan;
  }
  return cloud;
}

}  // namespace edgefit
