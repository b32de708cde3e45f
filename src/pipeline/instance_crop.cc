#include "edgefit/pipeline/instance_crop.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace edgefit {

bool InstanceCropOptions::IsValid(std::string* error) const {
  if (!(margin >= 0.0 && margin < 100.0)) {
    if (error != nullptr) *error = "crop margin must be in [0, 100) m";
    return false;
  }
  return true;
}

double ModelReach(const KinematicModel& model) {
  const auto& links = model.links();
  const auto& joints = model.joints();
  std::vector<double> origin(links.size(), -1.0);  // reach of each link's origin
  std::function<double(int)> reach_of = [&](int link) -> double {
    double& r = origin[static_cast<size_t>(link)];
    if (r >= 0.0) return r;
    const int pj = links[static_cast<size_t>(link)].parent_joint;
    if (pj < 0) return r = 0.0;
    const Joint& j = joints[static_cast<size_t>(pj)];
    const double travel = j.type == JointType::kPrismatic ? std::max(std::abs(j.lower), std::abs(j.upper)) : 0.0;
    return r = reach_of(j.parent_link) + j.T_parent_joint.translation().norm() + travel;
  };
  double reach = 0.0;
  for (size_t k = 0; k < links.size(); ++k) {
    double radius = 0.0;
    for (const Eigen::Vector3d& v : links[k].mesh.vertices) radius = std::max(radius, v.norm());
    reach = std::max(reach, reach_of(static_cast<int>(k)) + radius);
  }
  return reach;
}

ScanSet CropToRays(const ScanSet& scans, const std::vector<Eigen::Vector3d>& centers_world,
                   double radius) {
  ScanSet cropped = scans;
  for (OrganizedScan& scan : cropped.scans) {
    const Pose T_scanner_world = scan.T_world_scanner().inverse();
    std::vector<Eigen::Vector3f> directions;  // unit, scanner frame
    std::vector<float> cos_half_angle;
    bool keep_all = false;
    for (const Eigen::Vector3d& c : centers_world) {
      const Eigen::Vector3d c_scanner = T_scanner_world * c;
      const double distance = c_scanner.norm();
      if (distance <= radius) keep_all = true;
      if (keep_all) break;
      directions.push_back((c_scanner / distance).cast<float>());
      cos_half_angle.push_back(static_cast<float>(std::cos(std::asin(radius / distance))));
    }
    if (keep_all) continue;
    scan.SetMissingWhere([&](const Eigen::Vector3f& p) {
      const float length = p.norm();
      for (size_t k = 0; k < directions.size(); ++k) {
        if (p.dot(directions[k]) >= length * cos_half_angle[k]) return false;
      }
      return true;
    });
  }
  return cropped;
}

ScanSet CropToBox(const ScanSet& scans, const Eigen::AlignedBox3d& box_world) {
  ScanSet cropped = scans;
  for (OrganizedScan& scan : cropped.scans) {
    const Pose& T_world_scanner = scan.T_world_scanner();
    scan.SetMissingWhere([&](const Eigen::Vector3f& p) {
      return !box_world.contains(T_world_scanner * p.cast<double>());
    });
  }
  return cropped;
}

}  // namespace edgefit
