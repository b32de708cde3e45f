#include "report_page.h"

#include <string>

#include "html.h"
#include "three_view.h"

namespace edgefit {
namespace {

constexpr char kStyle[] = R"css(
h2 { font-size: 15px; margin: 18px 0 6px; }
.ok { color: #17803a; font-weight: bold; }
.bad { color: #b3261e; font-weight: bold; }
#legend { position: absolute; bottom: 8px; right: 8px; max-width: 250px; background: rgba(255,255,255,.85);
          padding: 6px 8px; border: 1px solid #ccc; border-radius: 4px; font-size: 11px; }
#legend canvas { display: block; margin: 3px 0; }
#side { flex: 1 1 420px; padding: 0 16px 16px; max-height: 640px; overflow-y: auto; }
table { border-collapse: collapse; font-size: 13px; }
td, th { border-bottom: 1px solid #e3e3e3; padding: 2px 8px; text-align: right; }
td:first-child, th:first-child { text-align: left; }
.verdict-ok { color: #17803a; } .verdict-bad { color: #b3261e; }
.histograms { display: flex; flex-wrap: wrap; gap: 8px; }
.histograms figure { margin: 0; font-size: 12px; }
)css";

constexpr char kScript[] = R"js(
const result = data.result;

function el(tag, attrs, text) {
  const e = document.createElement(tag);
  for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  return e;
}
function fmt(x, digits) { return (x === null || x === undefined || !isFinite(x)) ? '–' : x.toFixed(digits); }

// Distance colour (the report's ResidualColour, one entry per 0.1 mm up to
// not_modelled, then the grey of points farther away).
const scale = data.colours.residual_scale_m, farAway = data.colours.not_modelled_m;
const palette = decode(data.colours.palette, Uint8Array), last = palette.length / 3 - 1;
function colour(d, out, i) {
  const k = 3 * (d > farAway ? last : Math.min(Math.round(d * 1e4), last - 1));
  out[i] = palette[k] / 255; out[i + 1] = palette[k + 1] / 255; out[i + 2] = palette[k + 2] / 255;
}

// Header: verdict and base.
const q = result.quality || {};
document.getElementById('verdict').innerHTML = '';
document.getElementById('verdict').append(
    el('span', {class: q.ok ? 'ok' : 'bad'}, q.ok ? 'fit ok' : 'fit NOT ok'),
    document.createTextNode(q.message ? ': ' + q.message : ''));
if (result.base) {
  const b = result.base, deg = 180 / Math.PI;
  document.getElementById('base').textContent =
      'base: xyz ' + b.xyz.map(v => fmt(v, 4)).join(' ') + ' m, rpy ' +
      b.rpy.map(v => fmt(v * deg, 3)).join(' ') + ' deg' +
      (result.errors ? '; error ' + fmt(result.errors.base_translation_m * 1e3, 2) + ' mm, ' +
       fmt(result.errors.base_rotation_rad * deg, 4) + ' deg (survey frame ' +
       fmt(result.errors.base_survey_translation_m * 1e3, 2) + ' mm)' : '');
}

// Joints: value, verdict, standard deviation, error against a truth.
(function joints() {
  const table = document.getElementById('joints');
  const errors = result.errors ? result.errors.joints : null;
  const head = ['joint', 'value', 'verdict', 'std', ...(errors ? ['error'] : [])];
  const tr = el('tr'); head.forEach(h => tr.append(el('th', {}, h))); table.append(tr);
  for (const name of data.joint_order.filter(n => n in (result.joints || {}))) {
    const prismatic = data.joint_types[name] === 'prismatic';
    const f = prismatic ? 1e3 : 180 / Math.PI, unit = prismatic ? ' mm' : '°';
    const st = (result.joint_status || {})[name];
    const verdict = st ? st.verdict : 'dependent';
    const row = el('tr');
    row.append(el('td', {}, name), el('td', {}, fmt(result.joints[name] * f, 4) + unit),
               el('td', {class: ['ok', 'unobservable', 'dependent', 'given'].includes(verdict)
                                    ? 'verdict-ok' : 'verdict-bad'}, verdict),
               el('td', {}, st && st.std !== null && st.std !== undefined ? fmt(st.std * f, 4) + unit : '–'));
    if (errors) row.append(el('td', {}, name in errors ? fmt(errors[name] * f, 4) + unit : '–'));
    table.append(row);
  }
})();

// Per link: what the verdict rests on.
(function links() {
  const per = q.per_link || {};
  const table = document.getElementById('links');
  const tr = el('tr');
  ['link', 'visible samples', 'within gate', 'RMS', 'verdict'].forEach(h => tr.append(el('th', {}, h)));
  table.append(tr);
  for (const name of Object.keys(per)) {
    const l = per[name];
    const row = el('tr');
    row.append(el('td', {}, name), el('td', {}, String(l.visible)),
               el('td', {}, fmt(100 * l.inlier_share, 1) + ' %'), el('td', {}, fmt(l.rms_m * 1e3, 2) + ' mm'),
               el('td', {class: l.ok ? 'verdict-ok' : 'verdict-bad'}, l.verdict));
    table.append(row);
  }
})();

// What each station saw: its grid around the model, the same colours.
(function stations() {
  const box = document.getElementById('stations');
  for (const s of data.stations) {
    const fig = el('figure');
    const img = el('img', {alt: 'station ' + s.station, style: 'max-width: 100%'});
    img.src = 'data:image/png;base64,' + s.png;
    fig.append(img, el('figcaption', {}, 'station ' + s.station + ' (' + s.file + ')'));
    box.append(fig);
  }
})();

// Stage timings and options.
(function timings() {
  const table = document.getElementById('timings');
  for (const [stage, s] of Object.entries(result.timing_s || {})) {
    const row = el('tr'); row.append(el('td', {}, stage), el('td', {}, fmt(s, 2) + ' s')); table.append(row);
  }
  document.getElementById('options').textContent = JSON.stringify(result.options || {}, null, 1);
})();

// The scan's points near the model, coloured by distance.
const pts = data.points;
const positions = decode(pts.positions, Float32Array);
const dist = decode(pts['distance_0.1mm'], Uint16Array);
const linkOf = decode(pts.link, Uint16Array);
document.getElementById('pointinfo').textContent =
    pts.count + ' of the ' + pts.near + ' scan points within the model\'s box (every ' + pts.stride + ')';

// Residual histograms per link: points nearest the link, within not_modelled.
(function histograms() {
  const bins = 20, binWidth = farAway / bins, counts = {}, far = {};
  for (let i = 0; i < dist.length; ++i) {
    const name = data.link_names[linkOf[i]], d = dist[i] * 1e-4;
    counts[name] = counts[name] || new Array(bins).fill(0);
    if (d >= farAway) { far[name] = (far[name] || 0) + 1; continue; }
    counts[name][Math.floor(d / binWidth)]++;
  }
  const box = document.getElementById('histograms');
  for (const name of Object.keys(counts).sort()) {
    const c = counts[name], total = c.reduce((a, b) => a + b, 0);
    if (total < 50) continue;
    const fig = el('figure'), canvas = el('canvas', {width: 160, height: 60});
    const g = canvas.getContext('2d'), top = Math.max(...c);
    for (let b = 0; b < bins; ++b) {
      const rgb = [0, 0, 0]; colour((b + 0.5) * binWidth, rgb, 0);
      g.fillStyle = 'rgb(' + rgb.map(v => Math.round(255 * v)).join(',') + ')';
      const h = 56 * c[b] / top; g.fillRect(b * 8, 58 - h, 7, h);
    }
    fig.append(canvas, el('figcaption', {}, name + ': ' + total + ' points' +
                                           (far[name] ? ', ' + far[name] + ' farther' : '')));
    box.append(fig);
  }
  document.getElementById('histrange').textContent = '0 to ' + fmt(farAway * 1e3, 0) + ' mm';
})();

// The 3D view.
const colours = new Float32Array(positions.length);
for (let i = 0; i < dist.length; ++i) colour(dist[i] * 1e-4, colours, 3 * i);
const cloudGeometry = new THREE.BufferGeometry();
cloudGeometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
cloudGeometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
const cloud = new THREE.Points(cloudGeometry, new THREE.PointsMaterial({size: 2, sizeAttenuation: false, vertexColors: true}));
scene.add(cloud);

const model = new THREE.Group();
const material = new THREE.MeshLambertMaterial({color: 0x4a78c2, transparent: true, opacity: 0.45,
                                                side: THREE.DoubleSide, depthWrite: false});
for (const link of data.links) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(decode(link.positions, Float32Array), 3));
  g.setIndex(new THREE.BufferAttribute(decode(link.indices, Uint32Array), 1));
  g.computeVertexNormals();
  const mesh = new THREE.Mesh(g, material); mesh.name = link.name; model.add(mesh);
}
scene.add(model);

const bounds = new THREE.Box3().setFromObject(model);
const centre = bounds.getCenter(new THREE.Vector3()), size = bounds.getSize(new THREE.Vector3()).length();
const camera = new THREE.PerspectiveCamera(40, view.clientWidth / view.clientHeight, size / 100, size * 100);
camera.up.set(0, 0, 1);
const toward = data.scanners.length ? new THREE.Vector3(...data.scanners[0]).sub(centre).normalize()
                                    : new THREE.Vector3(1, -1, 0.5).normalize();
camera.position.copy(centre).addScaledVector(toward, 1.4 * size);
const controls = new THREE.OrbitControls(camera, renderer.domElement);
controls.target.copy(centre);
controls.update();

// Point colours: by distance (optionally only the points far from the
// model), or the edge map (points in valid edge regions, Eq. 6, red).
const edges = data.points.edge ? decode(data.points.edge, Uint8Array) : null;
function recolour() {
  const mode = document.getElementById('colour-by').value;
  const farOnly = document.getElementById('far-only').checked;
  const c = cloudGeometry.getAttribute('color');
  for (let i = 0; i < dist.length; ++i) {
    const d = dist[i] * 1e-4;
    if (mode === 'edges' && edges) {
      if (edges[i]) { c.array[3 * i] = 0.85; c.array[3 * i + 1] = 0.1; c.array[3 * i + 2] = 0.1; }
      else c.array[3 * i] = c.array[3 * i + 1] = c.array[3 * i + 2] = 0.82;
    } else if (farOnly && d <= farAway) {
      c.array[3 * i] = c.array[3 * i + 1] = c.array[3 * i + 2] = 0.93;
    } else {
      colour(d, c.array, 3 * i);
    }
  }
  c.needsUpdate = true;
  cloud.material.size = farOnly || mode === 'edges' ? 3 : 2;
  document.getElementById('distance-legend').style.display = mode === 'edges' ? 'none' : '';
  document.getElementById('edge-legend').style.display = mode === 'edges' ? '' : 'none';
}
function render() {
  cloud.visible = document.getElementById('show-scan').checked;
  model.visible = document.getElementById('show-model').checked;
  renderer.render(scene, camera);
}
for (const id of ['colour-by', 'far-only']) {
  document.getElementById(id).addEventListener('change', () => { recolour(); render(); });
}
for (const id of ['show-scan', 'show-model']) document.getElementById(id).addEventListener('change', render);
// Each station's viewpoint (where the scanner stood, looking at the model),
// and the overview.
function lookFrom(position) {
  camera.position.copy(position);
  controls.target.copy(centre);
  controls.update();
  render();
}
(function viewpoints() {
  const box = document.getElementById('viewpoints');
  const overview = camera.position.clone();
  const add = (label, position) => {
    const b = el('button', {type: 'button'}, label);
    b.addEventListener('click', () => lookFrom(position));
    box.append(b, document.createTextNode(' '));
  };
  add('overview', overview);
  data.scanners.forEach((s, k) => add('station ' + (k + 1), new THREE.Vector3(...s)));
})();
controls.addEventListener('change', render);
window.addEventListener('resize', () => {
  camera.aspect = view.clientWidth / view.clientHeight; camera.updateProjectionMatrix();
  renderer.setSize(view.clientWidth, view.clientHeight); render();
});
recolour();
render();

// The edge map: what Sec. 4 found, or why there is none.
(function edgeMap() {
  const m = data.edge_map, option = document.querySelector('#colour-by option[value=edges]');
  const text = m.available
      ? m.edge_points + ' of ' + m.points + ' points in ' + m.regions + ' valid edge regions (' +
        m.candidates + ' candidates; Eq. 6 weight ' + m.w_high + ' when the fit uses edge weights)'
      : 'no edge map: ' + m.why;
  document.getElementById('edgeinfo').textContent = text;
  document.getElementById('edge-legend').textContent = 'red: points in valid edge regions. ' + text;
  if (!m.available) option.disabled = true;
})();

// Legend.
(function legend() {
  const canvas = document.getElementById('colourbar'), g = canvas.getContext('2d'), rgb = [0, 0, 0];
  for (let x = 0; x < canvas.width; ++x) {
    colour(scale * x / (canvas.width - 1), rgb, 0);
    g.fillStyle = 'rgb(' + rgb.map(v => Math.round(255 * v)).join(',') + ')';
    g.fillRect(x, 0, 1, canvas.height);
  }
  document.getElementById('scalemax').textContent = fmt(scale * 1e3, 0) + ' mm';
  document.getElementById('farlabel').textContent = 'grey: farther than ' + fmt(farAway * 1e3, 0) +
      ' mm from the model (not the model: accessories, jackets, surroundings)';
})();

if (!status.textContent.startsWith('error')) status.textContent = 'ok: ' + drawnPixels() + ' pixels drawn';
)js";

}  // namespace

std::string ReportPage(const std::string& title, const std::string& three_js,
                       const std::string& orbit_controls_js, const std::string& data_json) {
  const std::string t = EscapeHtml(title);
  std::string page;
  page.reserve(data_json.size() + three_js.size() + orbit_controls_js.size() + 20000);
  page += ThreeViewPageHead(title, kStyle);
  page += "<header><h1>" + t + "</h1><div id=\"verdict\"></div><div id=\"base\"></div></header>\n";
  page += R"html(<main>
<div id="view">
 <div id="controls">
  <label><input type="checkbox" id="show-model" checked> fitted model</label><br>
  <label><input type="checkbox" id="show-scan" checked> scan</label><br>
  <label><input type="checkbox" id="far-only"> only points far from the model</label><br>
  <label>colour by <select id="colour-by"><option value="distance">distance to the model</option>
   <option value="edges">edge map (Sec. 4, Eq. 6)</option></select></label><br>
  <span id="viewpoints">view from </span>
 </div>
 <div id="legend"><div id="distance-legend">distance to the fitted model: 0
  <canvas id="colourbar" width="160" height="10"></canvas> <span id="scalemax"></span> and more<br>
  <span id="farlabel"></span></div><div id="edge-legend" style="display: none"></div>
  <span id="pointinfo"></span></div>
</div>
<div id="side">
 <h2>Joints</h2><table id="joints"></table>
 <h2>Links</h2><table id="links"></table>
 <h2>Edge map</h2><p id="edgeinfo"></p>
 <h2>Residuals per link (<span id="histrange"></span>)</h2><div class="histograms" id="histograms"></div>
 <h2>What each station saw</h2><div id="stations"></div>
 <h2>Stage timings</h2><table id="timings"></table>
 <h2>Options</h2><pre id="options"></pre>
</div>
</main>
<div id="status">loading</div>
)html";
  page += ThreeViewPageEnd(data_json, three_js, orbit_controls_js, kScript);
  return page;
}

}  // namespace edgefit
