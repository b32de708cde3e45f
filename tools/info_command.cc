// edgefit info: what is in a scan file or a URDF model.
//   edgefit info --scan=F[,F...] [--json]
//   edgefit info --urdf=F [--attach=eef.urdf@link] [--json]
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/scan/scan_noise.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit::tools {
namespace {

using nlohmann::json;

constexpr double kRadToDeg = 180.0 / M_PI;

json PoseJson(const Pose& T) {
  json rows = json::array();
  for (int r = 0; r < 4; ++r) {
    rows.push_back({T.matrix()(r, 0), T.matrix()(r, 1), T.matrix()(r, 2), T.matrix()(r, 3)});
  }
  return rows;
}

json BoxJson(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return nullptr;
  const Eigen::Vector3d size = box.sizes();
  return {{"min", {box.min().x(), box.min().y(), box.min().z()}},
          {"max", {box.max().x(), box.max().y(), box.max().z()}},
          {"size", {size.x(), size.y(), size.z()}}};
}

json ScanJson(const OrganizedScan& scan, const std::string& source, int index) {
  const size_t valid = scan.CountValid();
  json j = {{"source", source},
            {"index", index},
            {"rows", scan.rows()},
            {"cols", scan.cols()},
            {"valid", valid},
            {"missing", scan.size() - valid},
            {"organized", scan.organized()},
            {"has_color", scan.has_color()},
            {"file_order", scan.file_order() == OrganizedScan::FileOrder::kColumnMajor
                               ? "column_major"
                               : "row_major"},
            {"bytes_per_cell", scan.BytesPerCell()},
            {"T_world_scanner", PoseJson(scan.T_world_scanner())}};
  const ScanLattice& lattice = scan.lattice();
  if (!lattice.valid()) {
    j["lattice"] = nullptr;
  } else if (lattice.model() == ScanLattice::Model::kProjective) {
    const PinholeCamera& c = lattice.camera();
    j["lattice"] = {{"model", lattice.ModelName()},
                    {"fx", c.fx},
                    {"fy", c.fy},
                    {"cx", c.cx},
                    {"cy", c.cy},
                    {"distortion", c.distortion},
                    {"row_step_deg", lattice.row_step() * kRadToDeg},
                    {"col_step_deg", lattice.col_step() * kRadToDeg}};
  } else {
    const Eigen::Vector3d axis = lattice.R_scanner_lattice().col(2);
    j["lattice"] = {
        {"model", lattice.ModelName()},
        {"azimuth_step_deg", lattice.col_step() * kRadToDeg},
        {"elevation_step_deg", lattice.row_step() * kRadToDeg},
        {"row_step_deg", lattice.row_step() * kRadToDeg},
        {"col_step_deg", lattice.col_step() * kRadToDeg},
        {"azimuth_range_deg",
         {lattice.azimuth(0) * kRadToDeg, lattice.azimuth(lattice.cols() - 1) * kRadToDeg}},
        {"elevation_range_deg",
         {lattice.elevation(0) * kRadToDeg, lattice.elevation(lattice.rows() - 1) * kRadToDeg}},
        {"tilt_deg", std::acos(std::min(1.0, std::abs(axis.z()))) * kRadToDeg}};
  }
  return j;
}

int RunScanInfo(const Command& command) {
  ReadOptions read_options;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadOptionsFromFlags(&read_options));
  json out = {{"files", json::array()}, {"scans", json::array()}, {"range_noise", json::array()}};
  size_t total = 0, total_valid = 0;
  for (const std::string& path : SplitList(FLAGS_scan)) {
    ScanSet set;
    const Status status = ReadScans(path, read_options, &set);
    if (!status.ok()) return BadInput(command, status);
    out["files"].push_back(path);
    const ScanNoise noise = EstimateScanNoise(set, ScanNoiseOptions());
    json by_range = json::array();
    for (size_t b = 0; b < noise.sigma.size(); ++b) {
      if (std::isfinite(noise.sigma[b])) {
        by_range.push_back({{"range_m", (b + 0.5) * noise.bin}, {"sigma_m", noise.sigma[b]}});
      }
    }
    out["range_noise"].push_back({{"sigma_m", noise.median_sigma},
                                  {"measured", noise.measured},
                                  {"by_range", by_range}});
    for (size_t i = 0; i < set.scans.size(); ++i) {
      out["scans"].push_back(ScanJson(set.scans[i], path, static_cast<int>(i)));
      total += set.scans[i].size();
      total_valid += set.scans[i].CountValid();
    }
  }
  out["total_cells"] = total;
  out["total_valid"] = total_valid;
  if (FLAGS_json) {
    std::cout << out.dump(2) << std::endl;
    return kExitOk;
  }
  for (const json& s : out["scans"]) {
    std::printf("%s scan %d: %d rows x %d cols, %zu valid (%.1f%%), %s\n",
                s["source"].get<std::string>().c_str(), s["index"].get<int>(),
                s["rows"].get<int>(), s["cols"].get<int>(), s["valid"].get<size_t>(),
                100.0 * s["valid"].get<double>() /
                    std::max(1.0, s["rows"].get<double>() * s["cols"].get<double>()),
                s["organized"].get<bool>() ? "organized" : "unorganized");
    const json& l = s["lattice"];
    if (!l.is_null() && l["model"] == "projective") {
      std::printf("  lattice: projective (a depth camera), fx %.3f fy %.3f cx %.3f cy %.3f px%s\n",
                  l["fx"].get<double>(), l["fy"].get<double>(), l["cx"].get<double>(),
                  l["cy"].get<double>(),
                  l["distortion"] != json(std::vector<double>(8, 0.0)) ? ", with distortion" : "");
    } else if (!l.is_null()) {
      std::printf("  lattice: angular (a laser scanner), azimuth step %.5f deg over [%.2f, %.2f], "
                  "elevation step %.5f deg over [%.2f, %.2f], tilt %.3f deg\n",
                  l["azimuth_step_deg"].get<double>(), l["azimuth_range_deg"][0].get<double>(),
                  l["azimuth_range_deg"][1].get<double>(), l["elevation_step_deg"].get<double>(),
                  l["elevation_range_deg"][0].get<double>(),
                  l["elevation_range_deg"][1].get<double>(), l["tilt_deg"].get<double>());
    }
    const json& T = s["T_world_scanner"];
    std::printf("  scanner at (%.4f, %.4f, %.4f) m\n", T[0][3].get<double>(),
                T[1][3].get<double>(), T[2][3].get<double>());
  }
  for (size_t f = 0; f < out["range_noise"].size(); ++f) {
    const json& n = out["range_noise"][f];
    std::printf("%s: range noise %.2f mm (1.4826 x median distance to the local plane)",
                out["files"][f].get<std::string>().c_str(), 1e3 * n["sigma_m"].get<double>());
    for (const json& b : n["by_range"]) {
      std::printf("%s %.2f m: %.2f mm", &b == &n["by_range"][0] ? "; by range" : ",",
                  b["range_m"].get<double>(), 1e3 * b["sigma_m"].get<double>());
    }
    std::printf("\n");
  }
  std::printf("total: %zu cells, %zu valid points\n", total, total_valid);
  return kExitOk;
}

json JointJson(const KinematicModel& model, const Joint& joint) {
  json j = {{"name", joint.name},
            {"type", JointTypeName(joint.type)},
            {"parent", model.links()[joint.parent_link].name},
            {"child", model.links()[joint.child_link].name},
            {"axis", {joint.axis.x(), joint.axis.y(), joint.axis.z()}},
            {"independent", joint.IsIndependent()}};
  if (joint.has_limits) {
    j["lower"] = joint.lower;
    j["upper"] = joint.upper;
  } else {
    j["lower"] = nullptr;
    j["upper"] = nullptr;
  }
  if (joint.mimic_joint >= 0) {
    j["mimic"] = {{"joint", model.joints()[joint.mimic_joint].name},
                  {"multiplier", joint.mimic_multiplier},
                  {"offset", joint.mimic_offset}};
  }
  if (joint.loop_closure >= 0) j["loop_closure"] = model.loop_closures()[joint.loop_closure].name;
  return j;
}

int RunModelInfo(const Command& command) {
  std::vector<AttachSpec> specs;
  Status status = ParseAttachSpecList(FLAGS_attach, &specs);
  if (!status.ok()) return BadInput(command, status.WithContext("--attach"));
  KinematicModel model;
  status = LoadModelWithAttachments(FLAGS_urdf, specs, ModelLoadOptions(), &model);
  if (!status.ok()) return BadInput(command, status);
  json attachments = json::array();
  for (const AttachSpec& spec : specs) {
    attachments.push_back({{"path", spec.path}, {"parent_link", spec.parent_link},
                           {"T_parent_root", PoseJson(spec.T_parent_root)}});
  }
  std::vector<double> q = model.ZeroJoints();
  status = model.ResolveDependentJoints(&q);
  if (!status.ok()) return BadInput(command, status.WithContext(FLAGS_urdf));

  json links = json::array();
  size_t total_triangles = 0;
  for (const Link& link : model.links()) {
    json meshes = json::array();
    for (const Visual& v : link.visuals) {
      static const char* kKinds[] = {"mesh", "box", "cylinder", "sphere"};
      json m = {{"kind", kKinds[static_cast<int>(v.kind)]}, {"triangles", v.triangle_count}};
      if (v.kind == Visual::Kind::kMesh) {
        m["path"] = v.mesh_path;
        m["scale"] = {v.mesh_scale.x(), v.mesh_scale.y(), v.mesh_scale.z()};
      }
      meshes.push_back(m);
    }
    total_triangles += link.mesh.triangles.size();
    links.push_back({{"name", link.name},
                     {"parent_joint", link.parent_joint >= 0
                                          ? json(model.joints()[link.parent_joint].name)
                                          : json(nullptr)},
                     {"source", link.source},
                     {"triangles", link.mesh.triangles.size()},
                     {"visuals", meshes}});
  }
  json joints = json::array();
  for (int j : model.joint_order()) joints.push_back(JointJson(model, model.joints()[j]));
  json independent = json::array();
  for (int j : model.IndependentJoints()) independent.push_back(model.joints()[j].name);
  json loops = json::array();
  for (const LoopClosure& lc : model.loop_closures()) {
    json lj = {{"name", lc.name},
               {"link_a", model.links()[lc.link_a].name},
               {"link_b", model.links()[lc.link_b].name},
               {"joints", json::array()}};
    for (int j : lc.joints) lj["joints"].push_back(model.joints()[j].name);
    loops.push_back(lj);
  }
  const Eigen::AlignedBox3d box = model.BoundingBox(q);
  const json out = {{"name", model.name()},
                    {"urdf", FLAGS_urdf},
                    {"attachments", attachments},
                    {"links", links},
                    {"joints", joints},
                    {"independent_joints", independent},
                    {"loop_closures", loops},
                    {"triangles", total_triangles},
                    {"zero_pose_bbox", BoxJson(box)}};
  if (FLAGS_json) {
    std::cout << out.dump(2) << std::endl;
    return kExitOk;
  }
  std::printf("%s: %zu links, %zu joints (%zu independent), %zu triangles\n",
              model.name().c_str(), model.links().size(), model.joints().size(),
              independent.size(), total_triangles);
  std::printf("joints (parents first):\n");
  for (const json& j : joints) {
    std::printf("  %-28s %-10s %s -> %s", j["name"].get<std::string>().c_str(),
                j["type"].get<std::string>().c_str(), j["parent"].get<std::string>().c_str(),
                j["child"].get<std::string>().c_str());
    if (!j["lower"].is_null()) {
      const bool prismatic = j["type"] == "prismatic";
      const double k = prismatic ? 1.0 : kRadToDeg;
      std::printf("  [%.2f, %.2f] %s", j["lower"].get<double>() * k,
                  j["upper"].get<double>() * k, prismatic ? "m" : "deg");
    }
    if (j.contains("mimic")) {
      std::printf("  mimic %s x %.4g %+.4g", j["mimic"]["joint"].get<std::string>().c_str(),
                  j["mimic"]["multiplier"].get<double>(), j["mimic"]["offset"].get<double>());
    }
    if (j.contains("loop_closure")) {
      std::printf("  loop %s", j["loop_closure"].get<std::string>().c_str());
    }
    std::printf("\n");
  }
  std::printf("links:\n");
  for (const json& l : links) {
    std::printf("  %-28s %8zu triangles\n", l["name"].get<std::string>().c_str(),
                l["triangles"].get<size_t>());
  }
  if (!box.isEmpty()) {
    std::printf("zero-pose bounding box [m]: min (%.4f, %.4f, %.4f) max (%.4f, %.4f, %.4f)\n",
                box.min().x(), box.min().y(), box.min().z(), box.max().x(), box.max().y(),
                box.max().z());
  }
  return kExitOk;
}

int RunInfo(const Command& command) {
  const bool has_scan = !FLAGS_scan.empty(), has_urdf = !FLAGS_urdf.empty();
  if (has_scan == has_urdf) return BadInput(command, "give exactly one of --scan or --urdf");
  if (!FLAGS_attach.empty() && !has_urdf) return BadInput(command, "--attach needs --urdf");
  return has_scan ? RunScanInfo(command) : RunModelInfo(command);
}

}  // namespace

Command InfoCommand() {
  return {"info",
          "summary of a scan file (grids, valid points, lattice) or a URDF model",
          "Usage:\n"
          "  edgefit info --scan=F[,F...] [--camera_info=camera_info.yaml] [--json]\n"
          "  edgefit info --urdf=F [--attach=eef.urdf@link[:x,y,z,r,p,y]] [--json]\n"
          "Examples:\n"
          "  edgefit info --scan=assets/samples/two_scans.ptx\n"
          "  edgefit info --urdf=robot.urdf --attach=gun.urdf@tool0 --json",
          {"scan", "camera_info", "depth_scale", "urdf", "attach", "json"},
          &RunInfo};
}

}  // namespace edgefit::tools
