#include "edgefit/scanner/cell_scene.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "edgefit/core/atomic_file.h"
#include "edgefit/core/file_path.h"
#include "edgefit/core/split_mix64.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/scanner/random_joints.h"

namespace edgefit {
namespace {

std::string StringField(const nlohmann::json& a, const char* key) {
  return a.contains(key) && a[key].is_string() ? a[key].get<std::string>() : "";
}

Status LoadAsset(const nlohmann::json& a, const std::string& file, const std::string& where, uint64_t seed,
                 CellSceneAsset* asset) {
  auto fail = [&where](const std::string& what) { return Status::Error(where + ": " + what); };
  if (!a.is_object()) return fail("not a JSON object");
  asset->urdf = PathRelativeToFile(file, StringField(a, "urdf"));
  if (asset->urdf.empty()) return fail("no \"urdf\"");
  EDGEFIT_RETURN_IF_ERROR(ParseAttachSpecList(StringField(a, "attach"), &asset->attachments).WithContext(where));
  for (AttachSpec& spec : asset->attachments) spec.path = PathRelativeToFile(file, spec.path);
  EDGEFIT_RETURN_IF_ERROR(
      LoadModelWithAttachments(asset->urdf, asset->attachments, ModelLoadOptions(), &asset->model));
  if (!a.contains("base") || !a["base"].is_array() || a["base"].size() != 3) {
    return fail("\"base\" must be [x, y, yaw_deg]");
  }
  double base[3];
  for (int k = 0; k < 3; ++k) {
    if (!a["base"][k].is_number()) return fail("\"base\" must be [x, y, yaw_deg]");
    base[k] = a["base"][k].get<double>();
  }
  asset->base_x = base[0];
  asset->base_y = base[1];
  asset->base_yaw = base[2] * M_PI / 180.0;
  asset->T_world_base = PoseFromXyYaw(asset->base_x, asset->base_y, asset->base_yaw);
  const std::string posture = StringField(a, "posture"), joints = StringField(a, "joints");
  const bool random = a.contains("random_pose") && a["random_pose"].is_boolean() && a["random_pose"].get<bool>();
  if (!posture.empty() + !joints.empty() + random > 1) return fail("give at most one of posture, joints, random_pose");
  asset->q = asset->model.ZeroJoints();
  if (random) {
    if (!RandomJointValuesAboveFloor(asset->model, asset->T_world_base, 0.0, seed, &asset->q)) {
      return fail("no random posture stays above the floor");
    }
  } else if (!posture.empty()) {
    const size_t colon = posture.rfind(':');
    if (colon == std::string::npos) return fail("\"posture\": expected FILE.json:NAME");
    EDGEFIT_RETURN_IF_ERROR(LoadNamedPosture(PathRelativeToFile(file, posture.substr(0, colon)), posture.substr(colon + 1),
                                             asset->model, &asset->q)
                                .WithContext(where));
  }
  EDGEFIT_RETURN_IF_ERROR(ParseJointAssignments(joints, asset->model, &asset->q).WithContext(where));
  return asset->model.ResolveDependentJoints(&asset->q).WithContext(where + ": joint values");
}

}  // namespace

Status LoadCellScene(const std::string& path, uint64_t seed, std::vector<CellSceneAsset>* assets) {
  std::string text;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &text));
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return Status::Error(path + ": not a JSON object");
  if (!j.contains("assets") || !j["assets"].is_array() || j["assets"].empty()) {
    return Status::Error(path + ": no \"assets\" array");
  }
  std::vector<CellSceneAsset> loaded(j["assets"].size());
  for (size_t a = 0; a < loaded.size(); ++a) {
    const nlohmann::json& item = j["assets"][a];
    loaded[a].name = item.is_object() ? StringField(item, "name") : "";
    if (loaded[a].name.empty()) loaded[a].name = "asset_" + std::to_string(a + 1);
    const std::string where = path + ": asset '" + loaded[a].name + "'";
    for (size_t b = 0; b < a; ++b) {
      if (loaded[b].name == loaded[a].name) return Status::Error(where + ": the name is taken");
    }
    EDGEFIT_RETURN_IF_ERROR(LoadAsset(item, path, where, SplitMix64::StreamSeed(seed, 2000 + a), &loaded[a]));
  }
  *assets = std::move(loaded);
  return Status::Ok();
}

}  // namespace edgefit
