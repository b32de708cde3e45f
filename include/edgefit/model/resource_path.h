// Resolving the mesh filenames written in a URDF to files on disk.
#ifndef EDGEFIT_MODEL_RESOURCE_PATH_H_
#define EDGEFIT_MODEL_RESOURCE_PATH_H_

#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

// The candidate files for `uri` as written in the URDF at `urdf_path`, in
// the order they are tried:
//  - "file:///abs/x.stl" and "/abs/x.stl": that path;
//  - "rel/x.stl": relative to the URDF's directory;
//  - "package://pkg/rel/x.stl": "<root>/pkg/rel/x.stl" for each root in
//    `package_dirs`, then for the URDF's directory and each of its
//    ancestors; "<dir>/rel/x.stl" for each such ancestor whose name is
//    "pkg"; finally "rel/x.stl" relative to the URDF's directory and to its
//    parent (packages flattened next to the URDF).
std::vector<std::string> MeshPathCandidates(const std::string& uri, const std::string& urdf_path,
                                            const std::vector<std::string>& package_dirs);

// The first existing candidate; otherwise an error naming the URI and every
// path tried.
Status ResolveMeshPath(const std::string& uri, const std::string& urdf_path,
                       const std::vector<std::string>& package_dirs, std::string* resolved);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_RESOURCE_PATH_H_
