// The per-cell label sidecar of a virtual scan (`edgefit scan --labels=F.bin`).
//
// Format (all little endian):
//   bytes 0-3   magic "EFLB"
//   uint32      version (1)
//   uint32      scan count S
//   S x (uint32 rows, uint32 cols)
//   then for each scan in file order, rows * cols uint16 labels in the scan
//   file's point order (OrganizedScan::FileIndex: PTX column by column, PCD
//   row by row), values as in scene.h: 0 missing, 1 background, 2 accessory,
//   3 + k link k of the model, | 0x8000 (kTrueEdgeFlag) near a sharp edge.
#ifndef EDGEFIT_SCANNER_LABEL_FILE_H_
#define EDGEFIT_SCANNER_LABEL_FILE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/scanner/virtual_scanner.h"

namespace edgefit {

struct LabelFile {
  std::vector<int> rows, cols;                  // per scan
  std::vector<std::vector<uint16_t>> labels;   // per scan, in file point order
};

// Writes scan.labels, reordered to the point order of the scan file they go
// with, atomically. `scan_path` is that file: ".pcd" means row by row (the
// PCD writer always writes rows); anything else (".ptx", or "") means each
// scan's file_order() (the PTX writer honours it; column by column by default).
Status WriteLabels(const std::string& path, const VirtualScan& scan,
                   const std::string& scan_path = "");
// Reads a label file (labels stay in file point order).
Status ReadLabels(const std::string& path, LabelFile* labels);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_LABEL_FILE_H_
