#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <string>
#include <vector>

#include "binary_field.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/ply.h"
#include "read_common.h"
#include "text_parse.h"

namespace edgefit {
namespace {

using io_internal::AtLine;
using io_internal::LineCursor;
using io_internal::ScalarType;

struct PlyProperty {
  std::string name;  // lower case
  ScalarType type = ScalarType::kFloat32;
  bool list = false;
  int offset = 0;  // bytes into a binary record (scalar properties only)
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  std::vector<PlyProperty> properties;
  int record_bytes = 0;
  bool has_list = false;
};

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

Status ParseHeader(const std::string& name, LineCursor* cursor, std::string* format,
                   std::vector<PlyElement>* elements) {
  const char *b, *e;
  if (!cursor->Next(&b, &e) || io_internal::SplitTokens(b, e) != std::vector<std::string_view>{"ply"}) {
    return Status::Error(name + ": not a PLY file (first line is not 'ply')");
  }
  while (true) {
    if (!cursor->Next(&b, &e)) return Status::Error(name + ": header has no end_header (truncated?)");
    const auto t = io_internal::SplitTokens(b, e);
    const std::string where = AtLine(name, cursor->line());
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format") {
      if (t.size() != 3 || (t[1] != "ascii" && t[1] != "binary_little_endian" && t[1] != "binary_big_endian")) {
        return Status::Error(where + "unknown format line '" + io_internal::Excerpt(b, e) + "'");
      }
      *format = std::string(t[1]);
    } else if (t[0] == "element") {
      int64_t count = -1;
      const char* p = t.size() == 3 ? t[2].data() : e;
      if (t.size() != 3 || !io_internal::ParseInt(&p, e, &count) || count < 0 || count > INT_MAX) {
        return Status::Error(where + "expected 'element <name> <count>' with 0 <= count < 2^31");
      }
      elements->push_back({std::string(t[1]), count, {}, 0, false});
    } else if (t[0] == "property") {
      if (elements->empty()) return Status::Error(where + "property before any element");
      PlyElement& element = elements->back();
      PlyProperty property;
      ScalarType ignored;
      if (t.size() == 5 && t[1] == "list" && io_internal::PlyScalarType(std::string(t[2]), &ignored) &&
          io_internal::PlyScalarType(std::string(t[3]), &property.type)) {
        property.list = true;
        property.name = Lower(t[4]);
        element.has_list = true;
      } else if (t.size() == 3 && io_internal::PlyScalarType(std::string(t[1]), &property.type)) {
        property.name = Lower(t[2]);
        property.offset = element.record_bytes;
        element.record_bytes += io_internal::ScalarSize(property.type);
      } else {
        return Status::Error(where + "bad property line '" + io_internal::Excerpt(b, e) + "'");
      }
      element.properties.push_back(property);
    } else {
      return Status::Error(where + "unknown PLY header keyword '" + std::string(t[0]) + "'");
    }
  }
  if (format->empty()) return Status::Error(name + ": no format line in the header");
  return Status::Ok();
}

int FindProperty(const PlyElement& element, std::initializer_list<const char*> names) {
  for (size_t i = 0; i < element.properties.size(); ++i) {
    for (const char* n : names) {
      if (element.properties[i].name == n) return static_cast<int>(i);
    }
  }
  return -1;
}

}  // namespace

