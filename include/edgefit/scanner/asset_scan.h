// A virtual scan of one posed asset, the scene `edgefit scan` makes (paper
// Sec. 7.3): the model at joint values q on a floor, optional non-modelled
// accessories (harnesses, covers, brackets), clutter around it, scanners
// placed around it (or given), one ray per grid cell with range noise.
// One seed drives every random part through independent streams, so a
// scene is reproducible from (model, q, base, options).
#ifndef EDGEFIT_SCANNER_ASSET_SCAN_H_
#define EDGEFIT_SCANNER_ASSET_SCAN_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scanner/station_residuals.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/as_built.h"
#include "edgefit/scene/jackets.h"

namespace edgefit {

struct AssetScanOptions {
  bool accessories = false;  // add harnesses, hoses, covers, brackets
  int clutter = 4;           // pillars, pallets, fence panels away from the asset
  // Scanners placed around the asset (PlaceScanners: 2.5-5 m away, 1.2-1.8 m
  // high) unless explicit poses are given.
  int scanners = 3;
  std::vector<Pose> T_world_scanners;
  // Spacing, noise, beam, range, window; its seed is replaced by a stream of `seed`.
  VirtualScanOptions scan;
  // Robots as built: link surfaces off their CAD (as_built.h), protective
  // jackets (jackets.h); stations registered with residuals
  // (station_residuals.h). Their seeds are replaced by streams of `seed`.
  AsBuiltOptions as_built;
  JacketOptions jackets;
  StationResidualOptions station_residuals;
  uint64_t seed = 1;
};

// The sensors of `edgefit scan --sensor`, items joined by '+' and applied in
// order: "ideal" (one exact ray per cell, Gaussian range noise, exact
// station poses, surfaces exactly the CAD: every effect off), "realistic"
// (all four effects below), or one effect: "mixed_pixels" (the beam
// footprint, a FARO Focus class beam unless options->scan.beam already has
// one), "incidence" (noise and dropouts by incidence and reflectance),
// "stations" (registration residuals of 1-3 mm and 0.005-0.02 deg),
// "as_built" (surfaces 0.5-2 mm off the CAD), "jackets" (protective jackets:
// a property of the robot, so not part of "realistic").
Status ApplySensorPreset(const std::string& name, AssetScanOptions* options);

// The sub-seeds of `seed` for each random part (also the `edgefit scan`
// streams): 1 accessories, 2 clutter, 3 scanner placement, 4 range noise,
// 5 as-built surfaces, 6 jackets, 7 station residuals.
enum class AssetScanStream : uint64_t {
  kAccessories = 1,
  kClutter = 2,
  kPlacement = 3,
  kNoise = 4,
  kAsBuilt = 5,
  kJackets = 6,
  kStations = 7
};
uint64_t AssetScanSeed(uint64_t seed, AssetScanStream stream);

// Builds the scene and scans it. T_world_scanners receives the scanners'
// true poses (may be null); the scans carry the written ones, which differ
// when station_residuals is on. Fails on a model without geometry or bad options.
Status ScanAsset(const KinematicModel& model, const std::vector<double>& q,
                 const Pose& T_world_base, const AssetScanOptions& options, VirtualScan* result,
                 std::vector<Pose>* T_world_scanners);

// One posed asset of a cell.
struct CellAsset {
  const KinematicModel* model = nullptr;
  std::vector<double> q;
  Pose T_world_base = Pose::Identity();
};

// A cell: several assets on one floor, each with its own accessories,
// jackets and as-built surfaces, clutter around them all, scanners placed
// around them all (or given). Link k of asset a is labelled
// LinkLabel(first_link[a] + k): the assets' links counted in order. Asset 0
// draws from the streams ScanAsset uses (a one-asset cell is ScanAsset's
// scan, byte for byte); asset a > 0 from streams of SplitMix64::StreamSeed(seed, 1000 + a).
Status ScanCell(const std::vector<CellAsset>& assets, const AssetScanOptions& options,
                VirtualScan* result, std::vector<Pose>* T_world_scanners,
                std::vector<int>* first_link);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_ASSET_SCAN_H_
