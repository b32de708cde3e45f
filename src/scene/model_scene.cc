#include "edgefit/scene/model_scene.h"

#include <glog/logging.h>

namespace edgefit {

void AddModelToScene(const KinematicModel& model, const std::vector<Pose>& T_world_link,
                     Scene* scene) {
  CHECK(scene != nullptr);
  CHECK_EQ(T_world_link.size(), model.links().size());
  for (size_t k = 0; k < model.links().size(); ++k) {
    const Link& link = model.links()[k];
    if (link.mesh.empty()) continue;
    SceneMesh mesh;
    mesh.mesh_world.Append(link.mesh, T_world_link[k]);
    mesh.label = LinkLabel(static_cast<int>(k));
    mesh.link = static_cast<int>(k);
    mesh.kind = "link";
    scene->meshes.push_back(std::move(mesh));
  }
}

}  // namespace edgefit
