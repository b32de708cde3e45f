#include "edgefit/scanner/depth_camera.h"

#include <Eigen/Geometry>
#include <cmath>

#include "counter_rng.h"

namespace edgefit {

namespace {
// Streams of the camera's draws, above those of the range noise and dropouts.
constexpr uint64_t kGridStream = uint64_t{3} << 40;
constexpr uint64_t kPixelStream = uint64_t{4} << 40;

double GridDraw(uint64_t seed, uint64_t scan, int64_t gr, int64_t gc) {
  const uint64_t cell = (static_cast<uint64_t>(gr) << 32) ^ static_cast<uint64_t>(gc);
  return scanner_internal::StandardNormal(
      scanner_internal::CounterHash(seed, kGridStream + 2 * scan, cell),
      scanner_internal::CounterHash(seed, kGridStream + 2 * scan + 1, cell));
}
}  // namespace

bool DepthCameraOptions::IsValid(std::string* error) const {
  if (!enabled()) return true;
  if (width < 2 || height < 2 || width > 16384 || height > 16384) {
    *error = "depth camera: width and height must be 2..16384 px";
    return false;
  }
  if (!camera.IsValid(error)) return false;
  if (!(sigma_at_1m >= 0.0 && sigma_at_1m < 0.1)) {
    *error = "depth camera: sigma_at_1m must be in [0, 100 mm)";
  } else if (!(correlated_share >= 0.0 && correlated_share <= 1.0)) {
    *error = "depth camera: correlated_share must be in [0, 1]";
  } else if (correlation_px < 1) {
    *error = "depth camera: correlation_px must be at least 1";
  } else if (!(footprint_px >= 0.0 && footprint_px <= 8.0)) {
    *error = "depth camera: footprint_px must be in [0, 8]";
  } else {
    return true;
  }
  return false;
}

BeamOptions DepthCameraOptions::FlyingPixelBeam() const {
  BeamOptions beam;
  if (!(footprint_px > 0.0)) return beam;  // an ideal ray
  beam.sub_rays = 16;
  beam.exit_diameter = 0.0;
  beam.divergence = footprint_px / std::max(camera.fx, camera.fy);  // [rad] full angle
  beam.mixed_return = MixedReturn::kMean;
  beam.mixed_depth = 0.005;
  return beam;
}

double DepthCameraOptions::NoiseDraw(uint64_t seed, uint64_t scan, int row, int col) const {
  const double white = scanner_internal::StandardNormal(
      scanner_internal::CounterHash(seed, kPixelStream + 2 * scan,
                                    static_cast<uint64_t>(row) * 65536u + static_cast<uint64_t>(col)),
      scanner_internal::CounterHash(seed, kPixelStream + 2 * scan + 1,
                                    static_cast<uint64_t>(row) * 65536u + static_cast<uint64_t>(col)));
  if (!(correlated_share > 0.0)) return white;
  const double fr = static_cast<double>(row) / correlation_px;
  const double fc = static_cast<double>(col) / correlation_px;
  const int64_t r0 = static_cast<int64_t>(std::floor(fr)), c0 = static_cast<int64_t>(std::floor(fc));
  const double a = fr - r0, b = fc - c0;
  const double w[4] = {(1 - a) * (1 - b), (1 - a) * b, a * (1 - b), a * b};
  const double n = w[0] * GridDraw(seed, scan, r0, c0) + w[1] * GridDraw(seed, scan, r0, c0 + 1) +
                   w[2] * GridDraw(seed, scan, r0 + 1, c0) + w[3] * GridDraw(seed, scan, r0 + 1, c0 + 1);
  const double correlated = n / std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2] + w[3] * w[3]);
  return std::sqrt(correlated_share) * correlated + std::sqrt(1.0 - correlated_share) * white;
}

bool LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up,
            Pose* T_world_camera) {
  const Eigen::Vector3d z = target - eye;
  if (!(z.norm() > 1e-9) || !(up.norm() > 1e-9)) return false;
  const Eigen::Vector3d forward = z.normalized();
  const Eigen::Vector3d right = forward.cross(up.normalized());  // image x
  if (!(right.norm() > 1e-6)) return false;
  Eigen::Matrix3d R;
  R.col(0) = right.normalized();
  R.col(2) = forward;
  R.col(1) = R.col(2).cross(R.col(0));  // image y: down
  *T_world_camera = Pose::Identity();
  T_world_camera->linear() = R;
  T_world_camera->translation() = eye;
  return true;
}

}  // namespace edgefit
