// A triangle mesh as a binary little-endian PLY file (vertex: float x y z;
// face: uchar count, int vertex_indices), readable by MeshLab, CloudCompare
// and Blender. `edgefit fit --out_ply` writes the fitted model with it.
#ifndef EDGEFIT_MODEL_MESH_PLY_H_
#define EDGEFIT_MODEL_MESH_PLY_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// The file's bytes: header, then vertices rounded to float32 and faces,
// little-endian whatever the host. `comment` (one line) goes in the header.
std::string EncodeMeshPly(const TriangleMesh& mesh, const std::string& comment);

// Writes EncodeMeshPly(mesh, comment) to `path` atomically.
Status WriteMeshPly(const std::string& path, const TriangleMesh& mesh, const std::string& comment);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_MESH_PLY_H_
