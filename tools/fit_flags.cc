#include "fit_flags.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "command_line.h"
#include "common_flags.h"

DEFINE_string(kind, "auto",
              "auto | articulated | conveyance: the pipeline (conveyance: the base's rough pose "
              "from the arm tips, Sec. 6.1); auto takes a model whose joints are all prismatic "
              "for a conveyance system.");
DEFINE_string(weighting, "uniform",
              "uniform: every correspondence weight 1 (measured better); edge: the paper's "
              "Eq. (6) weights (--w_high at edge points) in every stage.");
DEFINE_string(loss, "trivial",
              "Loss of the precise ICP residuals: trivial, huber, cauchy, soft_l1, arctan, tukey.");
DEFINE_double(loss_scale_mm, 5.0, "Scale of --loss [mm].");
DEFINE_double(lambda, 1.0,
              "Eq. (10)/(14) penalty weight relative to the data (pose_penalty only).");
DEFINE_string(parameterization, "joint_space",
              "Joint constraint of the precise ICP: joint_space (1 parameter) or pose_penalty "
              "(the paper's 6-DoF pose + Eq. (10) penalties, then projection).");
DEFINE_bool(refine_chain, true,
            "After the sequential fit, refine the base pose and every joint together in one "
            "Ceres problem (solvers/refinement/); --norefine_chain: the sequential fit alone.");
DEFINE_bool(align_stations, true,
            "Register each station to the fitted model and fit again when one moved (their "
            "registration residuals); --noalign_stations: use the written station poses.");
DEFINE_int32(station_rounds, 3,
             "Registrations of the stations: after the first (at the sequential fit), the chain "
             "is refined on the corrected stations and they are registered again there, until "
             "their corrections settle or this many were made; 1: once.");
DEFINE_double(station_max_covered_share, 0.2,
              "A link with more than this share of its matched cells covered (a jacket) is left "
              "out of the stations' registration; 1: none is.");
DEFINE_int32(covering_rounds, 2,
             "Rounds of the whole-chain refinement without the coverings found at the last "
             "estimate (jackets, covers: points off the CAD surface over an area); 0: none.");
DEFINE_double(pair_sweep_deg, 5.0,
              "On noisy scans (a depth camera's frame): a round body whose sweep with its "
              "children is flat is swept again together with the joint that bends below it, on "
              "a grid of this step over both ranges [deg]; 0: off.");
DEFINE_double(visibility_tolerance_mm, 2.0,
              "The whole-chain refinement counts a CAD sample as seen when a scan's range at its "
              "cell is at most this much nearer than the sample [mm]: wider lets in samples just "
              "behind a nearer surface, which pull their link toward it.");
DEFINE_double(cad_deviation_mm, 0.5,
              "How far the real surfaces are off their CAD [mm], a standard deviation per patch "
              "of --cad_deviation_patch_mm: part of joint_std and base_std (castings, welds, "
              "paint); 0: the residuals alone (a lower bound).");
DEFINE_double(cad_deviation_patch_mm, 200.0,
              "The size of a patch of CAD surface that is off by one offset [mm].");
DEFINE_double(incidence_cosine, 0.0,
              "The whole-chain refinement weights each point by min(1, c / this), c the cosine "
              "of its beam's incidence on the CAD surface: returns at grazing incidence count "
              "less; 0: no such weights.");
DEFINE_bool(remove_mixed_pixels, false,
            "Remove mixed pixels (a range between a foreground edge and the surface behind it) "
            "from the scans before the edges and the fit.");
DEFINE_bool(refine_without_mixed_pixels, true,
            "The whole-chain refinement (the final values) on the scans without their mixed "
            "pixels; the stages before it keep them.");
DEFINE_double(mixed_pixel_tolerance_mm, 5.0,
              "A mixed pixel lies this far off the surfaces on both sides of it [mm].");
DEFINE_int32(mixed_pixel_lines, 3,
             "A mixed pixel is between the surfaces along this many of the 4 grid lines through "
             "it (1-4; fewer finds more, and more noisy surface cells with them).");
DEFINE_int32(mixed_pixel_neighbour_lines, 1,
             "... or along this many (0-4; 0: none) beside such a cell: the rest of a band of "
             "mixed pixels across an edge.");
DEFINE_string(roi, "",
              "Optional region of interest xmin,ymin,zmin,xmax,ymax,zmax in the world frame [m]: "
              "points outside it are left out of the fit (the outputs keep the whole scan).");
DEFINE_string(init, "",
              "Optional base hint x,y,yaw_deg (metres, degrees; the height comes from the "
              "scan's floor): skips the rough base stage. Never required.");

DEFINE_string(mounting, "auto",
              "How the base may be mounted: upright (standing on the floor: the cross sections "
              "of Sec. 5.1.1), any (hanging, on a wall, on a wedge: pose voting of the base and "
              "its first links), auto (upright on laser scans, both on a depth camera's "
              "frames).");
DEFINE_string(up, "",
              "Up in the scan's frame, x,y,z (any length): the upright base search levels the "
              "scans to it. Default: the frame's z (a levelled laser scan, a frame's VIEWPOINT), "
              "and on a depth camera's frame also the dominant floor or table plane's normal.");
DEFINE_bool(noise_scale, true,
            "Scale every distance threshold (gates, tolerances, the verdict's RMS) to the "
            "noise measured where the base meets the scan (no change at 3 mm or less, as on laser "
            "scans).");

