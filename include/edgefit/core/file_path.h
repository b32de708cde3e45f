// Paths named inside a file (a scene or model manifest) are relative to
// that file's folder.
#ifndef EDGEFIT_CORE_FILE_PATH_H_
#define EDGEFIT_CORE_FILE_PATH_H_

#include <string>

namespace edgefit {

// `path` as seen from the folder of `file`; absolute and empty paths as they are.
inline std::string PathRelativeToFile(const std::string& file, const std::string& path) {
  const size_t slash = file.find_last_of('/');
  if (path.empty() || path[0] == '/' || slash == std::string::npos) return path;
  return file.substr(0, slash) + "/" + path;
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_FILE_PATH_H_
