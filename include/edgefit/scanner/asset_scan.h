// A virtual scan of one posed asset, the scene `edgefit scan` makes (paper
// Sec. 7.3): the model at joint values q on a floor, optional non-modelled
// accessories (harnesses, covers, brackets), clutter around it, scanners
// placed around it (or given), one ray per grid cell with range noise.
// One seed drives every random part through independent streams, so a
// scene is reproducible from (model, q, base, options).
#ifndef EDGEFIT_SCANNER_ASSET_SCAN_H_
#define EDGEFIT_SCANNER_ASSET_SCAN_H_

#include <cstdint>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scanner/virtual_scanner.h"

namespace edgefit {

struct AssetScanOptions {
  bool accessories = false;  // add harnesses, hoses, covers, brackets
  int clutter = 4;           // pillars, pallets, fence panels away from the asset
  // Scanners placed around the asset (PlaceScanners: 2.5-5 m away, 1.2-1.8 m
  // high) unless explicit poses are given.
  int scanners = 3;
  std::vector<Pose> T_world_scanners;
  // Spacing, noise, range, window; its seed is replaced by a stream of `seed`.
  VirtualScanOptions scan;
  uint64_t seed = 1;
};

// The sub-seeds of `seed` for each random part (also the `edgefit scan`
// streams): 1 accessories, 2 clutter, 3 scanner placement, 4 range noise.
enum class AssetScanStream : uint64_t {
  kAccessories = 1,
  kClutter = 2,
  kPlacement = 3,
  kNoise = 4
};
uint64_t AssetScanSeed(uint64_t seed, AssetScanStream stream);

// Builds the scene and scans it. T_world_scanners receives the scanner poses
// used (may be null). Fails on a model without geometry or bad options.
Status ScanAsset(const KinematicModel& model, const std::vector<double>& q,
                 const Pose& T_world_base, const AssetScanOptions& options, VirtualScan* result,
                 std::vector<Pose>* T_world_scanners);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_ASSET_SCAN_H_
