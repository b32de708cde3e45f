// Internal helpers of the asset generators: placing parts in a link frame
// and writing a model's files.
#ifndef EDGEFIT_SRC_ASSETS_ASSET_OUTPUT_H_
#define EDGEFIT_SRC_ASSETS_ASSET_OUTPUT_H_

#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {
namespace assets_internal {

// Translation only.
Pose At(double x, double y, double z);
// A part built along its local +z placed with that axis along link +x / -x
// / +y / -y / -z, its local origin at (x, y, z).
Pose AlongX(double x, double y, double z);
Pose AlongMinusX(double x, double y, double z);
Pose AlongY(double x, double y, double z);
Pose AlongMinusY(double x, double y, double z);
Pose AlongMinusZ(double x, double y, double z);

// A link's mesh and the name of its file under meshes/.
struct LinkMesh {
  std::string link;
  TriangleMesh mesh;
};

// Creates <dir> and <dir>/meshes, then writes each mesh as
// <dir>/meshes/<link>.stl.
Status WriteLinkMeshes(const std::string& dir, const std::vector<LinkMesh>& meshes);

// Writes `text` to <dir>/<name> atomically.
Status WriteTextFile(const std::string& dir, const std::string& name, const std::string& text);

}  // namespace assets_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_ASSETS_ASSET_OUTPUT_H_
