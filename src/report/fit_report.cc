#include "edgefit/report/fit_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "base64.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/report/three_js.h"
#include "model_distance.h"
#include "report_page.h"
#include "station_image.h"

namespace edgefit {
namespace {

// The posed model: one mesh per link with triangles, world frame minus
// `origin` (float precision for survey coordinates far from zero).
nlohmann::json LinkMeshes(const KinematicModel& model, const std::vector<Pose>& T_world_link,
                          const Eigen::Vector3d& origin) {
  nlohmann::json links = nlohmann::json::array();
  for (size_t l = 0; l < model.links().size(); ++l) {
    const TriangleMesh& mesh = model.links()[l].mesh;
    if (mesh.empty()) continue;
    std::vector<float> positions;
    positions.reserve(3 * mesh.vertices.size());
    for (const Eigen::Vector3d& v : mesh.vertices) {
      const Eigen::Vector3d p = T_world_link[l] * v - origin;
      positions.insert(positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                         static_cast<float>(p.z())});
    }
    std::vector<uint32_t> indices;
    indices.reserve(3 * mesh.triangles.size());
    for (const Eigen::Vector3i& t : mesh.triangles) {
      indices.insert(indices.end(), {static_cast<uint32_t>(t.x()), static_cast<uint32_t>(t.y()),
                                     static_cast<uint32_t>(t.z())});
    }
    links.push_back({{"name", model.links()[l].name},
                     {"positions", Base64(positions)},
                     {"indices", Base64(indices)}});
  }
  return links;
}

// ResidualColour every 0.1 mm from 0 to not_modelled, then the colour of a
// point farther away: RGB bytes, base64 (the page colours by it).
std::string Palette(const FitReportOptions& options) {
  std::vector<uint8_t> rgb;
  const int steps = static_cast<int>(std::lround(options.not_modelled * 1e4));
  for (int k = 0; k <= steps + 1; ++k) {
    const double d = k <= steps ? 1e-4 * k : std::numeric_limits<double>::infinity();
    const std::array<uint8_t, 3> c = ResidualColour(d, options);
    rgb.insert(rgb.end(), c.begin(), c.end());
  }
  return Base64(rgb);
}

// The scan near the model (in `crop`, world), every stride-th valid point in
// cell order, with its distance to the model in 0.1 mm (capped at 6.5 m),
// the link of the nearest surface sample and, with `edges`, whether it lies
// in a valid edge region (w_edge > 1).
nlohmann::json ShownPoints(const ScanSet& scans, const std::vector<Pose>& T_world_scanner,
                           const Eigen::AlignedBox3d& crop, const Eigen::Vector3d& origin,
                           const ModelDistance& model_distance, const EdgeDetectionResult* edges,
                           const FitReportOptions& options) {
  auto world = [&](size_t s, size_t i) {
    return T_world_scanner[s] * scans.scans[s].point_scanner(i).cast<double>();
  };
  size_t near = 0;
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    for (size_t i = 0; i < scan.size(); ++i) near += scan.IsValid(i) && crop.contains(world(s, i));
  }
  const size_t stride = std::max<size_t>(1, (near + options.max_points - 1) / options.max_points);
  std::vector<Eigen::Vector3f> shown;
  std::vector<uint8_t> on_edge;
  shown.reserve(near / stride + 1);
  size_t k = 0;
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3d p = world(s, i);
      if (!crop.contains(p) || k++ % stride != 0) continue;
      shown.push_back((p - origin).cast<float>());
      if (edges != nullptr) on_edge.push_back(edges->w_edge[s][i] > 1.0f);
    }
  }
  std::vector<uint16_t> distance(shown.size(), std::numeric_limits<uint16_t>::max());
  std::vector<uint16_t> link(shown.size(), 0);
  const int64_t n = static_cast<int64_t>(shown.size());
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < n; ++i) {
    int nearest_link = -1;
    const double d = model_distance.Distance(shown[static_cast<size_t>(i)], &nearest_link);
    if (nearest_link < 0) continue;
    distance[static_cast<size_t>(i)] = static_cast<uint16_t>(std::min(65535.0, std::round(d * 1e4)));
    link[static_cast<size_t>(i)] = static_cast<uint16_t>(nearest_link);
  }
  std::vector<float> positions;
  positions.reserve(3 * shown.size());
  for (const Eigen::Vector3f& p : shown) positions.insert(positions.end(), {p.x(), p.y(), p.z()});
  nlohmann::json points = {{"count", shown.size()},
                           {"near", near},
                           {"stride", stride},
                           {"positions", Base64(positions)},
                           {"distance_0.1mm", Base64(distance)},
                           {"link", Base64(link)}};
  if (edges != nullptr) points["edge"] = Base64(on_edge);
  return points;
}

