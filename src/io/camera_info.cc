#include "edgefit/io/camera_info.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <vector>

#include "yaml_file.h"

namespace edgefit {
namespace {

// The first of `keys` that `node` holds (a null node when none).
YAML::Node First(const YAML::Node& node, std::initializer_list<const char*> keys) {
  for (const char* key : keys) {
    if (node[key]) return node[key];
  }
  return YAML::Node();
}

// A list of numbers, either inline ([a, b]) or as {rows, cols, data: [...]}.
bool Numbers(const YAML::Node& node, std::vector<double>* out) {
  const YAML::Node list = node.IsMap() ? node["data"] : node;
  if (!list || !list.IsSequence()) return false;
  out->clear();
  for (const YAML::Node& v : list) out->push_back(v.as<double>());
  return true;
}

Status Parse(const YAML::Node& root, CameraInfo* info) {
  if (!root.IsMap()) return Status::Error("not a camera_info map");
  const YAML::Node width = First(root, {"width", "image_width"});
  const YAML::Node height = First(root, {"height", "image_height"});
  if (!width || !height) return Status::Error("no width / height (or image_width / image_height)");
  info->width = width.as<int>();
  info->height = height.as<int>();
  if (info->width <= 0 || info->height <= 0) {
    return Status::Error("width and height must be > 0, got " + std::to_string(info->width) +
                         " x " + std::to_string(info->height));
  }
  std::vector<double> k;
  const YAML::Node k_node = First(root, {"k", "K", "camera_matrix"});
  if (!k_node || !Numbers(k_node, &k) || k.size() != 9) {
    return Status::Error("no camera matrix k (K, camera_matrix) of 9 numbers");
  }
  info->camera.fx = k[0];
  info->camera.cx = k[2];
  info->camera.fy = k[4];
  info->camera.cy = k[5];
  const YAML::Node model = First(root, {"distortion_model", "camera_model"});
  info->distortion_model = model ? model.as<std::string>() : "";
  std::vector<double> d;
  const YAML::Node d_node =
      First(root, {"d", "D", "distortion_coefficients", "distortion_coefficents"});
  if (d_node && !Numbers(d_node, &d)) return Status::Error("distortion d is not a list of numbers");
  bool any = false;
  for (const double v : d) any = any || v != 0.0;
  if (any) {
    const std::string& m = info->distortion_model;
    const size_t most = m == "rational_polynomial" ? 8 : m == "plumb_bob" || m.empty() ? 5 : 0;
    if (most == 0) {
      return Status::Error("distortion model '" + m +
                           "' is not read (plumb_bob and rational_polynomial are; a rectified "
                           "image has every coefficient 0)");
    }
    if (d.size() > most) {
      return Status::Error("distortion model '" + m + "' takes at most " + std::to_string(most) +
                           " coefficients, got " + std::to_string(d.size()));
    }
    for (size_t i = 0; i < d.size(); ++i) info->camera.distortion[i] = d[i];
  }
  std::string error;
  if (!info->camera.IsValid(&error)) return Status::Error(error);
  return Status::Ok();
}

}  // namespace

Status ReadCameraInfo(const std::string& path, CameraInfo* info) {
  EDGEFIT_RETURN_IF_ERROR(ReadYamlFile(path, "a camera_info YAML file", Parse, info));
  info->source = path;
  return Status::Ok();
}

}  // namespace edgefit
