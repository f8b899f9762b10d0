// The report page: a 3-D view of one layout in its mold, the Pareto front of a generation
// whose points load their layout, and the run's convergence. The data is the JSON that
// src/report/run_report.cpp writes into #report-data; lengths are in mm.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { decode, el, openRenderer, addLights, fitToCanvas } from 'mtcs/page';

performance.mark('mtcs-start');  // three.js is loaded and parsed
const data = JSON.parse(document.getElementById('report-data').textContent);
performance.mark('mtcs-data');  // the data parsed
const $ = (id) => document.getElementById(id);
const CIRCUIT_COLORS = ['#1f77b4', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2', '#7f7f7f'];
const circuitColor = (c) => CIRCUIT_COLORS[c % CIRCUIT_COLORS.length];

// ---------------------------------------------------------------- numbers and formats
const numberFormat = new Intl.NumberFormat('en-US', { maximumFractionDigits: 4 });  // toLocaleString builds one per call
function fmt(v, digits = 3) {
  if (v === null || v === undefined || Number.isNaN(v)) return '\u2013';
  if (!Number.isFinite(v)) return v > 0 ? '\u221e' : '\u2212\u221e';
  const a = Math.abs(v);
  if (a !== 0 && (a >= 1e6 || a < 1e-3)) return v.toExponential(2);
  return numberFormat.format(Number(v.toPrecision(digits + (a >= 1000 ? 1 : 0))));
}
const withUnit = (v, unit) => (unit ? `${fmt(v)} ${unit}` : fmt(v));
const objectiveLabel = (o) => (o.unit ? `${o.name.replace(/_/g, ' ')} (${o.unit})` : o.name.replace(/_/g, ' '));
// Shortfall colour: amount 0 (at the clearance) yellow, 1 (touching or crossing) red.
function shortfallColor(amount) {
  const t = Math.max(0, Math.min(1, amount));
  return new THREE.Color().setHSL((1 - t) * 0.15, 0.95, 0.5);
}
// Viridis-like ramp for the temperature.
const RAMP = [[0.267, 0.005, 0.329], [0.231, 0.322, 0.545], [0.129, 0.569, 0.549], [0.369, 0.788, 0.384], [0.993, 0.906, 0.144]];
function rampColor(t) {
  const x = Math.max(0, Math.min(1, t)) * (RAMP.length - 1);
  const i = Math.min(RAMP.length - 2, Math.floor(x));
  const f = x - i;
  return RAMP[i].map((a, k) => a + (RAMP[i + 1][k] - a) * f);
}
const rampCss = () => `linear-gradient(to right, ${RAMP.map((c) => `rgb(${c.map((v) => Math.round(v * 255)).join(',')})`).join(',')})`;

// ---------------------------------------------------------------- header
const objectives = data.objectives;
$('title').textContent = data.title;
document.title = data.title;
{
  const r = data.run;
  const s = r.seconds >= 1 ? `${fmt(r.seconds)} s` : `${fmt(r.seconds * 1000)} ms`;
  $('run-info').textContent = `run ${r.dir} \u00b7 mold ${r.mold} \u00b7 ${r.algorithm.toUpperCase()}, seed ${r.seed} \u00b7 ` +
    `${r.evaluations.toLocaleString('en-US')} evaluations in ${s} \u00b7 lengths in ${data.units}` + (r.program ? ` \u00b7 ${r.program}` : '');
  if (r.note) { $('note').textContent = r.note; $('note').hidden = false; }
}

// ---------------------------------------------------------------- 3-D view
const renderer = openRenderer($('view3d'));
if (!renderer) $('webgl-error').hidden = false;
const canvas = renderer ? renderer.domElement : $('view3d');
const scene3 = new THREE.Scene();
addLights(scene3);
const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e6);
camera.up.set(0, 0, 1);  // molds stand on z
const controls = renderer ? new OrbitControls(camera, canvas) : null;

// The section plane cuts everything (the renderer's global plane) from the start and keeps it:
// moving or switching the plane changes its numbers only, never a shader. "Off" is a plane that
// cuts nothing. A first render of an empty scene sets the renderer's clipping state, so that
// the shaders compiled ahead (warmUp) are the ones the first frame uses.
const sectionPlane = new THREE.Plane(new THREE.Vector3(0, 0, 1), 1e12);
if (renderer) {
  renderer.clippingPlanes = [sectionPlane];
  renderer.render(new THREE.Scene(), camera);
}
// Few shader programs: compiling them is most of the first frame in software WebGL
// (experiments/report/README.md). Lambert, not the physically based standard material (its
// shaders compile several times slower); every solid double-sided (one program), every
// see-through surface drawn in one pass (one more program).
function material(params) {
  return new THREE.MeshLambertMaterial({ side: THREE.DoubleSide, ...params });
}
function seeThrough(params) {
  return material({ transparent: true, depthWrite: false, forceSinglePass: true, ...params });
}
function lineMaterial(params) {
  return new THREE.LineBasicMaterial(params);
}
// Those programs compiled ahead, on stand-ins: the browser's GPU process compiles them while this
// script decodes and builds the meshes, and the first frame finds them ready (flush sends the
// work now; three.js checks a program only when it first draws with it). Kept until then.
const warmUp = new THREE.Scene();
if (renderer) {
  const tiny = new THREE.BufferGeometry();
  tiny.setAttribute('position', new THREE.Float32BufferAttribute([0, 0, 0, 1, 0, 0, 0, 1, 0], 3));
  tiny.setAttribute('normal', new THREE.Float32BufferAttribute([0, 0, 1, 0, 0, 1, 0, 0, 1], 3));
  const materials = [material({}), seeThrough({}), ...(data.temperature ? [material({ vertexColors: true })] : [])];
  for (const m of materials) warmUp.add(new THREE.Mesh(tiny, m));
  const line = new THREE.BufferGeometry();  // lines have no normals (a normal changes the program)
  line.setAttribute('position', tiny.getAttribute('position'));
  warmUp.add(new THREE.LineSegments(line, lineMaterial({})));
  warmUp.add(new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(document.createElement('canvas')), depthTest: false })));
  renderer.compile(warmUp, camera, scene3);
  renderer.getContext().flush();
}

