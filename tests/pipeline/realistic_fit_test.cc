// The robot pipeline on a small realistic scan (`edgefit scan
// --sensor=realistic --jackets`): the bundled robot with its weld gun,
// accessories and protective jackets over the upper arm and forearm, a
// FARO Focus class beam with mixed pixels, noise and dropouts by incidence
// and reflectance, station residuals and as-built surfaces, 4 mm spacing.
// Fails if accuracy regresses, if the stations are not brought together or
// if the jackets are not found.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/truth.h"
#include "model/bundled_robot_test_util.h"
#include "solvers/refinement/coverings.h"
#include "solvers/registration/station_alignment.h"

namespace edgefit {
namespace {

struct RealisticScene {
  KinematicModel model;
  std::vector<double> q;
  Pose T_world_base = Pose::Identity();
  VirtualScan scan;
  std::vector<Pose> T_world_scanners;  // true poses
  FitResult fit;
  FitErrors errors;
};

RealisticScene* MakeScene(const std::string& sensor, bool fit,
                          const FitOptions& fit_options = FitOptions()) {
  {
    auto* out = new RealisticScene;
    testing_util::LoadBundledRobotWithGun(
        "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.09",
        &out->model, &out->q);
    out->T_world_base = PoseFromXyzRpy({0.5, -0.2, 0.0}, {0.0, 0.0, 15.0 * kDeg});
    AssetScanOptions options;
    CHECK(ApplySensorPreset(sensor, &options).ok());
    options.accessories = true;
    options.scan.spacing = 0.004;
    options.seed = 7;
    CHECK(ScanAsset(out->model, out->q, out->T_world_base, options, &out->scan,
                    &out->T_world_scanners)
              .ok());
    if (!fit) return out;
    CHECK(Fit(out->model, out->scan.scans, fit_options, nullptr, &out->fit).ok());
    std::vector<Pose> T_survey_scanners;
    for (const OrganizedScan& scan : out->scan.scans.scans)
      T_survey_scanners.push_back(scan.T_world_scanner());
    CHECK(CompareWithTruth(out->model, out->fit.q, out->fit.T_world_base,
                           NamedJointValues(out->model, out->q), out->T_world_base,
                           SurveyFrame(out->T_world_scanners, T_survey_scanners), &out->errors,
                           out->fit.base_symmetry)
              .ok());
    return out;
  }
}

// Every effect together.
const RealisticScene& GetScene() {
  static RealisticScene* scene = MakeScene("realistic+jackets", true);
  return *scene;
}

// Every effect together, the mixed pixels kept in the whole-chain
// refinement too.
const RealisticScene& GetSceneRefinedWithMixedPixels() {
  FitOptions options;
  options.refine_without_mixed_pixels = false;
  static RealisticScene* scene = MakeScene("realistic+jackets", true, options);
  return *scene;
}

// Station residuals alone, not fitted.
const RealisticScene& GetStationScene() {
  static RealisticScene* scene = MakeScene("stations", false);
  return *scene;
}

// Station residuals and jackets, not fitted.
const RealisticScene& GetJacketStationScene() {
  static RealisticScene* scene = MakeScene("stations+jackets", false);
  return *scene;
}

// The pose of station j seen from station i, off from the truth [m, rad].
void RelativeError(const std::vector<Pose>& T, const std::vector<Pose>& truth, size_t i, size_t j,
                   double* translation, double* rotation) {
  const Pose D = (T[i].inverse() * T[j]) * (truth[i].inverse() * truth[j]).inverse();
  *translation = D.translation().norm();
  *rotation = Eigen::AngleAxisd(D.linear()).angle();
}

// Prints how far each pair of stations is off the truth, written and
// corrected; with factors > 0 expects the corrected pairs within those
// fractions of the written ones (translation, rotation).
void CompareStations(const std::vector<Pose>& written, const std::vector<Pose>& corrected,
                     const std::vector<Pose>& truth, const std::string& label,
                     double translation_factor, double rotation_factor) {
  ASSERT_EQ(written.size(), 3u);
  ASSERT_EQ(corrected.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    for (size_t j = i + 1; j < 3; ++j) {
      double t_written = 0, r_written = 0, t_corrected = 0, r_corrected = 0;
      RelativeError(written, truth, i, j, &t_written, &r_written);
      RelativeError(corrected, truth, i, j, &t_corrected, &r_corrected);
      std::printf("  stations %zu-%zu: %.3f mm %.4f deg written, %.3f mm %.4f deg %s\n", i, j,
                  1e3 * t_written, r_written / kDeg, 1e3 * t_corrected, r_corrected / kDeg,
                  label.c_str());
      if (translation_factor > 0.0) {
        EXPECT_LT(t_corrected, translation_factor * t_written);
      }
      if (rotation_factor > 0.0) {
        EXPECT_LT(r_corrected, rotation_factor * r_written);
      }
    }
  }
}

// The error of the prismatic joint (the gun's jaw: see README, known
// limits), the mean and the largest of the revolute ones (the balancer
// counts as revolute).
struct JointErrorSummary {
  double jaw = 0.0;
  double revolute_mean = 0.0;
  double revolute_max = 0.0;
};

JointErrorSummary Summarize(const FitErrors& errors) {
  JointErrorSummary summary;
  int revolute = 0;
  for (const JointError& e : errors.joints) {
    if (e.prismatic) {
      summary.jaw = e.error;
      continue;
    }
    summary.revolute_mean += e.error;
    summary.revolute_max = std::max(summary.revolute_max, e.error);
    ++revolute;
  }
  summary.revolute_mean /= revolute;
  return summary;
}

TEST(RealisticFitTest, RecoversJointsThroughJacketsAndStationResiduals) {
  const RealisticScene& s = GetScene();
  std::printf(
      "  %zu points; base %.3f mm %.4f deg (in the survey's frame %.3f mm %.4f deg); "
      "%.2f s; %s\n",
      s.scan.scans.TotalValid(), s.errors.base_translation * 1e3, s.errors.base_rotation / kDeg,
      s.errors.base_translation_survey * 1e3, s.errors.base_rotation_survey / kDeg,
      s.fit.timings.total, s.fit.ok ? "ok" : s.fit.message.c_str());
  for (const JointError& e : s.errors.joints) {
    std::printf("  %-24s error %.4f %s\n", e.name.c_str(),
                e.prismatic ? e.error * 1e3 : e.error / kDeg, e.prismatic ? "mm" : "deg");
  }
  const JointErrorSummary errors = Summarize(s.errors);
  // Measured: revolute mean 0.022 deg, largest 0.053 deg (joint_6), base
  // 0.64 mm off the truth, 0.09 mm off where the survey puts it (the
  // stations' mean residual is the world frame's), the gun's jaw 0.24 mm.
  // The limits are about twice the accuracy this scene had before the
  // stations were registered again at the refined estimate (0.028 deg,
  // 0.092 deg; the balancer counts as revolute). The jaw was 51 mm off,
  // reported ambiguous, while coverings could be found on the sliding
  // electrode: found at the first pass's wrong jaw, they hid its far end.
  EXPECT_LT(errors.revolute_mean, 0.05 * kDeg);
  EXPECT_LT(errors.revolute_max, 0.15 * kDeg);
  EXPECT_LT(s.errors.base_translation_survey, 0.0005);
  EXPECT_LT(errors.jaw, 0.0005);
  for (const BodyQuality& b : s.fit.bodies) EXPECT_TRUE(b.ok) << b.link << ": " << s.fit.message;
  for (const BodyQuality& b : s.fit.bodies) {
    EXPECT_FALSE(b.better_elsewhere) << b.link << ": the final basin check fired on a good fit";
  }
}

// joint_std holds the CAD's deviation from the real surfaces
// (ChainRefinementOptions::cad_deviation): on a scan of as-built surfaces
// every joint's error is within three of its standard deviations.
TEST(RealisticFitTest, JointStdCoversTheErrorsOfAsBuiltSurfaces) {
  const RealisticScene& s = GetScene();
  const ChainRefinementSummary& chain = s.fit.chain_refinement;
  ASSERT_TRUE(chain.covariance_ok);
  for (const JointError& e : s.errors.joints) {
    if (!e.independent) continue;
    const size_t j = static_cast<size_t>(e.joint);
    const double scale = e.prismatic ? 1e3 : 1.0 / kDeg;
    std::printf("  %-24s error %.4f, std %.4f (residuals alone %.4f) %s\n", e.name.c_str(),
                e.error * scale, chain.joint_std[j] * scale, chain.joint_std_residuals[j] * scale,
                e.prismatic ? "mm" : "deg");
    EXPECT_LT(e.error, 3.0 * chain.joint_std[j]) << e.name;
  }
}

// The whole-chain refinement without the mixed pixels (the default): the
// jaw, pinned along its slide by the electrode's small tip faces, where the
// beam's footprint leaves mixed pixels at the silhouette, comes closer; the
// other joints stay.
TEST(RealisticFitTest, MixedPixelsLeftOutOfTheRefinementBringTheJawCloser) {
  const JointErrorSummary left_out = Summarize(GetScene().errors);
  const JointErrorSummary kept = Summarize(GetSceneRefinedWithMixedPixels().errors);
  std::printf("  jaw %.4f mm, revolute mean %.4f deg; mixed pixels kept: %.4f mm, %.4f deg\n",
              1e3 * left_out.jaw, left_out.revolute_mean / kDeg, 1e3 * kept.jaw,
              kept.revolute_mean / kDeg);
  // Measured: jaw 0.243 against 0.455 mm, revolute mean 0.0222 against
  // 0.0207 deg.
  EXPECT_LT(left_out.jaw, 0.75 * kept.jaw);
  EXPECT_LT(left_out.revolute_mean, kept.revolute_mean + 0.005 * kDeg);
}

// Registered to the model at its true pose (exactly the CAD here), the
// stations come together. With as-built surfaces a station's correction
// also absorbs the side of each link it sees; in a fit it also depends on
// the sequential estimate.
TEST(RealisticFitTest, StationsRegisteredToTheModelAgree) {
  const RealisticScene& s = GetStationScene();
  SamplingOptions sampling;
  sampling.spacing = 0.004;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(s.model, sampling);
  ScanSet aligned = s.scan.scans;
  StationAlignmentSummary summary;
  ASSERT_TRUE(AlignStationsToModel(s.model, samples, s.T_world_base, s.q, nullptr, {},
                                   StationAlignmentOptions(), &aligned, &summary)
                  .ok());
  std::vector<Pose> written, corrected;
  for (size_t k = 0; k < aligned.scans.size(); ++k) {
    written.push_back(s.scan.scans.scans[k].T_world_scanner());
    corrected.push_back(aligned.scans[k].T_world_scanner());
    EXPECT_LT(summary.stations[k].rms_after, summary.stations[k].rms_before);
  }
  CompareStations(written, corrected, s.T_world_scanners, "aligned", 0.25, 0.5);
}

// The links mostly under a jacket are left out of the stations'
// registration (the jackets' fringes, too close to the CAD to be found as
// coverings, moved the stations of a FANUC bench scene by 7-8 mm and 0.1
// deg at the fit's estimates), and the rest of the model brings the
// stations together as well. At the true pose and 4 mm the bundled robot's
// jackets do not pull the stations, so this scene cannot show the change.
TEST(RealisticFitTest, StationsAgreeWithTheJacketedLinksLeftOut) {
  const RealisticScene& s = GetJacketStationScene();
  SamplingOptions sampling;
  sampling.spacing = 0.004;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(s.model, sampling);
  CorrespondenceSearch search(&s.scan.scans, nullptr);
  CellMask covered;
  CoveringSummary coverings;
  ASSERT_TRUE(FindCoverings(s.model, s.scan.scans, &search, samples, s.T_world_base, s.q,
                            CoveringOptions(), true, &covered, &coverings)
                  .ok());
  const StationAlignmentOptions options;
  const std::vector<uint8_t> left_out = coverings.LinksCoveredOver(options.max_covered_share);
  std::vector<std::string> names;
  for (size_t l = 0; l < left_out.size(); ++l) {
    if (left_out[l]) names.push_back(s.model.links()[l].name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"link_2", "link_4"}));

