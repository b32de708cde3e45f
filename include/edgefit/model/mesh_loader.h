// Mesh files (STL ascii/binary, COLLADA .dae, OBJ, anything assimp reads)
// into one TriangleMesh in the frame the file was authored in [m].
//
// ROS / rviz semantics: the vertices come out as authored, Z up. For COLLADA
// that means the node hierarchy transforms and the <unit meter="..."> scale
// are applied, but NOT the rotation assimp adds to turn a Z_UP file into
// Y_UP (AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION). Camera and light nodes
// carry no meshes and are skipped; polygons are triangulated; points and
// lines are dropped; bit-identical vertices are welded so that neighbouring
// triangles share edges (needed by sharp-edge extraction).
#ifndef EDGEFIT_MODEL_MESH_LOADER_H_
#define EDGEFIT_MODEL_MESH_LOADER_H_

#include <Eigen/Core>
#include <string>

#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// Loads `path`, multiplies every vertex by `scale` per axis (URDF <mesh
// scale>; a mirroring scale flips the triangles so they stay outward), and
// replaces *mesh. A file with no triangles is an error naming the file.
Status LoadMesh(const std::string& path, const Eigen::Vector3d& scale, TriangleMesh* mesh);

// Multiplies vertices by `scale` per axis, flipping triangle orientation when
// the scale mirrors (negative determinant).
void ScaleMesh(const Eigen::Vector3d& scale, TriangleMesh* mesh);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_MESH_LOADER_H_
