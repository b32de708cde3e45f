// Bodies of a kinematic tree for the fit: a link with every link fixed to
// it below (fixed joints, attached end effectors), which one joint moves as
// a whole; their CAD samples merged into the body link's frame; and the
// rotational symmetry test of Sec. 5.2.1.
#ifndef EDGEFIT_SOLVERS_JOINTS_BODY_H_
#define EDGEFIT_SOLVERS_JOINTS_BODY_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"

namespace edgefit {

// The CAD samples of the fit's stages: their spacing and how many of them
// a body keeps (evenly thinned, ThinSamples).
struct CadSampleOptions {
  // Spacing of the samples of the precise ICP stages and of the rough
  // Eq. (9) sweeps [m].
  double icp_spacing = 0.004;
  double sweep_spacing = 0.012;
  // At most this many samples per body: a large base at 4 mm has 250 k,
  // more than the pose needs and slow in Ceres.
  int max_icp_samples = 30000;
  int max_sweep_samples = 3000;
  // The subtree pass (a whole arm at once, one joint free) needs fewer:
  // 15000 kept every joint within 0.003 deg of 30000 on the 5.9 M point
  // weld_low scene and took a second off the chain. 7500, with the two
  // changes below it on the same page, kept the realistic bench's revolute
  // mean (benchmarks/results/2026-12-01-fewer-samples-where-a-solve-follows.md).
  // Halving max_icp_samples as well took about 1.2 s more off the demo's
  // fit, but the base of a real Med7 frame (004) then settled 2.1 m off,
  // in the clutter.
  int max_subtree_icp_samples = 7500;
  // Per body in the whole-chain refinement and its covariance: on the
  // bundled robot 30000 halved the revolute errors of the sequential fit;
  // 5000 gained nothing (0.0075 deg) and put the base farther off.
  int max_chain_samples = 30000;
  // The refinements between the station registrations (an estimate to
  // register the stations at) take at most this many per body, evenly
  // thinned from max_chain_samples; every other refinement takes those.
  // Thinned too, the settling solves of the fit's last refinement left its
  // last solve 0.1 mm to move at full density, in 6-7 iterations instead
  // of 2: the demo's fit took 0.2 s longer, not kept.
  int max_settling_chain_samples = 10000;
  // A model whose bounding box at its zero posture is longer than this on a
  // side is refused before it is sampled [m]: URDF lengths are metres, and
  // a URDF written in millimetres (a robot 3 km tall) would exhaust memory.
  double max_model_extent = 100.0;

  bool IsValid(std::string* error) const;
};

struct Body {
  int link = -1;                  // the body's frame
  int joint = -1;                 // the joint moving it (-1: the root body)
  std::vector<int> links;         // link first, then the links fixed below it
  std::vector<Pose> T_body_link;  // per entry of links
};

// The body of `link`: it and the links reached from it through fixed joints.
Body MakeBody(const KinematicModel& model, int link, int joint);

// `link` and every link below it through any joint, depth first in URDF
// order (link first).
std::vector<int> SubtreeLinks(const KinematicModel& model, int link);

// The subtree of `link` (SubtreeLinks),
// posed by T_world_link (forward kinematics at the current values), in the
// frame of `link`.
Body MakeSubtree(const KinematicModel& model, int link, int joint,
                 const std::vector<Pose>& T_world_link);

// Appends samples posed by T_out_samples (source triangles become -1).
void AppendPosedSamples(const SurfaceSamples& samples, const Pose& T_out_samples,
                        SurfaceSamples* out);

// Samples of the body's links (samples indexed like model.links()) in the
// body frame; T_body_extra places extra samples (another body's, posed).
void AppendBodySamples(const Body& body, const std::vector<SurfaceSamples>& link_samples,
                       const Pose& T_body_frame, SurfaceSamples* out);

// Keeps at most max_samples of *samples, every k-th (the sampler's order is
// stratified by area, so a stride keeps the density even).
void ThinSamples(int max_samples, SurfaceSamples* samples);

// The body's samples (AppendBodySamples in its own frame), at most
// max_samples (ThinSamples).
SurfaceSamples BodySamples(const Body& body, const std::vector<SurfaceSamples>& link_samples,
                           int max_samples);

// Sec. 5.2.1: whether the samples (body frame) are rotationally symmetric
// about the axis through the origin along axis_body: binned by radius and
// height (5 mm), a ring counts as round when 9 of its 12 30-degree sectors
// hold samples; symmetric when at least min_share of the samples lie on
// round rings.
bool IsRotationallySymmetric(const SurfaceSamples& samples, const Eigen::Vector3d& axis_body,
                             double min_share);

// The samples on round rings (as above) about the axis: the part of a body
// that looks the same at every value of its joint.
SurfaceSamples RoundPart(const SurfaceSamples& samples, const Eigen::Vector3d& axis_body);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_JOINTS_BODY_H_
