// The flags of a fit, defined once (fit_flags.cc) and read into FitOptions
// in one place for every command that fits: fit, bench (its axes override
// some of them per run) and, through `edgefit fit` processes, batch.
#ifndef EDGEFIT_TOOLS_FIT_FLAGS_H_
#define EDGEFIT_TOOLS_FIT_FLAGS_H_

#include <gflags/gflags.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit_options.h"

DECLARE_string(kind);
DECLARE_string(weighting);
DECLARE_string(loss);
DECLARE_double(loss_scale_mm);
DECLARE_double(lambda);
DECLARE_string(parameterization);
DECLARE_bool(refine_chain);
DECLARE_bool(align_stations);
DECLARE_int32(station_rounds);
DECLARE_double(station_max_covered_share);
DECLARE_int32(covering_rounds);
DECLARE_double(pair_sweep_deg);
DECLARE_double(visibility_tolerance_mm);
DECLARE_bool(remove_mixed_pixels);
DECLARE_double(mixed_pixel_tolerance_mm);
DECLARE_int32(mixed_pixel_lines);
DECLARE_int32(mixed_pixel_neighbour_lines);
DECLARE_string(init);

namespace edgefit::tools {

// The options of a fit of `kind` (FitOptionsFor) with every fit flag
// applied: --seed, --w_high, --weighting, --loss, --loss_scale_mm,
// --lambda, --parameterization, --refine_chain, --init. Errors name the flag.
Status FitOptionsFromFlags(AssetKind kind, FitOptions* options);

// Whether the fit flags are valid, before any file is read (--kind too).
Status CheckFitFlags();

// --roi as a world box; *given false when the flag is empty.
Status RoiFromFlags(Eigen::AlignedBox3d* box, bool* given);

// A command's own flags followed by the fit options' (--weighting ...
// --mixed_pixel_neighbour_lines), which edgefit fit, cell and bench take;
// weighting false: without --weighting (the bench's --weightings sets it).
std::vector<std::string> WithFitOptionFlags(std::vector<std::string> own, bool weighting = true);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_FIT_FLAGS_H_
