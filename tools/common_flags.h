// Flags shared by several subcommands (gflags flags are global, so each is
// defined once, in common_flags.cc).
#ifndef EDGEFIT_TOOLS_COMMON_FLAGS_H_
#define EDGEFIT_TOOLS_COMMON_FLAGS_H_

#include <gflags/gflags.h>

DECLARE_string(scan);
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
DECLARE_string(out_json);
DECLARE_int32(scanners);
DECLARE_double(spacing_mm);
DECLARE_double(noise_mm);

#endif  // EDGEFIT_TOOLS_COMMON_FLAGS_H_
