#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "edgefit/core/mapped_file.h"
#include "edgefit/io/ptx.h"
#include "edgefit/io/ptx_layout.h"
#include "read_common.h"
#include "text_parse.h"

namespace edgefit {
namespace {

using io_internal::AtLine;
using io_internal::Excerpt;
using io_internal::LineCursor;
using io_internal::OnlyBlanks;
using io_internal::ParseInt;
using io_internal::ParseReal;

// Lines per OpenMP work item: large enough to amortize scheduling, small
// enough to balance two to a few dozen threads on a 5 M point scan.
constexpr int64_t kLinesPerBlock = 16384;
// Shortest possible point line, "0 0 0 0\n": bounds the point count a file
// of a given size can hold, so a corrupt header cannot trigger a huge allocation.
constexpr int64_t kMinPointLineBytes = 8;

// One header line of `count` finite numbers.
Status ParseHeaderNumbers(const std::string& name, const char* what, int count, LineCursor* cursor,
                          double* values) {
  const char *b, *e;
  if (!cursor->Next(&b, &e)) {
    return Status::Error(AtLine(name, cursor->line() + 1) + "file ends inside a scan header (expected " +
                         what + ")");
  }
  const char* p = b;
  for (int i = 0; i <= count; ++i) {
    if (i == count ? !OnlyBlanks(p, e) : !ParseReal(&p, e, &values[i])) {
      return Status::Error(AtLine(name, cursor->line()) + "expected " + std::to_string(count) +
                           " numbers (" + what + "), got '" + Excerpt(b, e) + "'");
    }
    if (i < count && !std::isfinite(values[i])) {
      return Status::Error(AtLine(name, cursor->line()) + "non-finite number in the " + what);
    }
  }
  return Status::Ok();
}

Status ParseHeaderSize(const std::string& name, const char* what, LineCursor* cursor, int* size) {
  const char *b, *e;
  if (!cursor->Next(&b, &e)) {
    return Status::Error(AtLine(name, cursor->line() + 1) + "file ends inside a scan header (expected " +
                         what + ")");
  }
  const char* p = b;
  int64_t value = 0;
  if (!ParseInt(&p, e, &value) || !OnlyBlanks(p, e) || value <= 0 || value > INT_MAX) {
    return Status::Error(AtLine(name, cursor->line()) + "expected a positive integer (" + what +
                         "), got '" + Excerpt(b, e) + "'");
  }
  *size = static_cast<int>(value);
  return Status::Ok();
}

// The 4x4 matrix, rows of T_world_scanner^T: lines 1-3 = rotation columns
// with a trailing 0, line 4 = translation with a trailing 1.
Status ParseMatrix(const std::string& name, LineCursor* cursor, Pose* T_world_scanner) {
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    double v[4];
    EDGEFIT_RETURN_IF_ERROR(ParseHeaderNumbers(name, "4x4 matrix row", 4, cursor, v));
    for (int c = 0; c < 4; ++c) M(r, c) = v[c];
  }
  const int64_t last = cursor->line();
  if (std::abs(M(0, 3)) > 1e-6 || std::abs(M(1, 3)) > 1e-6 || std::abs(M(2, 3)) > 1e-6 ||
      std::abs(M(3, 3) - 1.0) > 1e-6) {
    return Status::Error(AtLine(name, last) + "the 4x4 matrix must end in columns 0 0 0 1 "
                         "(row-vector convention, translation on the last line)");
  }
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>().transpose();
  if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-4 || R.determinant() < 0.0) {
    return Status::Error(AtLine(name, last) + "the 4x4 matrix is not a rigid transform");
  }
  T_world_scanner->setIdentity();
  T_world_scanner->linear() = R;
  T_world_scanner->translation() = M.block<1, 3>(3, 0).transpose();
  return Status::Ok();
}

struct LineError {
  int64_t line = -1;
  std::string message;
};

