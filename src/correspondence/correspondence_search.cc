#include "edgefit/correspondence/correspondence_search.h"

namespace edgefit {

void CorrespondenceSearch::Find(const std::vector<Eigen::Vector3f>& q_world,
                                const Eigen::AlignedBox3d& crop_world,
                                const CorrespondenceOptions& options,
                                std::vector<Correspondence>* out) {
  if (options.use_lattice) {
    lattice_.Find(q_world, options, out);
  } else {
    kdtree_.Find(q_world, crop_world, options, out);
  }
}

}  // namespace edgefit