function v3(a) { return new THREE.Vector3(a[0], a[1], a[2]); }
function boxGeometry(box) {
  const size = v3(box.max).sub(v3(box.min));
  const g = new THREE.BoxGeometry(Math.max(size.x, 1e-3), Math.max(size.y, 1e-3), Math.max(size.z, 1e-3));
  g.translate(...v3(box.min).add(v3(box.max)).multiplyScalar(0.5).toArray());
  return g;
}
function meshGeometry(m) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(decode(m.positions, Float32Array), 3));
  g.setIndex(new THREE.BufferAttribute(decode(m.indices, Uint32Array), 1));
  g.computeVertexNormals();
  return g;
}
// The feature edges of an indexed mesh (dihedral angle above `degrees`, or open), as
// THREE.EdgesGeometry draws them but keyed by vertex index instead of by a string of every
// corner's coordinates: ~0.1 s instead of ~1 s on a 100k-triangle part (mesh_json's meshes share
// their vertices).
function featureEdges(g, degrees = 30) {
  const pos = g.getAttribute('position').array, idx = g.getIndex().array;
  const nv = pos.length / 3, nt = idx.length / 3, cos = Math.cos(degrees * Math.PI / 180);
  const normals = new Float32Array(3 * nt);
  for (let t = 0; t < nt; ++t) {
    const a = 3 * idx[3 * t], b = 3 * idx[3 * t + 1], c = 3 * idx[3 * t + 2];
    const ux = pos[b] - pos[a], uy = pos[b + 1] - pos[a + 1], uz = pos[b + 2] - pos[a + 2];
    const vx = pos[c] - pos[a], vy = pos[c + 1] - pos[a + 1], vz = pos[c + 2] - pos[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx, len = Math.hypot(nx, ny, nz) || 1;
    normals[3 * t] = nx / len; normals[3 * t + 1] = ny / len; normals[3 * t + 2] = nz / len;
  }
  const open = new Map();  // edge (lo * nv + hi) -> the first triangle seen on it
  const lines = [];
  const push = (i, j) => lines.push(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], pos[3 * j], pos[3 * j + 1], pos[3 * j + 2]);
  for (let t = 0; t < nt; ++t) {
    for (let e = 0; e < 3; ++e) {
      const i = idx[3 * t + e], j = idx[3 * t + (e + 1) % 3];
      const key = Math.min(i, j) * nv + Math.max(i, j);
      const other = open.get(key);
      if (other === undefined) { open.set(key, t); continue; }
      open.delete(key);
      const dot = normals[3 * t] * normals[3 * other] + normals[3 * t + 1] * normals[3 * other + 1] + normals[3 * t + 2] * normals[3 * other + 2];
      if (dot <= cos) push(i, j);
    }
  }
  for (const key of open.keys()) push(Math.floor(key / nv), key % nv);
  const out = new THREE.BufferGeometry();
  out.setAttribute('position', new THREE.Float32BufferAttribute(lines, 3));
  return out;
}
const edgesOf = (g, box) => (box ? new THREE.EdgesGeometry(g, 30) : featureEdges(g, 30));

// A solid cylinder from p0 to p1.
function cylinder(p0, p1, radius, mat, segments = 28) {
  const a = v3(p0), b = v3(p1);
  const axis = b.clone().sub(a);
  const length = Math.max(axis.length(), 1e-6);
  const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, length, segments), mat);
  mesh.position.copy(a).add(b).multiplyScalar(0.5);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis.normalize());
  return mesh;
}
// A flat plate `width` x `thickness` mm from p0 to p1 (a baffle's blade), across `across`.
function blade(p0, p1, width, thickness, mat) {
  const a = v3(p0), b = v3(p1);
  const axis = b.clone().sub(a);
  const mesh = new THREE.Mesh(new THREE.BoxGeometry(width, Math.max(axis.length(), 1e-6), thickness), mat);
  mesh.position.copy(a).add(b).multiplyScalar(0.5);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis.normalize());
  return mesh;
}
function sphere(at, radius, mat) {
  const m = new THREE.Mesh(new THREE.SphereGeometry(radius, 20, 14), mat);
  m.position.copy(v3(at));
  return m;
}
// A text label that always faces the camera, about `height` mm tall.
function label(text, at, height, color = '#1d2330') {
  const c = document.createElement('canvas');
  const ctx = c.getContext('2d');
  const px = 48;
  ctx.font = `600 ${px}px system-ui, sans-serif`;
  c.width = Math.ceil(ctx.measureText(text).width + px * 0.6);
  c.height = Math.ceil(px * 1.35);
  ctx.font = `600 ${px}px system-ui, sans-serif`;
  ctx.fillStyle = 'rgba(255,255,255,0.85)';
  ctx.fillRect(0, 0, c.width, c.height);
  ctx.fillStyle = color;
  ctx.textBaseline = 'middle';
  ctx.fillText(text, px * 0.3, c.height / 2);
  const texture = new THREE.CanvasTexture(c);
  texture.colorSpace = THREE.SRGBColorSpace;
  const sm = new THREE.SpriteMaterial({ map: texture, depthTest: false });
  const s = new THREE.Sprite(sm);
  s.scale.set(height * c.width / c.height, height, 1);
  s.position.copy(v3(at));
  s.renderOrder = 10;
  return s;
}
// Frees a layout's layer: its geometries, materials and label textures.
function dispose(group) {
  const materials = new Set();
  group.traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) materials.add(o.material); });
  for (const m of materials) {
    if (m.map) m.map.dispose();
    m.dispose();
  }
  group.clear();
}

// The scene's frame: the block's bounds.
const blockBounds = (() => {
  const b = data.scene.block;
  if (b.box) return new THREE.Box3(v3(b.box.min), v3(b.box.max));
  return new THREE.Box3().setFromBufferAttribute(meshGeometry(b.mesh).getAttribute('position'));
})();
const blockSize = blockBounds.getSize(new THREE.Vector3());
const blockCenter = blockBounds.getCenter(new THREE.Vector3());
const markSize = Math.max(blockSize.x, blockSize.y, blockSize.z) / 40;

// Layers: each a group with a checkbox and a key (1-7).
const layers = {};
function addLayer(key, title, visible = true) {
  const group = new THREE.Group();
  group.visible = visible;
  scene3.add(group);
  const box = el('input', { type: 'checkbox', id: `layer-${key}` });
  box.checked = visible;
  box.addEventListener('change', () => { group.visible = box.checked; render(); });
  const n = Object.keys(layers).length + 1;
  const lab = el('label', { for: `layer-${key}`, title: `key ${n}` }, [box, ` ${title}`]);
  $('layers').append(lab);
  layers[key] = { group, box, label: lab };
  return group;
}
function setLayerAvailable(key, available, why = '') {
  const l = layers[key];
  l.box.disabled = !available;
  l.label.classList.toggle('off', !available);
  l.label.title = available ? '' : why;
  l.group.visible = available && l.box.checked;
}

const blockLayer = addLayer('block', 'block');
const partLayer = addLayer('part', 'part');
const keepOutLayer = addLayer('keepouts', 'keep-outs');
const boreLayer = addLayer('bores', 'bores');
const portLayer = addLayer('ports', 'inlets / outlets');
const clashLayer = addLayer('clearances', 'violated clearances');
const temperatureLayer = addLayer('temperature', 'cavity temperature', !!data.temperature);
const coolantLayer = addLayer('coolant', 'bores by coolant temperature', false);

