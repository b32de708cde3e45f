#include "e57_pages.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "crc32c.h"

namespace edgefit {
namespace io_internal {
namespace {

// Pages read at once: 256 KiB, few system calls on a multi-GB file.
constexpr uint64_t kChunkPages = 256;

uint32_t StoredChecksum(const char* page) {
  const auto* b = reinterpret_cast<const uint8_t*>(page + kE57PageDataBytes);
  return (uint32_t{b[0]} << 24) | (uint32_t{b[1]} << 16) | (uint32_t{b[2]} << 8) | uint32_t{b[3]};
}

}  // namespace

E57PageReader::E57PageReader(std::string_view memory, std::string name)
    : name_(std::move(name)), memory_(memory), size_(memory.size()) {}

E57PageReader::~E57PageReader() {
  if (fd_ >= 0) ::close(fd_);
}

Status E57PageReader::Open(const std::string& path) {
  name_ = path;
  fd_ = ::open(path.c_str(), O_RDONLY);
  if (fd_ < 0) return Status::Error(path + ": cannot open: " + std::strerror(errno));
  struct stat st;
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    return Status::Error(path + ": cannot read (not a regular file?)");
  }
  size_ = static_cast<uint64_t>(st.st_size);
  return Status::Ok();
}

Status E57PageReader::CheckSize() const {
  if (size_ == 0) return Status::Error(name_ + ": empty file");
  if (size_ % kE57PageBytes != 0) {
    return Status::Error(name_ + ": " + std::to_string(size_) +
                         " bytes is not a whole number of 1024-byte E57 pages (file truncated?)");
  }
  return Status::Ok();
}

Status E57PageReader::LoadChunk(uint64_t first_page) {
  const uint64_t pages = std::min(kChunkPages, size_ / kE57PageBytes - first_page);
  const size_t bytes = static_cast<size_t>(pages * kE57PageBytes);
  chunk_.resize(bytes);
  const uint64_t offset = first_page * kE57PageBytes;
  if (fd_ >= 0) {
    size_t done = 0;
    while (done < bytes) {
      const ssize_t got = ::pread(fd_, chunk_.data() + done, bytes - done,
                                  static_cast<off_t>(offset + done));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        chunk_pages_ = 0;
        return Status::Error(name_ + ": read failed at byte " + std::to_string(offset + done));
      }
      done += static_cast<size_t>(got);
    }
  } else {
    std::memcpy(chunk_.data(), memory_.data() + offset, bytes);
  }
  for (uint64_t k = 0; k < pages; ++k) {
    const char* page = chunk_.data() + k * kE57PageBytes;
    if (Crc32c(page, kE57PageDataBytes) != StoredChecksum(page)) {
      chunk_pages_ = 0;
      return Status::Error(name_ + ": page " + std::to_string(first_page + k) +
                           " (bytes " + std::to_string((first_page + k) * kE57PageBytes) + "-" +
                           std::to_string((first_page + k + 1) * kE57PageBytes - 1) +
                           ") fails its CRC-32C checksum (file damaged)");
    }
  }
  chunk_first_page_ = first_page;
  chunk_pages_ = pages;
  return Status::Ok();
}

Status E57PageReader::Read(uint64_t logical, size_t n, void* out) {
  if (logical > logical_size() || n > logical_size() - logical) {
    return Status::Error(name_ + ": reading " + std::to_string(n) + " bytes at byte " +
                         std::to_string(E57Physical(logical)) + " runs past the end of the file (" +
                         std::to_string(size_) + " bytes; truncated?)");
  }
  char* dst = static_cast<char*>(out);
  while (n > 0) {
    const uint64_t page = logical / kE57PageDataBytes;
    if (page < chunk_first_page_ || page >= chunk_first_page_ + chunk_pages_) {
      EDGEFIT_RETURN_IF_ERROR(LoadChunk(page));
    }
    const uint64_t in_page = logical % kE57PageDataBytes;
    const size_t take = static_cast<size_t>(std::min<uint64_t>(n, kE57PageDataBytes - in_page));
    std::memcpy(dst, chunk_.data() + (page - chunk_first_page_) * kE57PageBytes + in_page, take);
    dst += take;
    logical += take;
    n -= take;
  }
  return Status::Ok();
}

void E57PageWriter::Write(const void* data, size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const size_t take = std::min<size_t>(n, kE57PageDataBytes - page_.size());
    page_.insert(page_.end(), p, p + take);
    p += take;
    n -= take;
    logical_ += take;
    if (page_.size() == kE57PageDataBytes) FlushPage();
  }
}

void E57PageWriter::WriteZeros(uint64_t n) {
  static const char kZeros[256] = {};
  while (n > 0) {
    const size_t take = static_cast<size_t>(std::min<uint64_t>(n, sizeof(kZeros)));
    Write(kZeros, take);
    n -= take;
  }
}

void E57PageWriter::FlushPage() {
  page_.resize(kE57PageDataBytes, '\0');
  const uint32_t crc = Crc32c(page_.data(), kE57PageDataBytes);
  const char stored[4] = {static_cast<char>(crc >> 24), static_cast<char>(crc >> 16),
                          static_cast<char>(crc >> 8), static_cast<char>(crc)};
  out_->write(page_.data(), static_cast<std::streamsize>(kE57PageDataBytes));
  out_->write(stored, 4);
  page_.clear();
}

void E57PageWriter::Finish() {
  if (!page_.empty()) {
    logical_ += kE57PageDataBytes - page_.size();
    FlushPage();
  }
}

}  // namespace io_internal
}  // namespace edgefit