// Parses point line `k` of the block at [p, e) into cell k of `scan`.
bool ParsePointLine(const char* p, const char* e, bool color, size_t k, OrganizedScan* scan,
                    std::string* error) {
  float v[4];
  for (int k = 0; k < 4; ++k) {
    // Some exporters write a missing return as a bare "0 0 0".
    if (k == 3 && v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f && OnlyBlanks(p, e)) return true;
    if (!ParseReal(&p, e, &v[k])) {
      *error = color ? "expected 7 numbers (x y z intensity r g b)" : "expected 4 numbers (x y z intensity)";
      return false;
    }
  }
  if (color) {
    int rgb[3];
    for (int& c : rgb) {
      if (!ParseInt(&p, e, &c) || c < 0 || c > 255) {
        *error = "expected colour integers 0..255 after x y z intensity";
        return false;
      }
    }
    scan->SetColor(k, {static_cast<uint8_t>(rgb[0]), static_cast<uint8_t>(rgb[1]),
                       static_cast<uint8_t>(rgb[2])});
  }
  if (!OnlyBlanks(p, e)) {
    *error = color ? "more than 7 numbers on a point line" : "more than 4 numbers on a point line";
    return false;
  }
  if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) || !std::isfinite(v[3])) {
    *error = "non-finite coordinate or intensity";
    return false;
  }
  if (v[0] != 0.0f || v[1] != 0.0f || v[2] != 0.0f) {  // 0 0 0 = no return
    scan->SetPoint(k, Eigen::Vector3f(v[0], v[1], v[2]), v[3]);
  }
  return true;
}

// The points of one scan: locate the lines (sequential memchr), then parse
// blocks of lines in parallel into cells in file order.
Status ParsePoints(const std::string& name, int scan_number, LineCursor* cursor,
                   OrganizedScan* scan) {
  const int64_t n = static_cast<int64_t>(scan->size());
  const int64_t first_line = cursor->line() + 1;
  const char* p = cursor->position();
  const char* end = cursor->end();
  std::vector<const char*> block_starts;
  block_starts.reserve(static_cast<size_t>(n / kLinesPerBlock + 1));
  for (int64_t k = 0; k < n; ++k) {
    if (p >= end) {
      return Status::Error(AtLine(name, first_line + k) + "scan " + std::to_string(scan_number) +
                           " ends after " + std::to_string(k) + " of " + std::to_string(n) +
                           " points (file truncated?)");
    }
    if (k % kLinesPerBlock == 0) block_starts.push_back(p);
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    p = nl != nullptr ? nl + 1 : end;
  }
  const char* data_end = p;
  // Colour or not, from the token count of the first point line that is
  // not a bare "0 0 0" (missing return).
  LineCursor lines(block_starts[0], data_end, first_line);
  const char *b, *e;
  size_t tokens = 3;
  while (tokens == 3 && lines.Next(&b, &e)) tokens = io_internal::SplitTokens(b, e).size();
  if (tokens != 4 && tokens != 7 && tokens != 3) {
    return Status::Error(AtLine(name, lines.line()) + "expected 4 (x y z intensity) or 7 (x y z intensity r g b) "
                         "numbers on a point line, got " + std::to_string(tokens));
  }
  const bool color = tokens == 7;
  if (color) scan->EnableColor();
  const int64_t blocks = static_cast<int64_t>(block_starts.size());
  std::vector<LineError> errors(static_cast<size_t>(blocks));
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t b = 0; b < blocks; ++b) {
    const char* q = block_starts[static_cast<size_t>(b)];
    const int64_t k_end = std::min(n, (b + 1) * kLinesPerBlock);
    for (int64_t k = b * kLinesPerBlock; k < k_end; ++k) {
      const char* nl = static_cast<const char*>(std::memchr(q, '\n', static_cast<size_t>(data_end - q)));
      const char* e = nl != nullptr ? nl : data_end;
      std::string error;
      if (!ParsePointLine(q, e, color, static_cast<size_t>(k), scan, &error)) {
        errors[static_cast<size_t>(b)] = {first_line + k, error + ", got '" + Excerpt(q, e) + "'"};
        break;
      }
      q = e + 1;
    }
  }
  for (const LineError& error : errors) {  // the first bad line wins
    if (error.line >= 0) return Status::Error(AtLine(name, error.line) + error.message);
  }
  *cursor = LineCursor(data_end, end, first_line + n);
  return Status::Ok();
}

}  // namespace