// Block: transparent faces and its edges.
{
  const b = data.scene.block;
  const g = b.box ? boxGeometry(b.box) : meshGeometry(b.mesh);
  const faces = new THREE.Mesh(g, seeThrough({ color: 0x9fb3c8, opacity: 0.12 }));
  faces.renderOrder = 5;
  blockLayer.add(faces);
  blockLayer.add(new THREE.LineSegments(edgesOf(g, b.box), lineMaterial({ color: 0x5b6b80 })));
}
// The part (cavity).
if (data.scene.cavity) {
  const c = data.scene.cavity;
  const g = c.box ? boxGeometry(c.box) : meshGeometry(c.mesh);
  partLayer.add(new THREE.Mesh(g, material({ color: 0xd9a441 })));
  partLayer.add(new THREE.LineSegments(edgesOf(g, c.box), lineMaterial({ color: 0x8a6410 })));
} else {
  setLayerAvailable('part', false, 'this mold has no part');
}
// Keep-outs, with their clearance as a faint sleeve.
{
  const solid = material({ color: 0x6b7280 });
  const sleeve = seeThrough({ color: 0x6b7280, opacity: 0.15 });
  for (const k of data.scene.keep_outs) {
    if (k.cylinder) {
      keepOutLayer.add(cylinder(k.cylinder.p0, k.cylinder.p1, k.cylinder.radius, solid));
      keepOutLayer.add(cylinder(k.cylinder.p0, k.cylinder.p1, k.cylinder.radius + k.clearance, sleeve));
    } else {
      keepOutLayer.add(new THREE.Mesh(meshGeometry(k.mesh), solid));
    }
  }
  if (!data.scene.keep_outs.length) setLayerAvailable('keepouts', false, 'this mold has no keep-outs');
}
// The cavity temperature (one layout's: data.temperature.member).
let temperatureMin = 0, temperatureMax = 1;
if (data.temperature) {
  const t = data.temperature;
  const g = meshGeometry(t.mesh);
  const values = decode(t.values, Float32Array);
  // The colour scale spans the field, so that its differences show.
  temperatureMin = t.min; temperatureMax = Math.max(t.max, t.min + 1e-9);
  const colors = new Float32Array(values.length * 3);
  values.forEach((v, i) => colors.set(Number.isFinite(v) ? rampColor((v - temperatureMin) / (temperatureMax - temperatureMin)) : [0.6, 0.6, 0.6], 3 * i));
  g.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  const m = new THREE.Mesh(g, material({ vertexColors: true, polygonOffset: true, polygonOffsetFactor: -1 }));
  temperatureLayer.add(m);
  // The hottest point, drawn through the surface (it often lies inside: a core, a lid's boss).
  const hot = new THREE.Mesh(new THREE.SphereGeometry(markSize / 2, 16, 12),
    new THREE.MeshBasicMaterial({ color: 0xff2020, depthTest: false, transparent: true, opacity: 0.9 }));
  hot.position.copy(v3(t.hottest));
  hot.renderOrder = 10;
  hot.name = 'hottest';
  temperatureLayer.add(hot);
} else {
  setLayerAvailable('temperature', false, 'no temperature in this report');
}

// The layout shown: bores, ports, violated clearances.
function showLayout(member) {
  for (const g of [boreLayer, portLayer, clashLayer, coolantLayer]) dispose(g);
  const layout = member.layout;
  const mats = new Map();
  const boreMaterial = (c) => {
    if (!mats.has(c)) mats.set(c, material({ color: circuitColor(c) }));
    return mats.get(c);
  };
  const plugMaterial = material({ color: 0x222222 });
  const insertMaterial = material({ color: 0xb08d57 });  // brass
  for (const b of layout.bores) {
    if (b.insert) {
      // A blind bore drawn see-through around its insert, which stands a diameter out of the
      // entry (the fitting): the blade or the tube, from the entry down to the tip.
      const [start, tip] = b.flow;
      const up = v3(start).sub(v3(tip)).normalize().multiplyScalar(b.diameter);
      const top = v3(start).add(up).toArray();
      boreLayer.add(cylinder(b.p0, b.p1, b.diameter / 2, seeThrough({ color: circuitColor(b.circuit), opacity: 0.45 })));
      const insert = b.tube ? cylinder(top, tip, b.tube[0] / 2, insertMaterial)
        : blade(top, tip, b.diameter * 0.92, Math.max(0.8, b.diameter * 0.1), insertMaterial);
      insert.userData.insert = b.insert;
      boreLayer.add(insert);
      boreLayer.add(label(`c${b.circuit} ${b.insert}`, v3(top).add(up).toArray(), markSize * 1.1));
      continue;
    }
    boreLayer.add(cylinder(b.p0, b.p1, b.diameter / 2, boreMaterial(b.circuit)));
    if (b.plugged) boreLayer.add(cylinder(b.p0, v3(b.p0).lerp(v3(b.p1), Math.min(1, b.diameter / Math.max(b.length, 1e-9))).toArray(), b.diameter / 2 + 0.6, plugMaterial));
  }
  const inMat = material({ color: 0x1565c0 }), outMat = material({ color: 0xc62828 });
  for (const p of layout.ports) {
    portLayer.add(sphere(p.inlet, markSize * 0.45, inMat));
    portLayer.add(sphere(p.outlet, markSize * 0.45, outMat));
    const lift = [0, 0, markSize * 1.3];
    portLayer.add(label(`c${p.circuit} in`, v3(p.inlet).add(v3(lift)).toArray(), markSize * 1.1, '#1565c0'));
    portLayer.add(label(`c${p.circuit} out`, v3(p.outlet).add(v3(lift).multiplyScalar(2.2)).toArray(), markSize * 1.1, '#c62828'));
  }
  // Each shortfall: a rod between the closest points and a ball at each, drawn over the solids
  // (a crossing has both points inside the solids), labelled with the shortfall when few.
  const drawn = member.violations.filter((v) => v.closest);
  for (const v of drawn) {
    const color = shortfallColor(v.amount);
    const [a, b] = v.closest;
    const dm = seeThrough({ color, emissive: color, emissiveIntensity: 0.6, depthTest: false, depthWrite: true, opacity: 0.95 });
    const parts = [sphere(a, markSize * 0.4, dm), sphere(b, markSize * 0.4, dm)];
    if (v3(a).distanceTo(v3(b)) > 1e-6) parts.push(cylinder(a, b, markSize * 0.12, dm, 10));
    if (drawn.length <= 24)
      parts.push(label(`${v.elements.join('\u2013')} ${fmt(v.distance)} < ${fmt(v.margin)} mm`, v3(a).add(v3(b)).multiplyScalar(0.5).add(new THREE.Vector3(0, 0, -markSize * 1.2)).toArray(), markSize * 0.9, '#b71c1c'));
    for (const p of parts) { p.renderOrder = 20; clashLayer.add(p); }
  }
  // Each bore coloured by its coolant's mean temperature along it (the warming from inlet to
  // outlet, as the model has it), over the plain bores.
  const coolant = coolantRange(member);
  if (coolant) {
    for (const b of layout.bores) {
      const c = coolant.byName.get(b.name);
      if (!c) continue;
      const t = ((c.in + c.out) / 2 - coolant.lo) / (coolant.hi - coolant.lo);
      coolantLayer.add(cylinder(b.flow[0], b.flow[1], b.diameter / 2 * 1.06, material({ color: new THREE.Color(...rampColor(t)) })));
    }
  }
  setLayerAvailable('coolant', !!coolant, member.coolant ? 'the heat per bore needs a temperature objective'
    : 'no coolant flow in the spec (thermal.coolant.flow_rate, supply_pressure or pump)');
  const temperatureHere = data.temperature && data.temperature.member === member.rank;
  setLayerAvailable('temperature', !!temperatureHere,
    data.temperature ? `the temperature is of member ${data.temperature.member} only` : 'no temperature in this report');
  drawLegend(member);
  render();
}

