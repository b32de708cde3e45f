// The posed equipment as scene meshes: each link mesh moved to the world by
// its forward-kinematics pose, labelled with the link it belongs to, so a
// scan cell that hits it gets LinkLabel(k) (scene.h).
#ifndef EDGEFIT_SCENE_MODEL_SCENE_H_
#define EDGEFIT_SCENE_MODEL_SCENE_H_

#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scene/scene.h"

namespace edgefit {

// Appends one SceneMesh per link with a non-empty mesh: mesh_world =
// T_world_link[k] * link.mesh, label LinkLabel(k), link k, kind "link".
// T_world_link is indexed like model.links() (ForwardKinematics output).
void AddModelToScene(const KinematicModel& model, const std::vector<Pose>& T_world_link,
                     Scene* scene);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_MODEL_SCENE_H_
