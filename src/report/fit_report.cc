#include "edgefit/report/fit_report.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "base64.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/core/point_kdtree.h"
#include "edgefit/model/surface_sampler.h"
#include "report_page.h"

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

std::string ThreePath(const FitReportOptions& options) {
  return options.three_js_dir + "/three.min.js";
}
std::string OrbitControlsPath(const FitReportOptions& options) {
  return options.three_js_dir + "/examples/js/controls/OrbitControls.js";
}

}  // namespace

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
  return true;
}

Status CheckFitReportScripts(const FitReportOptions& options) {
  for (const std::string& script : {ThreePath(options), OrbitControlsPath(options)}) {
    if (!std::ifstream(script).good()) {
      return Status::Error("report: three.js not found: " + script +
                           " (Debian's libjs-three; ./scripts/install-deps.sh installs it)");
    }
  }
  return Status::Ok();
}

Status WriteFitReport(const KinematicModel& model, const std::vector<double>& q,
                      const Pose& T_world_base, const ScanSet& scans,
                      const std::vector<Pose>& station_corrections, const nlohmann::json& result,
                      const std::string& title, const FitReportOptions& options,
                      const std::string& path) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("report: " + error);
  if (q.size() != model.joints().size()) return Status::Error("report: wrong joint count");
  if (!station_corrections.empty() && station_corrections.size() != scans.scans.size()) {
    return Status::Error("report: one station correction per scan expected");
  }
  std::vector<Pose> T_world_scanner;  // as the fit registered them
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const Pose& written = scans.scans[s].T_world_scanner();
    T_world_scanner.push_back(station_corrections.empty() ? written
                                                          : station_corrections[s] * written);
  }
  EDGEFIT_RETURN_IF_ERROR(CheckFitReportScripts(options));
  std::string three, orbit;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(ThreePath(options), &three));
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(OrbitControlsPath(options), &orbit));

  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  Eigen::AlignedBox3d box;
  for (size_t l = 0; l < model.links().size(); ++l) {
    if (!model.links()[l].mesh.empty()) box.extend(model.links()[l].mesh.BoundingBox(T_world_link[l]));
  }
  if (box.isEmpty()) return Status::Error("report: the model has no meshes");
  const Eigen::Vector3d origin = box.center();
  const Eigen::AlignedBox3d crop(box.min() - Eigen::Vector3d::Constant(options.margin),
                                 box.max() + Eigen::Vector3d::Constant(options.margin));

  // The scan near the model, every stride-th valid point in cell order.
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
  shown.reserve(near / stride + 1);
  size_t k = 0;
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3d p = world(s, i);
      if (crop.contains(p) && k++ % stride == 0) shown.push_back((p - origin).cast<float>());
    }
  }

  // Each shown point's distance to the model's surface samples, in 0.1 mm
  // (capped at 6.5 m).
  // Each shown point's distance to the model's surface samples, in 0.1 mm
  // (capped at 6.5 m), and the link of the nearest sample.
  std::vector<Eigen::Vector3f> samples;
  std::vector<uint16_t> link_of_sample;
  {
    SamplingOptions sampling;
    sampling.spacing = options.sample_spacing;
    sampling.seed = options.seed;
    const std::vector<SurfaceSamples> link_samples = SampleModelSurfaces(model, sampling);
    for (size_t l = 0; l < link_samples.size(); ++l) {
      for (const Eigen::Vector3f& p : link_samples[l].points) {
        samples.push_back((T_world_link[l] * p.cast<double>() - origin).cast<float>());
        link_of_sample.push_back(static_cast<uint16_t>(l));
      }
    }
  }
  if (samples.empty()) return Status::Error("report: the model has no surface samples");
  const PointVectorAdaptor adaptor{&samples};
  const PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  std::vector<uint16_t> distance(shown.size(), std::numeric_limits<uint16_t>::max());
  std::vector<uint16_t> link(shown.size(), 0);
  const int64_t n = static_cast<int64_t>(shown.size());
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < n; ++i) {
    uint32_t nearest = 0;
    float d2 = 0.0f;
    if (tree.knnSearch(shown[static_cast<size_t>(i)].data(), 1, &nearest, &d2) == 0) continue;
    distance[static_cast<size_t>(i)] =
        static_cast<uint16_t>(std::min(65535.0, std::round(std::sqrt(double{d2}) * 1e4)));
    link[static_cast<size_t>(i)] = link_of_sample[nearest];
  }
  std::vector<float> positions;
  positions.reserve(3 * shown.size());
  for (const Eigen::Vector3f& p : shown) positions.insert(positions.end(), {p.x(), p.y(), p.z()});

  nlohmann::json joint_types = nlohmann::json::object();
  for (const Joint& j : model.joints()) {
    if (j.IsMoving()) joint_types[j.name] = j.type == JointType::kPrismatic ? "prismatic" : "revolute";
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
                   {"not_modelled_m", options.not_modelled}}},
      {"scanners", scanners},
      {"joint_types", joint_types},
      {"link_names", link_names},
      {"links", LinkMeshes(model, T_world_link, origin)},
      {"points",
       {{"count", shown.size()},
        {"near", near},
        {"stride", stride},
        {"positions", Base64(positions)},
        {"distance_0.1mm", Base64(distance)},
        {"link", Base64(link)}}}};
  return WriteStringAtomically(path, ReportPage(title, three, orbit, data.dump()));
}

}  // namespace edgefit
