#include "edgefit/pipeline/cell_fit.h"

#include <glog/logging.h>

#include <algorithm>
#include <chrono>

#include "edgefit/pipeline/instance_crop.h"
#include "edgefit/scan/mixed_pixels.h"

namespace edgefit {

std::vector<size_t> SearchOrder(const std::vector<CellModel>& models) {
  std::vector<size_t> order(models.size());
  for (size_t m = 0; m < models.size(); ++m) order[m] = m;
  std::stable_partition(order.begin(), order.end(), [&models](size_t m) {
    return models[m].options.base.method != BaseOptions::Method::kArmTips;
  });
  return order;
}

bool IsInstance(const FitResult& fit) {
  bool base_ok = false;
  for (const BodyQuality& body : fit.bodies) {
    if (body.joint.empty()) base_ok = body.ok;
    if (body.verdict == JointVerdict::kMismatch) return false;
  }
  return base_ok;
}

Status FitCell(const std::vector<CellModel>& models, const CellOptions& options,
               const ProgressFn& progress, ScanSet* scans, CellResult* result) {
  CHECK(scans != nullptr);
  CHECK(result != nullptr);
  const auto start = std::chrono::steady_clock::now();
  *result = CellResult();
  result->points = scans->TotalValid();
  auto say = [&progress](const std::string& line) {
    if (progress) progress(line);
  };
  if (models.empty()) return Status::Ok();
  const FitOptions& first = models.front().options;
  if (first.remove_mixed_pixels) {
    *scans = WithoutMixedPixels(*scans, first.mixed_pixels, &result->mixed_pixels);
    say("cell: " + std::to_string(result->mixed_pixels) + " mixed pixels removed");
  }
  // The points instances are looked for in: the region's, or every one.
  const bool has_roi = !options.roi_world.isEmpty();
  ScanSet in_roi;
  if (has_roi) {
    in_roi = CropToBox(*scans, options.roi_world);
    result->roi_points = in_roi.TotalValid();
    if (result->roi_points == 0) {
      return Status::Error("the region of interest holds none of the " +
                           std::to_string(result->points) + " scan points");
    }
    say("cell: " + std::to_string(result->roi_points) + " of " + std::to_string(result->points) +
        " points in the region");
  }
  ScanSet* searched = has_roi ? &in_roi : scans;
  EdgeDetectionResult edges;  // Sec. 4, once for the cell, when a model's weighting uses it
  if (std::any_of(models.begin(), models.end(),
                  [](const CellModel& m) { return !m.options.uniform_weights; })) {
    say("cell: edges on " + std::to_string(searched->TotalValid()) + " points");
    EDGEFIT_RETURN_IF_ERROR(DetectEdges(*searched, first.edges, &edges));
  }
  result->edge_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result->models.assign(models.size(), CellModelOutcome());
  for (const size_t m : SearchOrder(models)) {
    const CellModel& cell_model = models[m];
    CHECK(cell_model.model != nullptr);
    CellModelOutcome outcome;
    const int wanted = cell_model.count > 0 ? cell_model.count : options.max_instances;
    while (outcome.found < wanted) {
      const std::string label = cell_model.name + " " + std::to_string(outcome.found + 1);
      say("cell: looking for " + label + " in " + std::to_string(searched->TotalValid()) +
          " points");
      FitOptions fit_options = cell_model.options;
      fit_options.crop.enabled = true;
      fit_options.min_base_inlier_share = fit_options.quality.min_inlier_share;
      fit_options.base.hypotheses.instance_separation = 0.5;  // [m]
      CellInstance instance;
      instance.model = static_cast<int>(m);
      instance.index = outcome.found + 1;
      EDGEFIT_RETURN_IF_ERROR(FitWithEdges(
          *cell_model.model, *searched, edges, fit_options,
          [&](const std::string& line) { say(label + ": " + line); }, &instance.fit));
      if (!IsInstance(instance.fit)) {
        outcome.stopped = instance.fit.message;
        outcome.rejected = true;
        outcome.T_world_base_rejected = instance.fit.T_world_base;
        break;
      }
      std::vector<std::vector<uint8_t>> marks;
      EDGEFIT_RETURN_IF_ERROR(MarkModelPoints(*scans, *cell_model.model, instance.fit.q,
                                              instance.fit.T_world_base, options.removal, &marks));
      EDGEFIT_RETURN_IF_ERROR(MarkAttachedPoints(*scans, *cell_model.model, instance.fit.q,
                                                 instance.fit.T_world_base, options.attached,
                                                 &marks));
      instance.removed_points = RemoveMarkedPoints(marks, scans);
      if (has_roi) RemoveMarkedPoints(marks, &in_roi);
      say("cell: " + label + " found; " + std::to_string(instance.removed_points) +
          " points removed");
      result->instances.push_back(std::move(instance));
      ++outcome.found;
    }
    if (cell_model.count == 0 && outcome.found == wanted) {
      outcome.stopped = "at most " + std::to_string(wanted) + " instances";
    }
    outcome.count_met = cell_model.count == 0 || outcome.found == cell_model.count;
    result->models[m] = outcome;
  }
  result->background_points = scans->TotalValid();
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
