// libFuzzer harness: any bytes given to the URDF loader (urdfdom, then
// edgefit's own checks: joint types, limits, mimics, loop closures) must
// load or fail with a Status, never crash, leak or run into undefined
// behaviour; a model that loads is posed (its dependent joints resolved,
// forward kinematics). Meshes are not read (mesh names still resolve).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/model/urdf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgefit::ModelLoadOptions options;
  options.load_meshes = false;
  options.use_ros_package_path = false;
  edgefit::KinematicModel model;
  const std::string xml(reinterpret_cast<const char*>(data), size);
  if (!edgefit::ParseKinematicModel(xml, "/nonexistent/fuzz.urdf", options, &model).ok()) {
    return 0;
  }
  std::vector<double> q = model.ZeroJoints();
  (void)model.ResolveDependentJoints(&q);
  (void)model.ForwardKinematics(q, edgefit::Pose::Identity());
  return 0;
}
