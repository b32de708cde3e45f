#include "edgefit/scanner/asset_scan.h"

#include <glog/logging.h>

#include "edgefit/core/split_mix64.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scene/accessories.h"
#include "edgefit/scene/environment.h"
#include "edgefit/scene/model_scene.h"

namespace edgefit {

uint64_t AssetScanSeed(uint64_t seed, AssetScanStream stream) {
  return SplitMix64::StreamSeed(seed, static_cast<uint64_t>(stream));
}

Status ScanAsset(const KinematicModel& model, const std::vector<double>& q,
                 const Pose& T_world_base, const AssetScanOptions& options, VirtualScan* result,
                 std::vector<Pose>* T_world_scanners) {
  CHECK(result != nullptr);
  if (q.size() != model.joints().size()) {
    return Status::Error("asset scan: " + std::to_string(q.size()) + " joint values for " +
                         std::to_string(model.joints().size()) + " joints");
  }
  if (options.T_world_scanners.empty() && options.scanners < 1) {
    return Status::Error("asset scan: need at least one scanner");
  }
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  const Eigen::AlignedBox3d asset_box = model.BoundingBox(q, T_world_base);
  if (asset_box.isEmpty()) return Status::Error("asset scan: the model has no geometry to scan");

  Scene scene;
  AddModelToScene(model, T_world_link, &scene);
  if (options.accessories) {
    AccessoryOptions accessories;
    accessories.seed = AssetScanSeed(options.seed, AssetScanStream::kAccessories);
    AddAccessories(model, q, T_world_link, accessories, &scene);
  }
  EnvironmentOptions environment;
  environment.clutter_count = options.clutter;
  environment.seed = AssetScanSeed(options.seed, AssetScanStream::kClutter);
  AddEnvironment(asset_box, environment, &scene);

  std::vector<Pose> scanners = options.T_world_scanners;
  if (scanners.empty()) {
    ScannerPlacementOptions placement;
    placement.count = options.scanners;
    placement.seed = AssetScanSeed(options.seed, AssetScanStream::kPlacement);
    scanners = PlaceScanners(asset_box, placement);
  }
  VirtualScanOptions scan = options.scan;
  scan.seed = AssetScanSeed(options.seed, AssetScanStream::kNoise);
  EDGEFIT_RETURN_IF_ERROR(ScanScene(scene, scanners, scan, result));
  if (T_world_scanners != nullptr) *T_world_scanners = std::move(scanners);
  return Status::Ok();
}

}  // namespace edgefit
