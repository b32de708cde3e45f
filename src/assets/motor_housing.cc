#include "edgefit/assets/motor_housing.h"

#include <glog/logging.h>

#include <cmath>

#include "edgefit/assets/rectangular_loft.h"
#include "edgefit/assets/revolved_mesh.h"
#include "edgefit/model/primitive_meshes.h"

namespace edgefit {

TriangleMesh MakeMotorHousing(const MotorHousingOptions& o) {
  CHECK_GT(o.flange_radius, o.radius);
  CHECK_GT(o.length, o.flange_thickness + 2.0 * o.chamfer);
  const double rc = o.cap_radius_ratio * o.radius;
  CHECK(rc > 0.0 && rc < o.radius - o.chamfer);
  const double c = o.chamfer;
  // Flange (chamfered front rim), step in to the body, chamfered rear rim,
  // step in to the encoder cap.
  TriangleMesh mesh = MakeRevolvedSolid({{0.0, o.flange_radius - c},
                                         {c, o.flange_radius},
                                         {o.flange_thickness, o.flange_radius},
                                         {o.flange_thickness, o.radius},
                                         {o.length - c, o.radius},
                                         {o.length, o.radius - c},
                                         {o.length, rc},
                                         {o.length + o.cap_height, rc}},
                                        o.segments);
  // Ribs sink 2 mm into the body so the parts overlap instead of touching.
  constexpr double kSink = 0.002;  // [m]
  const double rib_length = o.length - o.flange_thickness - 3.0 * c;
  for (int k = 0; k < o.rib_count; ++k) {
    // Offset by half a pitch so no rib sits under the connector on +x.
    const double theta = 2.0 * M_PI * (k + 0.5) / o.rib_count;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.rotate(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()));
    T.translate(Eigen::Vector3d(o.radius + 0.5 * o.rib_height - kSink, 0.0,
                                o.flange_thickness + c + 0.5 * rib_length));
    mesh.Append(MakeBoxMesh(Eigen::Vector3d(o.rib_height + kSink, o.rib_width, rib_length)), T);
  }
  if (o.connector) {
    const Eigen::Vector3d size(0.45 * o.radius + kSink, 0.7 * o.radius, 0.35 * o.length);
    const Eigen::Isometry3d T(
        Eigen::Translation3d(o.radius + 0.5 * size.x() - 2.0 * kSink, 0.0, 0.6 * o.length));
    mesh.Append(MakeChamferedBox(size, 0.2 * size.minCoeff()), T);
  }
  return mesh;
}

}  // namespace edgefit
