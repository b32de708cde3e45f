#include "edgefit/scanner/truth.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "edgefit/core/atomic_file.h"
#include "edgefit/core/pose_json.h"
#include "edgefit/scanner/label_file.h"

namespace edgefit {
namespace {

using Json = nlohmann::ordered_json;

Json PoseList(const std::vector<Pose>& poses) {
  Json list = Json::array();
  for (const Pose& T : poses) list.push_back(PoseRows(T));
  return list;
}

Json SensorJson(const TruthSensor& s, const LabelCounts& c) {
  const BeamOptions& b = s.beam;
  const RangeNoiseOptions& n = s.range_noise;
  const AsBuiltOptions& a = s.as_built;
  const StationResidualOptions& r = s.station_residuals;
  Json j;
  j["name"] = s.name;
  j["beam"] = {{"sub_rays", b.sub_rays},
               {"exit_diameter", b.exit_diameter},
               {"divergence", b.divergence},
               {"mixed_return", b.mixed_return == MixedReturn::kMean ? "mean" : "strongest"},
               {"mixed_depth", b.mixed_depth}};
  j["range_noise"] = {{"signal_model", n.signal_model},
                      {"reference_reflectance", n.reference_reflectance},
                      {"max_factor", n.max_factor},
                      {"dropout_signal_none", n.dropout_signal_none},
                      {"dropout_signal_full", n.dropout_signal_full}};
  j["as_built"] = {{"enabled", a.enabled},
                   {"amplitude_min", a.amplitude_min},
                   {"amplitude_max", a.amplitude_max},
                   {"wavelength_min", a.wavelength_min},
                   {"wavelength_max", a.wavelength_max}};
  j["jackets"] = s.jackets;
  j["station_residuals"] = {{"enabled", r.enabled},
                            {"translation_min", r.translation_min},
                            {"translation_max", r.translation_max},
                            {"rotation_min", r.rotation_min},
                            {"rotation_max", r.rotation_max}};
  j["scanners_written"] = PoseList(s.T_world_scanners_written);
  j["counts"] = {{"mixed_pixel", c.mixed_pixel}, {"jacket", c.jacket}};
  return j;
}

}  // namespace

bool TruthSensor::realistic() const {
  return beam.enabled() || range_noise.signal_model || as_built.enabled || !jackets.empty() ||
         station_residuals.enabled;
}

std::vector<std::pair<std::string, double>> NamedJointValues(const KinematicModel& model,
                                                             const std::vector<double>& q) {
  std::vector<std::pair<std::string, double>> named;
  for (size_t j = 0; j < model.joints().size() && j < q.size(); ++j) {
    if (model.joints()[j].IsMoving()) named.emplace_back(model.joints()[j].name, q[j]);
  }
  return named;
}

TruthSettings MakeTruthSettings(const VirtualScanOptions& options, int scanners, bool accessories,
                                bool random_pose) {
  TruthSettings s;
  s.spacing = options.spacing;
  s.noise_sigma = options.noise_sigma;
  s.scanners = scanners;
  s.accessories = accessories;
  s.random_pose = random_pose;
  s.full_dome = options.full_dome;
  s.max_range = options.max_range;
  s.true_edge_distance = options.true_edge_distance;
  return s;
}

LabelCounts CountLabels(const VirtualScan& scan, const KinematicModel& model, int first_link) {
  LabelCounts counts;
  std::vector<uint64_t> per_link(model.links().size(), 0);
  for (const auto& labels : scan.labels) {
    for (uint16_t label : labels) {
      ++counts.cells;
      const uint16_t cls = label & kLabelMask;
      if (label & kTrueEdgeFlag) ++counts.true_edge;
      if (label & kMixedPixelFlag) ++counts.mixed_pixel;
      if (label & kJacketFlag) ++counts.jacket;
      if (cls == kLabelMissing) {
        ++counts.missing;
        continue;
      }
      ++counts.valid;
      if (cls == kLabelBackground) {
        ++counts.background;
      } else if (cls == kLabelAccessory) {
        ++counts.accessory;
      } else {
        const int link = LinkOfLabel(cls) - first_link;
        if (link >= 0 && static_cast<size_t>(link) < per_link.size()) ++counts.link, ++per_link[link];
      }
    }
  }
  for (size_t k = 0; k < per_link.size(); ++k) {
    counts.per_link.emplace_back(model.links()[k].name, per_link[k]);
  }
  return counts;
}

const char* LabelsFormatDescription() {
  return "little-endian: 'EFLB', uint32 version=1, uint32 scans S, S x (uint32 rows, uint32 "
         "cols), then per scan in file order rows*cols uint16 in the scan file's point order; "
         "0 missing, 1 background, 2 accessory, 3+k link k (model links order), "
         "| 0x8000 within true_edge_distance of a sharp link edge, | 0x4000 mixed pixel, "
         "| 0x2000 protective jacket";
}

namespace {

Json TruthToJson(const Truth& truth) {
  Json j;
  j["model"] = {{"urdf", truth.urdf}, {"attachments", truth.attachments}};
  Json joints = Json::object();
  for (const auto& [name, value] : truth.joints) joints[name] = value;
  j["joints"] = joints;
  j["T_world_base"] = PoseRows(truth.T_world_base);
  j["base"] = {{"x", truth.base_x}, {"y", truth.base_y}, {"yaw", truth.base_yaw}};
  Json scanners = Json::array();
  for (const Pose& T : truth.T_world_scanners) scanners.push_back(PoseRows(T));
  j["scanners"] = scanners;
  j["seed"] = truth.seed;
  const TruthSettings& s = truth.settings;
  j["settings"] = {{"spacing", s.spacing},         {"noise_sigma", s.noise_sigma},
                   {"scanners", s.scanners},       {"accessories", s.accessories},
                   {"random_pose", s.random_pose}, {"full_dome", s.full_dome},
                   {"max_range", s.max_range},     {"true_edge_distance", s.true_edge_distance}};
  const LabelCounts& c = truth.counts;
  Json per_link = Json::object();
  for (const auto& [name, n] : c.per_link) per_link[name] = n;
  j["counts"] = {{"cells", c.cells},           {"valid", c.valid},         {"missing", c.missing},
                 {"background", c.background}, {"accessory", c.accessory}, {"link", c.link},
                 {"true_edge", c.true_edge},   {"per_link", per_link}};
  j["labels_format"] = LabelsFormatDescription();
  if (truth.sensor.realistic()) j["sensor"] = SensorJson(truth.sensor, c);
  return j;
}

Status TruthFromJson(const Json& j, const std::string& path, Truth* truth) {
  auto fail = [&path](const std::string& what) { return Status::Error(path + ": " + what); };
  if (!j.is_object()) return fail("not a JSON object");
  Truth t;
  // Every accessor below checks the type first: nlohmann throws on a mismatch.
  if (!j.contains("joints") || !j["joints"].is_object()) return fail("missing object 'joints'");
  for (const auto& [name, value] : j["joints"].items()) {
    if (!value.is_number()) return fail("joint '" + name + "' is not a number");
    t.joints.emplace_back(name, value.get<double>());
  }
  if (!j.contains("T_world_base") || !PoseFromJson(j["T_world_base"], &t.T_world_base)) {
    return fail("'T_world_base' is not a 4x4 matrix");
  }
  if (j.contains("model") && j["model"].is_object()) {
    const Json& m = j["model"];
    if (m.contains("urdf") && m["urdf"].is_string()) t.urdf = m["urdf"].get<std::string>();
    if (m.contains("attachments") && m["attachments"].is_array()) {
      for (const Json& a : m["attachments"]) {
        if (a.is_string()) t.attachments.push_back(a.get<std::string>());
      }
    }
  }
  if (j.contains("base") && j["base"].is_object()) {
    const Json& b = j["base"];
    auto number = [&b](const char* key) {
      return b.contains(key) && b[key].is_number() ? b[key].get<double>() : 0.0;
    };
    t.base_x = number("x");
    t.base_y = number("y");
    t.base_yaw = number("yaw");
  }
  if (j.contains("scanners") && j["scanners"].is_array()) {
    for (const Json& m : j["scanners"]) {
      Pose T;
      if (!PoseFromJson(m, &T)) return fail("a scanner pose is not a 4x4 matrix");
      t.T_world_scanners.push_back(T);
    }
  }
  if (j.contains("seed") && j["seed"].is_number_unsigned()) t.seed = j["seed"].get<uint64_t>();
  if (j.contains("settings") && j["settings"].is_object()) {
    const Json& s = j["settings"];
    auto number = [&s](const char* key, double fallback) {
      return s.contains(key) && s[key].is_number() ? s[key].get<double>() : fallback;
    };
    auto flag = [&s](const char* key) {
      return s.contains(key) && s[key].is_boolean() && s[key].get<bool>();
    };
    t.settings.spacing = number("spacing", 0.0);
    t.settings.noise_sigma = number("noise_sigma", 0.0);
    t.settings.scanners = static_cast<int>(number("scanners", 0.0));
    t.settings.accessories = flag("accessories");
    t.settings.random_pose = flag("random_pose");
    t.settings.full_dome = flag("full_dome");
    t.settings.max_range = number("max_range", 0.0);
    t.settings.true_edge_distance = number("true_edge_distance", 0.0);
  }
  if (j.contains("sensor") && j["sensor"].is_object()) {
    const Json& s = j["sensor"];
    if (s.contains("name") && s["name"].is_string()) t.sensor.name = s["name"].get<std::string>();
    if (s.contains("scanners_written") && s["scanners_written"].is_array()) {
      for (const Json& m : s["scanners_written"]) {
        Pose T;
        if (!PoseFromJson(m, &T)) return fail("a written scanner pose is not a 4x4 matrix");
        t.sensor.T_world_scanners_written.push_back(T);
      }
    }
    if (s.contains("jackets") && s["jackets"].is_array()) {
      for (const Json& name : s["jackets"]) {
        if (name.is_string()) t.sensor.jackets.push_back(name.get<std::string>());
      }
    }
  }
  if (j.contains("counts") && j["counts"].is_object()) {
    const Json& c = j["counts"];
    auto count = [&c](const char* key) {
      return c.contains(key) && c[key].is_number_unsigned() ? c[key].get<uint64_t>() : 0;
    };
    t.counts.cells = count("cells");
    t.counts.valid = count("valid");
    t.counts.missing = count("missing");
    t.counts.background = count("background");
    t.counts.accessory = count("accessory");
    t.counts.link = count("link");
    t.counts.true_edge = count("true_edge");
    if (c.contains("per_link") && c["per_link"].is_object()) {
      for (const auto& [name, n] : c["per_link"].items()) {
        if (n.is_number_unsigned()) t.counts.per_link.emplace_back(name, n.get<uint64_t>());
      }
    }
  }
  *truth = std::move(t);
  return Status::Ok();
}

Status ParseJsonFile(const std::string& path, Json* j) {
  std::string text;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &text));
  *j = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j->is_discarded() || !j->is_object()) return Status::Error(path + ": not a JSON object");
  return Status::Ok();
}

}  // namespace