  ScanSet aligned = s.scan.scans;
  StationAlignmentSummary summary;
  ASSERT_TRUE(AlignStationsToModel(s.model, samples, s.T_world_base, s.q, &covered, left_out,
                                   options, &aligned, &summary)
                  .ok());
  EXPECT_EQ(summary.links_left_out, left_out);
  std::vector<Pose> written, corrected;
  for (size_t k = 0; k < aligned.scans.size(); ++k) {
    written.push_back(s.scan.scans.scans[k].T_world_scanner());
    corrected.push_back(aligned.scans[k].T_world_scanner());
  }
  CompareStations(written, corrected, s.T_world_scanners, "aligned without the jacketed links",
                  0.5, 0.5);
}

// The fit's own registrations (at the sequential estimate, then again at
// the refined one until the corrections settle) bring the stations of the
// scene with every effect together as well.
TEST(RealisticFitTest, StationsOfTheFitAgree) {
  const RealisticScene& s = GetScene();
  const StationAlignmentSummary& summary = s.fit.stations;
  ASSERT_EQ(summary.stations.size(), 3u);
  EXPECT_GE(summary.rounds, 1);
  EXPECT_LE(summary.rounds, StationAlignmentOptions().rounds);
  std::vector<Pose> written, corrected;
  for (size_t k = 0; k < 3; ++k) {
    written.push_back(s.scan.scans.scans[k].T_world_scanner());
    corrected.push_back(summary.stations[k].correction * written.back());
  }
  // Each pair's rotation closer than written. The written ones are only
  // 0.009-0.016 deg apart, and at the fitted model (its joints up to 0.05
  // deg off) a pair came to 0.0074 or 0.0078 deg on one machine and under
  // half of written on another: half is not a bar this scene can hold. What
  // a user sees, where a station puts a point 5 m away (translation plus
  // rotation times 5 m), must be within half of written.
  CompareStations(written, corrected, s.T_world_scanners,
                  "fitted (" + std::to_string(summary.rounds) + " registrations)", 0.5, 1.0);
  for (size_t i = 0; i < 3; ++i) {
    for (size_t j = i + 1; j < 3; ++j) {
      double t_written = 0, r_written = 0, t_corrected = 0, r_corrected = 0;
      RelativeError(written, s.T_world_scanners, i, j, &t_written, &r_written);
      RelativeError(corrected, s.T_world_scanners, i, j, &t_corrected, &r_corrected);
      EXPECT_LT(t_corrected + 5.0 * r_corrected, 0.5 * (t_written + 5.0 * r_written))
          << "stations " << i << "-" << j;
    }
  }
}

TEST(RealisticFitTest, JacketsAreFoundOnTheUpperArmAndForearm) {
  const RealisticScene& s = GetScene();
  const CoveringSummary& c = s.fit.coverings;
  ASSERT_EQ(c.link_matched.size(), s.model.links().size());
  for (size_t l = 0; l < c.link_matched.size(); ++l) {
    if (c.link_matched[l] == 0) continue;
    const double share = c.Share(l);
    const std::string& name = s.model.links()[l].name;
    std::printf("  %-20s %5.1f %% of %zu matched cells covered\n", name.c_str(), 100 * share,
                c.link_matched[l]);
    if (name == "link_2" || name == "link_4") {
      EXPECT_GT(share, 0.25) << name;
    }
  }
}

}  // namespace
}  // namespace edgefit
