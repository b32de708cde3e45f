#include "asset_output.h"

#include <cmath>
#include <filesystem>
#include <system_error>

#include "edgefit/assets/stl_writer.h"
#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace assets_internal {
namespace {

Pose Rotated(double x, double y, double z, const Eigen::Vector3d& axis, double angle) {
  Pose T = Pose::Identity();
  T.translate(Eigen::Vector3d(x, y, z));
  T.rotate(Eigen::AngleAxisd(angle, axis));
  return T;
}

Status MakeDirectory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) return Status::Error(dir + ": cannot create directory: " + error.message());
  return Status::Ok();
}

}  // namespace

Pose At(double x, double y, double z) { return Pose(Eigen::Translation3d(x, y, z)); }
// Ry(+90 deg) takes +z to +x; Rx(-90 deg) takes +z to +y; Rx(+90 deg) to -y.
Pose AlongX(double x, double y, double z) { return Rotated(x, y, z, Eigen::Vector3d::UnitY(), M_PI_2); }
Pose AlongMinusX(double x, double y, double z) {
  return Rotated(x, y, z, Eigen::Vector3d::UnitY(), -M_PI_2);
}
Pose AlongY(double x, double y, double z) { return Rotated(x, y, z, Eigen::Vector3d::UnitX(), -M_PI_2); }
Pose AlongMinusY(double x, double y, double z) {
  return Rotated(x, y, z, Eigen::Vector3d::UnitX(), M_PI_2);
}
Pose AlongMinusZ(double x, double y, double z) {
  return Rotated(x, y, z, Eigen::Vector3d::UnitX(), M_PI);
}

Status WriteLinkMeshes(const std::string& dir, const std::vector<LinkMesh>& meshes) {
  EDGEFIT_RETURN_IF_ERROR(MakeDirectory(dir + "/meshes"));
  for (const LinkMesh& link : meshes) {
    EDGEFIT_RETURN_IF_ERROR(
        WriteBinaryStl(dir + "/meshes/" + link.link + ".stl", link.mesh, link.link));
  }
  return Status::Ok();
}

Status WriteTextFile(const std::string& dir, const std::string& name, const std::string& text) {
  EDGEFIT_RETURN_IF_ERROR(MakeDirectory(dir));
  return WriteStringAtomically(dir + "/" + name, text);
}

}  // namespace assets_internal
}  // namespace edgefit
