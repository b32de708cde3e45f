// edgefit cell: every instance of several models in the scans of one cell
// (pipeline/cell_fit.h), each fitted, its points removed before the next.
//   edgefit cell --models=M.json --scan=F[,F...] --out=cell.json [--out_dir=D]
//                [--out_background=B.e57] [--truth=cell_truth.json] [fit flags]
// M.json (paths relative to it):
//   {"models": [{"name": "robot", "urdf": "robot.urdf", "attach": "gun.urdf@tool0",
//                "kind": "auto", "count": 2}, {"name": "conveyor", ..., "count": "every"}]}
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "fit_result_file.h"
#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/core/file_path.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/cell_fit.h"
#include "edgefit/pipeline/result_json.h"
#include "edgefit/scanner/truth.h"
#include "fit_flags.h"

DEFINE_string(models, "",
              "cell: the models to look for, a JSON file {\"models\": [{\"name\", \"urdf\", "
              "\"attach\", \"kind\", \"count\": N or \"every\"}]} (paths relative to it).");
DECLARE_string(out_background);
DECLARE_double(background_distance_mm);

namespace edgefit::tools {
namespace {

using nlohmann::json;

struct LoadedModel {
  std::string name, urdf;
  std::vector<AttachSpec> specs;
  KinematicModel model;
  AssetKind kind = AssetKind::kArticulated;
  int count = 0;
};

Status LoadModels(const std::string& path, std::vector<LoadedModel>* models) {
  std::string text;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &text));
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object() || !j.contains("models") || !j["models"].is_array() ||
      j["models"].empty()) {
    return Status::Error(path + ": expected {\"models\": [...]} with at least one model");
  }
  std::vector<LoadedModel> loaded(j["models"].size());
  for (size_t m = 0; m < loaded.size(); ++m) {
    const json& e = j["models"][m];
    LoadedModel& l = loaded[m];
    auto text_of = [&e](const char* key) {
      return e.is_object() && e.contains(key) && e[key].is_string() ? e[key].get<std::string>()
                                                                    : "";
    };
    l.name = text_of("name").empty() ? "model_" + std::to_string(m + 1) : text_of("name");
    const std::string where = path + ": model '" + l.name + "'";
    l.urdf = PathRelativeToFile(path, text_of("urdf"));
    if (l.urdf.empty()) return Status::Error(where + ": no \"urdf\"");
    EDGEFIT_RETURN_IF_ERROR(ParseAttachSpecList(text_of("attach"), &l.specs).WithContext(where));
    for (AttachSpec& spec : l.specs) spec.path = PathRelativeToFile(path, spec.path);
    EDGEFIT_RETURN_IF_ERROR(
        LoadModelWithAttachments(l.urdf, l.specs, ModelLoadOptions(), &l.model));
    EDGEFIT_RETURN_IF_ERROR(
        ChooseAssetKind(text_of("kind").empty() ? "auto" : text_of("kind"), l.model, &l.kind)
            .WithContext(where));
    const json count = e.is_object() && e.contains("count") ? e["count"] : json("every");
    if (count.is_string() && count.get<std::string>() == "every") {
      l.count = 0;
    } else if (count.is_number_integer() && count.get<int>() >= 1 && count.get<int>() <= 64) {
      l.count = count.get<int>();
    } else {
      return Status::Error(where + ": \"count\" must be 1..64 or \"every\"");
    }
  }
  *models = std::move(loaded);
  return Status::Ok();
}