// Sec. 4 on the scans for the edge map; *map tells the page what it found
// or why there is none. Returns whether the map is there.
bool EdgeMap(const ScanSet& scans, const FitReportOptions& options, EdgeDetectionResult* edges,
             nlohmann::json* map) {
  if (!options.edge_map) {
    *map = {{"available", false}, {"why", "not asked for"}};
    return false;
  }
  EdgeDetectionOptions marking = options.edges;  // the regions, even when w_high is 1
  marking.w_high = std::max(2.0, marking.w_high);
  const Status status = DetectEdges(scans, marking, edges);
  if (!status.ok()) {
    *map = {{"available", false}, {"why", status.message()}};
    return false;
  }
  *map = {{"available", true},
          {"w_high", options.edges.w_high},
          {"points", edges->points},
          {"candidates", edges->candidates},
          {"edge_points", edges->edge_points},
          {"regions", edges->regions},
          {"seconds", edges->timings.total}};
  return true;
}

// What each station saw (StationImage), for the page; *pngs gets each PNG
// file's path and bytes when options.station_pngs.
Status StationViews(const ScanSet& scans, const std::vector<Pose>& T_world_scanner,
                    const Eigen::AlignedBox3d& crop, const Eigen::Vector3d& origin,
                    const ModelDistance& model_distance, const FitReportOptions& options,
                    const std::string& report_path, nlohmann::json* stations,
                    std::vector<std::pair<std::string, std::string>>* pngs) {
  *stations = nlohmann::json::array();
  for (size_t st = 0; st < scans.scans.size(); ++st) {
    const RgbImage image = StationImage(scans.scans[st], T_world_scanner[st], model_distance,
                                        origin, crop, options);
    if (image.width == 0) continue;
    std::string png;
    EDGEFIT_RETURN_IF_ERROR(EncodePng(image, &png));
    const std::string file = StationImagePath(report_path, st);
    stations->push_back({{"station", st + 1},
                         {"file", std::filesystem::path(file).filename().string()},
                         {"png", Base64(png.data(), png.size())}});
    if (options.station_pngs) pngs->emplace_back(file, std::move(png));
  }
  return Status::Ok();
}

// Writes each (path, bytes) and then the page, atomically; on a failure
// removes what it wrote. *written (may be null) gets the paths.
Status WriteAll(const std::vector<std::pair<std::string, std::string>>& files,
                std::vector<std::string>* written) {
  std::vector<std::string> done;
  for (const auto& [path, bytes] : files) {
    const Status status = WriteStringAtomically(path, bytes);
    if (!status.ok()) {
      for (const std::string& f : done) std::remove(f.c_str());
      return status;
    }
    done.push_back(path);
  }
  if (written != nullptr) written->insert(written->end(), done.begin(), done.end());
  return Status::Ok();
}

}  // namespace

std::string StationImagePath(const std::string& report_path, size_t station) {
  std::filesystem::path p(report_path);
  p.replace_filename(p.stem().string() + "_station_" + std::to_string(station + 1) + ".png");
  return p.string();
}

bool FitReportOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (max_points == 0) return fail("max_points must be > 0");
  if (!(margin >= 0.0)) return fail("margin must be >= 0");
  if (!(residual_scale > 0.0) || !(not_modelled >= residual_scale)) {
    return fail("residual_scale must be > 0 and not_modelled >= residual_scale");
  }
  if (!(sample_spacing > 0.0)) return fail("sample_spacing must be > 0");
  if (max_image_size < 16) return fail("max_image_size must be >= 16");
  std::string edge_error;
  if (edge_map && !edges.IsValid(&edge_error)) return fail("edges: " + edge_error);
  return true;
}

