#include "edgefit/world/world_background.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "edgefit/pipeline/model_points.h"
#include "edgefit/world/attached_geometry.h"
#include "edgefit/world/background_voxels.h"
#include "edgefit/world/floating_voxels.h"

namespace edgefit {

Status WorldBackground(const std::vector<double>& removal, const WorldBackgroundOptions& options,
                       ScanSet* scans, std::vector<WorldMachine>* machines,
                       std::vector<Eigen::Vector3f>* background, WorldBackgroundSummary* summary) {
  *summary = WorldBackgroundSummary();
  background->clear();
  if (removal.size() != machines->size()) return Status::Error("world: a removal distance per machine");
  // Mixed pixels are found on the whole grids (a machine's silhouette
  // included) and leave at the end.
  std::vector<std::vector<uint8_t>> mixed;
  if (options.drop_mixed_pixels) mixed = FindMixedPixels(*scans, options.mixed_pixels, &summary->mixed_pixels);
  for (size_t i = 0; i < machines->size(); ++i) {
    WorldMachine& m = (*machines)[i];
    ModelPointsOptions model_points;
    model_points.distance = removal[i];
    std::vector<std::vector<uint8_t>> marks;
    EDGEFIT_RETURN_IF_ERROR(MarkModelPoints(*scans, *m.model, m.q, m.T_world_base, model_points, &marks));
    const std::vector<std::vector<uint8_t>> own = marks;
    if (options.drop_mixed_pixels) {
      MarkSilhouetteMixedPixels(*scans, own, options.mixed_pixels, options.silhouette_cells, &mixed);
    }
    EDGEFIT_RETURN_IF_ERROR(
        MarkAttachedPoints(*scans, *m.model, m.q, m.T_world_base, options.attached, &marks));
    std::vector<Eigen::Vector3f> riding;
    for (size_t s = 0; s < scans->scans.size(); ++s) {
      for (size_t c = 0; c < marks[s].size(); ++c) {
        const bool is_mixed = !mixed.empty() && mixed[s][c] != 0;  // leaves, rides on nothing
        if (marks[s][c] != 0 && own[s][c] == 0 && !is_mixed && scans->scans[s].IsValid(c)) {
          riding.push_back(scans->scans[s].PointWorld(c).cast<float>());
        }
      }
    }
    summary->riding.push_back(riding.size());
    AttachedGeometryOptions attached;
    attached.voxel = options.voxel;
    m.attached = AttachedGeometry(*m.model, m.q, m.T_world_base, riding, attached);
    summary->machine_points += RemoveMarkedPoints(marks, scans);
  }
  if (options.drop_mixed_pixels) summary->mixed_pixels = RemoveMarkedPoints(mixed, scans);
  for (const OrganizedScan& scan : scans->scans) {
    for (size_t c = 0; c < scan.size(); ++c) {
      if (scan.IsValid(c)) background->push_back(scan.PointWorld(c).cast<float>());
    }
  }
  if (options.floating > 0.0) {
    const double v = options.voxel;
    const std::vector<std::array<int32_t, 3>> floating =
        FloatingVoxels(*machines, OccupiedVoxels(*background, v), v, options.floating);
    const auto in_floating = [&](const Eigen::Vector3f& p) {
      return std::binary_search(floating.begin(), floating.end(), VoxelOf(p, v));
    };
    const size_t before = background->size();
    background->erase(std::remove_if(background->begin(), background->end(), in_floating), background->end());
    summary->floating_voxels = floating.size();
    summary->floating_points = before - background->size();
  }
  return Status::Ok();
}

}  // namespace edgefit
