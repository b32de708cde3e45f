#include "edgefit/report/world_report.h"

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base64.h"
#include "edgefit/core/atomic_file.h"
#include "html.h"
#include "three_view.h"

namespace edgefit {
namespace {

constexpr char kWorldStyle[] = R"css(
header p { margin: 2px 0; }
#side { flex: 1 1 420px; padding: 8px 16px 16px; max-height: 640px; overflow-y: auto; }
#waypoint { width: 100%; }
#side svg { max-width: 100%; height: auto; }
#note { font-family: monospace; font-size: 12px; min-height: 3em; white-space: pre-wrap; }
.swatch { display: inline-block; width: 12px; height: 12px; vertical-align: middle; margin-right: 4px; }
)css";

constexpr char kWorldScript[] = R"js(
// Colours by kind; the machine checked darker than the others.
const materials = {
  background: new THREE.MeshLambertMaterial({color: 0xa8a8a8, side: THREE.DoubleSide}),
  machine: new THREE.MeshLambertMaterial({color: 0x8fb0de, side: THREE.DoubleSide}),
  checked: new THREE.MeshLambertMaterial({color: 0x2f62b3, side: THREE.DoubleSide}),
  attachment: new THREE.MeshLambertMaterial({color: 0xe08a2b, side: THREE.DoubleSide}),
};
const groups = {background: new THREE.Group(), machines: new THREE.Group()};
const moving = [];  // [mesh, poses (16 floats per waypoint, column-major)]
for (const part of data.parts) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(decode(part.positions, Float32Array), 3));
  g.setIndex(new THREE.BufferAttribute(decode(part.indices, Uint32Array), 1));
  g.computeVertexNormals();
  const material = part.kind === 'machine' && part.machine === data.machine ? materials.checked
                                                                          : materials[part.kind];
  const mesh = new THREE.Mesh(g, material);
  mesh.name = part.name;
  mesh.matrixAutoUpdate = false;
  const poses = decode(part.poses, Float32Array);
  mesh.matrix.fromArray(poses, 0);
  if (poses.length > 16) moving.push([mesh, poses]);
  (part.kind === 'background' ? groups.background : groups.machines).add(mesh);
}
scene.add(groups.background, groups.machines);

const bounds = new THREE.Box3().setFromObject(groups.machines);
if (bounds.isEmpty()) bounds.setFromObject(groups.background);
const centre = bounds.getCenter(new THREE.Vector3());
const size = Math.max(bounds.getSize(new THREE.Vector3()).length(), 0.5);
const camera = new THREE.PerspectiveCamera(40, view.clientWidth / view.clientHeight, size / 100, size * 100);
camera.up.set(0, 0, 1);
camera.position.copy(centre).addScaledVector(new THREE.Vector3(1, -1, 0.6).normalize(), 1.6 * size);
// Where it collides: seen through whatever hides it.
const marker = new THREE.Mesh(new THREE.SphereGeometry(size / 80, 16, 12),
                              new THREE.MeshBasicMaterial({color: 0xd00000, depthTest: false}));
marker.renderOrder = 1;
scene.add(marker);
const controls = new THREE.OrbitControls(camera, renderer.domElement);
controls.target.copy(centre);
controls.update();

const slider = document.getElementById('waypoint');
slider.max = String(data.notes.length - 1);
const points = decode(data.collision_points, Float32Array);
function render() {
  groups.background.visible = document.getElementById('show-background').checked;
  groups.machines.visible = document.getElementById('show-machines').checked;
  renderer.render(scene, camera);
}
function show(k) {
  for (const [mesh, poses] of moving) mesh.matrix.fromArray(poses, 16 * k);
  marker.visible = isFinite(points[3 * k]);
  if (marker.visible) marker.position.set(points[3 * k], points[3 * k + 1], points[3 * k + 2]);
  document.getElementById('at').textContent = (k + 1) + ' of ' + data.notes.length;
  document.getElementById('note').textContent = data.notes[k];
  render();
}
slider.addEventListener('input', () => show(Number(slider.value)));
let timer = null;
document.getElementById('play').addEventListener('click', () => {
  if (timer) { clearInterval(timer); timer = null; return; }
  timer = setInterval(() => {
    const k = (Number(slider.value) + 1) % data.notes.length;
    slider.value = String(k); show(k);
    if (k === data.notes.length - 1) { clearInterval(timer); timer = null; }
  }, Math.max(20, 4000 / data.notes.length));
});
for (const id of ['show-background', 'show-machines']) document.getElementById(id).addEventListener('change', render);
controls.addEventListener('change', render);
window.addEventListener('resize', () => {
  camera.aspect = view.clientWidth / view.clientHeight; camera.updateProjectionMatrix();
  renderer.setSize(view.clientWidth, view.clientHeight); render();
});
const first = data.notes.findIndex((n, k) => isFinite(points[3 * k]));
slider.value = String(Math.max(first, 0));
show(Math.max(first, 0));

if (!status.textContent.startsWith('error')) {
  status.textContent = 'ok: ' + drawnPixels() + ' pixels drawn, ' + data.parts.length + ' parts';
}
)js";

