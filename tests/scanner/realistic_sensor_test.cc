// The realistic sensor of `edgefit scan --sensor=realistic`: each effect
// does what its header claims.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "edgefit/core/angles.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scan/mixed_pixels.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/beam_footprint.h"
#include "edgefit/scanner/range_noise.h"
#include "edgefit/scanner/station_residuals.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/as_built.h"
#include "edgefit/scene/jackets.h"
#include "scanner/scanner_test_util.h"

namespace edgefit {
namespace {

SceneMesh Box(const Eigen::AlignedBox3d& box, uint16_t label, double reflectance = 0.5) {
  SceneMesh m;
  Pose T = Pose::Identity();
  T.translation() = box.center();
  m.mesh_world.Append(MakeBoxMesh(box.sizes()), T);
  m.label = label;
  m.reflectance = reflectance;
  return m;
}

Pose ScannerAt(double x, double y, double z) {
  Pose T = Pose::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

VirtualScanOptions FootprintOptions() {
  VirtualScanOptions options;
  options.spacing = 0.002;
  options.noise_sigma = 0.0;
  EXPECT_TRUE(BeamPreset("leica_p40", &options.beam).ok());
  return options;
}

// A plate at x = 4 in front of a wall at x = 4.5, seen from the origin
// through a Leica P40 class beam, with range noise `noise_sigma` [m].
Status ScanPlateBeforeWall(double noise_sigma, VirtualScan* scan) {
  Scene scene;
  scene.meshes.push_back(Box({Eigen::Vector3d(4.0, -0.1, 1.4), Eigen::Vector3d(4.02, 0.1, 1.6)},
                             LinkLabel(0)));
  scene.meshes.push_back(
      Box({Eigen::Vector3d(4.5, -3, -1), Eigen::Vector3d(4.6, 3, 4)}, kLabelBackground));
  VirtualScanOptions options = FootprintOptions();
  options.noise_sigma = noise_sigma;
  options.asset_box_world = Eigen::AlignedBox3d(Eigen::Vector3d(4.0, -0.15, 1.35),
                                                Eigen::Vector3d(4.02, 0.15, 1.65));
  return ScanScene(scene, {ScannerAt(0, 0, 1.5)}, options, scan);
}

// The plate before the wall: the silhouette's cells mix both ranges and
// are labelled; the plate's and the wall's inner cells are not.
TEST(BeamFootprintTest, MixedPixelsLieBetweenSurfacesAndCarryTheirLabel) {
  VirtualScan scan;
  ASSERT_TRUE(ScanPlateBeforeWall(0.0, &scan).ok());
  const OrganizedScan& s = scan.scans.scans[0];
  size_t mixed = 0, between = 0, plate = 0, wall = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!s.IsValid(i)) continue;
    const double x = s.PointWorld(i).x();
    if (scan.labels[0][i] & kMixedPixelFlag) {
      ++mixed;
      between += x > 4.0 + 0.003 && x < 4.5 - 0.003;
    } else if (std::abs(x - 4.0) < 1e-3) {
      ++plate;
    } else if (std::abs(x - 4.5) < 1e-3) {
      ++wall;
    } else {
      ADD_FAILURE() << "unlabelled point off both surfaces at x = " << x;
    }
  }
  // The plate's outline is about 2 * (100 + 100) = 400 cells long.
  EXPECT_GT(mixed, 300u);
  EXPECT_GT(between, mixed / 2) << "most mixed pixels float between the surfaces";
  EXPECT_GT(plate, 5000u);
  EXPECT_GT(wall, 5000u);
}

// A plane seen at 80 degrees incidence is one surface: no mixed pixels.
TEST(BeamFootprintTest, GrazingPlaneIsNotMixed) {
  Scene scene;
  scene.meshes.push_back(testing_util::FloorMesh(30.0));
  VirtualScanOptions options = FootprintOptions();
  // A patch of floor about 8.5 m away, seen from 1.5 m high: ~80 deg incidence.
  options.asset_box_world =
      Eigen::AlignedBox3d(Eigen::Vector3d(8.0, -0.3, 0.0), Eigen::Vector3d(9.0, 0.3, 0.01));
  options.window_margin_deg = 0.5;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {ScannerAt(0, 0, 1.5)}, options, &scan).ok());
  size_t valid = 0, mixed = 0;
  for (size_t i = 0; i < scan.labels[0].size(); ++i) {
    valid += scan.scans.scans[0].IsValid(i);
    mixed += (scan.labels[0][i] & kMixedPixelFlag) != 0;
  }
  EXPECT_GT(valid, 1000u);
  EXPECT_EQ(mixed, 0u);
}

