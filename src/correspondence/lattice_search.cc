#include "edgefit/correspondence/lattice_search.h"

#include <glog/logging.h>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace edgefit {

LatticeSearch::LatticeSearch(const ScanSet* scans, const CellWeights* weights,
                             const CellMask* excluded, const CellMask* missing)
    : scans_(scans), weights_(weights), excluded_(excluded), missing_(missing) {
  CHECK(scans_ != nullptr);
  const size_t n = scans_->scans.size();
  if (weights_ != nullptr) CHECK_EQ(weights_->size(), n);
  if (excluded_ != nullptr) CHECK_EQ(excluded_->size(), n);
  if (missing_ != nullptr) CHECK_EQ(missing_->size(), n);
  T_scanner_world_.resize(n);
  searchable_.resize(n);
  for (size_t s = 0; s < n; ++s) {
    const OrganizedScan& scan = scans_->scans[s];
    T_scanner_world_[s] = scan.T_world_scanner().inverse().matrix().topRows<3>();
    searchable_[s] = scan.organized() && scan.lattice().valid() &&
                     scan.lattice().rows() == scan.rows() && scan.lattice().cols() == scan.cols();
    if (weights_ != nullptr) CHECK_EQ((*weights_)[s].size(), scan.size());
    if (excluded_ != nullptr) CHECK_EQ((*excluded_)[s].size(), scan.size());
    if (missing_ != nullptr) CHECK_EQ((*missing_)[s].size(), scan.size());
  }
}

Correspondence LatticeSearch::Nearest(const Eigen::Vector3f& q_world, int window,
                                      float max_d2) const {
  return NearestIn(-1, q_world, window, max_d2);
}

Correspondence LatticeSearch::NearestIn(int only_scan, const Eigen::Vector3f& q_world, int window,
                                        float max_d2) const {
  const Eigen::Vector4d q_h(q_world.x(), q_world.y(), q_world.z(), 1.0);
  float best_d2 = std::numeric_limits<float>::infinity();
  int best_scan = -1, best_cell = -1;
  const std::vector<OrganizedScan>& scans = scans_->scans;
  for (size_t s = 0; s < scans.size(); ++s) {
    if (!searchable_[s] || (only_scan >= 0 && static_cast<int>(s) != only_scan)) continue;
    const OrganizedScan& scan = scans[s];
    const Eigen::Vector3d q_scanner = T_scanner_world_[s] * q_h;
    int row, col;
    // Outside the angular window (or at the origin): this scan cannot
    // have seen anything along the query's ray.
    if (!scan.lattice().ProjectToCell(q_scanner, &row, &col)) continue;
    const Eigen::Vector3f qf = q_scanner.cast<float>();
    const uint8_t* missing = missing_ != nullptr ? (*missing_)[s].data() : nullptr;
    const int rows = scan.rows(), cols = scan.cols();
    const bool wrap = scan.lattice().full_circle();
    const int r0 = std::max(0, row - window), r1 = std::min(rows - 1, row + window);
    for (int dc = -window; dc <= window; ++dc) {
      int c = col + dc;
      if (c < 0 || c >= cols) {
        if (!wrap) continue;
        c = ((c % cols) + cols) % cols;  // column cols-1 neighbours column 0
      }
      // Rows r0..r1 of column c: contiguous cells, in runs that end with
      // the scan's chunks.
      size_t cell = static_cast<size_t>(c) * static_cast<size_t>(rows) + static_cast<size_t>(r0);
      const size_t end = cell + static_cast<size_t>(r1 - r0 + 1);
      while (cell < end) {
        size_t run;
        const Eigen::Vector3f* p = scan.PointRun(cell, &run);
        run = std::min(run, end - cell);
        for (size_t k = 0; k < run; ++k, ++cell) {
          if (missing != nullptr && missing[cell] != 0) continue;
          // A missing cell is NaN, so d2 is NaN and both tests are false.
          const float d2 = (p[k] - qf).squaredNorm();
          if (d2 < best_d2 || (d2 == best_d2 && static_cast<int>(s) == best_scan &&
                               static_cast<int>(cell) < best_cell)) {
            best_d2 = d2;
            best_scan = static_cast<int>(s);
            best_cell = static_cast<int>(cell);
          }
        }
      }
    }
  }
  Correspondence b;
  b.scan = best_d2 <= max_d2 ? best_scan : -1;
  b.cell = best_cell;
  b.distance = std::sqrt(best_d2);
  b.weight = CellWeight(weights_, excluded_, b.scan, b.cell);
  return b;
}

void LatticeSearch::Find(const std::vector<Eigen::Vector3f>& q_world,
                         const CorrespondenceOptions& options, std::vector<Correspondence>* out) {
  FindIn(-1, q_world, options, out);
}

void LatticeSearch::FindIn(int only_scan, const std::vector<Eigen::Vector3f>& q_world,
                           const CorrespondenceOptions& options, std::vector<Correspondence>* out) {
  CHECK(out != nullptr);
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  const int64_t n = static_cast<int64_t>(q_world.size());
  const float max_d2 = static_cast<float>(options.max_distance * options.max_distance);
  best_.resize(q_world.size());

#pragma omp parallel for schedule(dynamic, 512)
  for (int64_t i = 0; i < n; ++i) {
    Correspondence& b = best_[static_cast<size_t>(i)];
    b = NearestIn(only_scan, q_world[static_cast<size_t>(i)], options.window, max_d2);
    b.source = static_cast<int>(i);
  }

  // Serial compaction keeps source order whatever the schedule.
  out->clear();
  for (const Correspondence& b : best_) {
    if (b.scan >= 0) out->push_back(b);
  }
}

}  // namespace edgefit
