// Loading a URDF into a KinematicModel (paper Sec. 3): links, joints
// (fixed, revolute, continuous, prismatic; <mimic>), limits, visuals with
// their origins, mesh scale and primitive shapes, plus the edgefit
// <loop_closure> extension (see loop_closure.h). Each link's visuals are
// merged into Link::mesh in the link frame [m].
//
// Every failure is one line that starts with the URDF path, e.g.
//   "robot.urdf: joint 'j3': unsupported type 'floating' (...)".
// urdfdom's own console output is captured, never printed.
#ifndef EDGEFIT_MODEL_URDF_LOADER_H_
#define EDGEFIT_MODEL_URDF_LOADER_H_

#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

struct ModelLoadOptions {
  // Load mesh files and tessellate primitives into Link::mesh. false leaves
  // the meshes empty (fast summaries); mesh paths are still resolved.
  bool load_meshes = true;
  // Build Link::mesh (and Link::visuals) from the links' <collision>
  // elements, as collision checkers do; a link without one takes its
  // <visual> elements. false: the <visual> elements, the surface the fit
  // matches to the scan.
  bool collision_geometry = false;
  // Extra roots searched first for "package://pkg/..." as "<root>/pkg/...".
  std::vector<std::string> package_dirs;
  // Also search the directories listed in $ROS_PACKAGE_PATH (after
  // package_dirs, before the URDF's own ancestors).
  bool use_ros_package_path = true;
  // Segments around a <cylinder> (>= 3): 48 keeps the chord error of a
  // 0.1 m radius below 0.25 mm and the facet angle (7.5 deg) far below the
  // 30 deg sharp-edge threshold.
  int cylinder_segments = 48;
  // Icosahedron subdivisions for a <sphere> (>= 0): 3 gives 1280 triangles,
  // facet angles ~5 deg.
  int sphere_subdivisions = 3;

  bool IsValid(std::string* error) const;
};

// The roots searched for "package://" mesh names: options.package_dirs,
// then $ROS_PACKAGE_PATH when options.use_ros_package_path.
std::vector<std::string> PackageDirs(const ModelLoadOptions& options);

// Replaces *model with the URDF at `urdf_path` (Finalize()d; Link::source is
// `urdf_path`). Each mesh file is read once per call, however many visuals
// use it.
Status LoadKinematicModel(const std::string& urdf_path, const ModelLoadOptions& options,
                          KinematicModel* model);

// The same for URDF text held in memory: `urdf_path` names it in messages
// and Link::source, and relative mesh names resolve against its folder.
Status ParseKinematicModel(const std::string& xml, const std::string& urdf_path,
                           const ModelLoadOptions& options, KinematicModel* model);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_URDF_LOADER_H_
