// The fit's thresholds scaled to the scans' noise (noise_scale.h): laser
// scans keep theirs; a depth camera's centimetre widens them in
// proportion, the occlusion tolerances to 3 sigma at least, and seek no
// coverings.
#include "edgefit/pipeline/noise_scale.h"

#include <gtest/gtest.h>

namespace edgefit {
namespace {

TEST(NoiseScaleTest, LaserScansKeepTheirThresholds) {
  const FitOptions options;
  EXPECT_EQ(NoiseScaleFor(0.001, options.noise), 1.0);
  EXPECT_EQ(NoiseScaleFor(0.003, options.noise), 1.0);
  const FitOptions same = ScaledToNoise(options, 0.002);
  EXPECT_EQ(same.base.icp.final_gate, options.base.icp.final_gate);
  EXPECT_EQ(same.chain.sweep.tau_dist, options.chain.sweep.tau_dist);
  EXPECT_EQ(same.quality.max_rms, options.quality.max_rms);
  EXPECT_EQ(same.refinement.chain.cad_deviation, options.refinement.chain.cad_deviation);
  EXPECT_EQ(same.refinement.coverings.rounds, options.refinement.coverings.rounds);
}

TEST(NoiseScaleTest, ADepthCamerasCentimetreWidensThem) {
  const FitOptions options;
  const double sigma = 0.012, k = 4.0;  // reference 3 mm
  EXPECT_DOUBLE_EQ(NoiseScaleFor(sigma, options.noise), k);
  const FitOptions scaled = ScaledToNoise(options, sigma);
  EXPECT_DOUBLE_EQ(scaled.chain.sweep.tau_dist, k * options.chain.sweep.tau_dist);
  // The RMS limit keeps its ratio to the final gate (3 mm of 5): 1.8 sigma.
  EXPECT_DOUBLE_EQ(scaled.quality.max_rms, 1.8 * sigma);
  // Final gates and occlusion tolerances: at least 3 sigma.
  EXPECT_DOUBLE_EQ(scaled.chain.joint_icp.final_gate, 3.0 * sigma);
  EXPECT_DOUBLE_EQ(scaled.refinement.chain.visibility_tolerance, 3.0 * sigma);
  EXPECT_DOUBLE_EQ(scaled.chain.sweep.visibility_tolerance,
                   k * options.chain.sweep.visibility_tolerance);  // 4 cm > 3 sigma
  // The first gate stays (the rough estimate's error), above the final one.
  EXPECT_GE(scaled.base.icp.correspondence.max_distance, scaled.base.icp.final_gate);
  EXPECT_EQ(scaled.base.icp.correspondence.max_distance,
            options.base.icp.correspondence.max_distance);
  // The correlated error in the covariance's patches.
  EXPECT_DOUBLE_EQ(scaled.refinement.chain.cad_deviation, options.noise.patch_deviation * sigma);
  // No coverings: a jacket's millimetres are inside the noise.
  EXPECT_EQ(scaled.refinement.coverings.rounds, 0);
  // Bounded, and off when asked.
  EXPECT_DOUBLE_EQ(NoiseScaleFor(1.0, options.noise), options.noise.max_scale);
  FitOptions off = options;
  off.noise.scale = false;
  EXPECT_EQ(NoiseScaleFor(sigma, off.noise), 1.0);
}

}  // namespace
}  // namespace edgefit
