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

// Whether a file can be written at `path` later: its folder exists and
// takes new files, and `path` is not a folder. Checked before long work so
// that a wrong output path fails at once, not after it.
Status CheckOutputPath(const std::string& path);

// The same for a folder that will receive files: `folder` is a folder that
// takes new files, or does not exist yet and its nearest existing parent
// does (CreateFolder makes it when the files are written).
Status CheckOutputFolder(const std::string& folder);

// Makes `folder` and the parents it needs ("mkdir -p"); *created: whether
// it did not exist before (may be null).
Status CreateFolder(const std::string& folder, bool* created);

// Reads a whole file into `content`; fails with "<path>: <reason>".
Status ReadFileToString(const std::string& path, std::string* content);

}  // namespace edgefit

#endif  // EDGEFIT_CORE_ATOMIC_FILE_H_