const char* KindName(WorldReportPart::Kind kind) {
  switch (kind) {
    case WorldReportPart::Kind::kBackground: return "background";
    case WorldReportPart::Kind::kAttachment: return "attachment";
    case WorldReportPart::Kind::kMachine: break;
  }
  return "machine";
}

// A part's mesh about its own centre, and its poses with that centre and
// the page's origin taken in (float precision for survey coordinates).
nlohmann::json PartData(const WorldReportPart& part, const Eigen::Vector3d& origin) {
  const Eigen::Vector3d centre = part.mesh.BoundingBox(Pose::Identity()).center();
  std::vector<float> positions;
  positions.reserve(3 * part.mesh.vertices.size());
  for (const Eigen::Vector3d& v : part.mesh.vertices) {
    const Eigen::Vector3d p = v - centre;
    positions.insert(positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                       static_cast<float>(p.z())});
  }
  std::vector<uint32_t> indices;
  indices.reserve(3 * part.mesh.triangles.size());
  for (const Eigen::Vector3i& t : part.mesh.triangles) {
    indices.insert(indices.end(), {static_cast<uint32_t>(t.x()), static_cast<uint32_t>(t.y()),
                                   static_cast<uint32_t>(t.z())});
  }
  std::vector<float> poses;
  poses.reserve(16 * part.T_world_part.size());
  for (const Pose& T : part.T_world_part) {
    Pose shown = T;
    shown.translation() += T.linear() * centre - origin;
    const Eigen::Matrix4d m = shown.matrix();  // column-major, as three.js's Matrix4.fromArray
    for (int i = 0; i < 16; ++i) poses.push_back(static_cast<float>(m.data()[i]));
  }
  return {{"name", part.name},
          {"machine", part.machine},
          {"kind", KindName(part.kind)},
          {"positions", Base64(positions)},
          {"indices", Base64(indices)},
          {"poses", Base64(poses)}};
}

}  // namespace

Status WriteWorldReport(const WorldReport& report, const std::string& path) {
  const size_t waypoints = report.waypoint_notes.size();
  if (waypoints == 0) return Status::Error("world report: no waypoints");
  if (report.collision_points.size() != waypoints) {
    return Status::Error("world report: one collision point per waypoint expected");
  }
  // The page's origin: the middle of the machines as they first stand.
  Eigen::AlignedBox3d box;
  for (const WorldReportPart& part : report.parts) {
    const size_t poses = part.T_world_part.size();
    if (poses != 1 && poses != waypoints) {
      return Status::Error("world report: part '" + part.name + "' has " + std::to_string(poses) +
                           " poses for " + std::to_string(waypoints) + " waypoints");
    }
    if (part.kind != WorldReportPart::Kind::kBackground && !part.mesh.empty()) {
      box.extend(part.mesh.BoundingBox(part.T_world_part.front()));
    }
  }
  const Eigen::Vector3d origin = box.isEmpty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(box.center());
  std::string three, orbit;
  EDGEFIT_RETURN_IF_ERROR(ReadThreeJs(report.three_js_dir, &three, &orbit));

  nlohmann::json parts = nlohmann::json::array();
  for (const WorldReportPart& part : report.parts) {
    if (!part.mesh.empty()) parts.push_back(PartData(part, origin));
  }
  std::vector<float> points;
  for (const Eigen::Vector3d& p : report.collision_points) {
    const Eigen::Vector3d shown = p - origin;
    points.insert(points.end(), {static_cast<float>(shown.x()), static_cast<float>(shown.y()),
                                 static_cast<float>(shown.z())});
  }
  const nlohmann::json data = {{"machine", report.machine},
                               {"parts", parts},
                               {"notes", report.waypoint_notes},
                               {"collision_points", Base64(points)}};

  std::string page = ThreeViewPageHead(report.title, kWorldStyle) + "<header><h1>" + EscapeHtml(report.title) +
                     "</h1>\n";
  for (const std::string& line : report.lines) page += "<p>" + EscapeHtml(line) + "</p>\n";
  page += R"html(</header>
<main>
<div id="view">
 <div id="controls">
  <label><input type="checkbox" id="show-machines" checked> machines</label><br>
  <label><input type="checkbox" id="show-background" checked> background</label><br>
  <span class="swatch" style="background: #2f62b3"></span>the machine checked
  <span class="swatch" style="background: #8fb0de"></span>others<br>
  <span class="swatch" style="background: #e08a2b"></span>attachments
  <span class="swatch" style="background: #a8a8a8"></span>background
  <span class="swatch" style="background: #d00000"></span>collision
 </div>
</div>
<div id="side">
 <p>waypoint <span id="at"></span> <button type="button" id="play">play / stop</button></p>
 <input type="range" id="waypoint" min="0" value="0" step="1">
 <div id="note"></div>
)html";
  for (const Chart& chart : report.charts) page += SvgChart(chart, 560, 300);
  page += "</div>\n</main>\n<div id=\"status\">loading</div>\n";
  page += ThreeViewPageEnd(data.dump(), three, orbit, kWorldScript);
  return WriteStringAtomically(path, page);
}

}  // namespace edgefit
