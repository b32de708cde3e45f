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
#include "edgefit/scanner/range_noise.h"
#include "embree_scene.h"

namespace edgefit {

struct VirtualScanner::Impl {
  scanner_internal::EmbreeScene embree;
  std::vector<uint16_t> labels;                  // per SceneMesh (geomID)
  std::vector<EdgeProximityIndex> edge_indices;  // per SceneMesh; empty unless a link mesh
  std::vector<double> reflectance;               // per SceneMesh
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
  impl->reflectance.resize(scene.meshes.size());
  const SharpEdgeOptions edge_options{options.sharp_edge_min_dihedral_deg};
  for (size_t id = 0; id < scene.meshes.size(); ++id) {
    const SceneMesh& m = scene.meshes[id];
    impl->labels[id] = m.label & (kLabelMask | kJacketFlag);
    impl->reflectance[id] = m.reflectance;
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

namespace {

// The central ray of one cell: first hit distance (infinity for a miss), the
// mesh it hit and its geometric normal as Embree gives it (not unit length).
struct CentralHit {
  float t = std::numeric_limits<float>::infinity();
  unsigned geom = RTC_INVALID_GEOMETRY_ID;
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();
  bool hit() const { return geom != RTC_INVALID_GEOMETRY_ID; }
};

// Dropout draws use streams above every range-noise stream (2 s, 2 s + 1).
constexpr uint64_t kDropoutStream = uint64_t{1} << 40;

CentralHit Cast(RTCScene scene, RTCIntersectContext* context, const Eigen::Vector3d& origin,
                const Eigen::Vector3d& direction, float max_range) {
  RTCRayHit rh;
  rh.ray.org_x = static_cast<float>(origin.x());
  rh.ray.org_y = static_cast<float>(origin.y());
  rh.ray.org_z = static_cast<float>(origin.z());
  rh.ray.dir_x = static_cast<float>(direction.x());
  rh.ray.dir_y = static_cast<float>(direction.y());
  rh.ray.dir_z = static_cast<float>(direction.z());
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = max_range;
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, context, &rh);
  CentralHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = rh.ray.tfar;
  hit.geom = rh.hit.geomID;
  hit.normal = Eigen::Vector3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  return hit;
}

double AbsCos(const CentralHit& hit, const Eigen::Vector3d& d_world) {
  const Eigen::Vector3d n = hit.normal.cast<double>();
  const double norm = n.norm();
  return norm > 0.0 ? std::abs(n.dot(d_world)) / norm : 1.0;
}

// What the beam of one cell returns (beam_footprint.h).
struct BeamReturn {
  double range = 0.0;   // [m] along the central direction
  double signal = 0.0;  // relative signal S (range_noise.h) times reference reflectance
  unsigned geom = RTC_INVALID_GEOMETRY_ID;  // the strongest contribution's mesh
  bool mixed = false;
};

}  // namespace

Status VirtualScanner::Scan(const std::vector<Pose>& T_world_scanner,
                            const VirtualScanOptions& options, VirtualScan* out) const {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("virtual scan: " + error);
  const Eigen::AlignedBox3d asset_box =
      options.asset_box_world ? *options.asset_box_world : impl_->default_asset_box;
  VirtualScan result;
  const RTCScene rtc_scene = impl_->embree.scene();
  const float max_range = static_cast<float>(options.max_range);
  const BeamOptions& beam = options.beam;
  const RangeNoiseOptions& noise_model = options.range_noise;

  // Sub-ray pattern over the unit disc (sunflower), with Gaussian weights.
  std::vector<Eigen::Vector2d> pattern;
  std::vector<double> profile;
  if (beam.enabled()) {
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int j = 0; j < beam.sub_rays; ++j) {
      const double r = std::sqrt((j + 0.5) / beam.sub_rays);
      pattern.emplace_back(r * std::cos(j * golden), r * std::sin(j * golden));
      profile.push_back(std::exp(-2.0 * r * r));
    }
  }

