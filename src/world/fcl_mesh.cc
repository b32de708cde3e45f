#include "fcl_mesh.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <limits>
#include <mutex>
#include <vector>

#include "edgefit/model/point_triangle_distance.h"

namespace edgefit {

constexpr size_t kContacts = 16;  // FCL's contacts weighed for a collision's point

struct FclMesh::Impl {
  TriangleMesh mesh;  // until the hierarchy is built from it
  std::once_flag built;
  fcl::BVHModel<fcl::OBBRSSd> model;

  // The hierarchy, built by the first query (once, whichever thread asks).
  const fcl::BVHModel<fcl::OBBRSSd>* Model() {
    std::call_once(built, [this] {
      std::vector<fcl::Triangle> triangles;
      triangles.reserve(mesh.triangles.size());
      for (const Eigen::Vector3i& t : mesh.triangles) {
        triangles.emplace_back(static_cast<size_t>(t[0]), static_cast<size_t>(t[1]),
                               static_cast<size_t>(t[2]));
      }
      model.beginModel(static_cast<int>(triangles.size()), static_cast<int>(mesh.vertices.size()));
      model.addSubModel(mesh.vertices, triangles);
      model.endModel();
      mesh = TriangleMesh();
    });
    return &model;
  }
};

FclMesh::FclMesh(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  CHECK(!mesh.empty());
  impl_->mesh = mesh;
}

FclMesh::~FclMesh() = default;

double FclMesh::Distance(const Pose& T_world_this, const FclMesh& other, const Pose& T_world_other,
                         double bound) const {
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  // FCL's traversal starts from the result's distance and only updates it
  // when nearer: beyond `bound` it prunes at once.
  result.min_distance = std::min(bound, std::numeric_limits<double>::max());
  const double d = fcl::distance(impl_->Model(), fcl::Transform3d(T_world_this.matrix()),
                                 other.impl_->Model(), fcl::Transform3d(T_world_other.matrix()),
                                 request, result);
  return std::max(0.0, d);  // FCL gives -1 (or 0) for crossing meshes
}

bool FclMesh::CollidesBox(const Pose& T_world_this, const Eigen::AlignedBox3d& box_world) const {
  const fcl::Boxd box(box_world.sizes());
  fcl::Transform3d T_world_box = fcl::Transform3d::Identity();
  T_world_box.translation() = box_world.center();
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(impl_->Model(), fcl::Transform3d(T_world_this.matrix()), &box, T_world_box, request,
               result);
  return result.isCollision();
}

bool FclMesh::Collides(const Pose& T_world_this, const FclMesh& other, const Pose& T_world_other,
                       Eigen::Vector3d* p_world) const {
  fcl::CollisionRequestd request;
  request.enable_contact = p_world != nullptr;
  request.num_max_contacts = p_world != nullptr ? kContacts : 1;
  fcl::CollisionResultd result;
  fcl::collide(impl_->Model(), fcl::Transform3d(T_world_this.matrix()), other.impl_->Model(),
               fcl::Transform3d(T_world_other.matrix()), request, result);
  if (p_world == nullptr || result.numContacts() == 0) return result.isCollision();
  // FCL's point for triangles that cross is on both; for coplanar ones that
  // overlap it may be on neither. The point of the contacts' triangles
  // nearest both is taken: FCL's, or a corner's nearest point on the other.
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < result.numContacts(); ++i) {
    const fcl::Contactd& contact = result.getContact(i);
    std::array<Eigen::Vector3d, 3> t, o;
    for (size_t k = 0; k < 3; ++k) {
      t[k] = T_world_this * impl_->model.vertices[impl_->model.tri_indices[contact.b1][k]];
      o[k] = T_world_other * other.impl_->model.vertices[other.impl_->model.tri_indices[contact.b2][k]];
    }
    std::vector<Eigen::Vector3d> candidates = {contact.pos};
    for (size_t k = 0; k < 3; ++k) {
      candidates.push_back(ClosestPointOnTriangle(t[k], o[0], o[1], o[2]));
      candidates.push_back(ClosestPointOnTriangle(o[k], t[0], t[1], t[2]));
    }
    for (const Eigen::Vector3d& p : candidates) {
      const double off = std::max(SquaredDistanceToTriangle(p, t[0], t[1], t[2]),
                                  SquaredDistanceToTriangle(p, o[0], o[1], o[2]));
      if (off < best) {
        best = off;
        *p_world = p;
      }
    }
  }
  return true;
}

}  // namespace edgefit
