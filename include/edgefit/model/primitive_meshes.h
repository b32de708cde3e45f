// Triangle meshes of the URDF primitive shapes, centred on their frame as
// URDF defines them: box of full edge lengths `size`, cylinder of `radius`
// and `length` along z, sphere of `radius`. Outward counter-clockwise
// triangles, welded vertices (edges shared), metres.
#ifndef EDGEFIT_MODEL_PRIMITIVE_MESHES_H_
#define EDGEFIT_MODEL_PRIMITIVE_MESHES_H_

#include <Eigen/Core>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// 8 vertices, 12 triangles.
TriangleMesh MakeBoxMesh(const Eigen::Vector3d& size);
// `segments` (>= 3) around; caps are fans around a centre vertex, so the rim
// circles are the only sharp edges.
TriangleMesh MakeCylinderMesh(double radius, double length, int segments);
// Icosahedron subdivided `subdivisions` times (20 * 4^s triangles), vertices
// projected onto the sphere.
TriangleMesh MakeSphereMesh(double radius, int subdivisions);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_PRIMITIVE_MESHES_H_
