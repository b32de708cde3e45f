#include "edgefit/pipeline/attached_points.h"

#include <glog/logging.h>

#include <deque>
#include <string>

#include "edgefit/core/point_kdtree.h"
#include "edgefit/pipeline/model_points.h"

namespace edgefit {

bool AttachedPointsOptions::IsValid(std::string* error) const {
  if (max_gap > 0.0 && max_distance > 0.0 && min_height >= 0.0 && sample_spacing > 0.0) return true;
  if (error != nullptr) *error = "attached points: max_gap, max_distance, sample_spacing > 0, min_height >= 0";
  return false;
}

Status MarkAttachedPoints(const ScanSet& scans, const KinematicModel& model,
                          const std::vector<double>& q, const Pose& T_world_base,
                          const AttachedPointsOptions& options,
                          std::vector<std::vector<uint8_t>>* marks) {
  CHECK(marks != nullptr);
  std::string error;
  if (!options.IsValid(&error)) return Status::Error(error);
  if (q.size() != model.joints().size()) return Status::Error("attached points: wrong joint count");
  if (marks->size() != scans.scans.size()) return Status::Error("attached points: marks of other scans");
  const std::vector<Eigen::Vector3f> surface =
      WorldSurfaceSamples(model, q, T_world_base, options.sample_spacing, options.seed);
  if (surface.empty()) return Status::Ok();
  PointVectorAdaptor adaptor{&surface};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  const float reach = static_cast<float>(options.max_distance + 0.5 * options.sample_spacing);
  const float max_gap2 = static_cast<float>(options.max_gap * options.max_gap);
  const double min_z = T_world_base.translation().z() + options.min_height;
  auto near_model = [&](const Eigen::Vector3d& p_world) {
    const Eigen::Vector3f p = p_world.cast<float>();
    uint32_t index = 0;
    float d2 = 0.0f;
    nanoflann::KNNResultSet<float, uint32_t> result(1);
    result.init(&index, &d2);
    tree.findNeighbors(result, p.data(), nanoflann::SearchParams());
    return d2 <= reach * reach;
  };
  const int64_t scan_count = static_cast<int64_t>(scans.scans.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t s = 0; s < scan_count; ++s) {
    const OrganizedScan& scan = scans.scans[static_cast<size_t>(s)];
    std::vector<uint8_t>& marked = (*marks)[static_cast<size_t>(s)];
    if (!scan.organized() || marked.size() != scan.size()) continue;
    std::deque<size_t> frontier;
    for (size_t cell = 0; cell < scan.size(); ++cell) {
      if (marked[cell] != 0 && scan.IsValid(cell)) frontier.push_back(cell);
    }
    while (!frontier.empty()) {
      const size_t cell = frontier.front();
      frontier.pop_front();
      const int row = scan.RowOf(cell), col = scan.ColOf(cell);
      const Eigen::Vector3f& p = scan.point_scanner(cell);
      const int neighbours[4][2] = {{row - 1, col}, {row + 1, col}, {row, col - 1}, {row, col + 1}};
      for (const auto& rc : neighbours) {
        if (rc[0] < 0 || rc[0] >= scan.rows() || rc[1] < 0 || rc[1] >= scan.cols()) continue;
        const size_t n = scan.Index(rc[0], rc[1]);
        if (marked[n] != 0 || !scan.IsValid(n)) continue;
        if ((scan.point_scanner(n) - p).squaredNorm() > max_gap2) continue;
        const Eigen::Vector3d world = scan.PointWorld(n);
        if (world.z() < min_z || !near_model(world)) continue;
        marked[n] = 1;
        frontier.push_back(n);
      }
    }
  }
  return Status::Ok();
}

}  // namespace edgefit
