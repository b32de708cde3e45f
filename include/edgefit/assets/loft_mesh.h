// Lofted solids: a closed triangle mesh through a sequence of planar rings.
//
// Ring k and ring k+1 are joined by one quad (two triangles) per ring edge,
// so when consecutive rings have parallel edges (rectangular sections, or
// circles of any radius) every side face is one planar quad and the creases
// between sections are the mesh's only dihedral edges. The first and last
// rings are closed by planar caps. A ring of a single vertex is an apex
// (cone tip): it gets no cap.
#ifndef EDGEFIT_ASSETS_LOFT_MESH_H_
#define EDGEFIT_ASSETS_LOFT_MESH_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

using Ring = std::vector<Eigen::Vector3d>;

// `rings` (>= 2) of equal size n >= 3 (or size 1 for an apex at either end),
// each convex and planar, ordered counter-clockwise about the loft direction
// (from the first ring towards the last). The result is closed with outward
// counter-clockwise triangles. Caps of up to 8 vertices are fanned from their
// first vertex (n - 2 large triangles); larger caps from their centroid, which
// avoids slivers on round end faces.
TriangleMesh MakeLoftMesh(const std::vector<Ring>& rings);

// Like MakeLoftMesh but the rings form a closed loop (last joined to first)
// with no caps: a solid torus-like shape such as a tube or a flange ring.
TriangleMesh MakeClosedLoftMesh(const std::vector<Ring>& rings);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_LOFT_MESH_H_