Status CheckFitReportScripts(const FitReportOptions& options) {
  return CheckThreeJs(options.three_js_dir);
}

Status WriteFitReport(const KinematicModel& model, const std::vector<double>& q,
                      const Pose& T_world_base, const ScanSet& scans,
                      const std::vector<Pose>& station_corrections, const nlohmann::json& result,
                      const std::string& title, const FitReportOptions& options,
                      const std::string& path, std::vector<std::string>* written) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("report: " + error);
  if (q.size() != model.joints().size()) return Status::Error("report: wrong joint count");
  if (!station_corrections.empty() && station_corrections.size() != scans.scans.size()) {
    return Status::Error("report: one station correction per scan expected");
  }
  std::string three, orbit;
  EDGEFIT_RETURN_IF_ERROR(ReadThreeJs(options.three_js_dir, &three, &orbit));
  std::vector<Pose> T_world_scanner;  // as the fit registered them
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const Pose& as_written = scans.scans[s].T_world_scanner();
    T_world_scanner.push_back(station_corrections.empty() ? as_written
                                                          : station_corrections[s] * as_written);
  }

  // The model's box, its centre the page's origin (float precision for
  // survey coordinates far from zero), and the scan shown around it.
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  Eigen::AlignedBox3d box;
  for (size_t l = 0; l < model.links().size(); ++l) {
    if (!model.links()[l].mesh.empty()) box.extend(model.links()[l].mesh.BoundingBox(T_world_link[l]));
  }
  if (box.isEmpty()) return Status::Error("report: the model has no meshes");
  const Eigen::Vector3d origin = box.center();
  const Eigen::AlignedBox3d crop(box.min() - Eigen::Vector3d::Constant(options.margin),
                                 box.max() + Eigen::Vector3d::Constant(options.margin));
  const ModelDistance model_distance(model, q, T_world_base, options.sample_spacing, options.seed,
                                     origin);
  if (model_distance.empty()) return Status::Error("report: the model has no surface samples");

  nlohmann::json stations;
  std::vector<std::pair<std::string, std::string>> files;  // the PNGs, then the page
  EDGEFIT_RETURN_IF_ERROR(StationViews(scans, T_world_scanner, crop, origin, model_distance,
                                       options, path, &stations, &files));
  EdgeDetectionResult edges;
  nlohmann::json edge_map;
  const bool has_edges = EdgeMap(scans, options, &edges, &edge_map);
  nlohmann::json joint_types = nlohmann::json::object();
  nlohmann::json joint_order = nlohmann::json::array();  // parents first: base to tool
  for (const int index : model.joint_order()) {
    const Joint& j = model.joints()[static_cast<size_t>(index)];
    if (!j.IsMoving()) continue;
    joint_types[j.name] = j.type == JointType::kPrismatic ? "prismatic" : "revolute";
    joint_order.push_back(j.name);
  }
  nlohmann::json link_names = nlohmann::json::array();
  for (const Link& l : model.links()) link_names.push_back(l.name);
  nlohmann::json scanners = nlohmann::json::array();
  for (const Pose& T : T_world_scanner) {
    const Eigen::Vector3d s = T.translation() - origin;
    scanners.push_back({s.x(), s.y(), s.z()});
  }
  const nlohmann::json data = {
      {"title", title},
      {"origin", {origin.x(), origin.y(), origin.z()}},
      {"result", result},
      {"colours", {{"residual_scale_m", options.residual_scale},
                   {"not_modelled_m", options.not_modelled},
                   {"palette", Palette(options)}}},
      {"scanners", scanners},
      {"stations", stations},
      {"joint_types", joint_types},
      {"joint_order", joint_order},
      {"link_names", link_names},
      {"links", LinkMeshes(model, T_world_link, origin)},
      {"edge_map", edge_map},
      {"points", ShownPoints(scans, T_world_scanner, crop, origin, model_distance,
                             has_edges ? &edges : nullptr, options)}};
  files.emplace_back(path, ReportPage(title, three, orbit, data.dump()));
  return WriteAll(files, written);
}

}  // namespace edgefit
