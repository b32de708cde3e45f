// Eq. (9) sweep loss and the robust-loss factory.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "costs/robust_loss.h"
#include "costs/sweep_loss.h"

namespace edgefit {
namespace {

TEST(SweepLossTest, InlierDividesByEdgeWeight) {
  // D = 0.004 m < tau = 0.01 m: Loss = D / w.
  EXPECT_DOUBLE_EQ(SweepLoss(0.004, 10.0, 0.01), 0.0004);
  EXPECT_DOUBLE_EQ(SweepLoss(0.004, 1.0, 0.01), 0.004);
  EXPECT_DOUBLE_EQ(SweepLoss(0.0, 10.0, 0.01), 0.0);
}

TEST(SweepLossTest, OutlierMultipliesByEdgeWeight) {
  // D = 0.05 m >= tau: Loss = D * w; the threshold itself is an outlier.
  EXPECT_DOUBLE_EQ(SweepLoss(0.05, 10.0, 0.01), 0.5);
  EXPECT_DOUBLE_EQ(SweepLoss(0.01, 10.0, 0.01), 0.1);
  EXPECT_DOUBLE_EQ(SweepLoss(0.05, 0.5, 0.01), 0.025);
}

TEST(SweepLossTest, HighWeightFavoursInliersAndPunishesOutliers) {
  const double tau = 0.01;
  EXPECT_LT(SweepLoss(0.005, 10.0, tau), SweepLoss(0.005, 1.0, tau));
  EXPECT_GT(SweepLoss(0.02, 10.0, tau), SweepLoss(0.02, 1.0, tau));
}

// Ceres' documented rho(s) and rho'(s) for scale a (residual-norm units).
struct ExpectedRho {
  double rho;
  double rho1;
};

ExpectedRho Expected(const std::string& name, double a, double s) {
  const double b = a * a;
  if (name == "trivial") return {s, 1.0};
  if (name == "huber")
    return s <= b ? ExpectedRho{s, 1.0} : ExpectedRho{2.0 * std::sqrt(b * s) - b, std::sqrt(b / s)};
  if (name == "cauchy") return {b * std::log1p(s / b), 1.0 / (1.0 + s / b)};
  if (name == "soft_l1")
    return {2.0 * b * (std::sqrt(1.0 + s / b) - 1.0), 1.0 / std::sqrt(1.0 + s / b)};
  if (name == "arctan") return {b * std::atan(s / b), 1.0 / (1.0 + (s / b) * (s / b))};
  if (name == "tukey") {
    if (s > b) return {b / 3.0, 0.0};
    const double u = 1.0 - s / b;
    return {b / 3.0 * (1.0 - u * u * u), u * u};
  }
  ADD_FAILURE() << "no expectation for " << name;
  return {0.0, 0.0};
}

class MakeLossTest : public testing::TestWithParam<std::string> {};

TEST_P(MakeLossTest, RhoMatchesCeresFormulas) {
  const double scale = 0.5;
  std::unique_ptr<ceres::LossFunction> loss;
  const Status status = MakeLoss(GetParam(), scale, &loss);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_NE(loss, nullptr);
  for (double s : {0.0, 0.1, 0.25, 2.0}) {  // below, at and above scale^2 = 0.25
    double rho[3];
    loss->Evaluate(s, rho);
    const ExpectedRho expected = Expected(GetParam(), scale, s);
    EXPECT_NEAR(rho[0], expected.rho, 1e-12) << "s = " << s;
    EXPECT_NEAR(rho[1], expected.rho1, 1e-12) << "s = " << s;
  }
}

TEST_P(MakeLossTest, QuadraticNearZero) {
  std::unique_ptr<ceres::LossFunction> loss;
  ASSERT_TRUE(MakeLoss(GetParam(), 1.0, &loss).ok());
  double rho[3];
  loss->Evaluate(1e-8, rho);
  EXPECT_NEAR(rho[0], 1e-8, 1e-14);
  EXPECT_NEAR(rho[1], 1.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(AllLosses, MakeLossTest, testing::ValuesIn(LossNames()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(MakeLossErrorTest, UnknownNameListsValidNames) {
  std::unique_ptr<ceres::LossFunction> loss;
  const Status status = MakeLoss("l2", 1.0, &loss);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(loss, nullptr);
  EXPECT_NE(status.message().find("'l2'"), std::string::npos) << status.message();
  for (const std::string& name : LossNames()) {
    EXPECT_NE(status.message().find(name), std::string::npos) << status.message();
  }
}

TEST(MakeLossErrorTest, RejectsNonPositiveScale) {
  std::unique_ptr<ceres::LossFunction> loss;
  EXPECT_FALSE(MakeLoss("huber", 0.0, &loss).ok());
  EXPECT_FALSE(MakeLoss("cauchy", -1.0, &loss).ok());
  EXPECT_FALSE(MakeLoss("tukey", std::nan(""), &loss).ok());
  EXPECT_EQ(loss, nullptr);
  EXPECT_TRUE(MakeLoss("trivial", 0.0, &loss).ok());  // scale ignored
}

TEST(LossNamesTest, ListsSixNames) {
  EXPECT_EQ(LossNames(),
            (std::vector<std::string>{"trivial", "huber", "cauchy", "soft_l1", "arctan", "tukey"}));
}

}  // namespace
}  // namespace edgefit