  for (size_t s = 0; s < T_world_scanner.size(); ++s) {
    const Pose& T = T_world_scanner[s];
    ScanLattice lattice;
    EDGEFIT_RETURN_IF_ERROR(
        MakeScanLattice(asset_box, T, options, &lattice).WithContext("scanner " + std::to_string(s)));
    const int rows = lattice.rows(), cols = lattice.cols();
    OrganizedScan scan(rows, cols);
    std::vector<uint16_t> labels(scan.size(), kLabelMissing);

    // Direction tables: d_scanner(row, col) = (ce ca, ce sa, se), exactly
    // ScanLattice::Direction for a level lattice (R_scanner_lattice = I);
    // a camera's pixel rays, per cell.
    const DepthCameraOptions& camera = options.camera;
    std::vector<double> cos_el(rows), sin_el(rows), cos_az(cols), sin_az(cols);
    std::vector<Eigen::Vector3d> pixel_rays;
    if (camera.enabled()) {
      pixel_rays.resize(scan.size());
      for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) pixel_rays[scan.Index(r, c)] = lattice.Direction(r, c);
      }
    } else {
      for (int r = 0; r < rows; ++r) {
        cos_el[r] = std::cos(lattice.elevation(r));
        sin_el[r] = std::sin(lattice.elevation(r));
      }
      for (int c = 0; c < cols; ++c) {
        cos_az[c] = std::cos(lattice.azimuth(c));
        sin_az[c] = std::sin(lattice.azimuth(c));
      }
    }
    auto direction = [&](int r, int c) -> Eigen::Vector3d {
      if (camera.enabled()) return pixel_rays[scan.Index(r, c)];
      return Eigen::Vector3d(cos_el[r] * cos_az[c], cos_el[r] * sin_az[c], sin_el[r]);
    };
    const Eigen::Matrix3d R = T.linear();
    const Eigen::Vector3d o_world = T.translation();
    const double sigma = options.noise_sigma;
    const uint64_t seed = options.seed;
    const double step = std::min(std::abs(lattice.row_step()), std::abs(lattice.col_step()));

    const auto start = std::chrono::steady_clock::now();
    // Pass 1: the central ray of every cell.
    std::vector<CentralHit> central(scan.size());
#pragma omp parallel for schedule(dynamic, 8)
    for (int c = 0; c < cols; ++c) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // a column sweeps one plane
      for (int r = 0; r < rows; ++r) {
        central[scan.Index(r, c)] = Cast(rtc_scene, &context, o_world, R * direction(r, c), max_range);
      }
    }

    // Does the footprint of cell (r, c) reach beyond the smooth surface of its
    // central hit? Looks at the central hits within the footprint's radius.
    auto needs_sub_rays = [&](int r, int c, const Eigen::Vector3d& p0, const Eigen::Vector3d& n0,
                              const CentralHit& hit) {
      const int k = static_cast<int>(std::ceil(beam.Radius(hit.t) / (hit.t * step)));
      for (int rr = std::max(0, r - k); rr <= std::min(rows - 1, r + k); ++rr) {
        for (int cc = std::max(0, c - k); cc <= std::min(cols - 1, c + k); ++cc) {
          const CentralHit& other = central[scan.Index(rr, cc)];
          if (other.geom != hit.geom) return true;
          const Eigen::Vector3d p = o_world + static_cast<double>(other.t) * (R * direction(rr, cc));
          if (std::abs(n0.dot(p - p0)) > 0.5 * beam.mixed_depth) return true;
        }
      }
      return false;
    };

    // The footprint's sub-rays: energy-weighted range, signal, mixed or not.
    auto cast_beam = [&](RTCIntersectContext* context, const Eigen::Vector3d& d_world,
                         const Eigen::Vector3d& p0, const Eigen::Vector3d& n0, double t0) {
      const Eigen::Vector3d u = d_world.unitOrthogonal(), v = d_world.cross(u);
      const double exit_radius = 0.5 * beam.exit_diameter;
      const double spread = std::tan(0.5 * beam.divergence);
      double energy_sum = 0.0, profile_sum = 0.0, strongest = -1.0;
      int strongest_j = -1;
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      std::vector<double> t(pattern.size()), depth(pattern.size()), energy(pattern.size(), 0.0);
      BeamReturn ret;
      for (size_t j = 0; j < pattern.size(); ++j) {
        profile_sum += profile[j];
        const Eigen::Vector3d offset = pattern[j].x() * u + pattern[j].y() * v;
        const Eigen::Vector3d origin = o_world + exit_radius * offset;
        const Eigen::Vector3d dir = (d_world + spread * offset).normalized();
        const CentralHit hit = Cast(rtc_scene, context, origin, dir, max_range);
        if (!hit.hit()) continue;
        t[j] = hit.t;
        const Eigen::Vector3d p = origin + t[j] * dir;
        depth[j] = n0.dot(p - p0);
        lo = std::min(lo, depth[j]);
        hi = std::max(hi, depth[j]);
        const double ratio = t0 / t[j];
        energy[j] = profile[j] * impl_->reflectance[hit.geom] * AbsCos(hit, dir) * ratio * ratio;
        energy_sum += energy[j];
        if (energy[j] > strongest) {
          strongest = energy[j];
          strongest_j = static_cast<int>(j);
          ret.geom = hit.geom;
        }
      }
      if (strongest_j < 0 || !(energy_sum > 0.0)) return ret;
      ret.mixed = hi - lo > beam.mixed_depth;
      double weighted = 0.0, weight = 0.0;
      for (size_t j = 0; j < pattern.size(); ++j) {
        if (!(energy[j] > 0.0)) continue;
        if (beam.mixed_return == MixedReturn::kStrongest &&
            std::abs(depth[j] - depth[strongest_j]) > beam.mixed_depth) {
          continue;
        }
        weighted += energy[j] * t[j];
        weight += energy[j];
      }
      ret.range = weighted / weight;
      ret.signal = energy_sum / profile_sum;
      return ret;
    };

    // Pass 2: the return of every cell with a central hit.
