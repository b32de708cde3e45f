// The script both 3D reports (report_page.cc, world_report.cc) run before
// their own: the status line, the page's data, decode(), a three.js
// renderer, scene and lights in the element #view, and drawnPixels().
#ifndef EDGEFIT_REPORT_THREE_VIEW_H_
#define EDGEFIT_REPORT_THREE_VIEW_H_

namespace edgefit {

inline constexpr char kThreeViewScript[] = R"js(
'use strict';
const status = document.getElementById('status');
window.addEventListener('error', e => { status.textContent = 'error: ' + e.message; });
const data = JSON.parse(document.getElementById('data').textContent);
function decode(b64, Type) {
  const bytes = Uint8Array.from(atob(b64), c => c.charCodeAt(0));
  return new Type(bytes.buffer);
}

const view = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
renderer.setPixelRatio(window.devicePixelRatio || 1);
renderer.setSize(view.clientWidth, view.clientHeight);
view.prepend(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xffffff);
scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 0.9));
const sun = new THREE.DirectionalLight(0xffffff, 0.5); sun.position.set(1, 2, 3); scene.add(sun);

// How many pixels the view drew (not white), for whoever checks the page
// without eyes.
function drawnPixels() {
  const gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const pixels = new Uint8Array(4 * w * h);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let drawn = 0;
  for (let i = 0; i < pixels.length; i += 4) drawn += (pixels[i] & pixels[i + 1] & pixels[i + 2]) !== 255;
  return drawn;
}
)js";

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_THREE_VIEW_H_