// The coolant's span over a member's bores (inlet to the warmest outlet), or null without one.
function coolantRange(member) {
  const bores = member.coolant && member.coolant.bores;
  if (!bores || !bores.length) return null;
  const lo = Math.min(...bores.map((b) => b.in)), hi = Math.max(...bores.map((b) => b.out));
  return { lo, hi: Math.max(hi, lo + 1e-9), byName: new Map(bores.map((b) => [b.name, b])) };
}

function drawLegend(member) {
  const legend = $('legend');
  legend.replaceChildren();
  const circuits = [...new Set(member.layout.bores.map((b) => b.circuit))].sort((a, b) => a - b);
  for (const c of circuits) {
    const d = [...new Set(member.layout.bores.filter((b) => b.circuit === c).map((b) => b.diameter))].join(', ');
    legend.append(el('div', { class: 'row' }, [el('span', { class: 'swatch', style: `background:${circuitColor(c)}` }), `circuit ${c} (\u2300 ${d} mm)`]));
  }
  legend.append(el('div', { class: 'row' }, [el('span', { class: 'dot', style: 'background:#1565c0' }), 'inlet ',
    el('span', { class: 'dot', style: 'background:#c62828' }), 'outlet']));
  if (member.violations.some((v) => v.closest))
    legend.append(el('div', { class: 'row' }, [el('span', { class: 'ramp', style: 'background:linear-gradient(to right,hsl(54,95%,50%),hsl(0,95%,50%))' }),
      'clearance shortfall 0\u2013100 %']));
  const coolant = coolantRange(member);
  if (coolant && layers.coolant.group.visible)
    legend.append(el('div', { class: 'row' }, [`coolant ${fmt(coolant.lo)}`, el('span', { class: 'ramp', style: `background:${rampCss()}` }),
      `${fmt(coolant.hi)} °C`]));
  if (data.temperature && data.temperature.member === member.rank && layers.temperature.group.visible)
    legend.append(el('div', { class: 'row' }, [`${fmt(temperatureMin)}`, el('span', { class: 'ramp', style: `background:${rampCss()}` }),
      `${fmt(temperatureMax)} \u00b0C (tier ${data.temperature.tier})`]));
}
layers.temperature.box.addEventListener('change', () => drawLegend(data.members[shown]));
layers.coolant.box.addEventListener('change', () => drawLegend(data.members[shown]));

// Camera, render on demand, resize.
function resetView() {
  const d = Math.max(blockSize.x, blockSize.y, blockSize.z);
  camera.position.copy(blockCenter).add(new THREE.Vector3(0.7 * d, -1.3 * d, 0.9 * d));
  camera.near = d / 100; camera.far = d * 50;
  camera.updateProjectionMatrix();
  if (controls) { controls.target.copy(blockCenter); controls.update(); }
  render();
}
let frames = 0;
let starting = true;  // one render once the page is built
function render() {
  if (!renderer || starting) return;
  renderer.render(scene3, camera);
  frames += 1;
}
// (The resize observer's first call, right after the first frame, finds the size unchanged.)
function resize() {
  if (renderer && fitToCanvas(renderer, camera)) render();
}
if (controls) {
  controls.addEventListener('change', render);
  controls.listenToKeyEvents(canvas);
  controls.keyPanSpeed = 20;
}
new ResizeObserver(resize).observe(canvas);
$('reset-view').addEventListener('click', resetView);

// Section plane: keeps the half below the position along the axis (or the other half).
function updateSection() {
  const axis = $('section-axis').value;
  const slider = $('section-pos');
  slider.disabled = axis === '';
  if (axis === '') {
    sectionPlane.set(new THREE.Vector3(0, 0, 1), 1e12);
    $('section-value').textContent = '';
  } else {
    const k = Number(axis);
    const lo = blockBounds.min.getComponent(k), hi = blockBounds.max.getComponent(k);
    const at = lo + (hi - lo) * Number(slider.value) / 1000;
    const flip = $('section-flip').checked ? -1 : 1;
    const n = new THREE.Vector3(); n.setComponent(k, -flip);
    sectionPlane.normal.copy(n);
    sectionPlane.constant = flip * at;
    $('section-value').textContent = `${'xyz'[k]} = ${fmt(at)} mm`;
  }
  render();
}
for (const id of ['section-axis', 'section-pos', 'section-flip']) $(id).addEventListener('input', updateSection);
// One click to the section through the hottest point, across the block's longest extent (as the
// thermal picture's first section): what lies in front of it is cut away.
if (data.temperature) {
  const button = $('section-hottest');
  button.hidden = false;
  button.addEventListener('click', () => {
    const k = [blockSize.x, blockSize.y, blockSize.z].reduce((best, v, i, all) => (v > all[best] ? i : best), 0);
    const lo = blockBounds.min.getComponent(k), hi = blockBounds.max.getComponent(k);
    $('section-axis').value = String(k);
    $('section-pos').value = String(Math.round(1000 * (data.temperature.hottest[k] - lo) / (hi - lo)));
    updateSection();
  });
}

