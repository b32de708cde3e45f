#include "edgefit/model/joint_values.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

class JointValuesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) +
                                       "/assets/models/balancer_arm.urdf",
                                   ModelLoadOptions(), &model_)
                    .ok());
    q_ = model_.ZeroJoints();
  }
  double Value(const std::string& joint) const { return q_[model_.JointIndex(joint)]; }

  KinematicModel model_;
  std::vector<double> q_;
};

TEST_F(JointValuesTest, ParsesValuesAndUnits) {
  ASSERT_TRUE(ParseJointAssignments("joint_1=0.25,joint_2=-30deg", model_, &q_).ok());
  EXPECT_DOUBLE_EQ(Value("joint_1"), 0.25);
  EXPECT_NEAR(Value("joint_2"), -M_PI / 6, 1e-15);
}

TEST_F(JointValuesTest, RejectsBadAssignmentsNamingTheJoint) {
  Status s = ParseJointAssignments("joint_9=0.1", model_, &q_);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("joint_9"), std::string::npos);
  s = ParseJointAssignments("piston_joint=0.5", model_, &q_);  // loop-closure driven
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("piston_joint"), std::string::npos);
  s = ParseJointAssignments("joint_2=3.0", model_, &q_);  // limit is 1 rad
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("outside its limits"), std::string::npos);
  EXPECT_FALSE(ParseJointAssignments("joint_1", model_, &q_).ok());
  EXPECT_FALSE(ParseJointAssignments("joint_1=abc", model_, &q_).ok());
  EXPECT_FALSE(ParseJointAssignments("joint_1=5furlongs", model_, &q_).ok());
  EXPECT_FALSE(ParseJointAssignments("joint_1=nan", model_, &q_).ok());
}

TEST_F(JointValuesTest, NamedPosturesFromFile) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("edgefit_postures_" + std::to_string(::getpid()) + ".json"))
                               .string();
  std::ofstream(path) << R"({"postures": {"zeta": {"joint_1": 0.5}, "alpha": {"joint_2": -0.2}}})";
  std::vector<std::string> names;
  ASSERT_TRUE(ListPostures(path, &names).ok());
  EXPECT_EQ(names, (std::vector<std::string>{"zeta", "alpha"}));  // file order
  ASSERT_TRUE(LoadNamedPosture(path, "alpha", model_, &q_).ok());
  EXPECT_DOUBLE_EQ(Value("joint_2"), -0.2);
  const Status missing = LoadNamedPosture(path, "omega", model_, &q_);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("zeta, alpha"), std::string::npos);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace edgefit
