#include "edgefit/scanner/label_file.h"

#include <cctype>
#include <cstring>

#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace {

constexpr char kMagic[4] = {'E', 'F', 'L', 'B'};
constexpr uint32_t kVersion = 1;

void PutU32(std::string* out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out->push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}
uint32_t GetU32(const unsigned char* p) {
  return uint32_t{p[0]} | (uint32_t{p[1]} << 8) | (uint32_t{p[2]} << 16) | (uint32_t{p[3]} << 24);
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) {
      return false;
    }
  }
  return true;
}

}  // namespace

Status WriteLabels(const std::string& path, const VirtualScan& scan, const std::string& scan_path) {
  const auto& scans = scan.scans.scans;
  if (scan.labels.size() != scans.size()) {
    return Status::Error(path + ": labels of " + std::to_string(scan.labels.size()) +
                         " scans for " + std::to_string(scans.size()) + " scans");
  }
  const bool row_major_file = EndsWith(scan_path, ".pcd");
  std::string data(kMagic, 4);
  PutU32(&data, kVersion);
  PutU32(&data, static_cast<uint32_t>(scans.size()));
  for (const OrganizedScan& s : scans) {
    PutU32(&data, static_cast<uint32_t>(s.rows()));
    PutU32(&data, static_cast<uint32_t>(s.cols()));
  }
  for (size_t k = 0; k < scans.size(); ++k) {
    OrganizedScan::FileOrder order = scans[k].file_order();
    if (row_major_file) order = OrganizedScan::FileOrder::kRowMajor;
    const auto& labels = scan.labels[k];
    if (labels.size() != scans[k].size()) {
      return Status::Error(path + ": scan " + std::to_string(k) + " has " +
                           std::to_string(labels.size()) + " labels for " +
                           std::to_string(scans[k].size()) + " cells");
    }
    const int cols = scans[k].cols();
    std::vector<uint16_t> in_file(labels.size());
    for (size_t i = 0; i < labels.size(); ++i) {
      // OrganizedScan::FileIndex for the chosen order.
      const size_t f = order == OrganizedScan::FileOrder::kColumnMajor
                           ? i
                           : static_cast<size_t>(scans[k].RowOf(i)) * static_cast<size_t>(cols) +
                                 static_cast<size_t>(scans[k].ColOf(i));
      in_file[f] = labels[i];
    }
    for (uint16_t v : in_file) {
      data.push_back(static_cast<char>(v & 0xff));
      data.push_back(static_cast<char>(v >> 8));
    }
  }
  return WriteStringAtomically(path, data);
}

Status ReadLabels(const std::string& path, LabelFile* labels) {
  std::string data;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &data));
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  if (data.size() < 12 || std::memcmp(p, kMagic, 4) != 0) {
    return Status::Error(path + ": not an edgefit label file (magic EFLB)");
  }
  if (GetU32(p + 4) != kVersion) {
    return Status::Error(path + ": unsupported label file version " + std::to_string(GetU32(p + 4)));
  }
  const uint64_t count = GetU32(p + 8);
  if (data.size() < 12 + 8 * count) return Status::Error(path + ": truncated header");
  LabelFile result;
  uint64_t offset = 12 + 8 * count, cells_total = 0;
  for (uint64_t k = 0; k < count; ++k) {
    result.rows.push_back(static_cast<int>(GetU32(p + 12 + 8 * k)));
    result.cols.push_back(static_cast<int>(GetU32(p + 16 + 8 * k)));
    cells_total += uint64_t{GetU32(p + 12 + 8 * k)} * GetU32(p + 16 + 8 * k);
  }
  if (data.size() != offset + 2 * cells_total) {
    return Status::Error(path + ": size " + std::to_string(data.size()) + " bytes, expected " +
                         std::to_string(offset + 2 * cells_total));
  }
  for (uint64_t k = 0; k < count; ++k) {
    const size_t n = static_cast<size_t>(result.rows[k]) * static_cast<size_t>(result.cols[k]);
    std::vector<uint16_t> v(n);
    for (size_t i = 0; i < n; ++i, offset += 2) {
      v[i] = static_cast<uint16_t>(p[offset] | (p[offset + 1] << 8));
    }
    result.labels.push_back(std::move(v));
  }
  *labels = std::move(result);
  return Status::Ok();
}

}  // namespace edgefit