// The cells of a scan of the plate before the wall that `found` flags,
// against the labels.
struct MixedPixelCounts {
  size_t labelled = 0, flagged = 0, right = 0;
  size_t far_off = 0, far_off_found = 0;  // off both surfaces by more than 2 cm: unmistakable
  double precision() const { return static_cast<double>(right) / std::max<size_t>(flagged, 1); }
  double recall() const { return static_cast<double>(right) / std::max<size_t>(labelled, 1); }
};

MixedPixelCounts CountMixedPixels(const VirtualScan& scan, const MixedPixelOptions& options) {
  const OrganizedScan& s = scan.scans.scans[0];
  const std::vector<uint8_t> found = FindMixedPixels(s, options);
  MixedPixelCounts counts;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!s.IsValid(i)) continue;
    const bool label = (scan.labels[0][i] & kMixedPixelFlag) != 0;
    counts.labelled += label;
    counts.flagged += found[i];
    counts.right += label && found[i];
    const double x = s.PointWorld(i).x();
    if (label && x > 4.02 + 0.02 && x < 4.5 - 0.02) {
      ++counts.far_off;
      counts.far_off_found += found[i];
    }
  }
  return counts;
}

// Mixed-pixel removal (scan/mixed_pixels.h) on the plate before the wall,
// with 1 mm range noise: it finds most labelled mixed pixels and little
// else. The cells mixed along 3 lines alone find fewer: the rest of the
// band a footprint leaves across the edge steps almost linearly from one
// surface to the other, each cell on the extrapolation through its
// neighbour in the band along most lines.
TEST(MixedPixelRemovalTest, FindsTheLabelledMixedPixelsOfAnEdge) {
  VirtualScan scan;
  ASSERT_TRUE(ScanPlateBeforeWall(0.001, &scan).ok());
  const MixedPixelCounts counts = CountMixedPixels(scan, MixedPixelOptions());
  MixedPixelOptions three_lines;
  three_lines.neighbour_lines = 0;
  const MixedPixelCounts three = CountMixedPixels(scan, three_lines);
  std::printf("  3 lines: precision %.3f, recall %.3f; and 1 beside them: %.3f, %.3f\n",
              three.precision(), three.recall(), counts.precision(), counts.recall());
  ASSERT_GT(counts.labelled, 300u);
  EXPECT_GT(counts.precision(), 0.9);
  EXPECT_GT(counts.recall(), three.recall() + 0.05);
  EXPECT_GE(static_cast<double>(counts.far_off_found), 0.9 * static_cast<double>(counts.far_off))
      << "the mixed pixels far off both surfaces";
}

