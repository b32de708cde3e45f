#include "edgefit/io/scan_io.h"

#include <algorithm>
#include <cctype>

#include "edgefit/io/depth_png.h"
#include "edgefit/io/e57.h"
#include "edgefit/io/pcd.h"
#include "edgefit/io/ply.h"
#include "edgefit/io/ptx.h"

namespace edgefit {
namespace {

enum class Format { kPtx, kPcd, kPly, kE57, kPng, kUnknown };

Format FormatOf(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return Format::kUnknown;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "ptx") return Format::kPtx;
  if (ext == "pcd") return Format::kPcd;
  if (ext == "ply") return Format::kPly;
  if (ext == "e57") return Format::kE57;
  if (ext == "png") return Format::kPng;
  return Format::kUnknown;
}

Status Unknown(const std::string& path) {
  return Status::Error(path + ": unknown scan format (expected a .ptx, .pcd, .ply or .e57 file, or a 16-bit depth .png)");
}

}  // namespace

Status ReadScans(const std::string& path, const ReadOptions& options, ScanSet* scans) {
  switch (FormatOf(path)) {
    case Format::kPtx: return ReadPtx(path, options, scans);
    case Format::kPcd: return ReadPcd(path, options, scans);
    case Format::kPly: return ReadPly(path, options, scans);
    case Format::kE57: return ReadE57(path, options, scans);
    case Format::kPng: return ReadDepthPng(path, options, scans);
    case Format::kUnknown: break;
  }
  return Unknown(path);
}

Status WriteScans(const std::string& path, const ScanSet& scans, const WriteOptions& options) {
  switch (FormatOf(path)) {
    case Format::kPtx: return WritePtx(path, scans);
    case Format::kPcd:
      if (scans.scans.size() != 1) {
        return Status::Error(path + ": a PCD file holds one scan, got " + std::to_string(scans.scans.size()));
      }
      return WritePcd(path, scans.scans[0], options);
    case Format::kPly: return WritePly(path, scans, options);
    case Format::kE57: return WriteE57(path, scans);
    case Format::kPng:
      return Status::Error(path + ": depth PNGs are read, not written (write .pcd, .ptx or .e57)");
    case Format::kUnknown: break;
  }
  return Unknown(path);
}

}  // namespace edgefit