Status ParsePly(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans) {
  LineCursor cursor(content.data(), content.data() + content.size());
  std::string format;
  std::vector<PlyElement> elements;
  EDGEFIT_RETURN_IF_ERROR(ParseHeader(name, &cursor, &format, &elements));
  const bool ascii = format == "ascii";
  const bool swap = !ascii && (format == "binary_little_endian") != io_internal::HostIsLittleEndian();
  const char* data = cursor.position();
  const char* end = cursor.end();
  // Skip the elements before the vertices.
  size_t v = 0;
  for (; v < elements.size() && elements[v].name != "vertex"; ++v) {
    const PlyElement& element = elements[v];
    if (ascii) {
      const char *b, *e;
      for (int64_t k = 0; k < element.count; ++k) {
        if (!cursor.Next(&b, &e)) return Status::Error(name + ": file ends inside element " + element.name);
      }
      data = cursor.position();
    } else if (element.has_list) {
      return Status::Error(name + ": binary element '" + element.name +
                           "' with list properties before the vertices is unsupported");
    } else {
      if (element.count * element.record_bytes > end - data) {
        return Status::Error(name + ": file ends inside element " + element.name + " (truncated?)");
      }
      data += element.count * element.record_bytes;
    }
  }
  if (v == elements.size()) return Status::Error(name + ": no vertex element");
  const PlyElement& vertex = elements[v];
  if (vertex.has_list) return Status::Error(name + ": list properties in the vertex element are unsupported");
  const int ix = FindProperty(vertex, {"x"}), iy = FindProperty(vertex, {"y"}), iz = FindProperty(vertex, {"z"});
  const int ii = FindProperty(vertex, {"intensity", "scalar_intensity"});
  const int ir = FindProperty(vertex, {"red"}), ig = FindProperty(vertex, {"green"}), ib = FindProperty(vertex, {"blue"});
  if (ix < 0 || iy < 0 || iz < 0) return Status::Error(name + ": vertex element lacks x, y or z");
  const bool color = ir >= 0 && ig >= 0 && ib >= 0;
  const int64_t n = vertex.count;
  const int64_t left = end - data;
  if (ascii ? n > (left + 1) / 2 : n * vertex.record_bytes > left) {
    return Status::Error(name + ": header promises " + std::to_string(n) + " vertices but only " +
                         std::to_string(left) + " bytes follow (file truncated?)");
  }
  OrganizedScan scan(1, static_cast<int>(n));
  scan.set_organized(false);
  if (color) scan.EnableColor();
  const size_t np = vertex.properties.size();
  std::vector<double> values(np);
  cursor = LineCursor(data, end, cursor.line() + 1);
  for (int64_t k = 0; k < n; ++k) {
    if (ascii) {
      const char *b, *e;
      if (!cursor.Next(&b, &e)) {
        return Status::Error(AtLine(name, cursor.line() + 1) + "file ends after " + std::to_string(k) + " of " +
                             std::to_string(n) + " vertices (truncated?)");
      }
      const char* p = b;
      for (double& value : values) {
        if (!io_internal::ParseReal(&p, e, &value)) {
          return Status::Error(AtLine(name, cursor.line()) + "expected " + std::to_string(np) + " numbers, got '" +
                               io_internal::Excerpt(b, e) + "'");
        }
      }
      if (!io_internal::OnlyBlanks(p, e)) {
        return Status::Error(AtLine(name, cursor.line()) + "more than " + std::to_string(np) + " numbers on a vertex line");
      }
    } else {
      const char* record = data + k * vertex.record_bytes;
      for (size_t i = 0; i < np; ++i) {
        values[i] = io_internal::DecodeScalar(record + vertex.properties[i].offset, vertex.properties[i].type, swap);
      }
    }
    const Eigen::Vector3d p(values[ix], values[iy], values[iz]);
    const double intensity = ii >= 0 ? values[ii] : 0.0;
    if (!p.allFinite() || !std::isfinite(intensity)) {
      return Status::Error(name + ": vertex " + std::to_string(k + 1) + ": non-finite coordinate or intensity");
    }
    scan.SetPoint(static_cast<size_t>(k), p.cast<float>(), static_cast<float>(intensity));
    if (color) {
      auto channel = [&](int i) {
        return static_cast<uint8_t>(std::clamp(std::lround(values[i]), 0L, 255L));
      };
      scan.SetColor(static_cast<size_t>(k), {channel(ir), channel(ig), channel(ib)});
    }
  }
  EDGEFIT_RETURN_IF_ERROR(io_internal::FinishScan(name, options, &scan));
  scans->scans.push_back(std::move(scan));
  scans->sources.push_back(name);
  return Status::Ok();
}

Status ReadPly(const std::string& path, const ReadOptions& options, ScanSet* scans) {
  std::string content;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &content));
  return ParsePly(content, path, options, scans);
}

}  // namespace edgefit
