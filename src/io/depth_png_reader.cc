#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <string>
#include <vector>

#include "edgefit/io/depth_png.h"
#include "read_common.h"

namespace edgefit {
namespace {

// The 16-bit grey pixels of a PNG, row by row; libpng's errors end in the
// setjmp below (nothing with a destructor lives between it and the reads).
Status DecodeGrey16(std::FILE* file, int* width, int* height, std::vector<uint16_t>* pixels) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return Status::Error("out of memory");
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> rows;
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, info == nullptr ? nullptr : &info, nullptr);
    return Status::Error("not a readable PNG file (truncated or corrupt)");
  }
  png_init_io(png, file);
  png_read_info(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  const int colour = png_get_color_type(png, info);
  if (bit_depth != 16 || colour != PNG_COLOR_TYPE_GRAY) {
    png_destroy_read_struct(&png, &info, nullptr);
    return Status::Error("a depth image must be 16-bit grey (16UC1), this one is " +
                         std::to_string(bit_depth) + "-bit, colour type " + std::to_string(colour));
  }
  *width = static_cast<int>(png_get_image_width(png, info));
  *height = static_cast<int>(png_get_image_height(png, info));
  png_set_swap(png);  // PNG is big endian
  pixels->assign(static_cast<size_t>(*width) * static_cast<size_t>(*height), 0);
  rows.resize(static_cast<size_t>(*height));
  for (int v = 0; v < *height; ++v) {
    rows[static_cast<size_t>(v)] =
        reinterpret_cast<png_bytep>(&(*pixels)[static_cast<size_t>(v) * static_cast<size_t>(*width)]);
  }
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return Status::Ok();
}

}  // namespace

Status ReadDepthPng(const std::string& path, const ReadOptions& options, ScanSet* scans) {
  const CameraInfo& info = options.camera;
  if (info.empty()) {
    return Status::Error(path + ": a depth PNG needs its camera's intrinsics (--camera_info=FILE, "
                                "a ROS camera_info YAML file)");
  }
  if (!(options.depth_scale > 0.0)) return Status::Error(path + ": depth scale must be > 0");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return Status::Error(path + ": cannot open the file");
  int width = 0, height = 0;
  std::vector<uint16_t> depth;
  const Status decoded = DecodeGrey16(file, &width, &height, &depth);
  std::fclose(file);
  if (!decoded.ok()) return Status::Error(path + ": " + decoded.message());
  if (width != info.width || height != info.height) {
    return Status::Error(path + ": the image is " + std::to_string(width) + " x " +
                         std::to_string(height) + " pixels, its camera (" + info.source + ") " +
                         std::to_string(info.width) + " x " + std::to_string(info.height));
  }
  OrganizedScan scan(height, width);
  scan.set_file_order(OrganizedScan::FileOrder::kRowMajor);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const uint16_t d = depth[static_cast<size_t>(v) * static_cast<size_t>(width) +
                               static_cast<size_t>(u)];
      if (d == 0) continue;  // no measurement
      const Eigen::Vector3d p = (options.depth_scale * d) * info.camera.Ray(u, v);
      scan.SetPoint(scan.Index(v, u), p.cast<float>(), 0.0f);
    }
  }
  EDGEFIT_RETURN_IF_ERROR(io_internal::FinishScan(path, options, &scan));
  scans->scans.push_back(std::move(scan));
  scans->sources.push_back(path);
  return Status::Ok();
}

}  // namespace edgefit