#pragma omp parallel for schedule(dynamic, 8)
    for (int c = 0; c < cols; ++c) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (int r = 0; r < rows; ++r) {
        const size_t cell = scan.Index(r, c);
        const CentralHit& hit = central[cell];
        if (!hit.hit()) continue;  // miss: missing cell, label 0
        const Eigen::Vector3d d_scanner = direction(r, c);
        const Eigen::Vector3d d_world = R * d_scanner;
        const double t = hit.t;
        const double abs_cos = AbsCos(hit, d_world);
        BeamReturn ret;
        ret.range = t;
        ret.geom = hit.geom;
        ret.signal = impl_->reflectance[hit.geom] * abs_cos;
        if (beam.enabled()) {
          const Eigen::Vector3d p0 = o_world + t * d_world;
          Eigen::Vector3d n0 = hit.normal.cast<double>();
          if (n0.norm() > 0.0) n0.normalize();
          if (needs_sub_rays(r, c, p0, n0, hit)) {
            const BeamReturn beam_return = cast_beam(&context, d_world, p0, n0, t);
            if (beam_return.geom != RTC_INVALID_GEOMETRY_ID) ret = beam_return;
          }
        }
        const double signal = ret.signal / noise_model.reference_reflectance;
        if (noise_model.signal_model) {
          const double p_drop = noise_model.DropoutProbability(signal);
          if (p_drop > 0.0 && scanner_internal::UnitOpen(scanner_internal::CounterHash(
                                  seed, kDropoutStream + s, cell)) < p_drop) {
            continue;
          }
        }
        // Range noise from (seed, scan, cell) only: thread-count independent.
        double range = ret.range;
        if (camera.enabled()) {  // depth noise: the depth z moves by sigma_z(z) n
          const double z = ret.range * d_scanner.z();
          if (camera.sigma_at_1m > 0.0 && z > 0.0) {
            range += camera.sigma_at_1m * z * z * camera.NoiseDraw(seed, s, r, c) / d_scanner.z();
          }
        } else if (sigma > 0.0) {
          const uint64_t h1 = scanner_internal::CounterHash(seed, 2 * s, cell);
          const uint64_t h2 = scanner_internal::CounterHash(seed, 2 * s + 1, cell);
          range += sigma * noise_model.NoiseFactor(signal) * scanner_internal::StandardNormal(h1, h2);
        }
        scan.SetPoint(cell, (d_scanner * range).cast<float>(), static_cast<float>(abs_cos));

        uint16_t label = impl_->labels[ret.geom];
        if (ret.mixed) label |= kMixedPixelFlag;
        const EdgeProximityIndex& edges = impl_->edge_indices[hit.geom];
        if (!ret.mixed && ret.geom == hit.geom && !edges.empty() &&
            edges.Within(o_world + t * d_world)) {
          label |= kTrueEdgeFlag;
        }
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