// A floor at about 80 degrees incidence, 1 mm range noise: one surface.
TEST(MixedPixelRemovalTest, KeepsANoisyGrazingPlane) {
  Scene scene;
  scene.meshes.push_back(testing_util::FloorMesh(30.0));
  VirtualScanOptions options = FootprintOptions();
  options.noise_sigma = 0.001;
  options.asset_box_world =
      Eigen::AlignedBox3d(Eigen::Vector3d(8.0, -0.3, 0.0), Eigen::Vector3d(9.0, 0.3, 0.01));
  options.window_margin_deg = 0.5;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {ScannerAt(0, 0, 1.5)}, options, &scan).ok());
  const OrganizedScan& s = scan.scans.scans[0];
  const std::vector<uint8_t> found = FindMixedPixels(s, MixedPixelOptions());
  size_t flagged = 0;
  for (const uint8_t f : found) flagged += f;
  EXPECT_GT(s.CountValid(), 1000u);
  EXPECT_LE(flagged, s.CountValid() / 1000) << flagged << " cells of a plane taken for mixed pixels";
}

TEST(BeamFootprintTest, PresetsAndRadius) {
  BeamOptions beam;
  ASSERT_TRUE(BeamPreset("faro_focus", &beam).ok());
  EXPECT_GT(beam.sub_rays, 1);
  EXPECT_NEAR(beam.Radius(0.0), 0.00125, 1e-12);
  EXPECT_NEAR(beam.Radius(10.0), 0.00125 + 10.0 * std::tan(0.5 * 0.00019), 1e-12);
  ASSERT_TRUE(BeamPreset("ideal", &beam).ok());
  EXPECT_FALSE(beam.enabled());
  EXPECT_FALSE(BeamPreset("laser_pointer", &beam).ok());
}

TEST(RangeNoiseTest, NoiseGrowsAndReturnsDropWithWeakerSignal) {
  RangeNoiseOptions off;
  EXPECT_EQ(off.NoiseFactor(0.01), 1.0);
  EXPECT_EQ(off.DropoutProbability(0.0), 0.0);
  RangeNoiseOptions on;
  on.signal_model = true;
  EXPECT_DOUBLE_EQ(on.NoiseFactor(1.0), 1.0);
  EXPECT_NEAR(on.NoiseFactor(std::cos(70 * kDeg)), 1.0 / std::sqrt(std::cos(70 * kDeg)), 1e-12);
  EXPECT_EQ(on.NoiseFactor(1e-6), on.max_factor);
  EXPECT_EQ(on.DropoutProbability(1.0), 0.0);
  EXPECT_EQ(on.DropoutProbability(0.01), 1.0);
  const double mid = 0.5 * (on.dropout_signal_none + on.dropout_signal_full);
  EXPECT_NEAR(on.DropoutProbability(mid), 0.5, 1e-12);
}

