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

Status ApplySensorPreset(const std::string& name, AssetScanOptions* options) {
  if (name.empty()) return Status::Error("empty sensor name");
  size_t start = 0;
  while (start <= name.size()) {
    size_t end = name.find('+', start);
    if (end == std::string::npos) end = name.size();
    const std::string item = name.substr(start, end - start);
    start = end + 1;
    const bool all = item == "realistic";
    if (item == "ideal") {
      EDGEFIT_RETURN_IF_ERROR(BeamPreset("ideal", &options->scan.beam));
      options->scan.range_noise.signal_model = false;
      options->station_residuals.enabled = false;
      options->as_built.enabled = false;
      options->jackets.enabled = false;
      continue;
    }
    if (!all && item != "mixed_pixels" && item != "incidence" && item != "stations" &&
        item != "as_built" && item != "jackets") {
      return Status::Error("unknown sensor '" + item +
                           "' (ideal, realistic, or effects joined by '+': mixed_pixels, "
                           "incidence, stations, as_built, jackets)");
    }
    if ((all || item == "mixed_pixels") && !options->scan.beam.enabled()) {
      EDGEFIT_RETURN_IF_ERROR(BeamPreset("faro_focus", &options->scan.beam));
    }
    if (all || item == "incidence") options->scan.range_noise.signal_model = true;
    if (all || item == "stations") options->station_residuals.enabled = true;
    if (all || item == "as_built") options->as_built.enabled = true;
    if (item == "jackets") options->jackets.enabled = true;
  }
  return Status::Ok();
}

namespace {

// The meshes of one posed asset: its links (labels shifted by `first_link`),
// as-built surfaces, jackets and accessories, drawn from streams of `seed`.
Status AddAssetToScene(const CellAsset& asset, int first_link, uint64_t seed,
                       const AssetScanOptions& options, Scene* scene) {
  const KinematicModel& model = *asset.model;
  if (asset.q.size() != model.joints().size()) {
    return Status::Error("asset scan: " + std::to_string(asset.q.size()) + " joint values for " +
                         std::to_string(model.joints().size()) + " joints");
  }
  const std::vector<Pose> T_world_link = model.ForwardKinematics(asset.q, asset.T_world_base);
  if (model.BoundingBox(asset.q, asset.T_world_base).isEmpty()) {
    return Status::Error("asset scan: the model has no geometry to scan");
  }
  const size_t first_mesh = scene->meshes.size();
  AddModelToScene(model, T_world_link, scene);
  for (size_t m = first_mesh; m < scene->meshes.size(); ++m) {
    SceneMesh& mesh = scene->meshes[m];
    if (mesh.link >= 0) mesh.label = LinkLabel(first_link + mesh.link);
  }
  if (options.as_built.enabled) {
    AsBuiltOptions as_built = options.as_built;
    as_built.seed = AssetScanSeed(seed, AssetScanStream::kAsBuilt);
    std::string error;
    if (!as_built.IsValid(&error)) return Status::Error("asset scan: " + error);
    for (size_t m = first_mesh; m < scene->meshes.size(); ++m) {
      SceneMesh& mesh = scene->meshes[m];
      if (mesh.link >= 0) ApplyAsBuilt(as_built, mesh.link, T_world_link[mesh.link], &mesh.mesh_world);
    }
  }
  if (options.jackets.enabled) {
    JacketOptions jackets = options.jackets;
    jackets.seed = AssetScanSeed(seed, AssetScanStream::kJackets);
    EDGEFIT_RETURN_IF_ERROR(AddJackets(model, T_world_link, jackets, scene));
  }
  if (options.accessories) {
    AccessoryOptions accessories;
    accessories.seed = AssetScanSeed(seed, AssetScanStream::kAccessories);
    AddAccessories(model, asset.q, T_world_link, accessories, scene);
  }
  return Status::Ok();
}

}  // namespace

Status ScanAsset(const KinematicModel& model, const std::vector<double>& q,
                 const Pose& T_world_base, const AssetScanOptions& options, VirtualScan* result,
                 std::vector<Pose>* T_world_scanners) {
  CellAsset asset;
  asset.model = &model;
  asset.q = q;
  asset.T_world_base = T_world_base;
  return ScanCell({asset}, options, result, T_world_scanners, nullptr);
}

Status ScanCell(const std::vector<CellAsset>& assets, const AssetScanOptions& options,
                VirtualScan* result, std::vector<Pose>* T_world_scanners,
                std::vector<int>* first_link) {
  CHECK(result != nullptr);
  if (assets.empty()) return Status::Error("cell scan: no assets");
  if (options.T_world_scanners.empty() && options.scanners < 1) {
    return Status::Error("asset scan: need at least one scanner");
  }
  Scene scene;
  Eigen::AlignedBox3d cell_box;
  std::vector<int> firsts;
  int links = 0;
  for (size_t a = 0; a < assets.size(); ++a) {
    CHECK(assets[a].model != nullptr);
    const uint64_t seed = a == 0 ? options.seed : SplitMix64::StreamSeed(options.seed, 1000 + a);
    EDGEFIT_RETURN_IF_ERROR(AddAssetToScene(assets[a], links, seed, options, &scene));
    cell_box.extend(assets[a].model->BoundingBox(assets[a].q, assets[a].T_world_base));
    firsts.push_back(links);
    links += static_cast<int>(assets[a].model->links().size());
  }
  if (kLabelFirstLink + links > kLabelMask) {
    return Status::Error("cell scan: " + std::to_string(links) + " links in all, more than the labels hold");
  }
  EnvironmentOptions environment;
  environment.clutter_count = options.clutter;
  environment.seed = AssetScanSeed(options.seed, AssetScanStream::kClutter);
  AddEnvironment(cell_box, environment, &scene);

  std::vector<Pose> scanners = options.T_world_scanners;
  if (scanners.empty()) {
    ScannerPlacementOptions placement;
    placement.count = options.scanners;
    placement.seed = AssetScanSeed(options.seed, AssetScanStream::kPlacement);
    scanners = PlaceScanners(cell_box, placement);
  }
  if (options.scan.camera.enabled()) {  // a depth camera at each place, looking at the cell
    for (Pose& T : scanners) {
      if (!LookAt(T.translation(), cell_box.center(), Eigen::Vector3d::UnitZ(), &T)) {
        return Status::Error("asset scan: a camera at the cell's centre or right above it");
      }
    }
  }
  VirtualScanOptions scan = options.scan;
  scan.seed = AssetScanSeed(options.seed, AssetScanStream::kNoise);
  std::string error;
  if (!options.station_residuals.IsValid(&error)) return Status::Error("asset scan: " + error);
  EDGEFIT_RETURN_IF_ERROR(ScanScene(scene, scanners, scan, result));
  StationResidualOptions stations = options.station_residuals;
  stations.seed = AssetScanSeed(options.seed, AssetScanStream::kStations);
  const std::vector<Pose> written = PerturbStationPoses(scanners, stations);
  for (size_t i = 0; i < written.size(); ++i) result->scans.scans[i].set_T_world_scanner(written[i]);
  if (T_world_scanners != nullptr) *T_world_scanners = std::move(scanners);
  if (first_link != nullptr) *first_link = std::move(firsts);
  return Status::Ok();
}

}  // namespace edgefit
