#include "edgefit/scene/main_chain.h"

#include <algorithm>

namespace edgefit {

std::vector<int> MainChainLinks(const KinematicModel& model) {
  const std::vector<Link>& links = model.links();
  if (links.empty() || model.root_link() < 0) return {};
  std::vector<double> weight(links.size(), 0.0);
  const int root = model.root_link();
  weight[root] = links[root].mesh.SurfaceArea();
  int best = root;
  // joint_order() is parents first, so a parent's weight is known in time.
  for (int j : model.joint_order()) {
    const Joint& joint = model.joints()[j];
    weight[joint.child_link] = weight[joint.parent_link] + links[joint.child_link].mesh.SurfaceArea();
    if (weight[joint.child_link] > weight[best]) best = joint.child_link;
  }
  std::vector<int> chain;
  for (int k = best; k >= 0;) {
    if (!links[k].mesh.empty()) chain.push_back(k);
    const int j = links[k].parent_joint;
    k = j < 0 ? -1 : model.joints()[j].parent_link;
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

}  // namespace edgefit
