#include "edgefit/scanner/virtual_scanner.h"

#include <embree3/rtcore.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "counter_rng.h"
#include "edgefit/model/sharp_edges.h"
#include "edgefit/scanner/edge_proximity.h"
#include "embree_scene.h"

namespace edgefit {

struct VirtualScanner::Impl {
  scanner_internal::EmbreeScene embree;
  std::vector<uint16_t> labels;                  // per SceneMesh (geomID)
  std::vector<EdgeProximityIndex> edge_indices;  // per SceneMesh; empty unless a link mesh
  Eigen::AlignedBox3d default_asset_box;
};

VirtualScanner::VirtualScanner(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VirtualScanner::~VirtualScanner() = default;

size_t VirtualScanner::triangle_count() const { return impl_->embree.triangle_count(); }

Status VirtualScanner::Create(const Scene& scene, const VirtualScanOptions& options,
                              std::unique_ptr<VirtualScanner>* scanner) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("virtual scan: " + error);
  auto impl = std::make_unique<Impl>();
  EDGEFIT_RETURN_IF_ERROR(impl->embree.Build(scene, options.robust));
  impl->default_asset_box = DefaultAssetBox(scene);
  impl->labels.resize(scene.meshes.size());
  impl->edge_indices.resize(scene.meshes.size());
  const SharpEdgeOptions edge_options{options.sharp_edge_min_dihedral_deg};
  for (size_t id = 0; id < scene.meshes.size(); ++id) {
    const SceneMesh& m = scene.meshes[id];
    impl->labels[id] = m.label & kLabelMask;
    if (!IsLinkLabel(m.label) || m.mesh_world.empty()) continue;
    // Sharp edges need shared vertices; STL-like meshes are welded first.
    TriangleMesh welded = m.mesh_world;
    WeldIdenticalVertices(&welded);
    MeshEdges edges = ExtractSharpEdges(welded, edge_options);
    impl->edge_indices[id] = EdgeProximityIndex(std::move(edges.sharp), options.true_edge_distance);
  }
  scanner->reset(new VirtualScanner(std::move(impl)));
  return Status::Ok();
}

Status VirtualScanner::Scan(const std::vector<Pose>& T_world_scanner,
                            const VirtualScanOptions& options, VirtualScan* out) const {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("virtual scan: " + error);
  const Eigen::AlignedBox3d asset_box =
      options.asset_box_world ? *options.asset_box_world : impl_->default_asset_box;
  VirtualScan result;
  const RTCScene rtc_scene = impl_->embree.scene();
  const float max_range = static_cast<float>(options.max_range);

  for (size_t s = 0; s < T_world_scanner.size(); ++s) {
    const Pose& T = T_world_scanner[s];
    AngularLattice lattice;
    EDGEFIT_RETURN_IF_ERROR(
        MakeScanLattice(asset_box, T, options, &lattice).WithContext("scanner " + std::to_string(s)));
    const int rows = lattice.rows(), cols = lattice.cols();
    OrganizedScan scan(rows, cols);
    std::vector<uint16_t> labels(scan.size(), kLabelMissing);

    // Direction tables: d_scanner(row, col) = (ce ca, ce sa, se), exactly
    // AngularLattice::Direction for a level lattice (R_scanner_lattice = I).
    std::vector<double> cos_el(rows), sin_el(rows), cos_az(cols), sin_az(cols);
    for (int r = 0; r < rows; ++r) {
      cos_el[r] = std::cos(lattice.elevation(r));
      sin_el[r] = std::sin(lattice.elevation(r));
    }
    for (int c = 0; c < cols; ++c) {
      cos_az[c] = std::cos(lattice.azimuth(c));
      sin_az[c] = std::sin(lattice.azimuth(c));
    }
    const Eigen::Matrix3d R = T.linear();
    const Eigen::Vector3d o_world = T.translation();
    const double sigma = options.noise_sigma;
    const uint64_t seed = options.seed;

    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 8)
    for (int c = 0; c < cols; ++c) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // a column sweeps one plane
      for (int r = 0; r < rows; ++r) {
        const Eigen::Vector3d d_scanner(cos_el[r] * cos_az[c], cos_el[r] * sin_az[c], sin_el[r]);
        const Eigen::Vector3d d_world = R * d_scanner;
        RTCRayHit rh;
        rh.ray.org_x = static_cast<float>(o_world.x());
        rh.ray.org_y = static_cast<float>(o_world.y());
        rh.ray.org_z = static_cast<float>(o_world.z());
        rh.ray.dir_x = static_cast<float>(d_world.x());
        rh.ray.dir_y = static_cast<float>(d_world.y());
        rh.ray.dir_z = static_cast<float>(d_world.z());
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = max_range;
        rh.ray.time = 0.0f;
        rh.ray.mask = 0xffffffffu;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(rtc_scene, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;  // miss: missing cell, label 0

        const size_t cell = scan.Index(r, c);
        const double t = rh.ray.tfar;
        // Range noise from (seed, scan, cell) only: thread-count independent.
        double range = t;
        if (sigma > 0.0) {
          const uint64_t h1 = scanner_internal::CounterHash(seed, 2 * s, cell);
          const uint64_t h2 = scanner_internal::CounterHash(seed, 2 * s + 1, cell);
          range += sigma * scanner_internal::StandardNormal(h1, h2);
        }
        const Eigen::Vector3d n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
        const double n_norm = n.norm();
        const float intensity =
            n_norm > 0.0 ? static_cast<float>(std::abs(n.dot(d_world)) / n_norm) : 1.0f;
        scan.SetPoint(cell, (d_scanner * range).cast<float>(), intensity);

        uint16_t label = impl_->labels[rh.hit.geomID];
        const EdgeProximityIndex& edges = impl_->edge_indices[rh.hit.geomID];
        if (!edges.empty() && edges.Within(o_world + t * d_world)) label |= kTrueEdgeFlag;
        labels[cell] = label;
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    scan.set_T_world_scanner(T);
    scan.set_lattice(std::move(lattice));
    result.scans.scans.push_back(std::move(scan));
    result.scans.sources.push_back("virtual scanner " + std::to_string(s));
    result.labels.push_back(std::move(labels));
    result.ray_seconds.push_back(seconds);
    result.rays += static_cast<size_t>(rows) * static_cast<size_t>(cols);
  }
  *out = std::move(result);
  return Status::Ok();
}

Status ScanScene(const Scene& scene, const std::vector<Pose>& T_world_scanner,
                 const VirtualScanOptions& options, VirtualScan* out) {
  std::unique_ptr<VirtualScanner> scanner;
  EDGEFIT_RETURN_IF_ERROR(VirtualScanner::Create(scene, options, &scanner));
  return scanner->Scan(T_world_scanner, options, out);
}

}  // namespace edgefit