// ---------------------------------------------------------------- the layout's tables
let shown = data.shown;
function fillTable(table, head, rows) {
  table.replaceChildren(el('thead', {}, [el('tr', {}, head.map(([t, cls]) => el('th', cls ? { class: cls } : {}, [t])))]),
    el('tbody', {}, rows));
}
function showTables(member) {
  const layout = member.layout;
  const drilled = layout.bores.reduce((s, b) => s + b.length, 0);
  const best = member.rank === data.best ? ' (best)' : '';
  $('layout-label').textContent = `generation ${data.generation}, member ${member.rank}${best}`;
  $('view-title').textContent = `generation ${data.generation} \u00b7 member ${member.rank}${best} \u00b7 ${layout.bores.length} bores`;
  const dl = el('dl', { id: 'layout-summary' });
  const item = (k, v, id) => { dl.append(el('dt', { text: k }), el('dd', id ? { id, text: v } : { text: v })); };
  item('bores', String(layout.bores.length), 'bore-count');
  item('circuits', String(layout.circuits));
  item('plugs', String(layout.plugs));
  item('drilled length', `${fmt(drilled)} mm`);
  item('feasible', member.feasible ? 'yes' : `no (violation ${fmt(member.violation)})`);
  item('scalarised value', fmt(member.value));
  if (data.temperature && data.temperature.member === member.rank) {
    const t = data.temperature;
    item('cavity temperature', `mean ${fmt(t.mean)} \u00b0C, std ${fmt(t.std)} K, max ${fmt(t.max)} \u00b0C at ` +
      `(${t.hottest.map((c) => fmt(c)).join(', ')}) mm, the red mark (tier ${t.tier})` +
      (t.singular ? `; ${t.singular} singular vertices (patch corners) in grey` : ''));
  }
  $('layout-summary').replaceWith(dl);
  fillTable($('objectives-table'), [['objective'], ['value', 'num']],
    objectives.map((o, k) => el('tr', {}, [el('td', { text: objectiveLabel(o) }), el('td', { class: 'num', text: fmt(member.objectives[k], 4) })])));
  $('violation-count').textContent = `(${member.violations.length})`;
  fillTable($('violations-table'), [['kind'], ['between'], ['found', 'num'], ['needed', 'num'], ['short', 'num']],
    member.violations.map((v) => el('tr', { class: 'bad' }, [el('td', { text: v.kind.replace(/_/g, ' ') }), el('td', { text: v.elements.join(' \u2013 ') }),
      el('td', { class: 'num', text: fmt(v.distance) }), el('td', { class: 'num', text: fmt(v.margin) }),
      el('td', { class: 'num', text: `${fmt(100 * v.amount)} %` })])));
  // Each circuit's coolant as a shop checks it (the rows that break a shop limit marked).
  const cc = member.coolant;
  const driven = cc && cc.from_supply ? `, ${cc.from_pump ? 'from the pump at' : 'from the supply at'} ${fmt(cc.supply_pressure / 1e5)} bar` : '';
  $('coolant-caption').textContent = cc ? `(${fmt(cc.total_flow)} l/min in all${driven})` : '(no flow in the spec)';
  const failing = new Set((cc ? cc.checks : []).map((c) => c.circuit));
  fillTable($('coolant-table'), [['circuit'], ['l/min', 'num'], ['m/s', 'num'], ['Reynolds', 'num'], ['drop bar', 'num'],
    ['heat W', 'num'], ['share', 'num'], ['out °C', 'num'], ['rise K', 'num'], ['film W/(m² K)', 'num']],
    (cc ? cc.circuits : []).map((c) => el('tr', failing.has(c.circuit) ? { class: 'bad' } : {}, [
      el('td', {}, [el('span', { class: 'dot', style: `background:${circuitColor(c.circuit)}` }),
        `c${c.circuit}` + (c.kind && c.kind !== 'drilled' ? ` ${c.kind}` : '')]),
      el('td', { class: 'num', text: fmt(c.flow) }), el('td', { class: 'num', text: fmt(c.velocity) }),
      el('td', { class: 'num', text: Math.round(c.reynolds).toLocaleString('en') }),
      el('td', { class: 'num', text: fmt(c.pressure_drop.total / 1e5) }),
      el('td', { class: 'num', text: c.heat === undefined ? '–' : fmt(c.heat) }),
      el('td', { class: 'num', text: c.heat_share === undefined ? '–' : `${fmt(100 * c.heat_share)} %` }),
      el('td', { class: 'num', text: c.coolant_out === undefined ? '–' : fmt(c.coolant_out, 4) }),
      el('td', { class: 'num', text: c.rise === undefined ? '–' : fmt(c.rise) }),
      el('td', { class: 'num', text: Math.round(c.film).toLocaleString('en') })])));
  // The design rules in bore diameters, out of range marked (depth 1.5-2.5 D, pitch 3-5 D).
  const rules = new Map(((member.design_rules || {}).bores || []).map((r) => [r.bore, r]));
  const inD = (v, verdict) => el('td', { class: verdict ? 'num bad' : 'num', title: verdict ? `${verdict} (outside the rule of thumb)` : '',
    text: v === null || v === undefined ? '\u2013' : fmt(v, 2) });
  fillTable($('bores-table'), [['bore'], ['\u2300 mm', 'num'], ['length mm', 'num'], ['depth D', 'num'], ['pitch D', 'num'], ['entry'], ['']],
    layout.bores.map((b) => el('tr', {}, [el('td', {}, [el('span', { class: 'dot', style: `background:${circuitColor(b.circuit)}` }), b.name]),
      el('td', { class: 'num', text: fmt(b.diameter) }), el('td', { class: 'num', text: fmt(b.length) }),
      inD(rules.get(b.name)?.depth_d, rules.get(b.name)?.depth_verdict), inD(rules.get(b.name)?.pitch_d, rules.get(b.name)?.pitch_verdict),
      el('td', { text: b.entry_face + (b.entry_angle ? ` ${fmt(b.entry_angle)}\u00b0` : '') }),
      el('td', { text: [b.insert ? `blind, ${b.insert}` + (b.tube ? ` (tube \u2300${fmt(b.tube[0])}/${fmt(b.tube[1])} mm)` : '') : '',
        b.plugged ? 'plugged' : '', b.through ? 'through' : '', b.dead_end > 0 ? `dead end ${fmt(b.dead_end)} mm` : ''].filter(Boolean).join(', ') })])));
}

function select(rank) {
  const member = data.members.find((m) => m.rank === rank);
  if (!member) return;
  shown = rank;
  showTables(member);
  showLayout(member);
  for (const ring of document.querySelectorAll('.plot .selected')) {
    const p = ring.ownerSVGElement.querySelector(`.point[data-rank="${rank}"]`);
    ring.setAttribute('cx', p.getAttribute('cx'));
    ring.setAttribute('cy', p.getAttribute('cy'));
  }
  document.body.dataset.shown = String(rank);
}

// ---------------------------------------------------------------- charts (SVG)
const SVG = 'http://www.w3.org/2000/svg';
function svg(tag, attrs = {}, parent = null) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.append(e);
  return e;
}
function niceTicks(lo, hi, count = 5) {
  if (!(hi > lo)) { const d = Math.abs(lo) * 0.1 || 1; lo -= d; hi += d; }
  const raw = (hi - lo) / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((s) => s * mag).find((s) => s >= raw);
  const ticks = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
  const decimals = Math.max(0, -Math.floor(Math.log10(step) + 1e-9) + (step / mag === 2.5 ? 1 : 0));
  const format = (t) => (Math.abs(t) >= 1e6 || (decimals > 4 && t !== 0) ? t.toExponential(1) : t.toLocaleString('en-US', { minimumFractionDigits: decimals, maximumFractionDigits: decimals }));
  return { lo: Math.min(lo, ticks[0]), hi: Math.max(hi, ticks[ticks.length - 1]), ticks, format };
}
// An empty chart with axes; returns the scales and the plot group.
function logTicks(values) {
  const lo = Math.floor(Math.log10(Math.min(...values))), hi = Math.max(Math.ceil(Math.log10(Math.max(...values))), lo + 1);
  const ticks = [];
  for (let k = lo; k <= hi; ++k) ticks.push(k);
  return { lo, hi, ticks, format: (t) => fmt(10 ** t) };
}
function chart(container, { title, xLabel, yLabel, xs, ys, width = 360, height = 250, log = false, logX = false }) {
  const wrap = el('div', { class: 'plot' });
  container.append(wrap);
  const m = { l: 58, r: 12, t: 22, b: 40 };
  const root = svg('svg', { viewBox: `0 0 ${width} ${height}`, role: 'img', 'aria-label': title });
  wrap.append(root);
  svg('text', { x: m.l, y: 14, 'font-weight': 600 }, root).textContent = title;
  const finite = (a, positive) => a.filter((v) => v !== null && Number.isFinite(v) && (!positive || v > 0));
  const fx = finite(xs, logX), fy = finite(ys, log);
  const tx = logX ? logTicks(fx) : niceTicks(Math.min(...fx), Math.max(...fx));
  const ty = log ? logTicks(fy) : niceTicks(Math.min(...fy), Math.max(...fy));
  const X = (v) => m.l + ((logX ? Math.log10(v) : v) - tx.lo) / (tx.hi - tx.lo) * (width - m.l - m.r);
  const Y = (v) => { const u = log ? Math.log10(v) : v; return height - m.b - (u - ty.lo) / (ty.hi - ty.lo) * (height - m.t - m.b); };
  const grid = svg('g', { class: 'grid' }, root), axis = svg('g', { class: 'axis' }, root);
  for (const t of tx.ticks) {
    const x = logX ? X(10 ** t) : X(t);
    svg('line', { x1: x, x2: x, y1: m.t, y2: height - m.b }, grid);
    svg('text', { x, y: height - m.b + 14, 'text-anchor': 'middle' }, axis).textContent = tx.format(t);
  }
  for (const t of ty.ticks) {
    const y = log ? Y(10 ** t) : Y(t);
    svg('line', { x1: m.l, x2: width - m.r, y1: y, y2: y }, grid);
    svg('text', { x: m.l - 5, y: y + 4, 'text-anchor': 'end' }, axis).textContent = ty.format(t);
  }
  svg('path', { d: `M${m.l},${m.t}V${height - m.b}H${width - m.r}`, fill: 'none' }, axis);
  svg('text', { class: 'label', x: (m.l + width - m.r) / 2, y: height - 6, 'text-anchor': 'middle' }, root).textContent = xLabel;
  svg('text', { class: 'label', x: 12, y: (m.t + height - m.b) / 2, 'text-anchor': 'middle', transform: `rotate(-90 12 ${(m.t + height - m.b) / 2})` }, root).textContent = yLabel;
  return { root, X, Y, plot: svg('g', {}, root), m, width, height, points: [] };
}

