#include "edgefit/scene/jackets.h"

#include <algorithm>
#include <cmath>

#include "edgefit/core/split_mix64.h"
#include "edgefit/scene/as_built.h"
#include "edgefit/scene/main_chain.h"

namespace edgefit {
namespace {

// A jacket face turns away from the link's axis (cosine of the angle between
// its normal and the radial direction) and is no end face.
constexpr double kMinOutward = 0.3;
constexpr double kMaxAlongAxis = 0.7;

int LongestAxis(const Eigen::AlignedBox3d& box) {
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  return axis;
}

// Area-weighted vertex normals of a welded mesh (outward for CCW triangles).
std::vector<Eigen::Vector3d> VertexNormals(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                  .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    for (int i = 0; i < 3; ++i) normals[t[i]] += n;  // |n| = twice the area
  }
  for (Eigen::Vector3d& n : normals) {
    const double norm = n.norm();
    if (norm > 0.0) n /= norm;
  }
  return normals;
}

TriangleMesh MakeJacket(const TriangleMesh& link_mesh, const JacketOptions& options,
                        SplitMix64* rng) {
  TriangleMesh mesh = link_mesh;
  WeldIdenticalVertices(&mesh);
  SubdivideMesh(options.max_edge, 2'000'000, &mesh);
  const Eigen::AlignedBox3d box = mesh.BoundingBox();
  const int axis = LongestAxis(box);
  const double lo = box.min()[axis], length = box.sizes()[axis];
  const double coverage = rng->Uniform(options.coverage_min, options.coverage_max);
  const double start = rng->Uniform(0.0, 1.0 - coverage);
  const double offset_a = rng->Uniform(options.offset_min, options.offset_max);
  const double offset_b = rng->Uniform(options.offset_min, options.offset_max);
  auto along = [&](const Eigen::Vector3d& v) { return (v[axis] - lo) / length - start; };

  const std::vector<Eigen::Vector3d> normals = VertexNormals(mesh);
  const Eigen::Vector3d centre = box.center();
  const Eigen::Vector3d a = Eigen::Vector3d::Unit(axis);
  TriangleMesh jacket;
  std::vector<int> index(mesh.vertices.size(), -1);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    bool inside = true;
    for (int i = 0; i < 3; ++i) {
      const double s = along(mesh.vertices[t[i]]);
      inside = inside && s >= 0.0 && s <= coverage;
    }
    if (!inside) continue;
    // A sleeve: faces turned away from the link's axis, not its end faces
    // nor the inner faces of a fork.
    const Eigen::Vector3d& v0 = mesh.vertices[t[0]];
    const Eigen::Vector3d n = (mesh.vertices[t[1]] - v0).cross(mesh.vertices[t[2]] - v0);
    const Eigen::Vector3d m = (v0 + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0 - centre;
    const Eigen::Vector3d radial = m - m.dot(a) * a;
    if (!(n.norm() > 0.0) || !(radial.norm() > 0.0)) continue;
    if (n.normalized().dot(radial.normalized()) < kMinOutward ||
        std::abs(n.normalized().dot(a)) > kMaxAlongAxis) {
      continue;
    }
    Eigen::Vector3i out;
    for (int i = 0; i < 3; ++i) {
      int& k = index[t[i]];
      if (k < 0) {
        const Eigen::Vector3d& v = mesh.vertices[t[i]];
        const double f = along(v) / coverage;
        k = static_cast<int>(jacket.vertices.size());
        jacket.vertices.push_back(v + ((1.0 - f) * offset_a + f * offset_b) * normals[t[i]]);
      }
      out[i] = k;
    }
    jacket.triangles.push_back(out);
  }
  return jacket;
}

}  // namespace

bool JacketOptions::IsValid(std::string* error) const {
  if (!(offset_min >= 0.0 && offset_min <= offset_max && offset_max < 0.1)) {
    *error = "jacket offsets must satisfy 0 <= min <= max < 100 mm";
  } else if (!(coverage_min > 0.0 && coverage_min <= coverage_max && coverage_max <= 1.0)) {
    *error = "jacket coverage must satisfy 0 < min <= max <= 1";
  } else if (!(max_edge > 0.0)) {
    *error = "jacket max_edge must be positive";
  } else {
    return true;
  }
  return false;
}

std::vector<int> JacketLinks(const KinematicModel& model, const JacketOptions& options) {
  std::vector<int> links;
  if (!options.links.empty()) {
    for (const std::string& name : options.links) links.push_back(model.LinkIndex(name));
    return links;
  }
  const std::vector<int> chain = MainChainLinks(model);
  std::vector<std::pair<double, int>> candidates;
  for (size_t i = 2; i + 2 < chain.size(); ++i) {
    const Eigen::AlignedBox3d box = model.links()[chain[i]].mesh.BoundingBox();
    candidates.emplace_back(-box.sizes().maxCoeff(), chain[i]);
  }
  std::sort(candidates.begin(), candidates.end());
  for (size_t i = 0; i < candidates.size() && i < 2; ++i) links.push_back(candidates[i].second);
  std::sort(links.begin(), links.end());
  return links;
}

Status AddJackets(const KinematicModel& model, const std::vector<Pose>& T_world_link,
                  const JacketOptions& options, Scene* scene) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("jackets: " + error);
  const std::vector<int> links = JacketLinks(model, options);
  for (size_t i = 0; i < links.size(); ++i) {
    if (links[i] < 0) return Status::Error("jackets: no link named '" + options.links[i] + "'");
    SplitMix64 rng = SplitMix64::Stream(options.seed, static_cast<uint64_t>(links[i]) + 1);
    const TriangleMesh jacket = MakeJacket(model.links()[links[i]].mesh, options, &rng);
    if (jacket.empty()) continue;
    SceneMesh mesh;
    mesh.mesh_world.Append(jacket, T_world_link[links[i]]);
    mesh.label = kLabelAccessory | kJacketFlag;
    mesh.kind = "jacket";
    mesh.reflectance = 0.6;  // white or aluminised fabric
    scene->meshes.push_back(std::move(mesh));
  }
  return Status::Ok();
}

}  // namespace edgefit
