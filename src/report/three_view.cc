#include "three_view.h"

#include <string>

#include "html.h"

namespace edgefit {
namespace {

constexpr char kThreeViewStyle[] = R"css(
body { font: 14px/1.4 sans-serif; margin: 0; color: #222; }
header { padding: 10px 16px; background: #f4f4f4; border-bottom: 1px solid #ddd; }
h1 { font-size: 18px; margin: 0 0 4px; }
main { display: flex; flex-wrap: wrap; }
#view { position: relative; flex: 1 1 640px; min-width: 480px; height: 620px; background: #fff; }
#controls { position: absolute; top: 8px; left: 8px; background: rgba(255,255,255,.85);
            padding: 6px 8px; border: 1px solid #ccc; border-radius: 4px; }
#status { font-size: 11px; color: #888; padding: 4px 16px; }
)css";

constexpr char kThreeViewScript[] = R"js(
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

}  // namespace

std::string ThreeViewPageHead(const std::string& title, const char* style) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" + EscapeHtml(title) +
         "</title>\n<style>" + kThreeViewStyle + style + "</style></head>\n<body>\n";
}

std::string ThreeViewPageEnd(const std::string& data_json, const std::string& three_js,
                             const std::string& orbit_controls_js, const char* script) {
  return "<script type=\"application/json\" id=\"data\">" + EscapeScript(data_json) + "</script>\n" +
         "<script>" + EscapeScript(three_js) + "</script>\n" + "<script>" + EscapeScript(orbit_controls_js) +
         "</script>\n<script>" + kThreeViewScript + script + "</script>\n</body></html>\n";
}

}  // namespace edgefit
