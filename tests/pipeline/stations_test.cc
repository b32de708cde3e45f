// The stations' bookkeeping, without a scan: the survey's frame against
// which a base is scored (fit_errors.h), and how far the stations'
// corrections move between registrations (station_alignment.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "solvers/registration/station_alignment.h"

namespace edgefit {
namespace {

// The survey's frame is the stations' mean residual: stations all off by
// one transform put the world exactly there; residuals that cancel leave it.
TEST(SurveyFrameTest, IsTheStationsMeanResidual) {
  const std::vector<Pose> truth = {PoseFromXyzRpy({3.0, 0.0, 1.5}, {0.0, 0.0, 1.0}),
                                   PoseFromXyzRpy({-2.0, 3.0, 1.2}, {0.0, 0.0, -2.0}),
                                   PoseFromXyzRpy({0.0, -4.0, 1.7}, {0.0, 0.0, 2.5})};
  const Pose D = PoseFromXyzRpy({0.002, -0.001, 0.0005}, {0.0001, -0.0002, 0.0003});
  std::vector<Pose> written;
  for (const Pose& T : truth) written.push_back(D * T);
  const Pose T_survey_world = SurveyFrame(truth, written);
  EXPECT_LT((T_survey_world.matrix() - D.matrix()).norm(), 1e-12);

  written = {PoseFromXyzRpy({0.002, 0.0, 0.0}, {0.0, 0.0, 0.0003}) * truth[0],
             PoseFromXyzRpy({-0.002, 0.0, 0.0}, {0.0, 0.0, -0.0003}) * truth[1], truth[2]};
  EXPECT_LT((SurveyFrame(truth, written).matrix() - Pose::Identity().matrix()).norm(), 1e-9);
  EXPECT_TRUE(SurveyFrame(truth, {}).isApprox(Pose::Identity()));

  // A model fitted exactly where the survey puts it: its base is the
  // survey's residual off the truth, and exact in the survey's frame.
  KinematicModel model;
  ASSERT_TRUE(LoadModelWithAttachments(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                       {}, ModelLoadOptions(), &model)
                  .ok());
  const std::vector<double> q = model.ZeroJoints();
  const Pose T_world_base = PoseFromXyzRpy({0.5, -0.2, 0.0}, {0.0, 0.0, 0.3});
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(model, q, D * T_world_base, NamedJointValues(model, q), T_world_base,
                               D, &errors)
                  .ok());
  EXPECT_GT(errors.base_translation, 0.001);
  EXPECT_LT(errors.base_translation_survey, 1e-12);
  EXPECT_LT(errors.base_rotation_survey, 1e-9);

  // Off that placement by a turn about the world's z and a shift: the
  // errors by world axis are those, as the fit's base_std states them.
  Pose T_world_base_fit = D * T_world_base;
  T_world_base_fit.linear() =
      Eigen::AngleAxisd(1e-4, Eigen::Vector3d::UnitZ()).matrix() * T_world_base_fit.linear();
  T_world_base_fit.translation() += Eigen::Vector3d(0.001, -0.002, 0.003);
  ASSERT_TRUE(CompareWithTruth(model, q, T_world_base_fit, NamedJointValues(model, q),
                               T_world_base, D, &errors)
                  .ok());
  EXPECT_LT((errors.base_rotation_survey_world - Eigen::Vector3d(0.0, 0.0, 1e-4)).norm(), 1e-12);
  EXPECT_LT((errors.base_translation_survey_world - Eigen::Vector3d(0.001, -0.002, 0.003)).norm(),
            1e-12);
  EXPECT_NEAR(errors.base_rotation_survey, 1e-4, 1e-12);
}

// How far a station's correction moved between two registrations: its
// origin's shift plus its rotation times 5 m.
TEST(StationCorrectionsTest, LargestChange) {
  const std::vector<Pose> written = {PoseFromXyzRpy({3.0, 0.0, 1.5}, {0.0, 0.0, 0.0}),
                                     PoseFromXyzRpy({0.0, 4.0, 1.5}, {0.0, 0.0, 1.0})};
  StationAlignmentSummary before, after;
  before.stations.resize(2);
  after.stations.resize(2);
  after.stations[0].correction = PoseFromXyzRpy({0.0002, 0.0, 0.0}, {0.0, 0.0, 0.0});
  // About the scanner's own origin: the origin stays, the rotation counts.
  const Eigen::Vector3d o = written[1].translation();
  Pose turn = Pose::Identity();
  turn.linear() = Eigen::AngleAxisd(1e-4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  turn.translation() = o - turn.linear() * o;
  after.stations[1].correction = turn;
  after.stations[1].rotation = 1e-4;
  after.stations[0].translation = 0.0002;
  EXPECT_NEAR(LargestChange(before, after, written), 5.0 * 1e-4, 1e-12);
  EXPECT_NEAR(LargestChange(after, after, written), 0.0, 1e-12);
  EXPECT_NEAR(LargestCorrection(after), 5.0 * 1e-4, 1e-12);
  before.stations.pop_back();
  EXPECT_TRUE(std::isinf(LargestChange(before, after, written)));
}

}  // namespace
}  // namespace edgefit
