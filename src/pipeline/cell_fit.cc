#include "edgefit/pipeline/cell_fit.h"

#include <glog/logging.h>

#include <chrono>

namespace edgefit {

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
  for (size_t m = 0; m < models.size(); ++m) {
    const CellModel& cell_model = models[m];
    CHECK(cell_model.model != nullptr);
    CellModelOutcome outcome;
    const int wanted = cell_model.count > 0 ? cell_model.count : options.max_instances;
    while (outcome.found < wanted) {
      const std::string label = cell_model.name + " " + std::to_string(outcome.found + 1);
      say("cell: looking for " + label + " in " + std::to_string(scans->TotalValid()) + " points");
      CellInstance instance;
      instance.model = static_cast<int>(m);
      instance.index = outcome.found + 1;
      EDGEFIT_RETURN_IF_ERROR(
          Fit(*cell_model.model, *scans, cell_model.options,
              [&](const std::string& line) { say(label + ": " + line); }, &instance.fit));
      if (!instance.fit.ok) {
        outcome.stopped = instance.fit.message;
        break;
      }
      std::vector<std::vector<uint8_t>> marks;
      EDGEFIT_RETURN_IF_ERROR(MarkModelPoints(*scans, *cell_model.model, instance.fit.q,
                                              instance.fit.T_world_base, options.removal, &marks));
      instance.removed_points = RemoveMarkedPoints(marks, scans);
      say("cell: " + label + " found; " + std::to_string(instance.removed_points) + " points removed");
      result->instances.push_back(std::move(instance));
      ++outcome.found;
    }
    if (cell_model.count == 0 && outcome.found == wanted) {
      outcome.stopped = "at most " + std::to_string(wanted) + " instances";
    }
    outcome.count_met = cell_model.count == 0 || outcome.found == cell_model.count;
    result->models.push_back(outcome);
  }
  result->background_points = scans->TotalValid();
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
