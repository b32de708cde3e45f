#include "edgefit/scene/accessories.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "accessory_parts.h"
#include "edgefit/scene/main_chain.h"

namespace edgefit {
namespace {

using scene_internal::ClampSite;
using scene_internal::PartContext;
using scene_internal::SurfaceClearance;

// Surface samples per link: enough for 1-2 cm spacing on a 1-3 m^2 robot
// link, few enough that brute-force nearest-sample queries stay fast.
constexpr int kMaxSamplesPerLink = 8000;

bool ValidRange(double lo, double hi) { return std::isfinite(lo) && std::isfinite(hi) && lo > 0 && lo <= hi; }

// Seeded sub-streams, so adding a cover does not change the harnesses.
enum Stream : uint64_t { kCovers = 1, kHarnesses, kHoses, kBrackets, kSamples };

void Add(const std::string& kind, TriangleMesh mesh, double radius, std::vector<int> links,
         Scene* scene, AccessoryReport* report) {
  AccessoryRecord record;
  record.kind = kind;
  record.scene_index = static_cast<int>(scene->meshes.size());
  record.radius = radius;
  record.links = std::move(links);
  // Covers count their top sheet only: the underside faces the link.
  record.area = kind == "cover" ? 0.5 * mesh.SurfaceArea() : mesh.SurfaceArea();
  SceneMesh scene_mesh;
  scene_mesh.mesh_world = std::move(mesh);
  scene_mesh.label = kLabelAccessory;
  scene_mesh.kind = kind;
  // Black cable and hose jackets return little light.
  if (kind == "harness" || kind == "hose") scene_mesh.reflectance = 0.08;
  scene->meshes.push_back(std::move(scene_mesh));
  report->area += record.area;
  if (kind == "harness") ++report->harnesses;
  if (kind == "hose") ++report->hoses;
  if (kind == "cover") ++report->covers;
  if (kind == "bracket") ++report->brackets;
  report->records.push_back(std::move(record));
}

}  // namespace

bool AccessoryOptions::IsValid(std::string* error) const {
  if (harness_count < 0 || hose_count < 0 || cover_count < 0 || bracket_count < 0) {
    *error = "accessory counts must be >= 0";
  } else if (!ValidRange(harness_radius_min, harness_radius_max) ||
             !ValidRange(hose_radius_min, hose_radius_max) ||
             !ValidRange(hose_loop_min, hose_loop_max) ||
             !ValidRange(cover_thickness_min, cover_thickness_max) ||
             !ValidRange(cover_offset_min, cover_offset_max) || !(cover_max_side > 0.0) ||
             !ValidRange(bracket_size_min, bracket_size_max)) {
    *error = "accessory size ranges need 0 < min <= max [m]";
  } else if (!(sag_fraction_min >= 0.0) || !(sag_fraction_min <= sag_fraction_max) ||
             !(sag_fraction_max <= 1.0) || !(sag_max >= 0.0)) {
    *error = "need 0 <= sag_fraction_min <= sag_fraction_max <= 1 and sag_max >= 0";
  } else if (bracket_size_min <= 0.01) {
    *error = "bracket_size_min must exceed 0.01 m (the plate thickness)";
  } else if (!(clearance >= 0.0) || !(sample_spacing > 0.0)) {
    *error = "clearance must be >= 0 and sample_spacing > 0 [m]";
  } else if (tube_segments < 3) {
    *error = "tube_segments must be >= 3";
  } else {
    return true;
  }
  return false;
}

std::string AccessoryReport::BriefReport() const {
  char line[160];
  std::snprintf(line, sizeof(line), "%d harnesses, %d hoses, %d covers, %d brackets, %.3f m^2",
                harnesses, hoses, covers, brackets, area);
  return line;
}

void AddAccessories(const KinematicModel& model, const std::vector<double>& q,
                    const std::vector<Pose>& T_world_link, const AccessoryOptions& options,
                    Scene* scene, AccessoryReport* report) {
  CHECK(scene != nullptr);
  CHECK_EQ(q.size(), model.joints().size());
  CHECK_EQ(T_world_link.size(), model.links().size());
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  AccessoryReport local_report;
  if (report == nullptr) report = &local_report;
  *report = AccessoryReport();

  SurfaceClearance clearance(model, T_world_link, options.sample_spacing, kMaxSamplesPerLink,
                             SplitMix64::Stream(options.seed, kSamples).Next());
  PartContext context;
  context.model = &model;
  context.T_world_link = &T_world_link;
  context.options = &options;
  context.clearance = &clearance;
  context.chain = MainChainLinks(model);
  const int n = static_cast<int>(context.chain.size());
  if (n == 0) return;

  // Covers first: tubes are then routed over them.
  {
    SplitMix64 rng = SplitMix64::Stream(options.seed, kCovers);
    std::vector<int> by_area(context.chain.begin() + (context.chain[0] == model.root_link() ? 1 : 0),
                             context.chain.end());
    std::stable_sort(by_area.begin(), by_area.end(), [&](int a, int b) {
      return clearance.LinkCloud(a).area > clearance.LinkCloud(b).area;
    });
    std::vector<int> targets;
    if (context.chain[0] == model.root_link()) targets.push_back(model.root_link());
    targets.insert(targets.end(), by_area.begin(), by_area.end());
    std::vector<TriangleMesh> covers;
    for (int i = 0; i < options.cover_count && !targets.empty(); ++i) {
      const int link = targets[i % targets.size()];
      TriangleMesh mesh;
      if (!scene_internal::BuildCover(context, link, &rng, &mesh)) continue;
      covers.push_back(mesh);
      Add("cover", std::move(mesh), 0.0, {link}, scene, report);
    }
    for (size_t i = 0; i < covers.size(); ++i) clearance.AddObstacle(covers[i], options.seed + i);
  }

  std::vector<ClampSite> clamps;
  if (n >= 2) {
    SplitMix64 rng = SplitMix64::Stream(options.seed, kHarnesses);
    for (int h = 0; h < options.harness_count; ++h) {
      // The first spans base to forearm (the wrist is left to the hoses);
      // the others a seeded range of at least two links.
      int first = 0, last = std::max(1, n - 2);
      if (h > 0) {
        first = rng.Int(0, n - 2);
        last = rng.Int(first + 1, std::max(first + 1, n - 2));
      }
      TriangleMesh mesh;
      double radius = 0.0;
      std::vector<int> links;
      std::vector<ClampSite> sites;
      if (!scene_internal::BuildHarness(context, first, last, &rng, &mesh, &radius, &links,
                                        &sites)) {
        continue;
      }
      clamps.insert(clamps.end(), sites.begin(), sites.end());
      Add("harness", std::move(mesh), radius, std::move(links), scene, report);
    }
    rng = SplitMix64::Stream(options.seed, kHoses);
    for (int h = 0; h < options.hose_count; ++h) {
      TriangleMesh mesh;
      double radius = 0.0;
      std::vector<int> links;
      if (!scene_internal::BuildHose(context, &rng, &mesh, &radius, &links)) continue;
      Add("hose", std::move(mesh), radius, std::move(links), scene, report);
    }
  }

  SplitMix64 rng = SplitMix64::Stream(options.seed, kBrackets);
  if (options.harness_clamps) {
    for (const ClampSite& site : clamps) {
      TriangleMesh mesh;
      if (scene_internal::BuildClampBracket(context, site, &rng, &mesh)) {
        Add("bracket", std::move(mesh), 0.0, {site.link}, scene, report);
      }
    }
  }
  // Free brackets on chain links, weighted by area (bigger links carry more).
  double total_area = 0.0;
  for (int link : context.chain) total_area += clearance.LinkCloud(link).area;
  for (int b = 0; b < options.bracket_count && total_area > 0.0; ++b) {
    double u = rng.Uniform() * total_area;
    int link = context.chain.back();
    for (int candidate : context.chain) {
      u -= clearance.LinkCloud(candidate).area;
      if (u < 0) {
        link = candidate;
        break;
      }
    }
    TriangleMesh mesh;
    if (scene_internal::BuildFreeBracket(context, link, &rng, &mesh)) {
      Add("bracket", std::move(mesh), 0.0, {link}, scene, report);
    }
  }
  VLOG(1) << "AddAccessories: " << report->BriefReport();
}

}  // namespace edgefit
