#include "edgefit/scan/organized_scan.h"

#include <glog/logging.h>

#include <limits>

namespace edgefit {

OrganizedScan::OrganizedScan(int rows, int cols) : rows_(rows), cols_(cols) {
  CHECK_GE(rows, 0);
  CHECK_GE(cols, 0);
  const size_t n = static_cast<size_t>(rows) * static_cast<size_t>(cols);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cells_->points.assign(n, Eigen::Vector3f(nan, nan, nan));
  cells_->intensity.assign(n, 0.0f);
}

void OrganizedScan::Detach() {
  if (cells_.use_count() > 1) cells_ = std::make_shared<Cells>(*cells_);
}

void OrganizedScan::SetMissing(size_t i) {
  Detach();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cells_->points[i] = Eigen::Vector3f(nan, nan, nan);
  cells_->intensity[i] = 0.0f;
}

void OrganizedScan::EnableColor() {
  Detach();
  if (cells_->colors.empty()) cells_->colors.assign(cells_->points.size(), {0, 0, 0});
}

void OrganizedScan::SetColor(size_t i, const std::array<uint8_t, 3>& rgb) {
  EnableColor();
  cells_->colors[i] = rgb;
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
  const Cells& c = *cells_;
  if (c.points.empty()) return 0.0;
  const size_t bytes = c.points.capacity() * sizeof(Eigen::Vector3f) +
                       c.intensity.capacity() * sizeof(float) +
                       c.colors.capacity() * sizeof(std::array<uint8_t, 3>);
  return static_cast<double>(bytes) / static_cast<double>(c.points.size());
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
