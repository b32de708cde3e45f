// result.json of a fit (docs/result_json.md; the contract of DESIGN.md):
// the base pose, every moving joint, their standard deviations, the time
// per stage, the quality of every body and the options that made it.
#ifndef EDGEFIT_PIPELINE_RESULT_JSON_H_
#define EDGEFIT_PIPELINE_RESULT_JSON_H_

#include <nlohmann/json.hpp>

#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit_options.h"
#include "edgefit/pipeline/fit_result.h"

namespace edgefit {

// The result of a fit of `model` (kind, options: as fitted). timing_s
// holds the stages; the caller adds "load" and "total" (reading the files
// and writing the outputs are its own), and "errors" against a truth.
nlohmann::json FitResultJson(const KinematicModel& model, AssetKind kind, const FitOptions& options,
                             const FitResult& fit);

// result.json's base_std: the base's standard deviations about and along
// the world axes, `rotation_rad` and `xyz_m` (null where not computed).
nlohmann::json BaseStdJson(const ChainRefinementSummary& chain);

// result.json's options: the weighting, the loss and every extension's
// setting, as fitted (edgefit bench writes them with each run too).
nlohmann::json FitOptionsJson(const FitOptions& options);

// The stages' seconds, as result.json's timing_s holds them: edges,
// stations, base_rough, base_precise, chain, refine, alternatives.
nlohmann::json FitTimingsJson(const FitTimings& timings);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_RESULT_JSON_H_