Status ParsePtx(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans, const std::function<void(const char*)>& parsed_up_to) {
  ScanSet parsed;
  LineCursor cursor(content.data(), content.data() + content.size());
  while (true) {
    // Blank lines between scans and at the end are tolerated.
    const char *b, *e;
    const char* before = cursor.position();
    const int64_t line_before = cursor.line();
    if (!cursor.NextNonBlank(&b, &e)) break;
    cursor = LineCursor(b, cursor.end(), line_before + 1 + std::count(before, b, '\n'));
    const int scan_number = static_cast<int>(parsed.scans.size()) + 1;
    int first = 0, second = 0;
    EDGEFIT_RETURN_IF_ERROR(ParseHeaderSize(name, "number of columns", &cursor, &first));
    EDGEFIT_RETURN_IF_ERROR(ParseHeaderSize(name, "number of rows", &cursor, &second));
    double ignored[3];
    EDGEFIT_RETURN_IF_ERROR(ParseHeaderNumbers(name, "scanner position", 3, &cursor, ignored));
    for (const char* axis : {"scanner X axis", "scanner Y axis", "scanner Z axis"}) {
      EDGEFIT_RETURN_IF_ERROR(ParseHeaderNumbers(name, axis, 3, &cursor, ignored));
    }
    Pose T_world_scanner = Pose::Identity();
    EDGEFIT_RETURN_IF_ERROR(ParseMatrix(name, &cursor, &T_world_scanner));
    const int64_t n = static_cast<int64_t>(first) * second;
    const int64_t left = cursor.end() - cursor.position();
    if (n > (left + 1) / kMinPointLineBytes) {
      return Status::Error(AtLine(name, cursor.line() - 9) + "scan " + std::to_string(scan_number) +
                           " header promises " + std::to_string(first) + " x " + std::to_string(second) +
                           " points but only " + std::to_string(left) + " bytes follow (file truncated?)");
    }
    // Cells in file order first (cell index == line index); layout after.
    OrganizedScan in_file_order(second, first);
    if (!options.intensity) in_file_order.DropIntensity();  // before the points: never held
    in_file_order.set_T_world_scanner(T_world_scanner);
    EDGEFIT_RETURN_IF_ERROR(ParsePoints(name, scan_number, &cursor, &in_file_order));
    if (parsed_up_to) parsed_up_to(cursor.position());
    const PtxLayout layout = options.detect_ptx_layout
                                 ? DetectPtxLayout(in_file_order, first, second)
                                 : StandardPtxLayout(first, second);
    parsed.scans.push_back(ApplyPtxLayout(std::move(in_file_order), layout));
    parsed.sources.push_back(name);
  }
  if (parsed.scans.empty()) return Status::Error(name + ": no scans (empty file)");
  // Syntax errors anywhere in the file come first; then per-scan checks.
  for (size_t i = 0; i < parsed.scans.size(); ++i) {
    EDGEFIT_RETURN_IF_ERROR(
        io_internal::FinishScan(name + ": scan " + std::to_string(i + 1), options, &parsed.scans[i]));
  }
  for (size_t i = 0; i < parsed.scans.size(); ++i) {
    scans->scans.push_back(std::move(parsed.scans[i]));
    scans->sources.push_back(std::move(parsed.sources[i]));
  }
  return Status::Ok();
}

Status ReadPtx(const std::string& path, const ReadOptions& options, ScanSet* scans) {
  MappedFile file;
  EDGEFIT_RETURN_IF_ERROR(file.Open(path));
  return ParsePtx(file.view(), path, options, scans,
                  [&file](const char* upto) { file.Release(upto); });
}

}  // namespace edgefit
