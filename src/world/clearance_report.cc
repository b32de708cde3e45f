// ClearanceWorld::Picture: the world and one machine's way through it, as
// the world report (report/world_report.h) shows them.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "clearance_impl.h"
#include "edgefit/core/format.h"
#include "edgefit/world/background_voxels.h"
#include "edgefit/world/clearance.h"

namespace edgefit {
namespace {

constexpr char kAttachedSuffix[] = "_attached.stl";  // planning_world.cc's attachment meshes

bool IsAttachment(const Visual& visual) {
  const std::string& p = visual.mesh_path;
  const size_t n = sizeof(kAttachedSuffix) - 1;
  return p.size() >= n && p.compare(p.size() - n, n, kAttachedSuffix) == 0;
}

// Triangles [first, first + count) of `mesh` with the vertices they use.
TriangleMesh SubMesh(const TriangleMesh& mesh, size_t first, size_t count) {
  TriangleMesh out;
  std::unordered_map<int, int> index;
  for (size_t t = first; t < first + count && t < mesh.triangles.size(); ++t) {
    Eigen::Vector3i tri;
    for (int c = 0; c < 3; ++c) {
      const auto [it, added] = index.emplace(mesh.triangles[t][c], static_cast<int>(out.vertices.size()));
      if (added) out.vertices.push_back(mesh.vertices[static_cast<size_t>(mesh.triangles[t][c])]);
      tri[c] = it->second;
    }
    out.triangles.push_back(tri);
  }
  return out;
}

// Millimetres, or "-" where there is nothing to measure.
std::string Mm(double d) { return std::isfinite(d) ? FormatNumber("%.1f mm", 1e3 * d) : std::string("-"); }

}  // namespace

bool ClearancePictureOptions::IsValid(std::string* error) const {
  if (!(margin >= 0.0) || !std::isfinite(margin)) *error = "margin must be >= 0";
  else if (max_background_triangles < 12) *error = "max_background_triangles must be >= 12";
  else return true;
  return false;
}

Status ClearanceWorld::Picture(const std::vector<std::vector<double>>& waypoints,
                               const std::vector<PostureClearance>& results,
                               const ClearancePictureOptions& options, WorldReport* report) const {
  const Impl& w = *impl_;
  if (std::string error; !options.IsValid(&error)) return Status::Error("picture: " + error);
  if (waypoints.empty() || results.size() != waypoints.size()) {
    return Status::Error("picture: one result per waypoint expected");
  }
  report->machine = w.machine;
  report->parts.clear();
  // Every link with a mesh, split into its own geometry and what rides on
  // it; the machine checked at each waypoint, the others as scanned.
  std::vector<std::vector<Pose>> T_world_link;  // [waypoint][link]
  for (const std::vector<double>& q : waypoints) T_world_link.push_back(w.cell.ForwardKinematics(q));
  const std::vector<Pose> T_scanned = w.cell.ForwardKinematics(w.q_scanned);
  std::vector<bool> own(w.cell.links().size(), false);
  for (const int l : w.own) own[static_cast<size_t>(l)] = true;
  for (size_t l = 0; l < w.cell.links().size(); ++l) {
    const Link& link = w.cell.links()[l];
    if (link.mesh.empty()) continue;
    const std::string machine = own[l] ? w.machine : [&] {
      for (const std::string& m : w.machines) {
        if (link.name.rfind(m + "_", 0) == 0) return m;
      }
      return std::string();
    }();
    std::vector<Pose> poses;
    if (own[l]) {
      for (const std::vector<Pose>& T : T_world_link) poses.push_back(T[l]);
    } else {
      poses.push_back(T_scanned[l]);
    }
    size_t first = 0;
    TriangleMesh cad, attached;
    for (const Visual& visual : link.visuals) {
      const size_t count = static_cast<size_t>(visual.triangle_count);
      (IsAttachment(visual) ? attached : cad).Append(SubMesh(link.mesh, first, count));
      first += count;
    }
    if (first != link.mesh.triangles.size()) cad = link.mesh;  // not split by visuals: all its own
    for (const bool is_attached : {false, true}) {
      const TriangleMesh& mesh = is_attached ? attached : cad;
      if (mesh.empty()) continue;
      WorldReportPart part;
      part.kind = is_attached ? WorldReportPart::Kind::kAttachment : WorldReportPart::Kind::kMachine;
      part.name = link.name + (is_attached ? " (attached)" : "");
      part.machine = machine;
      part.mesh = mesh;
      part.T_world_part = poses;
      report->parts.push_back(std::move(part));
    }
  }
  // The background near the way, its voxels merged until it fits.
  if (!w.background_path.empty()) {
    Eigen::AlignedBox3d region = w.Reach(waypoints);
    region.min().array() -= options.margin;
    region.max().array() += options.margin;
    std::vector<std::array<int32_t, 3>> voxels;
    double voxel = 0.0;
    EDGEFIT_RETURN_IF_ERROR(ReadBackgroundVoxels(w.background_path, region, &voxels, &voxel));
    TriangleMesh surface = VoxelUnionRectangles(voxels, voxel);
    while (surface.triangles.size() > options.max_background_triangles) {
      for (std::array<int32_t, 3>& v : voxels) {
        for (int32_t& i : v) i = static_cast<int32_t>(std::floor(i / 2.0));
      }
      std::sort(voxels.begin(), voxels.end());
      voxels.erase(std::unique(voxels.begin(), voxels.end()), voxels.end());
      voxel *= 2.0;
      surface = VoxelUnionRectangles(voxels, voxel);
    }
    report->lines.push_back("background: " + std::to_string(surface.triangles.size()) +
                            " triangles, the outer faces of its " + FormatNumber("%.0f mm", 1e3 * voxel) +
                            " voxels within " + FormatNumber("%.2f m", options.margin) +
                            " of where the machine's moving links go");
    WorldReportPart part;
    part.kind = WorldReportPart::Kind::kBackground;
    part.name = "background";
    part.mesh = std::move(surface);
    part.T_world_part = {Pose::Identity()};
    report->parts.push_back(std::move(part));
  }

  // Each waypoint's line and collision point, and the plot.
  report->waypoint_notes.clear();
  report->collision_points.clear();
  Chart chart;
  chart.title = "Clearance along the trajectory (log scale, 0 drawn at the bottom)";
  chart.x_label = "waypoint";
  chart.y_label = "least distance [mm]";
  chart.log_y = true;
  ChartSeries background{"to the background", {}, {}}, machines{"to the other machines", {}, {}},
      self{"between its own links", {}, {}}, hits{"collision (at the waypoint or on the way to it)", {}, {}};
  const double none = std::numeric_limits<double>::quiet_NaN();
  const auto mm = [none](double d) { return std::isfinite(d) ? 1e3 * d : none; };
  // Few waypoints: each its own tick, numbered from 1 as in the text output.
  const bool by_name = results.size() <= 20;
  for (size_t k = 0; k < results.size(); ++k) {
    const PostureClearance& c = results[k];
    report->waypoint_notes.push_back(
        "background " + Mm(c.distance_to_background) + ", machines " + Mm(c.distance_to_machines) +
        ", self " + Mm(c.self_distance) + "\n" +
        (c.colliding ? "COLLIDES: " + DescribeCollision(c) : std::string("free")));
    report->collision_points.push_back(c.colliding ? c.p_world_collision : Eigen::Vector3d::Constant(none));
    if (by_name) chart.categories.push_back(std::to_string(k + 1));
    const double x = static_cast<double>(by_name ? k : k + 1);
    for (ChartSeries* s : {&background, &machines, &self, &hits}) s->x.push_back(x);
    background.y.push_back(mm(c.distance_to_background));
    machines.y.push_back(mm(c.distance_to_machines));
    self.y.push_back(mm(c.self_distance));
    hits.y.push_back(c.colliding ? 0.0 : none);
  }
  hits.line = false;
  for (ChartSeries* s : {&background, &machines, &self, &hits}) {
    if (s != &hits) s->markers = results.size() <= 100;  // a line is what a long trajectory shows
    if (std::any_of(s->y.begin(), s->y.end(), [](double y) { return std::isfinite(y); })) {
      chart.series.push_back(*s);
    }
  }
  report->charts = {chart};
  return Status::Ok();
}

}  // namespace edgefit
