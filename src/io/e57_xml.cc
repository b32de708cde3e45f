#include "e57_xml.h"

#include <tinyxml2.h>

#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace edgefit {
namespace io_internal {
namespace {

using tinyxml2::XMLElement;

const char* TypeOf(const XMLElement* e) {
  const char* type = e->Attribute("type");
  return type != nullptr ? type : "";
}

bool IsType(const XMLElement* e, const char* type) { return std::string(TypeOf(e)) == type; }

// The element's text without surrounding blanks ("" when empty).
std::string Text(const XMLElement* e) {
  const char* text = e->GetText();
  std::string s = text != nullptr ? text : "";
  const size_t first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

bool ParseInt64(const std::string& s, int64_t* value) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (errno != 0 || end != s.c_str() + s.size()) return false;
  *value = static_cast<int64_t>(v);
  return true;
}

bool ParseUint64(const std::string& s, uint64_t* value) {
  if (s.empty() || s[0] == '-') return false;
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if (errno != 0 || end != s.c_str() + s.size()) return false;
  *value = static_cast<uint64_t>(v);
  return true;
}

bool ParseDouble(const std::string& s, double* value) {
  if (s.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(*value);
}

Status Bad(const std::string& where, const std::string& what) {
  return Status::Error(where + ": " + what);
}

// An Integer, ScaledInteger or Float attribute of `e`, or `fallback`.
Status Int64Attribute(const XMLElement* e, const char* attribute, int64_t fallback,
                      const std::string& where, int64_t* value) {
  const char* text = e->Attribute(attribute);
  *value = fallback;
  if (text == nullptr) return Status::Ok();
  if (!ParseInt64(text, value)) {
    return Bad(where, std::string(attribute) + "=\"" + text + "\" is not a 64-bit integer");
  }
  return Status::Ok();
}

Status DoubleAttribute(const XMLElement* e, const char* attribute, double fallback,
                       const std::string& where, double* value) {
  const char* text = e->Attribute(attribute);
  *value = fallback;
  if (text == nullptr) return Status::Ok();
  if (!ParseDouble(text, value)) {
    return Bad(where, std::string(attribute) + "=\"" + text + "\" is not a finite number");
  }
  return Status::Ok();
}

// The value of a numeric element (empty text = 0, as the standard's default).
Status Number(const XMLElement* e, const std::string& where, double* value) {
  const std::string text = Text(e);
  const std::string at = where + "/" + e->Name();
  if (IsType(e, "Float")) {
    if (text.empty()) return *value = 0.0, Status::Ok();
    if (!ParseDouble(text, value)) return Bad(at, "'" + text + "' is not a finite number");
    return Status::Ok();
  }
  if (IsType(e, "Integer") || IsType(e, "ScaledInteger")) {
    int64_t raw = 0;
    if (!text.empty() && !ParseInt64(text, &raw)) return Bad(at, "'" + text + "' is not an integer");
    double scale = 1.0, offset = 0.0;
    EDGEFIT_RETURN_IF_ERROR(DoubleAttribute(e, "scale", 1.0, at, &scale));
    EDGEFIT_RETURN_IF_ERROR(DoubleAttribute(e, "offset", 0.0, at, &offset));
    *value = static_cast<double>(raw) * scale + offset;
    return Status::Ok();
  }
  return Bad(at, std::string("expected a number, found type '") + TypeOf(e) + "'");
}

// The number child `child` of `e`, if present; `*found` says whether it was.
Status OptionalNumber(const XMLElement* e, const char* child, const std::string& where,
                      double* value, bool* found = nullptr) {
  const XMLElement* c = e != nullptr ? e->FirstChildElement(child) : nullptr;
  if (found != nullptr) *found = c != nullptr;
  if (c == nullptr) return Status::Ok();
  return Number(c, where, value);
}

Status AddFields(const XMLElement* structure, const std::string& prefix, const std::string& where,
                 std::vector<E57Field>* fields) {
  for (const XMLElement* c = structure->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string path = prefix + c->Name();
    const std::string at = where + "/" + path;
    E57Field field;
    field.name = path;
    if (IsType(c, "Structure")) {
      EDGEFIT_RETURN_IF_ERROR(AddFields(c, path + "/", where, fields));
      continue;
    }
    if (IsType(c, "Float")) {
      const char* precision = c->Attribute("precision");
      field.type = E57Field::Type::kFloat;
      field.single = precision != nullptr && std::string(precision) == "single";
    } else if (IsType(c, "Integer") || IsType(c, "ScaledInteger")) {
      field.type = IsType(c, "Integer") ? E57Field::Type::kInteger : E57Field::Type::kScaledInteger;
      EDGEFIT_RETURN_IF_ERROR(
          Int64Attribute(c, "minimum", std::numeric_limits<int64_t>::min(), at, &field.minimum));
      EDGEFIT_RETURN_IF_ERROR(
          Int64Attribute(c, "maximum", std::numeric_limits<int64_t>::max(), at, &field.maximum));
      if (field.minimum > field.maximum) return Bad(at, "minimum is above maximum");
      EDGEFIT_RETURN_IF_ERROR(DoubleAttribute(c, "scale", 1.0, at, &field.scale));
      EDGEFIT_RETURN_IF_ERROR(DoubleAttribute(c, "offset", 0.0, at, &field.offset));
      if (field.scale == 0.0) return Bad(at, "scale is 0");
    } else {
      return Bad(at, std::string("a points field of type '") + TypeOf(c) +
                         "' (edgefit reads Integer, ScaledInteger and Float fields)");
    }
    fields->push_back(field);
  }
  return Status::Ok();
}

Status ParsePose(const XMLElement* pose, const std::string& where, Pose* T) {
  T->setIdentity();
  if (pose == nullptr) return Status::Ok();
  const XMLElement* rotation = pose->FirstChildElement("rotation");
  const XMLElement* translation = pose->FirstChildElement("translation");
  if (rotation != nullptr) {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
    EDGEFIT_RETURN_IF_ERROR(OptionalNumber(rotation, "w", where + "/pose/rotation", &w));
    EDGEFIT_RETURN_IF_ERROR(OptionalNumber(rotation, "x", where + "/pose/rotation", &x));
    EDGEFIT_RETURN_IF_ERROR(OptionalNumber(rotation, "y", where + "/pose/rotation", &y));
    EDGEFIT_RETURN_IF_ERROR(OptionalNumber(rotation, "z", where + "/pose/rotation", &z));
    const Eigen::Quaterniond q(w, x, y, z);
    if (std::abs(q.norm() - 1.0) > 1e-3) {
      return Bad(where + "/pose/rotation", "the quaternion has norm " + std::to_string(q.norm()) +
                                               " (not a rotation)");
    }
    T->linear() = q.normalized().toRotationMatrix();
  }
  if (translation != nullptr) {
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      EDGEFIT_RETURN_IF_ERROR(OptionalNumber(translation, axes[k], where + "/pose/translation", &t[k]));
    }
    T->translation() = t;
  }
  return Status::Ok();
}

Status ParseScan(const XMLElement* e, const std::string& where, E57Scan* scan) {
  if (const XMLElement* name = e->FirstChildElement("name")) scan->name = Text(name);
  if (const XMLElement* guid = e->FirstChildElement("guid")) scan->guid = Text(guid);
  EDGEFIT_RETURN_IF_ERROR(ParsePose(e->FirstChildElement("pose"), where, &scan->T_world_scanner));
  if (const XMLElement* b = e->FirstChildElement("indexBounds")) {
    const std::string at = where + "/indexBounds";
    double v[4] = {0, 0, 0, 0};
    const char* names[4] = {"rowMinimum", "rowMaximum", "columnMinimum", "columnMaximum"};
    bool found[4] = {false, false, false, false};
    for (int k = 0; k < 4; ++k) EDGEFIT_RETURN_IF_ERROR(OptionalNumber(b, names[k], at, &v[k], &found[k]));
    scan->has_index_bounds = found[1] && found[3];
    scan->row_min = static_cast<int64_t>(v[0]);
    scan->row_max = static_cast<int64_t>(v[1]);
    scan->col_min = static_cast<int64_t>(v[2]);
    scan->col_max = static_cast<int64_t>(v[3]);
  }
  if (const XMLElement* l = e->FirstChildElement("colorLimits")) {
    const std::string at = where + "/colorLimits";
    const char* colours[3] = {"Red", "Green", "Blue"};
    for (int k = 0; k < 3; ++k) {
      bool found_min = false, found_max = false;
      EDGEFIT_RETURN_IF_ERROR(OptionalNumber(l, ("color" + std::string(colours[k]) + "Minimum").c_str(),
                                             at, &scan->color_min[k], &found_min));
      EDGEFIT_RETURN_IF_ERROR(OptionalNumber(l, ("color" + std::string(colours[k]) + "Maximum").c_str(),
                                             at, &scan->color_max[k], &found_max));
      scan->has_color_limits = scan->has_color_limits || found_max;
    }
  }
  if (const XMLElement* l = e->FirstChildElement("intensityLimits")) {
    bool found = false;
    EDGEFIT_RETURN_IF_ERROR(OptionalNumber(l, "intensityMinimum", where + "/intensityLimits",
                                           &scan->intensity_min));
    EDGEFIT_RETURN_IF_ERROR(OptionalNumber(l, "intensityMaximum", where + "/intensityLimits",
                                           &scan->intensity_max, &found));
    scan->has_intensity_limits = found;
  }
  const XMLElement* points = e->FirstChildElement("points");
  if (points == nullptr || !IsType(points, "CompressedVector")) {
    return Bad(where, "no points (a CompressedVector named 'points')");
  }
  const std::string at = where + "/points";
  const char* offset = points->Attribute("fileOffset");
  const char* count = points->Attribute("recordCount");
  if (offset == nullptr || !ParseUint64(offset, &scan->points.file_offset)) {
    return Bad(at, "missing or bad fileOffset");
  }
  if (count == nullptr || !ParseUint64(count, &scan->points.record_count)) {
    return Bad(at, "missing or bad recordCount");
  }
  const XMLElement* prototype = points->FirstChildElement("prototype");
  if (prototype == nullptr || !IsType(prototype, "Structure")) return Bad(at, "no prototype Structure");
  EDGEFIT_RETURN_IF_ERROR(AddFields(prototype, "", at + "/prototype", &scan->points.fields));
  if (scan->points.fields.empty()) return Bad(at, "the prototype has no fields");
  return Status::Ok();
}

std::string Real(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  return buffer;
}

std::string CData(const std::string& text) { return "<![CDATA[" + text + "]]>"; }

}  // namespace

int E57Field::Bits() const {
  if (type == Type::kFloat) return single ? 32 : 64;
  const uint64_t span = static_cast<uint64_t>(maximum) - static_cast<uint64_t>(minimum);
  int bits = 0;
  while (bits < 64 && (span >> bits) != 0) ++bits;
  return bits;
}

Status ParseE57Xml(std::string_view xml, const std::string& name, std::vector<E57Scan>* scans) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    return Status::Error(name + ": the XML section is not well-formed XML (" +
                         std::string(doc.ErrorStr() != nullptr ? doc.ErrorStr() : "") + ")");
  }
  const XMLElement* root = doc.RootElement();
  if (root == nullptr || std::string(root->Name()) != "e57Root") {
    return Status::Error(name + ": the XML section's root is not e57Root");
  }
  const XMLElement* data3d = root->FirstChildElement("data3D");
  if (data3d == nullptr) return Status::Ok();
  int index = 0;
  for (const XMLElement* e = data3d->FirstChildElement(); e != nullptr; e = e->NextSiblingElement(), ++index) {
    E57Scan scan;
    EDGEFIT_RETURN_IF_ERROR(ParseScan(e, name + ": /data3D/" + std::to_string(index), &scan));
    scans->push_back(std::move(scan));
  }
  return Status::Ok();
}

