#include "edgefit/correspondence/kdtree_search.h"

#include <glog/logging.h>

#include <cmath>
#include <cstdint>

#include "edgefit/core/point_kdtree.h"

namespace edgefit {

struct KdTreeSearch::Tree {
  explicit Tree(const std::vector<Eigen::Vector3f>* points)
      : adaptor{points}, index(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
  PointVectorAdaptor adaptor;
  PointKdTree index;  // built in its constructor
};

KdTreeSearch::KdTreeSearch(const ScanSet* scans, const CellWeights* weights,
                           const CellMask* excluded, const CellMask* missing)
    : scans_(scans), weights_(weights), excluded_(excluded), missing_(missing) {
  CHECK(scans_ != nullptr);
  if (weights_ != nullptr) {
    CHECK_EQ(weights_->size(), scans_->scans.size());
    for (size_t s = 0; s < scans_->scans.size(); ++s) {
      CHECK_EQ((*weights_)[s].size(), scans_->scans[s].size());
    }
  }
  for (const CellMask* mask : {excluded_, missing_}) {
    if (mask == nullptr) continue;
    CHECK_EQ(mask->size(), scans_->scans.size());
    for (size_t s = 0; s < scans_->scans.size(); ++s) {
      CHECK_EQ((*mask)[s].size(), scans_->scans[s].size());
    }
  }
}

KdTreeSearch::~KdTreeSearch() = default;

bool KdTreeSearch::SetCrop(const Eigen::AlignedBox3d& crop_world) {
  if (built_ && crop_world.min() == crop_world_.min() && crop_world.max() == crop_world_.max()) {
    return false;
  }
  tree_.reset();
  points_world_.clear();
  scan_of_.clear();
  cell_of_.clear();
  for (size_t s = 0; s < scans_->scans.size(); ++s) {
    const OrganizedScan& scan = scans_->scans[s];
    const uint8_t* missing = missing_ != nullptr ? (*missing_)[s].data() : nullptr;
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i) || (missing != nullptr && missing[i] != 0)) continue;
      const Eigen::Vector3d p_world = scan.PointWorld(i);
      if (!crop_world.contains(p_world)) continue;
      points_world_.push_back(p_world.cast<float>());
      scan_of_.push_back(static_cast<int>(s));
      cell_of_.push_back(static_cast<int>(i));
    }
  }
  if (!points_world_.empty()) tree_ = std::make_unique<Tree>(&points_world_);
  crop_world_ = crop_world;
  built_ = true;
  return true;
}

void KdTreeSearch::Find(const std::vector<Eigen::Vector3f>& q_world,
                        const Eigen::AlignedBox3d& crop_world, const CorrespondenceOptions& options,
                        std::vector<Correspondence>* out) {
  CHECK(out != nullptr);
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  SetCrop(crop_world);
  out->clear();
  if (tree_ == nullptr) return;
  const int64_t n = static_cast<int64_t>(q_world.size());
  const float max_d2 = static_cast<float>(options.max_distance * options.max_distance);
  best_.resize(q_world.size());

#pragma omp parallel for schedule(dynamic, 512)
  for (int64_t i = 0; i < n; ++i) {
    uint32_t index = 0;
    float d2 = 0.f;
    Correspondence& b = best_[static_cast<size_t>(i)];
    b.source = static_cast<int>(i);
    b.scan = -1;
    if (tree_->index.knnSearch(q_world[i].data(), 1, &index, &d2) != 1 || !(d2 <= max_d2)) {
      continue;
    }
    b.scan = scan_of_[index];
    b.cell = cell_of_[index];
    // Recomputed rather than sqrt(d2) so both searches report the same value
    // for the same pair.
    b.distance = (points_world_[index] - q_world[i]).norm();
    b.weight = CellWeight(weights_, excluded_, b.scan, b.cell);
  }
  for (const Correspondence& b : best_) {
    if (b.scan >= 0) out->push_back(b);
  }
}

}  // namespace edgefit
