// A pose read back from the JSON layout PoseRows writes (result.json, the
// truth file): four rows of four numbers. Header-only and generic in the
// JSON type (nlohmann::json or ordered_json), so core needs no JSON library.
#ifndef EDGEFIT_CORE_POSE_JSON_H_
#define EDGEFIT_CORE_POSE_JSON_H_

#include <Eigen/Geometry>
#include <cmath>

#include "edgefit/core/pose.h"

namespace edgefit {

// False, leaving *T as it was, unless j is 4 x 4 finite numbers whose
// rotation is orthonormal (1e-6) and whose last row is 0 0 0 1.
template <class Json>
bool PoseFromJson(const Json& j, Pose* T) {
  if (!j.is_array() || j.size() != 4) return false;
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    if (!j[r].is_array() || j[r].size() != 4) return false;
    for (int c = 0; c < 4; ++c) {
      if (!j[r][c].is_number()) return false;
      m(r, c) = j[r][c].template get<double>();
      if (!std::isfinite(m(r, c))) return false;
    }
  }
  const Eigen::Matrix3d R = m.topLeftCorner<3, 3>();
  if (!(R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-6) ||
      !m.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1))) {
    return false;
  }
  T->matrix() = m;
  return true;
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_POSE_JSON_H_
