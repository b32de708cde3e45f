#include "station_image.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgefit {

std::array<uint8_t, 3> ResidualColour(double distance, const FitReportOptions& options) {
  if (!(distance <= options.not_modelled)) return {158, 158, 158};
  const double t = std::min(distance / options.residual_scale, 1.0);
  const double r = t < 0.5 ? 2.0 * t : 1.0;
  const double g = t < 0.5 ? 0.75 + 0.5 * t : 2.0 * (1.0 - t);
  auto byte = [](double v) { return static_cast<uint8_t>(std::lround(255.0 * v)); };
  return {byte(r), byte(g), byte(0.1)};
}

RgbImage StationImage(const OrganizedScan& scan, const Pose& T_world_scanner,
                      const ModelDistance& distance, const Eigen::Vector3d& origin,
                      const Eigen::AlignedBox3d& crop, const FitReportOptions& options) {
  RgbImage image;
  if (!scan.organized()) return image;  // a cloud without a grid: nothing the scanner "saw"
  int row0 = scan.rows(), row1 = -1, col0 = scan.cols(), col1 = -1;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (!scan.IsValid(i) || !crop.contains(T_world_scanner * scan.point_scanner(i).cast<double>())) {
      continue;
    }
    row0 = std::min(row0, scan.RowOf(i));
    row1 = std::max(row1, scan.RowOf(i));
    col0 = std::min(col0, scan.ColOf(i));
    col1 = std::max(col1, scan.ColOf(i));
  }
  if (row1 < 0) return image;
  const int margin_r = (row1 - row0) / 20 + 1, margin_c = (col1 - col0) / 20 + 1;
  row0 = std::max(0, row0 - margin_r);
  row1 = std::min(scan.rows() - 1, row1 + margin_r);
  col0 = std::max(0, col0 - margin_c);
  col1 = std::min(scan.cols() - 1, col1 + margin_c);
  const int extent = std::max(row1 - row0 + 1, col1 - col0 + 1);
  const int step = std::max(1, (extent + options.max_image_size - 1) / options.max_image_size);
  image.height = (row1 - row0) / step + 1;
  image.width = (col1 - col0) / step + 1;
  image.rgb.assign(3 * static_cast<size_t>(image.width) * static_cast<size_t>(image.height), 255);
  // Up is up: rows run up or down in elevation; left is left: azimuth
  // grows counter-clockwise seen from above, so to the scanner's left.
  const ScanLattice& lattice = scan.lattice();
  const bool rows_up = !lattice.valid() || lattice.row_step() > 0.0;
  const bool cols_left = !lattice.valid() || lattice.col_step() > 0.0;
  const Pose T = T_world_scanner;
#pragma omp parallel for schedule(dynamic, 8)
  for (int y = 0; y < image.height; ++y) {
    const int row = rows_up ? row1 - y * step : row0 + y * step;
    for (int x = 0; x < image.width; ++x) {
      const int col = cols_left ? col1 - x * step : col0 + x * step;
      if (row < 0 || col < 0) continue;
      const size_t cell = scan.Index(row, col);
      if (!scan.IsValid(cell)) continue;
      const Eigen::Vector3d p = T * scan.point_scanner(cell).cast<double>() - origin;
      const std::array<uint8_t, 3> c =
          ResidualColour(distance.Distance(p.cast<float>(), nullptr), options);
      uint8_t* out = &image.rgb[3 * (static_cast<size_t>(y) * static_cast<size_t>(image.width) +
                                     static_cast<size_t>(x))];
      out[0] = c[0];
      out[1] = c[1];
      out[2] = c[2];
    }
  }
  return image;
}

namespace {

void AppendToString(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}

}  // namespace

Status EncodePng(const RgbImage& image, std::string* png_bytes) {
  png_bytes->clear();
  if (image.width <= 0 || image.height <= 0) return Status::Error("png: empty image");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return Status::Error("png: out of memory");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info == nullptr ? nullptr : &info);
    return Status::Error("png: encoding failed");
  }
  png_set_write_fn(png, png_bytes, &AppendToString, nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, const_cast<png_bytep>(&image.rgb[3 * static_cast<size_t>(y) *
                                                        static_cast<size_t>(image.width)]));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return Status::Ok();
}

}  // namespace edgefit
