#include "edgefit/core/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace edgefit {

MappedFile::~MappedFile() {
  if (data_ != nullptr) munmap(data_, size_);
}

Status MappedFile::Open(const std::string& path) {
  if (data_ != nullptr) munmap(data_, size_);
  data_ = nullptr;
  size_ = 0;
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Status::Error(path + ": cannot open: " + std::strerror(errno));
  struct stat info;
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    close(fd);
    return Status::Error(path + ": cannot read (not a regular file?)");
  }
  size_ = static_cast<size_t>(info.st_size);
  if (size_ > 0) {
    void* mapped = mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapped == MAP_FAILED) {
      const int error = errno;
      close(fd);
      size_ = 0;
      return Status::Error(path + ": cannot map: " + std::strerror(error));
    }
    data_ = static_cast<char*>(mapped);
    madvise(data_, size_, MADV_SEQUENTIAL);
  }
  close(fd);
  return Status::Ok();
}

void MappedFile::Release(const char* upto) {
  if (data_ == nullptr || upto <= data_) return;
  const size_t page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  const size_t bytes = (static_cast<size_t>(upto - data_) / page) * page;
  if (bytes > 0) madvise(data_, bytes, MADV_DONTNEED);
}

}  // namespace edgefit