int RunCell(const Command& command) {
  if (FLAGS_models.empty()) return BadInput(command, "--models is required");
  if (FLAGS_scan.empty()) return BadInput(command, "--scan is required");
  if (FLAGS_out.empty()) return BadInput(command, "--out is required");
  if (!(FLAGS_background_distance_mm > 0.0))
    return BadInput(command, "--background_distance_mm must be > 0");
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckFitFlags());
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputPaths({FLAGS_out, FLAGS_out_background}));
  if (!FLAGS_out_dir.empty())
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputFolder(FLAGS_out_dir));
  CellOptions options;
  bool has_roi = false;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, RoiFromFlags(&options.roi_world, &has_roi));
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  const auto start = std::chrono::steady_clock::now();

  std::vector<LoadedModel> loaded;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, LoadModels(FLAGS_models, &loaded));
  std::vector<CellModel> models;
  for (const LoadedModel& l : loaded) {
    CellModel m;
    m.name = l.name;
    m.model = &l.model;
    m.count = l.count;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, FitOptionsFromFlags(l.kind, &m.options));
    models.push_back(std::move(m));
  }
  ScanSet scans;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadScanList(FLAGS_scan, !FLAGS_out_background.empty(), &scans));
  std::vector<CellTruthAsset> truth;
  if (!FLAGS_truth.empty())
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadCellTruthJson(FLAGS_truth, &truth));
  const double load_seconds = SecondsSince(start);

  options.removal.distance = FLAGS_background_distance_mm * 1e-3;
  CellResult cell;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, FitCell(models, options, &Progress, &scans, &cell));

  // Outputs: each atomic; a later failure removes the earlier ones.
  std::vector<std::string> written;
  bool made_out_dir = false;
  auto fail = [&](const Status& status) {
    for (const std::string& path : written) std::remove(path.c_str());
    if (made_out_dir) std::remove(FLAGS_out_dir.c_str());  // made by this run, empty again
    return BadInput(command, status);
  };
  if (!FLAGS_out_dir.empty()) {
    const Status made = CreateFolder(FLAGS_out_dir, &made_out_dir);
    if (!made.ok()) return fail(made);
  }
  json out;
  out["scan"] = SplitList(FLAGS_scan);
  out["models"] = json::array();
  bool all_counts = true;
  for (size_t m = 0; m < loaded.size(); ++m) {
    const CellModelOutcome& o = cell.models[m];
    all_counts = all_counts && o.count_met;
    out["models"].push_back(
        {{"name", loaded[m].name},
         {"urdf", loaded[m].urdf},
         {"count", loaded[m].count == 0 ? json("every") : json(loaded[m].count)},
         {"found", o.found},
         {"count_met", o.count_met},
         {"stopped", o.stopped}});
    if (o.rejected) {
      out["models"].back()["rejected_fit_base_xyz"] = {o.T_world_base_rejected.translation().x(),
                                                       o.T_world_base_rejected.translation().y(),
                                                       o.T_world_base_rejected.translation().z()};
    }
  }
  std::vector<bool> taken(truth.size(), false);
  out["instances"] = json::array();
  std::printf("cell: %zu instances in %.1f s\n", cell.instances.size(), cell.seconds);
  for (const CellInstance& instance : cell.instances) {
    const LoadedModel& l = loaded[static_cast<size_t>(instance.model)];
    const std::string id = l.name + "_" + std::to_string(instance.index);
    json result = FitResultJson(l.model, l.kind,
                                models[static_cast<size_t>(instance.model)].options, instance.fit);
    result["inputs"] = FitInputsJson(l.urdf, l.specs, SplitList(FLAGS_scan), nullptr);
    json summary = {{"id", id},
                    {"model", l.name},
                    {"ok", instance.fit.ok},
                    {"message", instance.fit.message},
                    {"removed_points", instance.removed_points},
                    {"base", result["base"]}};
    const int match =
        truth.empty() ? -1 : MatchTruthAsset(truth, taken, l.model, instance.fit.T_world_base);
    std::string scored = truth.empty() ? "" : "  (no truth asset within 0.5 m)";
    if (match >= 0) {
      taken[static_cast<size_t>(match)] = true;
      FitErrors errors;
      const Status status =
          ScoreFit(l.model, instance.fit, truth[static_cast<size_t>(match)].truth, &errors);
      if (!status.ok()) return fail(status.WithContext(FLAGS_truth));
      double worst = 0.0;
      for (const JointError& j : errors.joints) {
        if (!j.prismatic && j.independent && !j.unobservable)
          worst = std::max(worst, std::abs(j.error));
      }
      result["errors"] = FitErrorsJson(errors);
      result["errors"]["truth_asset"] = truth[static_cast<size_t>(match)].name;
      summary["truth_asset"] = truth[static_cast<size_t>(match)].name;
      summary["worst_revolute_error_deg"] = worst * 180.0 / M_PI;
      summary["base_error_mm"] = errors.base_translation * 1e3;
      summary["base_survey_error_mm"] = errors.base_translation_survey * 1e3;
      char line[200];
      std::snprintf(line, sizeof(line),
                    "  = %s: base %.2f mm (in the survey's frame %.2f mm), worst revolute joint "
                    "%.4f deg",
                    truth[static_cast<size_t>(match)].name.c_str(), errors.base_translation * 1e3,
                    errors.base_translation_survey * 1e3, worst * 180.0 / M_PI);
      scored = line;
    }
    if (!FLAGS_out_dir.empty()) {
      const std::string path = FLAGS_out_dir + "/" + id + ".json";
      const Status status = WriteStringAtomically(path, result.dump(2) + "\n");
      if (!status.ok()) return fail(status);
      written.push_back(path);
      summary["result"] = path;
    } else {
      summary["result"] = result;
    }
    out["instances"].push_back(summary);
    const Eigen::Vector3d xyz = instance.fit.T_world_base.translation();
    std::printf("  %-16s base %.3f %.3f %.3f m, yaw %.2f deg, %zu points%s\n", id.c_str(), xyz.x(),
                xyz.y(), xyz.z(),
                RpyFromRotation(instance.fit.T_world_base.linear()).z() * 180.0 / M_PI,
                instance.removed_points, scored.c_str());
    if (!instance.fit.ok) std::printf("    quality NOT OK: %s\n", instance.fit.message.c_str());
  }
  if (!truth.empty()) {
    json missed = json::array();
    for (size_t a = 0; a < truth.size(); ++a) {
      if (!taken[a]) missed.push_back(truth[a].name);
    }
    out["truth_assets_not_found"] = missed;
  }
  for (size_t m = 0; m < loaded.size(); ++m) {
    const CellModelOutcome& o = cell.models[m];
    // The first reason only (all of them in the result's "stopped").
    const size_t cut = o.stopped.find("; ");
    const std::string reason =
        cut == std::string::npos ? o.stopped : o.stopped.substr(0, cut) + "; ...";
    std::printf("  %s: %d found%s%s\n", loaded[m].name.c_str(), o.found,
                o.count_met ? "" : " (fewer than asked)",
                reason.empty() ? "" : ("; stopped: " + reason).c_str());
  }
  out["background"] = {{"points", cell.background_points},
                       {"removed_points", cell.points - cell.background_points},
                       {"distance_m", options.removal.distance}};
  if (!FLAGS_out_background.empty()) {
    const Status status = WriteScans(FLAGS_out_background, scans, WriteOptions());
    if (!status.ok()) return fail(status);
    written.push_back(FLAGS_out_background);
    out["background"]["file"] = FLAGS_out_background;
  }
  if (has_roi) {
    const Eigen::AlignedBox3d& box = options.roi_world;
    out["roi"] = {{"min", {box.min().x(), box.min().y(), box.min().z()}},
                  {"max", {box.max().x(), box.max().y(), box.max().z()}},
                  {"points", cell.roi_points}};
  }
  out["ok"] = all_counts;
  out["timing_s"] = {
      {"load", load_seconds},
      {"fit", cell.seconds},
      {"total", SecondsSince(start)}};
  const Status status = WriteStringAtomically(FLAGS_out, out.dump(2) + "\n");
  if (!status.ok()) return fail(status);
  std::printf("background: %zu of %zu points kept; cell %s\n", cell.background_points, cell.points,
              all_counts ? "ok" : "NOT OK: a model's count was not met");
  return kExitOk;
}

}  // namespace

Command CellCommand() {
  return {
      "cell",
      "every instance of several models in the scans of a cell, each fitted and removed",
      "Usage:\n"
      "  edgefit cell --models=M.json --scan=F[,F...] --out=cell.json [--out_dir=D]\n"
      "               [--out_background=B.e57] [--background_distance_mm=8] "
      "[--truth=cell_truth.json]\n"
      "               [--roi=xmin,ymin,zmin,xmax,ymax,zmax] [fit flags: --weighting, --loss, ...]\n"
      "               [--threads=N] [--seed=N]\n"
      "Example:\n"
      "  edgefit scan --scene=examples/cell/cell.json --scanners=4 --out=cell.e57 "
      "--truth=cell_truth.json\n"
      "  edgefit cell --models=examples/cell/models.json --scan=cell.e57 "
      "--truth=cell_truth.json \\\n"
      "    --out=cell_result.json --out_background=cell_rest.e57",
      WithFitOptionFlags({"models", "scan", "camera_info", "depth_scale", "out", "out_dir", "out_background",
                          "background_distance_mm", "truth", "roi", "threads", "seed"}),
      &RunCell};
}

}  // namespace edgefit::tools
