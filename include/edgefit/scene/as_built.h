// As-built deviation of link surfaces: a real casting or weldment is not its
// CAD model. Each link's surface is moved by a smooth, seeded displacement
// field defined in the link frame (so it moves with the link):
//
//   d(x_link) = A / S * sum_k a_k sin(w_k . x_link + phi_k) u_k,
//
// K = 4 terms, wave vectors w_k of random direction and wavelength in
// [wavelength_min, wavelength_max], unit directions u_k, weights a_k in
// [0.5, 1], S = sum_k a_k so that |d| <= A, and the amplitude A of each link
// drawn in [amplitude_min, amplitude_max]. The field is a function of the
// position only, so coincident vertices move together and the mesh stays
// closed. Triangles are first split uniformly (edge midpoints shared) until
// no edge is longer than max_edge, so that large flat CAD faces bend too.
#ifndef EDGEFIT_SCENE_AS_BUILT_H_
#define EDGEFIT_SCENE_AS_BUILT_H_

#include <cstdint>
#include <string>

#include "edgefit/core/pose.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct AsBuiltOptions {
  bool enabled = false;
  double amplitude_min = 0.0005;  // [m] largest displacement of a link, lower bound
  double amplitude_max = 0.002;   // [m] ... upper bound
  double wavelength_min = 0.2;    // [m]
  double wavelength_max = 0.8;    // [m]
  double max_edge = 0.04;         // [m] triangles are split down to this edge length
  // A mesh is split only while it stays below this many triangles.
  int max_triangles = 400'000;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// The displacement field of link `link` (seeded by options.seed and link).
class AsBuiltField {
 public:
  AsBuiltField(const AsBuiltOptions& options, int link);
  Eigen::Vector3d Displacement(const Eigen::Vector3d& x_link) const;
  double amplitude() const { return amplitude_; }

 private:
  double amplitude_ = 0.0;
  Eigen::Vector3d wave_[4], direction_[4];
  double weight_[4], phase_[4];
};

// Splits mesh_world (the link's mesh posed by T_world_link) and moves every
// vertex by the field of `link`.
void ApplyAsBuilt(const AsBuiltOptions& options, int link, const Pose& T_world_link,
                  TriangleMesh* mesh_world);

// Splits every triangle into four (edge midpoints shared between triangles)
// until no edge exceeds max_edge or the next split would pass max_triangles.
void SubdivideMesh(double max_edge, int max_triangles, TriangleMesh* mesh);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_AS_BUILT_H_
