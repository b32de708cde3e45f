// L-brackets on the link surface (accessory_parts.h): the plate lies on the
// tangent plane of a surface sample, 1 mm off it; a bracket whose corners
// would sink more than 2 mm into any link (a concave spot, an edge) is
// rejected, so brackets only ever occlude the CAD surface.
#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "accessory_parts.h"

namespace edgefit {
namespace scene_internal {
namespace {

constexpr double kLiftOff = 0.001;       // [m] plate above the tangent plane
constexpr double kMaxPenetration = 0.002;  // [m] tolerated sinking of a corner

// Frame with z = n, x = the tangent closest to `along`.
Pose BracketFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& n,
                  const Eigen::Vector3d& along) {
  Eigen::Vector3d x = along - along.dot(n) * n;
  x = x.norm() > 1e-6 ? Eigen::Vector3d(x.normalized()) : n.unitOrthogonal();
  Pose T = Pose::Identity();
  T.linear().col(0) = x;
  T.linear().col(1) = n.cross(x);
  T.linear().col(2) = n;
  T.translation() = origin;
  return T;
}

bool Clear(const PartContext& context, const TriangleMesh& mesh) {
  for (const Eigen::Vector3d& v : mesh.vertices) {
    if (context.clearance->Clearance(v, 0.05, nullptr) < -kMaxPenetration) return false;
  }
  return true;
}

// Largest leg for a bracket on `link`: the option, but at most 3/4 of the
// link's smallest extent, so small links get small brackets.
double MaxLeg(const PartContext& context, int link) {
  const AccessoryOptions& options = *context.options;
  const double extent = context.model->links()[link].mesh.BoundingBox().sizes().minCoeff();
  return std::max(options.bracket_size_min, std::min(options.bracket_size_max, 0.75 * extent));
}

}  // namespace

bool BuildClampBracket(const PartContext& context, const ClampSite& site, SplitMix64* rng,
                       TriangleMesh* mesh) {
  const AccessoryOptions& options = *context.options;
  const SurfaceCloud& cloud = context.clearance->LinkCloud(site.link);
  if (cloud.p_world.empty()) return false;
  size_t foot = 0;
  for (size_t i = 1; i < cloud.p_world.size(); ++i) {
    if ((cloud.p_world[i] - site.p_world).squaredNorm() <
        (cloud.p_world[foot] - site.p_world).squaredNorm()) {
      foot = i;
    }
  }
  const Eigen::Vector3d& n = cloud.n_world[foot];
  const double thickness = rng->Uniform(0.004, 0.008);
  const double max_leg = MaxLeg(context, site.link);
  const double width = rng->Uniform(options.bracket_size_min, std::min(0.08, max_leg));
  const double plate = rng->Uniform(options.bracket_size_min, max_leg);
  // The upright leg reaches past the tube centre, as a clamp holder does.
  const double height = std::clamp((site.p_world - cloud.p_world[foot]).dot(n) + site.radius,
                                   options.bracket_size_min, max_leg);
  // The upright stands beside the tube: offset sideways by radius + 4 mm.
  const Pose T0 = BracketFrame(cloud.p_world[foot] + kLiftOff * n, n, site.tangent_world);
  const Pose T_world_bracket =
      T0 * Eigen::Translation3d(0.0, site.radius + 0.004, 0.0);
  *mesh = MakeLBracketMesh(T_world_bracket, width, plate, height, thickness);
  if (!Clear(context, *mesh)) {
    mesh->vertices.clear();
    mesh->triangles.clear();
    return false;
  }
  return true;
}

bool BuildFreeBracket(const PartContext& context, int link, SplitMix64* rng, TriangleMesh* mesh) {
  const AccessoryOptions& options = *context.options;
  const SurfaceCloud& cloud = context.clearance->LinkCloud(link);
  if (cloud.p_world.empty()) return false;
  for (int attempt = 0; attempt < 20; ++attempt) {
    const size_t i = static_cast<size_t>(rng->Next() % cloud.p_world.size());
    const Eigen::Vector3d& n = cloud.n_world[i];
    const Eigen::Vector3d along(rng->Uniform(-1, 1), rng->Uniform(-1, 1), rng->Uniform(-1, 1));
    const double thickness = rng->Uniform(0.004, 0.01);
    const double max_leg = MaxLeg(context, link);
    const double width = rng->Uniform(options.bracket_size_min, max_leg);
    const double plate = rng->Uniform(options.bracket_size_min, max_leg);
    const double height = rng->Uniform(options.bracket_size_min, max_leg);
    *mesh = MakeLBracketMesh(BracketFrame(cloud.p_world[i] + kLiftOff * n, n, along), width, plate,
                             height, thickness);
    if (Clear(context, *mesh)) return true;
  }
  mesh->vertices.clear();
  mesh->triangles.clear();
  return false;
}

}  // namespace scene_internal
}  // namespace edgefit
