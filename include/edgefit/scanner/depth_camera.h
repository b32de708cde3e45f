// A virtual depth camera (stereo or structured light) for the virtual
// scanner: one ray per pixel of a pinhole camera (pinhole_camera.h) instead
// of the laser scanner's angular grid, and the depth errors such a sensor
// makes, so that the fit can be measured on frames of any robot seen the way
// a depth camera sees it (real frames are few).
//
// Depth noise grows with the square of the depth, as a stereo camera's
// disparity error does (z = f b / d, so sigma_z = z^2 sigma_d / (f b)):
//
//   sigma_z(z) = sigma_at_1m * (z / 1 m)^2                          [m]
//
// and a stereo matcher averages over a window, so most of it is correlated
// over several pixels: per pixel the standard normal draw is
//
//   n = sqrt(correlated_share) * N_grid(r, c) + sqrt(1 - correlated_share) * N_pixel
//
// N_grid interpolated bilinearly between independent draws on a grid of
// correlation_px pixels (and rescaled to unit variance), N_pixel independent.
// The depth z (not the range along the ray) moves by sigma_z(z) n.
//
// Flying pixels at silhouettes: the scanner's beam footprint model
// (beam_footprint.h) with a footprint of footprint_px pixels (FlyingPixelBeam):
// across a depth step the depth is the energy-weighted mean of both
// surfaces, as the matcher's window mixes them.
//
// Defaults: a ZED 2i class stereo camera; the real Med7 frames of
// ../shared/data/real measure 4.5-11.6 mm, their base 1.65 m from the
// camera.
#ifndef EDGEFIT_SCANNER_DEPTH_CAMERA_H_
#define EDGEFIT_SCANNER_DEPTH_CAMERA_H_

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "edgefit/core/pose.h"
#include "edgefit/scan/pinhole_camera.h"
#include "edgefit/scanner/beam_footprint.h"

namespace edgefit {

struct DepthCameraOptions {
  int width = 0, height = 0;  // [px]; 0: no camera (the laser scanner's angular grid)
  PinholeCamera camera;       // intrinsics (camera_info.yaml), no distortion needed
  double sigma_at_1m = 0.0025;   // [m] depth noise at 1 m depth; grows with depth^2
  double correlated_share = 0.8; // share of the noise variance correlated over correlation_px
  int correlation_px = 12;       // [px] grid of the correlated noise
  double footprint_px = 2.0;     // [px] full width of a pixel's footprint (flying pixels); 0: none

  bool enabled() const { return width > 0; }
  bool IsValid(std::string* error) const;
  // The beam footprint (16 sub-rays, energy-weighted mean depth) that makes
  // the flying pixels; an ideal ray with footprint_px = 0.
  BeamOptions FlyingPixelBeam() const;
  // The standard normal draw n of pixel (row, col) of scan `scan` (above):
  // a function of (seed, scan, row, col) only.
  double NoiseDraw(uint64_t seed, uint64_t scan, int row, int col) const;
};

// The camera's pose in the world (optical frame: x right, y down, z
// forward) at `eye` looking at `target`, with world `up` drawn upwards in
// the image. Fails (false) when the eye is at the target or looks along up.
bool LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up,
            Pose* T_world_camera);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_DEPTH_CAMERA_H_
