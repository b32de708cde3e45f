#include "edgefit/scan/organized_scan.h"

#include <glog/logging.h>

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

void OrganizedScan::Detach() {
  for (size_t c = 0; c < chunks_.size(); ++c) OwnChunk(c);
  if (intensity_ != nullptr) OwnIntensity();
  if (colors_ != nullptr && colors_.use_count() > 1) {
    colors_ = std::make_shared<std::vector<std::array<uint8_t, 3>>>(*colors_);
  }
}

void OrganizedScan::SetMissing(size_t i) {
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
  size_t n = 0;
  for (size_t i = 0; i < size(); ++i) n += IsValid(i) ? 1 : 0;
  return n;
}

double OrganizedScan::BytesPerCell() const {
  if (size_ == 0) return 0.0;
  const size_t bytes = chunks_.size() * (sizeof(Chunk) + sizeof(chunks_[0])) +
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