const tooltip = $('tooltip');
function tip(event, text) {
  tooltip.textContent = text;
  tooltip.hidden = false;
  tooltip.style.left = `${event.clientX + 14}px`;
  tooltip.style.top = `${event.clientY + 10}px`;
}
function memberText(mm) {
  return `member ${mm.rank}${mm.rank === data.best ? ' (best)' : ''}: ${mm.layout.bores.length} bores, ${mm.feasible ? 'feasible' : 'infeasible'}` +
    (mm.front ? ', on the front' : '') + '\n' + objectives.map((o, k) => `${objectiveLabel(o)}: ${fmt(mm.objectives[k], 4)}`).join('\n');
}

// Pareto front: one scatter per pair of objectives (all layouts of the generation).
function drawFront() {
  const box = $('front-plots');
  const m = objectives.length;
  $('front-caption').textContent = `(generation ${data.generation}, ${data.members.filter((x) => x.front).length} of ${data.members.length} layouts non-dominated)`;
  const pairs = [];
  if (m === 1) pairs.push([0, null]);
  for (let i = 0; i < m; ++i) for (let j = i + 1; j < m; ++j) pairs.push([i, j]);
  for (const [i, j] of pairs) {
    const xs = data.members.map((x) => x.objectives[i]);
    const ys = j === null ? data.members.map((x) => x.rank) : data.members.map((x) => x.objectives[j]);
    const c = chart(box, { title: j === null ? objectives[i].name : `${objectives[j].name.replace(/_/g, ' ')} vs ${objectives[i].name.replace(/_/g, ' ')}`,
      xLabel: objectiveLabel(objectives[i]), yLabel: j === null ? 'member' : objectiveLabel(objectives[j]), xs, ys });
    // Dominated first, the front on top.
    const order = [...data.members].sort((a, b) => (a.front - b.front) || (b.feasible - a.feasible));
    for (const mm of order) {
      const x = c.X(mm.objectives[i]), y = c.Y(j === null ? mm.rank : mm.objectives[j]);
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      const attrs = { class: 'point', cx: x, cy: y, r: mm.front ? 5.5 : 4.5, 'data-rank': mm.rank, tabindex: 0 };
      let p;
      if (!mm.feasible) p = svg('circle', { ...attrs, fill: '#c62828', 'fill-opacity': 0.75, stroke: '#fff', 'stroke-width': 1 }, c.plot);
      else if (mm.front) p = svg('circle', { ...attrs, fill: '#1f6fd1', stroke: '#fff', 'stroke-width': 1.2 }, c.plot);
      else p = svg('circle', { ...attrs, fill: '#fff', 'fill-opacity': 0.01, stroke: '#8a93a3', 'stroke-width': 1.5 }, c.plot);
      c.points.push({ rank: mm.rank, x, y });
      p.addEventListener('keydown', (e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); select(mm.rank); } });
      p.addEventListener('mousemove', (e) => tip(e, memberText(mm)));
      p.addEventListener('mouseleave', () => { tooltip.hidden = true; });
    }
    svg('circle', { class: 'selected', r: 9, cx: -100, cy: -100 }, c.root);
    c.root.addEventListener('click', (e) => pickAt(c, e));
  }
}

// A click on a scatter picks the nearest point on screen; points within a few pixels of it (equal
// or nearly equal objectives) are one stack: clicking it again steps to the next member, and a
// list under the plots names them all.
let pickStack = null;
function pickAt(c, event) {
  const ctm = c.root.getScreenCTM();
  if (!ctm) return;
  const at = new DOMPoint(event.clientX, event.clientY).matrixTransform(ctm.inverse());
  const px = 7 / Math.hypot(ctm.a, ctm.b);  // 7 screen pixels in the plot's units
  const near = c.points.map((p) => ({ rank: p.rank, d: Math.hypot(p.x - at.x, p.y - at.y) })).sort((a, b) => a.d - b.d || a.rank - b.rank);
  if (!near.length || near[0].d > 2 * px) return;
  const stack = near.filter((p) => p.d <= near[0].d + px).map((p) => p.rank).sort((a, b) => a - b);
  const key = stack.join(',');
  const nearest = stack.indexOf(near[0].rank);
  const again = (pickStack && pickStack.key === key) || stack[nearest] === shown;
  const next = again ? (stack.indexOf(shown) + 1) % stack.length : nearest;
  pickStack = { key, stack };
  select(stack[next]);
  showStack(stack);
}
function showStack(stack) {
  const box = $('front-pick');
  box.replaceChildren();
  box.hidden = stack.length < 2;
  if (box.hidden) return;
  box.append(`${stack.length} layouts overlap here (click the point again for the next):`);
  for (const rank of stack) {
    const b = el('button', { type: 'button', 'data-rank': rank, text: `member ${rank}` });
    b.setAttribute('aria-pressed', String(rank === shown));
    b.addEventListener('click', () => { select(rank); showStack(stack); });
    box.append(b);
  }
}

