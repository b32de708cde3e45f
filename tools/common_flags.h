// Flags shared by several subcommands (gflags flags are global, so each is
// defined once, in common_flags.cc).
#ifndef EDGEFIT_TOOLS_COMMON_FLAGS_H_
#define EDGEFIT_TOOLS_COMMON_FLAGS_H_

#include <gflags/gflags.h>

#include <string>

DECLARE_string(scan);
DECLARE_string(camera_info);
DECLARE_double(depth_scale);
DECLARE_string(urdf);
DECLARE_string(attach);
DECLARE_bool(json);
DECLARE_int32(threads);
DECLARE_uint64(seed);
DECLARE_double(w_high);
DECLARE_string(labels);
DECLARE_string(out);
DECLARE_string(truth);
DECLARE_string(out_ply);
DECLARE_string(shard);
DECLARE_string(out_csv);
DECLARE_string(out_json);
DECLARE_string(out_report);
DECLARE_int32(scanners);
DECLARE_double(spacing_mm);
DECLARE_double(noise_mm);
DECLARE_string(beam);
DECLARE_bool(jackets);
DECLARE_string(joints);
DECLARE_string(result);
DECLARE_string(out_dir);

namespace edgefit {
struct AssetScanOptions;
struct ReadOptions;
struct ScanSet;
class Status;
namespace tools {
// The scan readers' options: --camera_info (read here), --depth_scale.
Status ReadOptionsFromFlags(ReadOptions* options);
// Every file of the comma list `list` (--scan) read with
// ReadOptionsFromFlags, appended to *scans; `intensity`: keep the points'
// intensities (ReadOptions::intensity: a fit needs them only to write scans).
Status ReadScanList(const std::string& list, bool intensity, ScanSet* scans);
// Applies `sensor` (ApplySensorPreset), then --beam (when the sensor has a
// footprint) and --jackets.
Status SensorOptionsFromFlags(const std::string& sensor, AssetScanOptions* options);
}  // namespace tools
}  // namespace edgefit

#endif  // EDGEFIT_TOOLS_COMMON_FLAGS_H_
