// A file read through the page cache instead of a copy on the heap: text
// readers that parse a file front to back (PTX) map it, and let go of the
// pages they are done with, so that reading a scan does not hold the whole
// file and the scan at once.
#ifndef EDGEFIT_CORE_MAPPED_FILE_H_
#define EDGEFIT_CORE_MAPPED_FILE_H_

#include <string>
#include <string_view>

#include "edgefit/core/status.h"

namespace edgefit {

class MappedFile {
 public:
  MappedFile() = default;
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  // Maps a regular file read-only; an empty file maps to an empty view.
  // Fails with one line naming the file when it cannot be opened or mapped.
  Status Open(const std::string& path);
  std::string_view view() const { return {data_, size_}; }
  // The pages wholly before `upto` (a pointer into view()) leave memory;
  // reading them again reads the file again.
  void Release(const char* upto);

 private:
  char* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace edgefit

#endif  // EDGEFIT_CORE_MAPPED_FILE_H_
