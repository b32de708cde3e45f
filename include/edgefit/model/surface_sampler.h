// Area-uniform surface samples of link meshes: the model points that the
// weighted ICP stages match against scan points (paper Sec. 5).
//
// Count: a mesh of area A gets N = round(A / spacing^2) points (at least 1
// when A > 0). Small triangles get no guaranteed point: CAD tessellations
// put many tiny triangles on fillets, and one point each would make those
// regions far denser than flat faces. Placement is stratified along the
// cumulative triangle area (point i takes u = (i + U[0,1)) / N of the total
// area), so the density is uniform across faces of any size with much less
// clumping than independent draws; within a triangle the point is uniform
// (barycentric square-root rule). Normals are the unit face normals
// (counter-clockwise, outward for a well-formed mesh).
//
// Deterministic: a SplitMix64 generator per link, seeded from (seed, link
// index); uniform doubles from the top 53 bits of each raw 64-bit draw (no
// std distributions, whose output differs between standard libraries).
#ifndef EDGEFIT_MODEL_SURFACE_SAMPLER_H_
#define EDGEFIT_MODEL_SURFACE_SAMPLER_H_

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct SamplingOptions {
  double spacing = 0.002;  // [m] mean distance between samples (2 mm).
  uint64_t seed = 1;       // Same seed, same mesh -> same samples.

  bool IsValid(std::string* error) const;
};

// Samples in the mesh frame (the link frame for link meshes). float keeps
// millions of points affordable; link-frame coordinates of a few metres
// keep ~0.5 um resolution.
struct SurfaceSamples {
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;  // Unit face normals.
  std::vector<int> triangles;            // Index of the source triangle.

  size_t size() const { return points.size(); }
};

// Samples of one mesh, with the generator seeded by `seed`.
SurfaceSamples SampleMeshSurface(const TriangleMesh& mesh, double spacing, uint64_t seed);

// Samples of every link's mesh (empty for links without one), indexed like
// model.links(); link l uses seed Mix(options.seed, l), so a link's samples
// do not depend on the other links or on the thread count.
std::vector<SurfaceSamples> SampleModelSurfaces(const KinematicModel& model,
                                                const SamplingOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_SURFACE_SAMPLER_H_
