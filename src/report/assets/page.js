// What the report's pages (report.js, interference.js) share: decoding their meshes, making DOM
// elements, and their 3-D view's renderer, background and lights, and size.
import * as THREE from 'three';

// Base64 (the page data's meshes and fields) to a typed array.
export function decode(base64, Type) {
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);  // a plain loop: Uint8Array.from(text, fn) is ~5x slower
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return new Type(bytes.buffer);
}

// An element with attributes ('text': its text, 'class': its class) and children.
export function el(tag, attrs = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'text') e.textContent = v;
    else if (k === 'class') e.className = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

export const BACKGROUND = 0xeef1f6;  // tests/report/*.mjs look for it in screenshots

// The renderer on the canvas, or null when the browser has no WebGL 2. Multisampling triples
// the first frame in software WebGL (SwiftShader, llvmpipe: experiments/report/README.md), so
// there the view is drawn without it; a GPU gets a fresh canvas with antialiasing. The drawing
// buffer is kept for screenshots. The canvas drawn on is renderer.domElement.
export function openRenderer(canvas) {
  const attributes = { alpha: true, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: true, powerPreference: 'default' };
  let context = canvas.getContext('webgl2', { ...attributes, antialias: false });
  if (!context) return null;
  const info = context.getExtension('WEBGL_debug_renderer_info');
  const device = info ? String(context.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  if (!/swiftshader|llvmpipe|softpipe|software/i.test(device)) {
    const fresh = canvas.cloneNode(false);
    canvas.replaceWith(fresh);
    const smooth = fresh.getContext('webgl2', { ...attributes, antialias: true });
    if (smooth) {
      context.getExtension('WEBGL_lose_context')?.loseContext();
      canvas = fresh, context = smooth;
    } else {
      fresh.replaceWith(canvas);
    }
  }
  try {
    return new THREE.WebGLRenderer({ canvas, context });
  } catch {
    return null;
  }
}

export function addLights(scene) {
  scene.background = new THREE.Color(BACKGROUND);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f99, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(1, -1.5, 2.5);
  scene.add(sun);
}

// The drawing buffer sized to the canvas on screen; false when it already is (setting a canvas's
// size clears it even to the same value, and the page would have to draw everything again).
export function fitToCanvas(renderer, camera) {
  const canvas = renderer.domElement;
  const w = canvas.clientWidth, h = canvas.clientHeight, ratio = Math.min(window.devicePixelRatio || 1, 2);
  if (!w || !h || (canvas.width === Math.floor(w * ratio) && canvas.height === Math.floor(h * ratio))) return false;
  renderer.setPixelRatio(ratio);
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
  return true;
}
