// Known joints from a ROS joint_states YAML file (joint_states.h).
#include "edgefit/io/joint_states.h"

#include <gtest/gtest.h>

#include <fstream>

namespace edgefit {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(JointStatesTest, ReadsTheNamedPositions) {
  // As edgefit fit --out_joint_states writes it.
  const std::string path = Write("joints.yaml",
                                 "# edgefit fit: sensor_msgs/JointState (radians, metres)\n"
                                 "name: [joint_1, joint_2, gun_joint]\n"
                                 "position: [0.5, -1.25, 0.09]\nvelocity: []\neffort: []\n");
  std::vector<std::pair<std::string, double>> values;
  ASSERT_TRUE(ReadJointStates(path, &values).ok());
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[1].first, "joint_2");
  EXPECT_EQ(values[1].second, -1.25);
}

TEST(JointStatesTest, BadFilesNameTheFile) {
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"no_position.yaml", "name: [a, b]\n"},
           {"lengths.yaml", "name: [a, b]\nposition: [0.1]\n"},
           {"not_numbers.yaml", "name: [a]\nposition: [x]\n"},
           {"garbage.yaml", "name: [a\n"}}) {
    const std::string path = Write(name, text);
    std::vector<std::pair<std::string, double>> values;
    const Status status = ReadJointStates(path, &values);
    ASSERT_FALSE(status.ok()) << name;
    EXPECT_EQ(status.message().rfind(path + ": ", 0), 0u) << status.message();
    EXPECT_TRUE(values.empty());
  }
  std::vector<std::pair<std::string, double>> values;
  EXPECT_FALSE(ReadJointStates(::testing::TempDir() + "/missing.yaml", &values).ok());
}

}  // namespace
}  // namespace edgefit