// Noise measured on two plates, one facing the scanner and one turned by
// 70 deg, and a black plate that returns nothing.
TEST(RangeNoiseTest, ScanNoiseFollowsIncidenceAndDarkSurfacesDropOut) {
  Scene scene;
  scene.meshes.push_back(Box({Eigen::Vector3d(4.0, -0.6, 1.0), Eigen::Vector3d(4.01, -0.2, 2.0)},
                             LinkLabel(0)));
  SceneMesh turned = Box({Eigen::Vector3d(-0.005, -0.2, -0.5), Eigen::Vector3d(0.005, 0.2, 0.5)},
                         LinkLabel(1));
  Pose T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(70 * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(4.0, 0.2, 1.5);
  for (Eigen::Vector3d& v : turned.mesh_world.vertices) v = T * v;
  scene.meshes.push_back(turned);
  scene.meshes.push_back(Box({Eigen::Vector3d(4.0, 0.6, 1.0), Eigen::Vector3d(4.01, 1.0, 2.0)},
                             LinkLabel(2), /*reflectance=*/0.01));
  VirtualScanOptions options;
  options.spacing = 0.003;
  options.noise_sigma = 0.001;
  options.range_noise.signal_model = true;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {ScannerAt(0, 0, 1.5)}, options, &scan).ok());
  const OrganizedScan& s = scan.scans.scans[0];
  // Residual along the plate normal, per plate, on the face towards the
  // scanner (the thin side faces are left out by a 5 sigma gate).
  const Eigen::Vector3d n_turned = T.linear() * Eigen::Vector3d::UnitX();
  double sum2[2] = {0, 0};
  size_t n[3] = {0, 0, 0}, used[2] = {0, 0};
  for (size_t i = 0; i < s.size(); ++i) {
    const uint16_t label = scan.labels[0][i] & kLabelMask;
    if (!IsLinkLabel(label)) continue;
    const int plate = LinkOfLabel(label);
    ++n[plate];
    const Eigen::Vector3d p = s.PointWorld(i);
    const double r =
        plate == 0 ? p.x() - 4.0 : n_turned.dot(p - T.translation()) + 0.005;  // front faces
    // Away from the turned plate's end faces (10 mm wide, seen too).
    const bool inner = plate != 1 || std::abs((T.linear() * Eigen::Vector3d::UnitY())
                                                  .dot(p - T.translation())) < 0.18;
    if (plate < 2 && inner && std::abs(r) < 0.005) {
      sum2[plate] += r * r;
      ++used[plate];
    }
  }
  ASSERT_GT(n[0], 1000u);
  ASSERT_GT(n[1], 500u);
  EXPECT_EQ(n[2], 0u) << "a surface of reflectance 0.01 returns nothing";
  // Along the normal, a range error e moves the point by e cos(theta): the
  // normal residual's sigma is sigma0 S^-1/2 cos(theta) with S = cos(theta)
  // at the reference reflectance; sigma0 facing the scanner.
  const double sigma_face = std::sqrt(sum2[0] / used[0]);
  const double sigma_turned = std::sqrt(sum2[1] / used[1]);
  const double incidence = std::acos(std::abs(n_turned.normalized().dot(Eigen::Vector3d(4, 0.2, 0).normalized())));
  const double expected = std::sqrt(std::cos(incidence));
  EXPECT_NEAR(sigma_face, 0.001, 0.0001);
  EXPECT_NEAR(sigma_turned / sigma_face, expected, 0.15 * expected);
}

TEST(StationResidualTest, WrittenPosesAreOffWithinTheirRanges) {
  std::vector<Pose> truth;
  for (int i = 0; i < 8; ++i) truth.push_back(ScannerAt(i, 2.0 * i, 1.5));
  StationResidualOptions options;
  EXPECT_EQ(PerturbStationPoses(truth, options)[3].matrix(), truth[3].matrix()) << "off: exact";
  options.enabled = true;
  const std::vector<Pose> written = PerturbStationPoses(truth, options);
  for (size_t i = 0; i < truth.size(); ++i) {
    const double shift = (written[i].translation() - truth[i].translation()).norm();
    const double angle =
        Eigen::AngleAxisd(written[i].linear() * truth[i].linear().transpose()).angle();
    EXPECT_GE(shift, options.translation_min - 1e-12);
    EXPECT_LE(shift, options.translation_max + 1e-12);
    EXPECT_GE(angle, options.rotation_min - 1e-12);
    EXPECT_LE(angle, options.rotation_max + 1e-12);
  }
  EXPECT_NE(written[0].matrix(), written[1].matrix());
}

