// OrganizedScan: one terrestrial laser scan as a rows x cols grid.
//
// Rows index elevation, columns index azimuth (paper Sec. 4.1, P[i][j]).
// Cells are stored column by column, as PTX writes them:
//   cell index = col * rows + row.
// Points are kept in the scanner frame as float (12 bytes) with T_world_scanner
// in double, so a cell costs 12 (xyz) + 4 (intensity, unless dropped: a fit
// reads none) + 3 (optional RGB) bytes: 19 bytes at most, under the 40 bytes
// per cell budget (io_test checks a loaded scan with BytesPerCell). A
// missing cell (no return) has NaN coordinates.
//
// Points are held in chunks of kChunkCells. Copies share their chunks until
// one of them writes a cell (SetPoint, SetMissing: that copy then takes the
// chunk of that cell as its own; SetPoint also all the intensities,
// SetColor and EnableColor all the colours), so a copy that only moves its
// station (set_T_world_scanner, lattice) costs no cells, and one with some
// cells set missing (the coverings left out) costs only their chunks.
// A chunk whose cells are all missing (sky, out of range, what a crop
// leaves out) can be let go for one such chunk that every scan shares
// (ShareEmptyChunks, which the readers call; SetMissingWhere): it costs a
// pointer, and a cell written there takes a chunk of its own again.
// Writing distinct cells from several threads is safe on a scan made by the
// constructor (its cells are its own); SetMissingWhere writes a copy's in
// parallel itself.
#ifndef EDGEFIT_SCAN_ORGANIZED_SCAN_H_
#define EDGEFIT_SCAN_ORGANIZED_SCAN_H_

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/scan/scan_lattice.h"

namespace edgefit {

class OrganizedScan {
 public:
  // How the file that held the scan ordered its cells; kept so that per-cell
  // outputs (edge weights, labels) can be written "in the file's point order".
  enum class FileOrder {
    kColumnMajor,  // PTX: column by column (cell index order)
    kRowMajor,     // organized PCD: row by row
  };

  OrganizedScan() = default;
  // A grid of rows x cols missing cells, no intensity, identity pose.
  OrganizedScan(int rows, int cols);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  size_t size() const { return size_; }
  size_t Index(int row, int col) const {
    return static_cast<size_t>(col) * static_cast<size_t>(rows_) + static_cast<size_t>(row);
  }
  int RowOf(size_t index) const { return static_cast<int>(index % static_cast<size_t>(rows_)); }
  int ColOf(size_t index) const { return static_cast<int>(index / static_cast<size_t>(rows_)); }

  // An unorganized cloud (PLY) is held as 1 x N with organized() == false and
  // no lattice; grid neighbourhoods mean nothing for it.
  bool organized() const { return organized_; }
  void set_organized(bool organized) { organized_ = organized; }

  bool IsValid(size_t i) const { return !std::isnan(point_scanner(i).x()); }
  // Point in the scanner frame [m]; NaN for a missing cell.
  const Eigen::Vector3f& point_scanner(size_t i) const {
    return (*chunks_[i >> kChunkBits])[i & kChunkMask];
  }
  // Points of cells i, i + 1, ... to the end of i's chunk, contiguous:
  // *count of them (at least 1), for loops along a column.
  const Eigen::Vector3f* PointRun(size_t i, size_t* count) const {
    *count = kChunkCells - (i & kChunkMask);
    return &point_scanner(i);
  }
  Eigen::Vector3d PointWorld(size_t i) const {
    return T_world_scanner_ * point_scanner(i).cast<double>();
  }
  // 0 for a missing cell, and after DropIntensity.
  float intensity(size_t i) const {
    return intensity_ != nullptr && IsValid(i) ? (*intensity_)[i] : 0.0f;
  }
  bool has_color() const { return colors_ != nullptr; }
  // RGB of cell i; only when has_color().
  const std::array<uint8_t, 3>& color(size_t i) const { return (*colors_)[i]; }

  void SetPoint(size_t i, const Eigen::Vector3f& p_scanner, float intensity) {
    OwnChunk(i >> kChunkBits)[i & kChunkMask] = p_scanner;
    if (intensity_ != nullptr) OwnIntensity()[i] = intensity;
  }
  // Frees the intensities (a fit never reads them); SetPoint keeps none.
  void DropIntensity() { intensity_.reset(); }
  bool has_intensity() const { return intensity_ != nullptr; }
  void SetMissing(size_t i);
  void SetColor(size_t i, const std::array<uint8_t, 3>& rgb);  // allocates colors on first use
  // Allocates the colours (black) up front, so threads may SetColor distinct cells.
  void EnableColor();
  // Lets every chunk with no valid cell go for the shared empty one.
  void ShareEmptyChunks();
  // Sets missing every valid cell whose point p_scanner makes drop(p_scanner)
  // true, chunk by chunk in parallel: a chunk with none dropped stays shared
  // with copies, one with all dropped becomes the shared empty one, only the
  // others are copied (a crop of a copy costs its boundary's chunks).
  void SetMissingWhere(const std::function<bool(const Eigen::Vector3f&)>& drop);

  // 1,024 cells (12 KiB) per chunk: about half a laser scan's column.
  static constexpr int kChunkBits = 10;
  static constexpr size_t kChunkCells = size_t{1} << kChunkBits;
  static constexpr size_t kChunkMask = kChunkCells - 1;

  const Pose& T_world_scanner() const { return T_world_scanner_; }
  void set_T_world_scanner(const Pose& T) { T_world_scanner_ = T; }

  FileOrder file_order() const { return file_order_; }
  void set_file_order(FileOrder order) { file_order_ = order; }
  // Position of cell `i` in the file's point order.
  size_t FileIndex(size_t i) const;

  // The angular lattice; valid only after EstimateLattice (lattice_estimation.h; the readers call it) or set_lattice.
  const ScanLattice& lattice() const { return lattice_; }
  void set_lattice(ScanLattice lattice) { lattice_ = std::move(lattice); }

  size_t CountValid() const;
  // Bytes held per grid cell (memory budget check); the shared empty chunk
  // counts as nothing.
  double BytesPerCell() const;

 private:
  int rows_ = 0;
  int cols_ = 0;
  bool organized_ = true;
  using Chunk = std::array<Eigen::Vector3f, kChunkCells>;
  // Chunk c and the intensities, made this scan's own (copied if a copy
  // shares them).
  Chunk& OwnChunk(size_t c);
  // The all-missing chunk scans share (never written: OwnChunk copies it).
  static const std::shared_ptr<Chunk>& EmptyChunk();
  std::vector<float>& OwnIntensity();

  size_t size_ = 0;
  std::vector<std::shared_ptr<Chunk>> chunks_;
  std::shared_ptr<std::vector<float>> intensity_ = std::make_shared<std::vector<float>>();
  std::shared_ptr<std::vector<std::array<uint8_t, 3>>> colors_;  // null: no colour
  Pose T_world_scanner_ = Pose::Identity();
  FileOrder file_order_ = FileOrder::kColumnMajor;
  ScanLattice lattice_;
};

// A set of scans of one scene, in file order (DESIGN.md: ScanSet).
struct ScanSet {
  std::vector<OrganizedScan> scans;
  std::vector<std::string> sources;  // file each scan came from

  size_t TotalCells() const;
  size_t TotalValid() const;
};

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_ORGANIZED_SCAN_H_
