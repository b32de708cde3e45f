// Binary STL output for the procedural benchmark meshes.
//
// Byte-for-byte deterministic: the 80-byte header holds a fixed text and the
// solid's name (zero padded, no timestamp), vertices are the mesh's doubles
// rounded to float32, normals are computed from the rounded corners, and
// every field is written little-endian whatever the host. The header never
// starts with "solid", so readers do not mistake the file for ASCII STL.
#ifndef EDGEFIT_ASSETS_STL_WRITER_H_
#define EDGEFIT_ASSETS_STL_WRITER_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// The file's bytes: header, uint32 triangle count, then per triangle the
// unit normal, three corners (float32 x, y, z each) and a zero uint16.
std::string EncodeBinaryStl(const TriangleMesh& mesh, const std::string& solid_name);

// Writes EncodeBinaryStl(mesh, solid_name) to `path` atomically.
Status WriteBinaryStl(const std::string& path, const TriangleMesh& mesh,
                      const std::string& solid_name);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_STL_WRITER_H_
