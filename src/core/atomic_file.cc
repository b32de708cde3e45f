#include "edgefit/core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace edgefit {

Status WriteFileAtomically(const std::string& path,
                           const std::function<Status(std::ostream&)>& write) {
  const std::string tmp_path = path + ".tmp." + std::to_string(::getpid());
  Status status;
  {
    std::ofstream out(tmp_path, std::ios::binary | std::ios::trunc);
    if (!out) {
      return Status::Error(path + ": cannot open for writing: " + std::strerror(errno));
    }
    status = write(out);
    out.flush();
    if (status.ok() && !out) status = Status::Error(path + ": write failed (disk full?)");
  }
  if (!status.ok()) {
    std::remove(tmp_path.c_str());
    return status;
  }
  if (std::rename(tmp_path.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp_path.c_str());
    return Status::Error(path + ": cannot move the finished file into place: " + reason);
  }
  return Status::Ok();
}

Status WriteStringAtomically(const std::string& path, const std::string& content) {
  return WriteFileAtomically(path, [&content](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    return Status::Ok();
  });
}

namespace {

// `folder` ("" is the working folder) exists, is a folder and takes files.
Status CheckFolderTakesFiles(const std::string& what, const std::string& folder) {
  const std::string dir = folder.empty() ? "." : folder;
  std::error_code error;
  if (!std::filesystem::exists(dir, error)) {
    return Status::Error(what + ": the folder " + dir + " does not exist");
  }
  if (!std::filesystem::is_directory(dir, error)) {
    return Status::Error(what + ": " + dir + " is not a folder");
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    return Status::Error(what + ": cannot write in the folder " + dir + ": " +
                         std::strerror(errno));
  }
  return Status::Ok();
}

}  // namespace

Status CheckOutputPath(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    return Status::Error(path + ": is a folder, not a file name");
  }
  return CheckFolderTakesFiles(path, std::filesystem::path(path).parent_path().string());
}

Status CheckOutputFolder(const std::string& folder) {
  std::error_code error;
  std::filesystem::path existing(folder);
  while (!existing.empty() && !std::filesystem::exists(existing, error)) {
    existing = existing.parent_path();
  }
  return CheckFolderTakesFiles(folder, existing.string());
}

Status CreateFolder(const std::string& folder, bool* created) {
  std::error_code error;
  const bool made = std::filesystem::create_directories(folder, error);
  if (error) return Status::Error(folder + ": cannot make the folder: " + error.message());
  if (!std::filesystem::is_directory(folder, error)) {
    return Status::Error(folder + ": is not a folder");
  }
  if (created != nullptr) *created = made;
  return Status::Ok();
}

Status ReadFileToString(const std::string& path, std::string* content) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open: " + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) return Status::Error(path + ": cannot read (not a regular file?)");
  content->resize(static_cast<size_t>(size));
  in.seekg(0, std::ios::beg);
  in.read(content->data(), size);
  if (!in) return Status::Error(path + ": read failed");
  return Status::Ok();
}

}  // namespace edgefit
