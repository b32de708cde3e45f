#include "edgefit/scan/organized_scan.h"

#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace edgefit {

OrganizedScan::OrganizedScan(int rows, int cols) : rows_(rows), cols_(cols) {
  CHECK_GE(rows, 0);
  CHECK_GE(cols, 0);
  size_ = static_cast<size_t>(rows) * static_cast<size_t>(cols);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  chunks_.resize((size_ + kChunkMask) >> kChunkBits);
  for (auto& chunk : chunks_) {
    chunk = std::make_shared<Chunk>();
    chunk->fill(Eigen::Vector3f(nan, nan, nan));
  }
  intensity_->assign(size_, 0.0f);
}

OrganizedScan::Chunk& OrganizedScan::OwnChunk(size_t c) {
  if (chunks_[c].use_count() > 1) chunks_[c] = std::make_shared<Chunk>(*chunks_[c]);
  return *chunks_[c];
}

std::vector<float>& OrganizedScan::OwnIntensity() {
  if (intensity_.use_count() > 1) intensity_ = std::make_shared<std::vector<float>>(*intensity_);
  return *intensity_;
}

const std::shared_ptr<OrganizedScan::Chunk>& OrganizedScan::EmptyChunk() {
  static const std::shared_ptr<Chunk> empty = [] {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto chunk = std::make_shared<Chunk>();
    chunk->fill(Eigen::Vector3f(nan, nan, nan));
    return chunk;
  }();
  return empty;
}

void OrganizedScan::ShareEmptyChunks() {
  for (std::shared_ptr<Chunk>& chunk : chunks_) {
    if (chunk == EmptyChunk()) continue;
    bool empty = true;
    for (size_t k = 0; k < kChunkCells && empty; ++k) empty = std::isnan((*chunk)[k].x());
    if (empty) chunk = EmptyChunk();
  }
}

void OrganizedScan::SetMissingWhere(const std::function<bool(const Eigen::Vector3f&)>& drop) {
  const int64_t chunks = static_cast<int64_t>(chunks_.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (int64_t c = 0; c < chunks; ++c) {
    const size_t chunk = static_cast<size_t>(c);
    if (chunks_[chunk] == EmptyChunk()) continue;
    std::array<bool, kChunkCells> dropped;
    size_t valid = 0, n_dropped = 0;
    for (size_t k = 0; k < kChunkCells; ++k) {
      const Eigen::Vector3f& p = (*chunks_[chunk])[k];
      dropped[k] = !std::isnan(p.x()) && drop(p);
      valid += std::isnan(p.x()) ? 0 : 1;
      n_dropped += dropped[k] ? 1 : 0;
    }
    if (n_dropped == 0) continue;
    if (n_dropped == valid) {
      chunks_[chunk] = EmptyChunk();
      continue;
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Chunk& own = OwnChunk(chunk);
    for (size_t k = 0; k < kChunkCells; ++k) {
      if (dropped[k]) own[k] = Eigen::Vector3f(nan, nan, nan);
    }
  }
}

void OrganizedScan::SetMissing(size_t i) {
  if (chunks_[i >> kChunkBits] == EmptyChunk()) return;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  OwnChunk(i >> kChunkBits)[i & kChunkMask] = Eigen::Vector3f(nan, nan, nan);
}

void OrganizedScan::EnableColor() {
  if (colors_ == nullptr) {
    colors_ = std::make_shared<std::vector<std::array<uint8_t, 3>>>(
        size_, std::array<uint8_t, 3>{0, 0, 0});
  } else if (colors_.use_count() > 1) {
    colors_ = std::make_shared<std::vector<std::array<uint8_t, 3>>>(*colors_);
  }
}

void OrganizedScan::SetColor(size_t i, const std::array<uint8_t, 3>& rgb) {
  EnableColor();
  (*colors_)[i] = rgb;
}

size_t OrganizedScan::FileIndex(size_t i) const {
  if (file_order_ == FileOrder::kColumnMajor) return i;
  return static_cast<size_t>(RowOf(i)) * static_cast<size_t>(cols_) +
         static_cast<size_t>(ColOf(i));
}

size_t OrganizedScan::CountValid() const {
  // Chunk by chunk, the shared empty ones skipped (an integer sum: the same
  // for any thread count).
  const int64_t chunks = static_cast<int64_t>(chunks_.size());
  size_t n = 0;
#pragma omp parallel for schedule(static) reduction(+ : n)
  for (int64_t c = 0; c < chunks; ++c) {
    const size_t chunk = static_cast<size_t>(c);
    if (chunks_[chunk] == EmptyChunk()) continue;
    const size_t end = std::min(kChunkCells, size_ - chunk * kChunkCells);
    const Chunk& points = *chunks_[chunk];
    for (size_t k = 0; k < end; ++k) n += std::isnan(points[k].x()) ? 0 : 1;
  }
  return n;
}

double OrganizedScan::BytesPerCell() const {
  if (size_ == 0) return 0.0;
  size_t own = 0;
  for (const std::shared_ptr<Chunk>& chunk : chunks_) own += chunk != EmptyChunk() ? 1 : 0;
  const size_t bytes = own * sizeof(Chunk) + chunks_.size() * sizeof(chunks_[0]) +
                       (intensity_ != nullptr ? intensity_->capacity() * sizeof(float) : 0) +
                       (colors_ != nullptr ? colors_->capacity() * sizeof((*colors_)[0]) : 0);
  return static_cast<double>(bytes) / static_cast<double>(size_);
}
size_t ScanSet::TotalCells() const {
  size_t n = 0;
  for (const auto& s : scans) n += s.size();
  return n;
}

size_t ScanSet::TotalValid() const {
  size_t n = 0;
  for (const auto& s : scans) n += s.CountValid();
  return n;
}

}  // namespace edgefit
