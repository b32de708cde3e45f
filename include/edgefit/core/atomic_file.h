// Atomic output files: a failed run leaves no partial file (DESIGN.md,
// command-line contract). Content goes to "<path>.tmp.<pid>" in the same
// directory and is renamed over <path> only when the writer succeeded.
#ifndef EDGEFIT_CORE_ATOMIC_FILE_H_
#define EDGEFIT_CORE_ATOMIC_FILE_H_

#include <functional>
#include <ostream>
#include <string>

#include "edgefit/core/status.h"

namespace edgefit {

// Calls `write` with a binary stream on a temporary file beside `path`, then
// renames it to `path`. If `write` fails, or the stream goes bad, the
// temporary file is removed and `path` is left as it was.
Status WriteFileAtomically(const std::string& path,
                           const std::function<Status(std::ostream&)>& write);

// Convenience: writes `content` atomically.
Status WriteStringAtomically(const std::string& path, const std::string& content);

// Reads a whole file into `content`; fails with "<path>: <reason>".
Status ReadFileToString(const std::string& path, std::string* content);

}  // namespace edgefit

#endif  // EDGEFIT_CORE_ATOMIC_FILE_H_