Status WriteTruthJson(const std::string& path, const Truth& truth) {
  return WriteStringAtomically(path, TruthToJson(truth).dump(2) + "\n");
}

Status ReadTruthJson(const std::string& path, Truth* truth) {
  Json j;
  EDGEFIT_RETURN_IF_ERROR(ParseJsonFile(path, &j));
  if (j.contains("assets")) {
    return Status::Error(path + ": the truth of a cell (several assets): read it with ReadCellTruthJson");
  }
  return TruthFromJson(j, path, truth);
}

Status WriteCellTruthJson(const std::string& path, const std::vector<CellTruthAsset>& assets) {
  Json j;
  Json list = Json::array();
  for (const CellTruthAsset& a : assets) {
    Json one;
    one["name"] = a.name;
    one["first_label"] = LinkLabel(a.first_link);
    const Json asset = TruthToJson(a.truth);
    for (auto it = asset.begin(); it != asset.end(); ++it) one[it.key()] = it.value();
    list.push_back(one);
  }
  j["assets"] = list;
  return WriteStringAtomically(path, j.dump(2) + "\n");
}

Status ReadCellTruthJson(const std::string& path, std::vector<CellTruthAsset>* assets) {
  Json j;
  EDGEFIT_RETURN_IF_ERROR(ParseJsonFile(path, &j));
  std::vector<CellTruthAsset> read;
  if (!j.contains("assets")) {  // one asset: the single-asset layout
    read.emplace_back();
    EDGEFIT_RETURN_IF_ERROR(TruthFromJson(j, path, &read.back().truth));
  } else {
    if (!j["assets"].is_array()) return Status::Error(path + ": 'assets' is not an array");
    for (const Json& a : j["assets"]) {
      CellTruthAsset one;
      if (a.is_object() && a.contains("name") && a["name"].is_string()) one.name = a["name"].get<std::string>();
      if (a.is_object() && a.contains("first_label") && a["first_label"].is_number_unsigned()) {
        one.first_link = LinkOfLabel(static_cast<uint16_t>(a["first_label"].get<unsigned>()));
      }
      EDGEFIT_RETURN_IF_ERROR(TruthFromJson(a, path + ": asset '" + one.name + "'", &one.truth));
      read.push_back(std::move(one));
    }
  }
  *assets = std::move(read);
  return Status::Ok();
}

}  // namespace edgefit
