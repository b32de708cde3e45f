// Sec. 5.1.1 / 6.1: the rough base poses (stages.h).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "solvers/base/base_hypotheses.h"
#include "solvers/base/base_rough.h"
#include "solvers/base/conveyance_base_rough.h"
#include "solvers/base/floor_height.h"
#include "stages.h"

namespace edgefit {
namespace {

// The rough stage of options.base.method into result->base_rough (and
// result->arm_tips); arm tips that find no placement fall back to the
// cross sections.
Status RoughBase(const ScanSet& scans, double floor_z, const KinematicModel& model,
                 const TriangleMesh& base_mesh, const FitOptions& options,
                 const BasePoseLoss& base_loss, const ProgressFn& say, FitResult* result) {
  using Method = BaseOptions::Method;
  if (options.base.method == Method::kArmTips) {
    say("base: rough registration (arm tips in a height map, symmetry axis)");
    ConveyanceBaseRoughOptions tips = options.base.arm_tips;
    tips.symmetry.seed = options.seed;
    const Status status = FitConveyanceBaseRough(scans, floor_z, model, base_mesh, tips, base_loss,
                                                 &result->arm_tips);
    if (status.ok()) {
      result->base_rough_method = Method::kArmTips;
      result->base_rough.T_world_base = result->arm_tips.T_world_base;
      result->base_rough.candidates = result->arm_tips.candidates;
      result->base_rough.floor_z = result->arm_tips.floor_z;
      result->base_rough.seconds = result->arm_tips.seconds;
      char line[240];
      std::snprintf(line, sizeof(line),
                    "base: %d convex tips in the scan, %zu at arm tips' heights (%d paired), %zu "
                    "model tips, %d matches, %d poses scored",
                    result->arm_tips.convex_scan_tips, result->arm_tips.scan_tips.size(),
                    result->arm_tips.symmetric_scan_tips, result->arm_tips.model_tips.size(),
                    result->arm_tips.matches, result->arm_tips.scored);
      say(line);
      return Status::Ok();
    }
    say("base: " + status.message() + "; trying cross-section corners (Sec. 5.1.1)");
  }
  say("base: rough registration (cross-section corners, RANSAC)");
  BaseRoughOptions rough = options.base.cross_sections;
  rough.seed = options.seed;
  result->base_rough_method = Method::kCrossSections;
  return FitBaseRough(scans, floor_z, base_mesh, rough, &result->base_rough);
}

}  // namespace

Status RoughBasePoses(const KinematicModel& model, const ScanSet& scans, const Body& base,
                      const CadSamples& cad, ScanTools* tools, const FitOptions& options,
                      const ProgressFn& say, FitResult* result, std::vector<RoughPose>* roughs) {
  const JointSweep& sweep = tools->sweep;
  roughs->clear();
  const auto start = std::chrono::steady_clock::now();
  // The base stands level on the floor (Sec. 5.1.1, 6.1).
  const Eigen::AlignedBox3d& roi = options.base.method == BaseOptions::Method::kArmTips
                                       ? options.base.arm_tips.roi_world
                                       : options.base.cross_sections.roi_world;
  double floor_z = 0.0;
  const Status floor = EstimateFloorHeight(
      scans, options.base.has_initial ? Eigen::AlignedBox3d() : roi, options.base.floor, &floor_z);
  if (options.base.has_initial) {
    if (!floor.ok()) return Status::Error("base hint: " + floor.message());
    Pose T_world_base = options.base.T_world_base_initial;
    T_world_base.translation().z() += floor_z;
    roughs->push_back({T_world_base});
    return Status::Ok();
  }
  using Mounting = BaseOptions::Mounting;
  const Mounting mounting = options.base.mounting;
  TriangleMesh base_mesh;
  for (size_t k = 0; k < base.links.size(); ++k) {
    base_mesh.Append(model.links()[static_cast<size_t>(base.links[k])].mesh, base.T_body_link[k]);
  }
  const SurfaceSamples base_sweep = BodySamples(base, cad.sweep, options.samples.max_sweep_samples);
  auto base_loss = [&](const Pose& T) { return sweep.LossAt(base_sweep, T, options.chain.sweep); };
  Status upright = Status::Error("not tried (any mounting)");
  if (mounting != Mounting::kAny) {
    upright = floor.ok() ? RoughBase(scans, floor_z, model, base_mesh, options, base_loss, say, result)
                         : Status::Error(floor.message());
    if (!upright.ok()) result->base_rough.candidates.clear();
  }
  std::vector<RoughPose> voted;
  if (mounting == Mounting::kAny || (mounting == Mounting::kAuto && AnyCameraFrame(scans))) {
    if (!upright.ok() && mounting == Mounting::kAuto) say("base: upright: " + upright.message());
    const Status status = VoteBasePoses(model, scans, base, cad, options, tools, say, &voted);
    if (!status.ok() && !upright.ok()) {
      return Status::Error("base rough registration: " + upright.message() +
                           "; any mounting: " + status.message());
    }
  } else if (!upright.ok()) {
    return Status::Error("base rough registration: " + upright.message());
  }
  if (!upright.ok()) {  // voted poses only, ranked by their bodies' loss
    *roughs = std::move(voted);
    result->base_rough.T_world_base = roughs->front().T_world_base;
    result->timings.base_rough = Since(start);
    return Status::Ok();
  }
  for (const Pose& T :
       RankBaseHypotheses(&result->base_rough.candidates, base_mesh.BoundingBox().sizes(),
                          result->base_rough_method == BaseOptions::Method::kCrossSections,
                          base_loss, base_sweep.size(), options.base.hypotheses, say)) {
    roughs->push_back({T});
  }
  for (const RoughPose& v : voted) {  // the chain tells the readings apart
    if (std::all_of(roughs->begin(), roughs->end(), [&v](const RoughPose& r) {
          return IsDistinctPose(r.T_world_base, v.T_world_base);
        })) {
      roughs->push_back(v);
    }
  }
  result->base_rough.T_world_base = roughs->front().T_world_base;
  result->timings.base_rough = Since(start);
  return Status::Ok();
}

}  // namespace edgefit
