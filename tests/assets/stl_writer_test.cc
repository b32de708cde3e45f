#include "edgefit/assets/stl_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "edgefit/assets/mesh_topology.h"
#include "edgefit/assets/rectangular_loft.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/model/mesh_loader.h"

namespace edgefit {
namespace {

TEST(StlWriterTest, LayoutIsDeterministicAndLittleEndian) {
  const TriangleMesh box = MakeChamferedBox({0.3, 0.2, 0.1}, 0.01);
  const std::string bytes = EncodeBinaryStl(box, "box");
  ASSERT_EQ(bytes.size(), 84u + 50u * box.triangles.size());
  EXPECT_EQ(bytes, EncodeBinaryStl(box, "box"));
  EXPECT_NE(bytes.substr(0, 5), "solid");
  EXPECT_EQ(bytes.substr(0, 28), std::string("edgefit procedural mesh: box"));
  EXPECT_EQ(bytes[28], '\0');
  const unsigned char* count = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
  EXPECT_EQ(count[0] | count[1] << 8 | count[2] << 16 | count[3] << 24,
            static_cast<int>(box.triangles.size()));
}

// The normal is the one of the float32 corners a reader sees, in every
// build type (GCC 12 -O3 once folded the float rounding away here).
TEST(StlWriterTest, NormalIsThatOfTheRoundedCorners) {
  TriangleMesh sliver;
  const double s = 0.05 * std::sin(M_PI / 64.0), c = -0.05 * std::cos(M_PI / 64.0);
  sliver.vertices = {{-0.004, 0.0, -0.05}, {-0.004, s, c}, {0.02, s, c}};
  sliver.triangles = {{0, 1, 2}};
  const std::string bytes = EncodeBinaryStl(sliver, "sliver");
  float normal[3];
  std::memcpy(normal, bytes.data() + 84, sizeof(normal));
  // From the float corners; the exact double geometry gives 0.0245412290.
  EXPECT_EQ(normal[1], 0.024541055783629417f);
}

TEST(StlWriterTest, RoundTripsThroughTheMeshLoader) {
  const TriangleMesh box = MakeChamferedBox({0.3, 0.2, 0.1}, 0.01);
  const std::string path = ::testing::TempDir() + "/edgefit_stl_writer_" +
                           std::to_string(::getpid()) + ".stl";
  ASSERT_TRUE(WriteBinaryStl(path, box, "box").ok());
  TriangleMesh loaded;
  const Status status = LoadMesh(path, Eigen::Vector3d::Ones(), &loaded);
  ASSERT_TRUE(status.ok()) << status.message();
  WeldIdenticalVertices(&loaded);
  EXPECT_EQ(loaded.triangles.size(), box.triangles.size());
  EXPECT_EQ(loaded.vertices.size(), box.vertices.size());
  EXPECT_TRUE(AnalyzeMeshTopology(loaded).IsClosedAndOriented());
  EXPECT_NEAR(SignedVolume(loaded), SignedVolume(box), 1e-8);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace edgefit
