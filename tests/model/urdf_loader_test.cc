#include "edgefit/model/urdf_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace edgefit {
namespace {
namespace fs = std::filesystem;

const std::string kTetra = EDGEFIT_SOURCE_DIR "/assets/models/meshes/tetra_ascii.stl";

void WriteFile(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string Robot(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n" + body + "\n</robot>\n";
}

std::string MeshLink(const std::string& name, const std::string& filename,
                     const std::string& extra = "") {
  return "<link name=\"" + name + "\"><visual>" + extra + "<geometry><mesh filename=\"" + filename +
         "\"" + (extra.empty() ? "" : " scale=\"0.001 0.001 0.001\"") +
         "/></geometry></visual></link>";
}

class UrdfLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("urdf_loader_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Loads `xml` written at dir_/rel; captures everything printed meanwhile.
  Status Load(const std::string& rel, const std::string& xml, KinematicModel* model) {
    WriteFile(dir_ / rel, xml);
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    const Status status = LoadKinematicModel((dir_ / rel).string(), {}, model);
    printed_ = ::testing::internal::GetCapturedStdout() + ::testing::internal::GetCapturedStderr();
    return status;
  }
  fs::path dir_;
  std::string printed_;
};

TEST_F(UrdfLoaderTest, UnsupportedJointTypeIsOneClearLine) {
  KinematicModel model;
  for (const std::string type : {"floating", "planar", "spherical"}) {
    const Status status = Load("robot.urdf", Robot(R"(<link name="a"/><link name="b"/>
        <joint name="j3" type=")" + type + R"("><parent link="a"/><child link="b"/></joint>)"),
                               &model);
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.message(), (dir_ / "robot.urdf").string() + ": joint 'j3': unsupported type '" +
                                    type + "' (edgefit handles fixed, revolute, continuous, prismatic)");
    EXPECT_EQ(printed_, "");
  }
}

TEST_F(UrdfLoaderTest, BrokenXmlAndUrdfdomErrorsAreOneLineAndSilent) {
  KinematicModel model;
  Status status = Load("broken.urdf", "<robot name=\"r\"><link name=\"a\">\n</robot>", &model);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message().rfind((dir_ / "broken.urdf").string() + ": XML error at line", 0), 0u)
      << status.message();
  EXPECT_EQ(status.message().find('\n'), std::string::npos);
  // A revolute joint without <limit>: urdfdom rejects it and logs; we capture.
  status = Load("nolimit.urdf", Robot(R"(<link name="a"/><link name="b"/>
      <joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint>)"), &model);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message().rfind((dir_ / "nolimit.urdf").string() + ": not a valid URDF: ", 0), 0u)
      << status.message();
  EXPECT_EQ(status.message().find('\n'), std::string::npos);
  EXPECT_EQ(printed_, "");
  status = LoadKinematicModel((dir_ / "absent.urdf").string(), {}, &model);
  EXPECT_EQ(status.message(), (dir_ / "absent.urdf").string() + ": cannot open file");
}

TEST_F(UrdfLoaderTest, PackageUrisResolveInPackageDirAndFlattenedLayouts) {
  // <ws>/my_pkg/urdf/robot.urdf referring to package://my_pkg/meshes/t.stl.
  fs::create_directories(dir_ / "ws/my_pkg/meshes");
  fs::copy_file(kTetra, dir_ / "ws/my_pkg/meshes/t.stl");
  KinematicModel model;
  Status status = Load("ws/my_pkg/urdf/robot.urdf",
                       Robot(MeshLink("a", "package://my_pkg/meshes/t.stl")), &model);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(model.links()[0].visuals[0].mesh_path, (dir_ / "ws/my_pkg/meshes/t.stl").string());
  EXPECT_EQ(model.links()[0].mesh.triangles.size(), 4u);
  // Flattened: robot.urdf beside meshes/, package name unknown on disk.
  fs::create_directories(dir_ / "flat/meshes");
  fs::copy_file(kTetra, dir_ / "flat/meshes/t.stl");
  status = Load("flat/robot.urdf", Robot(MeshLink("a", "package://other_pkg/meshes/t.stl")), &model);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(model.links()[0].visuals[0].mesh_path, (dir_ / "flat/meshes/t.stl").string());
  // Relative path, visual origin and scale.
  status = Load("flat/rel.urdf",
                Robot(MeshLink("a", "meshes/t.stl", "<origin xyz=\"1 0 0\" rpy=\"0 0 1.5707963267948966\"/>")),
                &model);
  ASSERT_TRUE(status.ok()) << status.message();
  const Eigen::AlignedBox3d bb = model.links()[0].mesh.BoundingBox();
  EXPECT_TRUE(bb.min().isApprox(Eigen::Vector3d(0.999, 0, 0), 1e-9)) << bb.min().transpose();
  EXPECT_TRUE(bb.max().isApprox(Eigen::Vector3d(1.0, 0.001, 0.001), 1e-9)) << bb.max().transpose();
  EXPECT_EQ(model.links()[0].visuals[0].mesh_scale, Eigen::Vector3d::Constant(0.001));
}

TEST_F(UrdfLoaderTest, MissingMeshNamesEveryPathTried) {
  KinematicModel model;
  const Status status =
      Load("pkg_a/urdf/robot.urdf", Robot(MeshLink("base", "package://pkg_a/meshes/gone.stl")), &model);
  ASSERT_FALSE(status.ok());
  const std::string& m = status.message();
  EXPECT_NE(m.find("link 'base': mesh 'package://pkg_a/meshes/gone.stl' not found; tried: "),
            std::string::npos) << m;
  EXPECT_NE(m.find((dir_ / "pkg_a/meshes/gone.stl").string()), std::string::npos) << m;
  EXPECT_NE(m.find((dir_ / "pkg_a/urdf/meshes/gone.stl").string()), std::string::npos) << m;
}

TEST_F(UrdfLoaderTest, MimicAndOrderFromTheFile) {
  KinematicModel model;
  const Status status = Load("mimic.urdf", Robot(R"(<link name="z_base"/><link name="b"/><link name="a"/>
      <joint name="m" type="revolute"><parent link="z_base"/><child link="b"/><axis xyz="1 0 0"/>
        <limit lower="-1" upper="1" effort="0" velocity="0"/>
        <mimic joint="k" multiplier="-2" offset="0.1"/></joint>
      <joint name="k" type="continuous"><parent link="z_base"/><child link="a"/></joint>)"), &model);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(model.links()[0].name, "z_base");  // File order, not sorted.
  EXPECT_EQ(model.joints()[0].name, "m");
  EXPECT_EQ(model.joints()[0].mimic_joint, 1);
  EXPECT_EQ(model.joints()[0].mimic_multiplier, -2.0);
  EXPECT_EQ(model.joints()[1].axis, Eigen::Vector3d::UnitX());  // URDF default axis.
  std::vector<double> q = {0.0, 0.3};
  ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  EXPECT_DOUBLE_EQ(q[0], -0.5);
  EXPECT_EQ(model.IndependentJoints(), std::vector<int>{1});
}

}  // namespace
}  // namespace edgefit