// Convergence: best and median scalarised value, feasible share, hypervolume, per evaluations.
function drawConvergence() {
  const cv = data.convergence;
  const box = $('convergence-plots');
  const xs = cv.evaluations;
  const line = (c, ys, color, dash = '') => {
    let d = '';
    ys.forEach((y, k) => { if (y === null || !Number.isFinite(c.Y(y))) return; d += `${d ? 'L' : 'M'}${c.X(xs[k]).toFixed(1)},${c.Y(y).toFixed(1)}`; });
    svg('path', { d, fill: 'none', stroke: color, 'stroke-width': 1.8, 'stroke-dasharray': dash }, c.plot);
  };
  const mark = (c) => {
    const k = cv.generation.indexOf(data.generation);
    if (k < 0) return;
    svg('line', { x1: c.X(xs[k]), x2: c.X(xs[k]), y1: c.m.t, y2: c.height - c.m.b, stroke: '#111', 'stroke-dasharray': '3 3' }, c.plot);
  };
  const values = [...cv.best, ...cv.median].filter((v) => v !== null && Number.isFinite(v));
  const positive = values.every((v) => v > 0);
  const log = positive && Math.max(...values) / Math.min(...values) > 50;
  const logX = xs.length > 1 && xs[0] > 0 && xs[xs.length - 1] / xs[0] > 100;
  const xLabel = logX ? 'evaluations (log)' : 'evaluations';
  const c1 = chart(box, { title: 'scalarised value (lower is better)', xLabel, yLabel: log ? 'value (log)' : 'value', xs, ys: [...cv.best, ...cv.median], log, logX });
  line(c1, cv.best, '#1f6fd1'); line(c1, cv.median, '#ff7f0e', '5 3'); mark(c1);
  svg('text', { x: c1.width - c1.m.r - 4, y: c1.m.t + 14, 'text-anchor': 'end', fill: '#1f6fd1', 'font-weight': 600 }, c1.root).textContent = '\u2014 best';
  svg('text', { x: c1.width - c1.m.r - 4, y: c1.m.t + 28, 'text-anchor': 'end', fill: '#ff7f0e', 'font-weight': 600 }, c1.root).textContent = '- - median';
  const share = cv.feasible_share.map((v) => 100 * v);
  const c2 = chart(box, { title: 'feasible share of the population', xLabel, yLabel: 'feasible (%)', xs, ys: [0, 100, ...share], logX });
  line(c2, share, '#2ca02c'); mark(c2);
  const c3 = chart(box, { title: 'hypervolume of the feasible front', xLabel, yLabel: 'hypervolume (scaled)', xs, ys: [0, ...cv.hypervolume], logX });
  line(c3, cv.hypervolume, '#9467bd'); mark(c3);
  if (data.run.algorithm === 'es')
    box.append(el('p', { class: 'hint', text: 'The ES minimises one weighted sum: its population gathers at one point, so its front and hypervolume shrink as it converges. ' +
      'SMS-EMOA (--algorithm sms-emoa) spreads a front. The dashed line marks the generation shown.' }));
  else box.append(el('p', { class: 'hint', text: 'The dashed line marks the generation shown.' }));
  c3.root.append(Object.assign(svg('title'), { textContent: `reference point ${cv.hv_ref.map((v) => fmt(v)).join(', ')} (objective / its scale)` }));
}

// ---------------------------------------------------------------- anytime behaviour (SVG, on demand)
// What optimisers are compared by (replay's anytime.csv): the best feasible weighted objective and
// the feasible front's hypervolume so far, against evaluations and against wall time; the dashed
// lines are each generation's own. Drawn when the panel is first opened: nothing at load.
const anytime = data.anytime;
function drawAnytime() {
  const box = $('anytime-plots');
  if (box.dataset.drawn) return;
  box.dataset.drawn = '1';
  const line = (c, xs, ys, color, dash = '') => {
    let d = '';
    ys.forEach((y, k) => { if (y === null || !Number.isFinite(c.Y(y))) return; d += `${d ? 'L' : 'M'}${c.X(xs[k]).toFixed(1)},${c.Y(y).toFixed(1)}`; });
    svg('path', { d, fill: 'none', stroke: color, 'stroke-width': dash ? 1.2 : 1.8, 'stroke-dasharray': dash, class: dash ? 'generation' : 'so-far' }, c.plot);
  };
  const feasible = anytime.best_so_far.some((v) => v !== null);
  for (const [x, xLabel] of [['evaluations', 'evaluations'], ['seconds', 'wall time (s)']]) {
    const xs = anytime[x];
    if (feasible) {
      const c = chart(box, { title: `best feasible objective vs ${xLabel.replace(' (s)', '')}`, xLabel, yLabel: 'weighted objective', xs, ys: [...anytime.best_so_far, ...anytime.best_feasible] });
      line(c, xs, anytime.best_feasible, '#8ab4e8', '4 3'); line(c, xs, anytime.best_so_far, '#1f6fd1');
    }
    const c = chart(box, { title: `hypervolume vs ${xLabel.replace(' (s)', '')}`, xLabel, yLabel: 'hypervolume (scaled)', xs, ys: [0, ...anytime.hypervolume_so_far] });
    line(c, xs, anytime.hypervolume, '#c5b0d5', '4 3'); line(c, xs, anytime.hypervolume_so_far, '#9467bd');
  }
  if (!feasible) box.append(el('p', { class: 'hint', text: 'No stored generation has a feasible layout: no best objective to draw.' }));
}
if (anytime && anytime.evaluations.length) {
  const n = anytime.evaluations.length;
  $('anytime-caption').textContent = `(${n} generations, ${anytime.evaluations[n - 1].toLocaleString('en-US')} evaluations, ${fmt(anytime.seconds[n - 1])} s)`;
  $('anytime-about').textContent = 'Solid: the best so far; dashed: each stored generation\'s population. Hypervolume of the feasible front in scaled objectives ' +
    `against the run's reference point ${anytime.ref.map((v) => fmt(v)).join(', ')} (summary.json's and replay's, as the convergence chart above). ` +
    'The same rows as mtcs replay\'s anytime.csv.';
  $('anytime-panel').addEventListener('toggle', () => { if ($('anytime-panel').open) drawAnytime(); });
} else {
  $('anytime-panel').hidden = true;
}

