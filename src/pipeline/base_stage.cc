// Sec. 5.1.1 / 6.1: the rough base poses (stages.h).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "edgefit/scan/scan_noise.h"
#include "solvers/base/base_hypotheses.h"
#include "solvers/base/base_rough.h"
#include "solvers/base/conveyance_base_rough.h"
#include "solvers/base/floor_height.h"
#include "stages.h"

namespace edgefit {
namespace {

// The rough stage of options.base.method into result->base_rough (and
// result->arm_tips); arm tips that find no placement fall back to the
// cross sections, which run at each of noise_levels (the scan's sigmas,
// BaseRoughOptions::NoiseLevels): result->base_rough is the first level's
// that found corners, with every level's candidates.
Status RoughBase(const ScanSet& scans, double floor_z, const KinematicModel& model,
                 const TriangleMesh& base_mesh, const FitOptions& options,
                 const std::vector<double>& noise_levels, const BasePoseLoss& base_loss,
                 const ProgressFn& say, FitResult* result) {
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
  result->base_rough_method = Method::kCrossSections;
  Status first = Status::Ok();  // the first level's failure, when none finds corners
  bool found = false;
  for (const double sigma : noise_levels) {
    BaseRoughOptions rough = options.base.cross_sections.ScaledToNoise(sigma);
    rough.seed = options.seed;
    BaseRoughResult level;
    const Status status = FitBaseRough(scans, floor_z, base_mesh, rough, &level);
    if (noise_levels.size() > 1) {
      char line[200];
      std::snprintf(line, sizeof(line),
                    "base: section corners at %.1f times their distances: %d in the scan, %zu "
                    "candidates",
                    options.base.cross_sections.NoiseScale(sigma),
                    level.scan_corners, status.ok() ? level.candidates.size() : size_t{0});
      say(line);
    }
    if (!status.ok()) {
      if (first.ok()) first = status;
      continue;
    }
    if (!found) {
      result->base_rough = level;
    } else {
      for (const Pose& T : level.candidates) result->base_rough.candidates.push_back(T);
    }
    found = true;
  }
  return found ? Status::Ok() : first;
}

// The upright stage on the scans turned by R_level (up to the world z):
// its hypotheses ranked by the base's Eq. (9) loss, mapped back to the
// scans' frame, into *poses; result->base_rough records how (its floor and
// candidates in the levelled frame).
Status UprightPoses(const KinematicModel& model, const ScanSet& scans,
                    const Eigen::Matrix3d& R_level, const TriangleMesh& base_mesh,
                    const BasePoseLoss& base_loss, size_t samples, const FitOptions& options,
                    const std::vector<double>& noise_levels, const ProgressFn& say,
                    FitResult* result, std::vector<Pose>* poses) {
  const bool turned = !R_level.isIdentity(1e-12);
  Pose T_level_world = Pose::Identity();
  T_level_world.linear() = R_level;
  FitOptions levelled_options = options;
  ScanSet levelled;
  if (turned) {  // a region of interest is a box of the scans' frame
    levelled_options.base.cross_sections.roi_world = Eigen::AlignedBox3d();
    levelled_options.base.arm_tips.roi_world = Eigen::AlignedBox3d();
    levelled = scans;
    for (OrganizedScan& scan : levelled.scans) {
      scan.set_T_world_scanner(T_level_world * scan.T_world_scanner());
    }
  }
  const ScanSet& search = turned ? levelled : scans;
  const BaseOptions& base = levelled_options.base;
  const Eigen::AlignedBox3d& roi = base.method == BaseOptions::Method::kArmTips
                                       ? base.arm_tips.roi_world
                                       : base.cross_sections.roi_world;
  double floor_z = 0.0;
  EDGEFIT_RETURN_IF_ERROR(EstimateFloorHeight(search, roi, base.floor, &floor_z));
  const Pose T_world_level = T_level_world.inverse();
  const BasePoseLoss levelled_loss = [&](const Pose& T) { return base_loss(T_world_level * T); };
  EDGEFIT_RETURN_IF_ERROR(
      RoughBase(search, floor_z, model, base_mesh, levelled_options, noise_levels, levelled_loss,
                say, result));
  for (const Pose& T :
       RankBaseHypotheses(&result->base_rough.candidates, base_mesh.BoundingBox().sizes(),
                          result->base_rough_method == BaseOptions::Method::kCrossSections,
                          levelled_loss, samples, base.hypotheses, say)) {
    poses->push_back(T_world_level * T);
  }
  return Status::Ok();
}

// A depth camera's frame need not be level: with the dominant plane more
// than min_up_tilt from its z, the upright stage runs levelled to it too,
// its poses after *poses (the chain tells them apart).
void UprightPosesOnThePlane(const KinematicModel& model, const ScanSet& scans,
                            const TriangleMesh& base_mesh, const BasePoseLoss& base_loss,
                            size_t samples, const FitOptions& options,
                            const std::vector<double>& noise_levels, const ProgressFn& say,
                            FitResult* result, std::vector<Pose>* poses) {
  UpOptions up_options = options.base.up_estimation;
  up_options.seed = options.seed;
  UpEstimate up;
  const Status found = EstimateUp(scans, up_options, &up);
  char line[240];
  if (!found.ok()) {
    say(found.message() + ": the frame's z");
    return;
  }
  std::snprintf(line, sizeof(line),
                "up: the dominant plane (%.0f %% of the points) is %.1f deg from the frame's z%s",
                100.0 * static_cast<double>(up.inliers) / static_cast<double>(up.sampled),
                up.tilt * 180.0 / M_PI,
                up.tilt > options.base.min_up_tilt ? ": the upright stage levelled to it too" : "");
  say(line);
  if (!(up.tilt > options.base.min_up_tilt)) return;
  FitResult levelled = *result;
  std::vector<Pose> more;
  const Status status = UprightPoses(model, scans, LevellingRotation(up.up), base_mesh, base_loss,
                                     samples, options, noise_levels, say, &levelled, &more);
  if (!status.ok()) {
    say("up: levelled to the plane: " + status.message());
    return;
  }
  result->up = up.up;
  result->up_from = "plane";
  result->up_plane_share = static_cast<double>(up.inliers) / static_cast<double>(up.sampled);
  if (poses->empty()) {  // the frame's z found nothing: report this stage
    result->base_rough = levelled.base_rough;
    result->base_rough_method = levelled.base_rough_method;
    result->arm_tips = levelled.arm_tips;
  }
  for (const Pose& T : more) {
    if (std::all_of(poses->begin(), poses->end(),
                    [&T](const Pose& p) { return IsDistinctPose(p, T); })) {
      poses->push_back(T);
    }
  }
}

}  // namespace

Status RoughBasePoses(const KinematicModel& model, const ScanSet& scans, const Body& base,
                      const CadSamples& cad, ScanTools* tools, const FitOptions& options,
                      const ProgressFn& say, FitResult* result, std::vector<RoughPose>* roughs) {
  const JointSweep& sweep = tools->sweep;
  roughs->clear();
  const auto start = std::chrono::steady_clock::now();
  if (options.base.has_initial) {  // the hint stands on the scan's floor
    double floor_z = 0.0;
    const Status floor =
        EstimateFloorHeight(scans, Eigen::AlignedBox3d(), options.base.floor, &floor_z);
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
  // The base stands level on the floor (Sec. 5.1.1, 6.1): up is the
  // frame's z, or the one given.
  const bool up_given = !options.base.up.isZero();
  if (up_given) {
    result->up = options.base.up.normalized();
    result->up_from = "given";
  }
  const bool camera = AnyCameraFrame(scans);
  Status upright = Status::Error("not tried (any mounting)");
  std::vector<Pose> upright_poses;
  if (mounting != Mounting::kAny) {
    // The section corners' distances widened to the scan's local noise
    // (BaseRoughOptions::ScaledToNoise): a depth camera's few millimetres,
    // at each of its levels over the ranges (NoiseLevels).
    const BaseRoughOptions& sections = options.base.cross_sections;
    const std::vector<double> noise_levels =
        sections.NoiseLevels(EstimateScanNoise(scans, ScanNoiseOptions()));
    if (noise_levels.size() > 1 || sections.NoiseScale(noise_levels.front()) > 1.0) {
      std::string scales;
      for (const double sigma : noise_levels) {
        char k[32];
        std::snprintf(k, sizeof(k), "%s%.1f", scales.empty() ? "" : ", ",
                      sections.NoiseScale(sigma));
        scales += k;
      }
      char line[300];
      std::snprintf(line, sizeof(line),
                    "base: the scan's local noise is %.1f mm (median; up to %.1f mm by "
                    "range): section corners and matches at %s times their distances",
                    1e3 * noise_levels.front(),
                    1e3 * *std::max_element(noise_levels.begin(), noise_levels.end()),
                    scales.c_str());
      say(line);
    }
    const Eigen::Matrix3d R_level =
        up_given ? LevellingRotation(result->up) : Eigen::Matrix3d::Identity();
    upright = UprightPoses(model, scans, R_level, base_mesh, base_loss, base_sweep.size(), options,
                           noise_levels, say, result, &upright_poses);
    if (!upright.ok()) result->base_rough.candidates.clear();
    if (!up_given && mounting == Mounting::kAuto && camera) {
      UprightPosesOnThePlane(model, scans, base_mesh, base_loss, base_sweep.size(), options,
                             noise_levels, say, result, &upright_poses);
      if (!upright_poses.empty()) upright = Status::Ok();
    }
  }
  std::vector<RoughPose> voted;
  if (mounting == Mounting::kAny || (mounting == Mounting::kAuto && camera)) {
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
  for (const Pose& T : upright_poses) roughs->push_back({T});
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
