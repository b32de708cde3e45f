#include "edgefit/io/ptx_layout.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "edgefit/core/median.h"

namespace edgefit {
namespace {

constexpr size_t kMaxSamples = 20000;

bool Usable(const OrganizedScan& scan, size_t f) {
  return scan.IsValid(f) && scan.point_scanner(f).squaredNorm() > 0.0f;
}

double Angle(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const Eigen::Vector3d u = a.cast<double>().normalized(), v = b.cast<double>().normalized();
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Median angle between points f and f + m over a sample of f; < 0 if no pair.
double MedianAngleAtOffset(const OrganizedScan& scan, size_t m) {
  const size_t n = scan.size();
  if (m >= n) return -1.0;
  const size_t stride = std::max<size_t>(1, (n - m) / kMaxSamples);
  std::vector<double> angles;
  for (size_t f = 0; f + m < n; f += stride) {
    if (Usable(scan, f) && Usable(scan, f + m)) angles.push_back(Angle(scan.point_scanner(f), scan.point_scanner(f + m)));
  }
  return angles.empty() ? -1.0 : MedianInPlace(&angles);
}

}  // namespace

PtxLayout StandardPtxLayout(int header_first, int header_second) {
  PtxLayout layout;
  layout.rows = header_second;
  layout.cols = header_first;
  return layout;
}

PtxLayout DetectPtxLayout(const OrganizedScan& scan, int header_first, int header_second) {
  const PtxLayout standard = StandardPtxLayout(header_first, header_second);
  CHECK_EQ(scan.size(), static_cast<size_t>(header_first) * static_cast<size_t>(header_second));
  // 1. Inner size: line 2 (standard) unless line 1 makes f, f+m closer.
  size_t inner = static_cast<size_t>(header_second);
  if (header_first != header_second) {
    const double a_second = MedianAngleAtOffset(scan, static_cast<size_t>(header_second));
    const double a_first = MedianAngleAtOffset(scan, static_cast<size_t>(header_first));
    if (a_first >= 0.0 && (a_second < 0.0 || a_first < a_second)) inner = static_cast<size_t>(header_first);
  }
  const size_t outer = scan.size() / inner;
  // 2. Fast index: elevation or azimuth change between consecutive points.
  const size_t n = scan.size();
  const size_t stride = std::max<size_t>(1, n / kMaxSamples);
  std::vector<double> d_elevation, d_azimuth;
  for (size_t f = 0; f + 1 < n; f += stride) {
    if (inner > 1 && f % inner == inner - 1) continue;  // run boundary
    if (!Usable(scan, f) || !Usable(scan, f + 1)) continue;
    const Eigen::Vector3d a = scan.point_scanner(f).cast<double>(), b = scan.point_scanner(f + 1).cast<double>();
    const double ea = std::atan2(a.z(), a.head<2>().norm()), eb = std::atan2(b.z(), b.head<2>().norm());
    const double da = std::remainder(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()), 2.0 * M_PI);
    d_elevation.push_back(std::abs(eb - ea));
    d_azimuth.push_back(std::abs(da) * std::cos(0.5 * (ea + eb)));
  }
  if (d_elevation.empty()) return standard;
  const bool fast_is_elevation =
      inner == 1 ? false : MedianInPlace(&d_elevation) >= MedianInPlace(&d_azimuth);
  PtxLayout layout;
  if (fast_is_elevation) {
    layout.rows = static_cast<int>(inner);
    layout.cols = static_cast<int>(outer);
    layout.order = OrganizedScan::FileOrder::kColumnMajor;
  } else {
    layout.rows = static_cast<int>(outer);
    layout.cols = static_cast<int>(inner);
    layout.order = OrganizedScan::FileOrder::kRowMajor;
  }
  return layout;
}

OrganizedScan ApplyPtxLayout(OrganizedScan in_file_order, const PtxLayout& layout) {
  CHECK_EQ(in_file_order.size(), static_cast<size_t>(layout.rows) * static_cast<size_t>(layout.cols));
  if (layout.order == OrganizedScan::FileOrder::kColumnMajor && layout.rows == in_file_order.rows()) {
    in_file_order.set_file_order(OrganizedScan::FileOrder::kColumnMajor);
    return in_file_order;
  }
  OrganizedScan scan(layout.rows, layout.cols);
  scan.set_T_world_scanner(in_file_order.T_world_scanner());
  scan.set_file_order(layout.order);
  if (!in_file_order.has_intensity()) scan.DropIntensity();
  if (in_file_order.has_color()) scan.EnableColor();
  for (size_t i = 0; i < scan.size(); ++i) {
    const size_t f = scan.FileIndex(i);
    scan.SetPoint(i, in_file_order.point_scanner(f), in_file_order.intensity(f));
    if (scan.has_color()) scan.SetColor(i, in_file_order.color(f));
  }
  return scan;
}

}  // namespace edgefit