std::string E57Xml(const std::vector<E57Scan>& scans, const std::string& file_guid) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<e57Root type=\"Structure\" xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\">\n"
    << "  <formatName type=\"String\">" << CData("ASTM E57 3D Imaging Data File") << "</formatName>\n"
    << "  <guid type=\"String\">" << CData(file_guid) << "</guid>\n"
    << "  <versionMajor type=\"Integer\">1</versionMajor>\n"
    << "  <versionMinor type=\"Integer\">0</versionMinor>\n"
    << "  <e57LibraryVersion type=\"String\">" << CData("edgefit") << "</e57LibraryVersion>\n"
    << "  <coordinateMetadata type=\"String\"></coordinateMetadata>\n"
    << "  <data3D type=\"Vector\" allowHeterogeneousChildren=\"1\">\n";
  for (const E57Scan& s : scans) {
    const Eigen::Quaterniond q(s.T_world_scanner.linear());
    const Eigen::Vector3d t = s.T_world_scanner.translation();
    x << "    <vectorChild type=\"Structure\">\n"
      << "      <guid type=\"String\">" << CData(s.guid) << "</guid>\n"
      << "      <name type=\"String\">" << CData(s.name) << "</name>\n"
      << "      <pose type=\"Structure\">\n"
      << "        <rotation type=\"Structure\">\n"
      << "          <w type=\"Float\">" << Real(q.w()) << "</w>\n"
      << "          <x type=\"Float\">" << Real(q.x()) << "</x>\n"
      << "          <y type=\"Float\">" << Real(q.y()) << "</y>\n"
      << "          <z type=\"Float\">" << Real(q.z()) << "</z>\n"
      << "        </rotation>\n"
      << "        <translation type=\"Structure\">\n"
      << "          <x type=\"Float\">" << Real(t.x()) << "</x>\n"
      << "          <y type=\"Float\">" << Real(t.y()) << "</y>\n"
      << "          <z type=\"Float\">" << Real(t.z()) << "</z>\n"
      << "        </translation>\n"
      << "      </pose>\n";
    if (s.has_index_bounds) {
      x << "      <indexBounds type=\"Structure\">\n"
        << "        <rowMinimum type=\"Integer\">" << s.row_min << "</rowMinimum>\n"
        << "        <rowMaximum type=\"Integer\">" << s.row_max << "</rowMaximum>\n"
        << "        <columnMinimum type=\"Integer\">" << s.col_min << "</columnMinimum>\n"
        << "        <columnMaximum type=\"Integer\">" << s.col_max << "</columnMaximum>\n"
        << "        <returnMinimum type=\"Integer\">0</returnMinimum>\n"
        << "        <returnMaximum type=\"Integer\">0</returnMaximum>\n"
        << "      </indexBounds>\n";
    }
    if (s.has_intensity_limits) {
      x << "      <intensityLimits type=\"Structure\">\n"
        << "        <intensityMinimum type=\"Float\">" << Real(s.intensity_min) << "</intensityMinimum>\n"
        << "        <intensityMaximum type=\"Float\">" << Real(s.intensity_max) << "</intensityMaximum>\n"
        << "      </intensityLimits>\n";
    }
    if (s.has_color_limits) {
      x << "      <colorLimits type=\"Structure\">\n";
      const char* colours[3] = {"Red", "Green", "Blue"};
      for (int k = 0; k < 3; ++k) {
        x << "        <color" << colours[k] << "Minimum type=\"Integer\">" << Real(s.color_min[k])
          << "</color" << colours[k] << "Minimum>\n"
          << "        <color" << colours[k] << "Maximum type=\"Integer\">" << Real(s.color_max[k])
          << "</color" << colours[k] << "Maximum>\n";
      }
      x << "      </colorLimits>\n";
    }
    x << "      <points type=\"CompressedVector\" fileOffset=\"" << s.points.file_offset
      << "\" recordCount=\"" << s.points.record_count << "\">\n"
      << "        <prototype type=\"Structure\">\n";
    for (const E57Field& f : s.points.fields) {
      x << "          <" << f.name;
      if (f.type == E57Field::Type::kFloat) {
        x << " type=\"Float\" precision=\"" << (f.single ? "single" : "double") << "\"";
      } else {
        x << " type=\"" << (f.type == E57Field::Type::kInteger ? "Integer" : "ScaledInteger")
          << "\" minimum=\"" << f.minimum << "\" maximum=\"" << f.maximum << "\"";
        if (f.type == E57Field::Type::kScaledInteger) {
          x << " scale=\"" << Real(f.scale) << "\" offset=\"" << Real(f.offset) << "\"";
        }
      }
      x << "/>\n";
    }
    x << "        </prototype>\n"
      << "        <codecs type=\"Vector\" allowHeterogeneousChildren=\"1\"></codecs>\n"
      << "      </points>\n"
      << "    </vectorChild>\n";
  }
  x << "  </data3D>\n"
    << "  <images2D type=\"Vector\" allowHeterogeneousChildren=\"1\"></images2D>\n"
    << "</e57Root>\n";
  return x.str();
}

}  // namespace io_internal
}  // namespace edgefit
