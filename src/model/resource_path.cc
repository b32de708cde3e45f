#include "edgefit/model/resource_path.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace edgefit {
namespace fs = std::filesystem;

std::vector<std::string> MeshPathCandidates(const std::string& uri, const std::string& urdf_path,
                                            const std::vector<std::string>& package_dirs) {
  std::error_code ec;
  fs::path urdf_dir = fs::absolute(fs::path(urdf_path), ec).parent_path();
  std::vector<fs::path> candidates;
  const std::string kFile = "file://", kPackage = "package://";
  if (uri.rfind(kPackage, 0) == 0) {
    const std::string rest = uri.substr(kPackage.size());
    const size_t slash = rest.find('/');
    const std::string package = rest.substr(0, slash);
    const fs::path relative = slash == std::string::npos ? fs::path() : fs::path(rest.substr(slash + 1));
    for (const std::string& root : package_dirs) candidates.push_back(fs::path(root) / package / relative);
    for (fs::path dir = urdf_dir;; dir = dir.parent_path()) {
      candidates.push_back(dir / package / relative);
      if (dir.filename() == package) candidates.push_back(dir / relative);
      if (dir == dir.parent_path() || dir.empty()) break;
    }
    candidates.push_back(urdf_dir / relative);
    candidates.push_back(urdf_dir.parent_path() / relative);
  } else if (uri.rfind(kFile, 0) == 0) {
    candidates.push_back(fs::path(uri.substr(kFile.size())));
  } else if (fs::path(uri).is_absolute()) {
    candidates.push_back(fs::path(uri));
  } else {
    candidates.push_back(urdf_dir / uri);
  }
  std::vector<std::string> out;
  for (const fs::path& p : candidates) {
    const std::string s = p.lexically_normal().string();
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  }
  return out;
}

Status ResolveMeshPath(const std::string& uri, const std::string& urdf_path,
                       const std::vector<std::string>& package_dirs, std::string* resolved) {
  const std::vector<std::string> candidates = MeshPathCandidates(uri, urdf_path, package_dirs);
  std::string tried;
  for (const std::string& candidate : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) {
      *resolved = candidate;
      return Status::Ok();
    }
    tried += (tried.empty() ? "" : ", ") + candidate;
  }
  return Status::Error("mesh '" + uri + "' not found; tried: " + tried);
}

}  // namespace edgefit
