// The main chain of a kinematic tree: the links an arm's dress pack (cables,
// hoses) follows from the base to the wrist (paper Sec. 7.3 accessories).
#ifndef EDGEFIT_SCENE_MAIN_CHAIN_H_
#define EDGEFIT_SCENE_MAIN_CHAIN_H_

#include <vector>

#include "edgefit/model/kinematic_model.h"

namespace edgefit {

// Link indices from the root to the end of the heaviest root-to-link path,
// where a path weighs the summed mesh area of its links [m^2]. For a serial
// robot that is the arm to the last link with a mesh (flange and tool frames
// without meshes are dropped); in a tree it prefers the arm over a light
// side branch such as a balancer cylinder. Ties keep the shallower link.
// Only links with meshes are returned (the root too only if it has one).
std::vector<int> MainChainLinks(const KinematicModel& model);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_MAIN_CHAIN_H_
