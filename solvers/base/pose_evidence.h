// What a pose's samples say for it, from their Eq. (9) losses
// (JointSweep::LossAt's per-sample losses, -1 for a hidden sample): those
// seen within `inlier` speak for it, those seen with no scan point within
// `gate` against it (the sensor saw past or beside them: free space), and
// hidden ones say nothing. The mean loss, hidden samples at the inlier
// boundary, asks how closely a pose fits; the evidence asks where the
// machine is. The voted base poses are ranked by it (mounting_stage.cc): on
// the Med7's depth frame 004 (arm folded over its base, another white arm
// and clutter 2 m away) the mean loss put the right pose 12th of 288, 1.2 mm
// per sample behind poses in the clutter; by evidence it is first, and it
// stays first on frames 000-003. The fitted whole models of the two places
// could not be told apart by it (every link, or the base and first links),
// nor by the visible samples of their bodies that fit: seven joints bent
// into the clutter explain it about as well as the arm's wrongly fitted
// wrist its own surface; the whole model's Eq. (9) loss decides there.
#ifndef EDGEFIT_SOLVERS_BASE_POSE_EVIDENCE_H_
#define EDGEFIT_SOLVERS_BASE_POSE_EVIDENCE_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace edgefit {

struct PoseEvidence {
  size_t samples = 0;
  int64_t inliers = 0;     // seen, loss below the inlier distance
  int64_t free_space = 0;  // seen, no scan point within the gate

  // inlier, gate [m]: the Eq. (9) inlier distance and the sweep's distance cap.
  void Add(const std::vector<float>& losses, double inlier, double gate) {
    samples += losses.size();
    // In float, as the losses: a loss capped at the gate is the gate's float.
    const float inlier_f = static_cast<float>(inlier), gate_f = static_cast<float>(gate);
    for (const float l : losses) {
      if (l < 0.0f) continue;
      if (l < inlier_f) ++inliers;
      if (l >= gate_f) ++free_space;
    }
  }
  // (inliers - free_space) / samples, in [-1, 1]; 0 without samples.
  double Share() const {
    return samples == 0 ? 0.0
                        : static_cast<double>(inliers - free_space) / static_cast<double>(samples);
  }
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_POSE_EVIDENCE_H_