TEST(AsBuiltTest, FieldIsBoundedSmoothAndMovesCoincidentVerticesTogether) {
  AsBuiltOptions options;
  options.enabled = true;
  const AsBuiltField field(options, 3);
  EXPECT_GE(field.amplitude(), options.amplitude_min);
  EXPECT_LE(field.amplitude(), options.amplitude_max);
  double largest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d x(0.001 * i, 0.0007 * i, -0.0003 * i);
    const Eigen::Vector3d d = field.Displacement(x);
    largest = std::max(largest, d.norm());
    // Smooth: over 1 mm the field changes by at most A * 2 pi / wavelength_min * 1 mm.
    const double slope = field.amplitude() * 2.0 * M_PI / options.wavelength_min;
    EXPECT_LE((field.Displacement(x + Eigen::Vector3d(0.001, 0, 0)) - d).norm(),
              slope * 0.001 + 1e-12);
  }
  EXPECT_LE(largest, field.amplitude() + 1e-12);
  EXPECT_GT(largest, 0.2 * field.amplitude());

  // An unwelded box (24 corners for 8 positions): split and moved, it stays closed.
  TriangleMesh mesh = MakeBoxMesh(Eigen::Vector3d(0.3, 0.2, 0.1));
  ApplyAsBuilt(options, 3, Pose::Identity(), &mesh);
  EXPECT_GT(mesh.triangles.size(), 12u * 16u);
  TriangleMesh welded = mesh;
  const size_t before = welded.vertices.size();
  WeldIdenticalVertices(&welded);
  EXPECT_EQ(welded.triangles.size(), mesh.triangles.size());
  EXPECT_LE(welded.vertices.size(), before);
}

// The bundled robot's jackets: the upper arm and the forearm, each vertex 3-8
// mm off the link's surface.
TEST(JacketTest, BundledRobotJacketsCoverUpperArmAndForearmAtTheirOffset) {
  KinematicModel model;
  ASSERT_TRUE(LoadModelWithAttachments(EDGEFIT_SOURCE_DIR "/assets/robot/robot.urdf", {},
                                       ModelLoadOptions(), &model)
                  .ok());
  JacketOptions options;
  options.enabled = true;
  const std::vector<int> links = JacketLinks(model, options);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_EQ(model.links()[links[0]].name, "link_2");
  EXPECT_EQ(model.links()[links[1]].name, "link_4");
  const std::vector<double> q = model.ZeroJoints();
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, Pose::Identity());
  Scene scene;
  ASSERT_TRUE(AddJackets(model, T_world_link, options, &scene).ok());
  ASSERT_EQ(scene.meshes.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const SceneMesh& jacket = scene.meshes[k];
    EXPECT_EQ(jacket.label, kLabelAccessory | kJacketFlag);
    TriangleMesh link_world;
    link_world.Append(model.links()[links[k]].mesh, T_world_link[links[k]]);
    const testing_util::MeshProximity inner(link_world, options.offset_min - 0.0005);
    const testing_util::MeshProximity outer(link_world, options.offset_max + 0.0005);
    size_t too_close = 0, too_far = 0;
    for (const Eigen::Vector3d& v : jacket.mesh_world.vertices) {
      too_close += inner.Within(v);
      too_far += !outer.Within(v);
    }
    const double n = static_cast<double>(jacket.mesh_world.vertices.size());
    EXPECT_GT(n, 100);
    // Vertex normals at concave corners and creases point partly into the
    // link: some vertices come closer than the offset there (9 % measured).
    EXPECT_LT(too_close, 0.15 * n);
    EXPECT_EQ(too_far, 0u);
  }
  options.links = {"no_such_link"};
  EXPECT_FALSE(AddJackets(model, T_world_link, options, &scene).ok());
}

TEST(SensorPresetTest, NamesAndEffects) {
  AssetScanOptions options;
  ASSERT_TRUE(ApplySensorPreset("realistic", &options).ok());
  EXPECT_TRUE(options.scan.beam.enabled());
  EXPECT_TRUE(options.scan.range_noise.signal_model);
  EXPECT_TRUE(options.station_residuals.enabled);
  EXPECT_TRUE(options.as_built.enabled);
  EXPECT_FALSE(options.jackets.enabled);
  ASSERT_TRUE(ApplySensorPreset("ideal+stations+jackets", &options).ok());
  EXPECT_FALSE(options.scan.beam.enabled());
  EXPECT_TRUE(options.station_residuals.enabled);
  EXPECT_TRUE(options.jackets.enabled);
  EXPECT_FALSE(options.as_built.enabled);
  EXPECT_FALSE(ApplySensorPreset("realistic+fog", &options).ok());
}

}  // namespace
}  // namespace edgefit