// ---------------------------------------------------------------- drilling maps (2-D canvas)
// Each bore entry's accessibility map (data.drilling_maps, of one member's layout): the bore as a
// straight tool pivoting at its entry, which directions miss the part. Drawn as
// `mtcs access-map --out am.png` draws it (gamma about z across, phi from +z down), only when
// the panel is open: the first frame does not wait for it.
const FREE_COLOR = '#bfe3c0', BLOCKED_COLOR = '#c8453a';
const drillingMaps = data.drilling_maps;
const drillingCells = new Map();  // entry index -> decoded cells, on first draw
function drillingEntry(k) {
  if (!drillingCells.has(k)) drillingCells.set(k, decode(drillingMaps.entries[k].map, Uint8Array));
  return drillingCells.get(k);
}
function drawDrillingMap(k) {
  const dm = drillingMaps, e = dm.entries[k], cells = drillingEntry(k);
  const cv = $('drilling-map');
  const ratio = Math.min(window.devicePixelRatio || 1, 2);
  const W = cv.clientWidth || 360, H = cv.clientHeight || 200;
  cv.width = Math.round(W * ratio); cv.height = Math.round(H * ratio);
  const g = cv.getContext('2d');
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  g.fillStyle = '#fff'; g.fillRect(0, 0, W, H);
  const m = { l: 42, r: 14, t: 8, b: 34 };
  const pw = W - m.l - m.r, ph = H - m.t - m.b;
  const cw = pw / dm.cols, ch = ph / dm.rows;
  for (let i = 0; i < dm.rows; ++i)
    for (let j = 0; j < dm.cols; ++j) {
      g.fillStyle = cells[i * dm.cols + j] ? BLOCKED_COLOR : FREE_COLOR;
      g.fillRect(m.l + j * cw, m.t + i * ch, Math.ceil(cw), Math.ceil(ch));
    }
  g.strokeStyle = '#555'; g.lineWidth = 1; g.strokeRect(m.l, m.t, pw, ph);
  g.fillStyle = '#1d2330'; g.font = '11px system-ui, sans-serif';
  g.textAlign = 'center'; g.textBaseline = 'top';
  for (let a = 0; a <= 360; a += 90) g.fillText(`${a}`, m.l + (a / 360) * pw, m.t + ph + 3);
  g.fillText('\u03b3: angle about z (deg)', m.l + pw / 2, m.t + ph + 18);
  g.textAlign = 'right'; g.textBaseline = 'middle';
  for (let a = 0; a <= 180; a += 45) g.fillText(`${a}`, m.l - 4, m.t + (a / 180) * ph);
  g.save(); g.translate(11, m.t + ph / 2); g.rotate(-Math.PI / 2); g.textAlign = 'center';
  g.fillText('\u03c6: from +z (deg)', 0, 0); g.restore();
  // The bore's own direction, at its exact angles: a ring, filled when that direction is free.
  const [dx, dy, dz] = e.direction;
  const phi = Math.acos(Math.max(-1, Math.min(1, dz))) * 180 / Math.PI;
  const gamma = ((Math.atan2(dy, dx) * 180 / Math.PI) + 360) % 360;
  const x = m.l + (gamma / 360) * pw, y = m.t + (phi / 180) * ph;
  if (dx || dy || dz) {
    g.beginPath(); g.arc(x, y, 5, 0, 2 * Math.PI);
    g.fillStyle = e.direction_free ? '#fff' : '#111'; g.fill();
    g.lineWidth = 2; g.strokeStyle = '#111'; g.stroke();
  }
  const total = dm.rows * dm.cols;
  $('drilling-info').textContent = e.inside
    ? `${e.bore}: the entry lies inside the part, no direction is free.`
    : `${e.bore}: entry (${e.entry.map((v) => fmt(v, 5)).join(', ')}) mm, tool \u2300 ${fmt(2 * e.radius)} mm \u00d7 ${fmt(e.length, 5)} mm; ` +
      `${e.free} of ${total} directions free (${(100 * e.free / total).toFixed(1)} %); its own direction ` +
      `(\u03c6 ${phi.toFixed(1)}\u00b0, \u03b3 ${gamma.toFixed(1)}\u00b0) is ${e.direction_free ? 'free' : 'blocked'}.`;
  cv.dataset.entry = String(k);
}
function showDrillingEntry(k) {
  if (!drillingMaps || k < 0 || k >= drillingMaps.entries.length) return;
  $('drilling-entry').value = String(k);
  if ($('drilling-panel').open) drawDrillingMap(k);
}
if (drillingMaps) {
  const dm = drillingMaps, total = dm.rows * dm.cols;
  const blocked = dm.entries.filter((e) => !e.direction_free).length;
  $('drilling-caption').textContent = `(${dm.entries.length} entries${blocked ? `, ${blocked} blocked` : ''})`;
  $('drilling-about').replaceChildren(`Of member ${dm.member}. Each bore as a straight tool (its radius and drilled length) pivoting at its entry: ` +
    `which directions miss the part (${dm.part}, ${dm.grid}\u00b3 voxels of ${fmt(dm.voxel_size)} mm; ${dm.rows} \u00d7 ${dm.cols} cells of ` +
    `${fmt(180 / dm.rows)}\u00b0 \u00d7 ${fmt(360 / dm.cols)}\u00b0).`, el('br'),
    el('span', { class: 'key free-dir' }), ' free ', el('span', { class: 'key blocked-dir' }), ' blocked \u25cb the bore\u2019s direction (filled black: blocked). Hover or click a bore in the table to draw its map.');
  $('drilling-entry').replaceChildren(...dm.entries.map((e, k) => el('option', { value: String(k),
    text: `${e.bore}: ${(100 * e.free / total).toFixed(1)} % free, direction ${e.direction_free ? 'free' : 'BLOCKED'}` })));
  $('drilling-entry').addEventListener('change', () => showDrillingEntry(Number($('drilling-entry').value)));
  $('drilling-panel').addEventListener('toggle', () => { if ($('drilling-panel').open) showDrillingEntry(Number($('drilling-entry').value || 0)); });
  // A bore of the table (of the member the maps are of) draws its map when hovered or clicked.
  const entryOfRow = (event) => {
    const row = event.target.closest('#bores-table tbody tr');
    if (!row || shown !== dm.member) return -1;
    const name = row.cells[0].textContent;
    return dm.entries.findIndex((e) => e.bore === name);
  };
  $('bores-table').addEventListener('mouseover', (event) => showDrillingEntry(entryOfRow(event)));
  $('bores-table').addEventListener('click', (event) => {
    const k = entryOfRow(event);
    if (k < 0) return;
    $('drilling-panel').open = true;
    showDrillingEntry(k);
  });
} else {
  $('drilling-caption').textContent = '(none: no cavity with volume)';
}

// ---------------------------------------------------------------- keys and start
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement || e.ctrlKey || e.metaKey || e.altKey) return;
  const keys = Object.keys(layers);
  if (e.key >= '1' && e.key <= String(keys.length)) {
    const l = layers[keys[Number(e.key) - 1]];
    if (!l.box.disabled) { l.box.checked = !l.box.checked; l.box.dispatchEvent(new Event('change')); }
  } else if (e.key === 'r' || e.key === 'R') {
    resetView();
  } else if (e.key === 'n' || e.key === 'p') {
    const k = data.members.findIndex((m) => m.rank === shown);
    const next = data.members[(k + (e.key === 'n' ? 1 : data.members.length - 1)) % data.members.length];
    select(next.rank);
  }
});

// A link may name the state to open in: #member=K&section=AXIS:FRACTION (e.g. z:0.8)&flip=1&hide=block,part
function applyHash() {
  const params = new URLSearchParams(location.hash.slice(1));
  const member = Number(params.get('member'));
  if (params.has('member') && data.members.some((m) => m.rank === member)) shown = member;
  const section = (params.get('section') || '').split(':');
  if ('xyz'.includes(section[0]) && section[0]) {
    $('section-axis').value = String('xyz'.indexOf(section[0]));
    $('section-pos').value = String(Math.round(1000 * Math.max(0, Math.min(1, Number(section[1] ?? 0.5)))));
    $('section-flip').checked = params.get('flip') === '1';
  }
  for (const key of (params.get('hide') || '').split(',')) if (layers[key]) { layers[key].box.checked = false; layers[key].group.visible = false; }
}

performance.mark('mtcs-scene');  // the block, the part, the keep-outs and the temperature built
applyHash();
drawFront();
drawConvergence();
resize();
resetView();
select(shown);
updateSection();
starting = false;
performance.mark('mtcs-built');  // the page and the scene are built; the first frame follows
render();
dispose(warmUp);
// For tests and scripts: the page is drawn.
window.mtcsReport = { select, frames: () => frames, programs: () => (renderer ? renderer.info.programs.length : 0), data,
  coolantBores: () => coolantLayer.children.length, inserts: () => boreLayer.children.filter((m) => m.userData.insert).length,
  hottestMark: () => { const h = temperatureLayer.getObjectByName('hottest'); return h ? h.position.toArray() : null; } };
performance.mark('mtcs-drawn');
document.body.dataset.ready = '1';