namespace edgefit::tools {

Status FitOptionsFromFlags(AssetKind kind, FitOptions* options) {
  *options = FitOptionsFor(kind);
  options->seed = FLAGS_seed;
  options->edges.w_high = FLAGS_w_high;
  if (FLAGS_weighting != "edge" && FLAGS_weighting != "uniform") {
    return Status::Error("--weighting must be edge or uniform, not '" + FLAGS_weighting + "'");
  }
  options->uniform_weights = FLAGS_weighting == "uniform";
  options->residuals.loss = FLAGS_loss;
  options->residuals.loss_scale = FLAGS_loss_scale_mm * 1e-3;
  options->residuals.lambda = FLAGS_lambda;
  EDGEFIT_RETURN_IF_ERROR(
      ParseJointParameterization(FLAGS_parameterization, &options->residuals.parameterization));
  options->refinement.chain.refine = FLAGS_refine_chain;
  options->stations.align = FLAGS_align_stations;
  options->stations.rounds = FLAGS_station_rounds;
  options->stations.max_covered_share = FLAGS_station_max_covered_share;
  options->refinement.coverings.rounds = FLAGS_covering_rounds;
  options->chain.pair_sweep_step = FLAGS_pair_sweep_deg * M_PI / 180.0;
  options->refinement.chain.visibility_tolerance = FLAGS_visibility_tolerance_mm * 1e-3;
  options->refinement.chain.cad_deviation = FLAGS_cad_deviation_mm * 1e-3;
  options->refinement.chain.cad_deviation_patch = FLAGS_cad_deviation_patch_mm * 1e-3;
  options->refinement.chain.incidence_cosine = FLAGS_incidence_cosine;
  options->remove_mixed_pixels = FLAGS_remove_mixed_pixels;
  options->refine_without_mixed_pixels = FLAGS_refine_without_mixed_pixels;
  options->mixed_pixels.tolerance = FLAGS_mixed_pixel_tolerance_mm * 1e-3;
  options->mixed_pixels.min_lines = FLAGS_mixed_pixel_lines;
  options->mixed_pixels.neighbour_lines = FLAGS_mixed_pixel_neighbour_lines;
  using Mounting = BaseOptions::Mounting;
  if (FLAGS_mounting == "auto") options->base.mounting = Mounting::kAuto;
  else if (FLAGS_mounting == "upright") options->base.mounting = Mounting::kUpright;
  else if (FLAGS_mounting == "any") options->base.mounting = Mounting::kAny;
  else return Status::Error("--mounting must be auto, upright or any, not '" + FLAGS_mounting + "'");
  options->noise.scale = FLAGS_noise_scale;
  if (!FLAGS_up.empty()) {
    std::vector<double> up;
    EDGEFIT_RETURN_IF_ERROR(ParseNumberList("up", FLAGS_up, 0.0, &up));
    if (up.size() != 3 || !(Eigen::Vector3d(up[0], up[1], up[2]).norm() > 0.0)) {
      return Status::Error("--up must be x,y,z, not all zero, not '" + FLAGS_up + "'");
    }
    options->base.up = Eigen::Vector3d(up[0], up[1], up[2]);
  }
  if (!FLAGS_init.empty()) {
    double x = 0.0, y = 0.0, yaw = 0.0;
    EDGEFIT_RETURN_IF_ERROR(ParseXyYawDeg("--init", FLAGS_init, &x, &y, &yaw));
    options->base.has_initial = true;
    options->base.T_world_base_initial = PoseFromXyYaw(x, y, yaw);
  }
  std::string error;
  if (!options->IsValid(&error)) return Status::Error(error);
  return Status::Ok();
}

Status CheckFitFlags() {
  if (FLAGS_kind != "auto" && FLAGS_kind != "articulated" && FLAGS_kind != "conveyance") {
    return Status::Error("--kind must be auto, articulated or conveyance");
  }
  FitOptions options;
  return FitOptionsFromFlags(AssetKind::kArticulated, &options);
}

std::vector<std::string> WithFitOptionFlags(std::vector<std::string> own, bool weighting) {
  if (weighting) own.emplace_back("weighting");
  for (const char* flag : {"w_high", "loss", "loss_scale_mm", "lambda",
                           "parameterization", "refine_chain", "align_stations",
                           "station_rounds", "station_max_covered_share", "covering_rounds",
                           "pair_sweep_deg", "visibility_tolerance_mm", "cad_deviation_mm",
                           "cad_deviation_patch_mm", "incidence_cosine", "remove_mixed_pixels",
                           "refine_without_mixed_pixels", "mixed_pixel_tolerance_mm",
                           "mixed_pixel_lines", "mixed_pixel_neighbour_lines", "mounting",
                           "noise_scale", "up"}) {
    own.emplace_back(flag);
  }
  return own;
}

Status RoiFromFlags(Eigen::AlignedBox3d* box, bool* given) {
  *given = !FLAGS_roi.empty();
  if (!*given) return Status::Ok();
  const std::vector<std::string> parts = SplitList(FLAGS_roi);
  double v[6];
  bool numbers = parts.size() == 6;
  for (size_t k = 0; numbers && k < 6; ++k) {
    char* rest = nullptr;
    v[k] = std::strtod(parts[k].c_str(), &rest);
    numbers = *rest == '\0' && !parts[k].empty() && std::isfinite(v[k]);
  }
  if (!numbers || !(v[0] < v[3] && v[1] < v[4] && v[2] < v[5])) {
    return Status::Error("--roi: expected xmin,ymin,zmin,xmax,ymax,zmax in metres with min < max, got '" +
                         FLAGS_roi + "'");
  }
  *box = Eigen::AlignedBox3d(Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5]));
  return Status::Ok();
}

}  // namespace edgefit::tools
