// Reads a YAML file with yaml-cpp and parses it: a file that does not open,
// does not parse or does not convert is one Status naming the file.
#ifndef EDGEFIT_SRC_IO_YAML_FILE_H_
#define EDGEFIT_SRC_IO_YAML_FILE_H_

#include <yaml-cpp/yaml.h>

#include <exception>
#include <string>

#include "edgefit/core/status.h"

namespace edgefit {

// `parse(root, out)` fills *out; `what` names the expected content ("a
// camera_info YAML file"). On failure *out is reset to T().
template <typename T, typename Parse>
Status ReadYamlFile(const std::string& path, const std::string& what, Parse parse, T* out) {
  *out = T();
  Status status = Status::Ok();
  try {
    status = parse(YAML::LoadFile(path), out);
  } catch (const YAML::BadFile&) {
    status = Status::Error("cannot open the file");
  } catch (const std::exception& e) {  // yaml-cpp's parser and conversion errors
    status = Status::Error("not " + what + ": " + e.what());
  }
  if (!status.ok()) {
    *out = T();
    return Status::Error(path + ": " + status.message());
  }
  return Status::Ok();
}

}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_YAML_FILE_H_
