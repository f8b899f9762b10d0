// The interference page (mtcs interfere A B --report): both components, the triangles of the
// intersecting pairs highlighted (red: interference beyond the touch tolerance, yellow: contact),
// the intersection segments, and the pairs listed by solid and face as the paper's viewer shows
// them. The data is the JSON src/report/interference_page.cpp writes; lengths in the meshes' units.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { decode, el, openRenderer, addLights, fitToCanvas } from 'mtcs/page';

const data = JSON.parse(document.getElementById('report-data').textContent);
const check = data.check;
const $ = (id) => document.getElementById(id);
const fmt = (v) => (Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-3) ? v.toExponential(3) : String(Number(v.toPrecision(4))));

// ---------------------------------------------------------------- header and tables
$('title').textContent = data.title;
document.title = data.title;
$('run-info').textContent = `A: ${check.a} \u00b7 B: ${check.b}, moved by (${check.translate.map(fmt).join(', ')}) \u00b7 touch tolerance ${fmt(check.touch_tolerance)}` +
  (data.program ? ` \u00b7 ${data.program}` : '');
const verdict = check.interferes ? 'INTERFERENCE' : check.pair_count ? 'contact only' : 'apart';
$('verdict').textContent = verdict;
$('verdict').style.color = check.interferes ? 'var(--bad)' : 'var(--ink)';
$('pair-count').textContent = String(check.pair_count);
$('group-count').textContent = String(check.groups.length);
{
  const dl = el('dl');
  const row = (k, v) => dl.append(el('dt', { text: k }), el('dd', { text: v }));
  for (const [name, m] of [['A', data.a], ['B', data.b]])
    row(name, `${m.triangles.toLocaleString('en-US')} triangles, ${m.solids} solid(s), ${m.faces} faces; ${m.hit} in pairs`);
  row('intersecting pairs', `${check.pair_count} (${check.penetrating_pairs} beyond the touch tolerance)`);
  if (check.solids_of_a_inside_b.length) row('solids of A inside B', check.solids_of_a_inside_b.join(', '));
  if (check.solids_of_b_inside_a.length) row('solids of B inside A', check.solids_of_b_inside_a.join(', '));
  if (!check.pair_count) row('distance', fmt(check.distance));
  $('layout-summary').replaceChildren(...dl.childNodes);
}
function table(id, head, rows, onClick) {
  const t = $(id);
  t.replaceChildren(el('tr', {}, head.map((h) => el('th', { text: h, class: 'num' }))));
  rows.forEach((r, i) => {
    const tr = el('tr', { class: r.bad ? 'bad' : '', tabindex: 0, 'data-index': i }, r.cells.map((c) => el('td', { text: String(c), class: 'num' })));
    if (onClick) {
      tr.addEventListener('click', () => onClick(i));
      tr.addEventListener('keydown', (e) => { if (e.key === 'Enter') onClick(i); });
    }
    t.append(tr);
  });
}
table('groups-table', ['solid A', 'face A', 'solid B', 'face B', 'pairs', 'beyond tol.'],
  check.groups.map((g) => ({ bad: g.penetrating > 0, cells: [g.solid_a, g.face_a, g.solid_b, g.face_b, g.pairs, g.penetrating] })),
  (i) => flyTo(check.pairs.filter((p) => ['solid_a', 'face_a', 'solid_b', 'face_b'].every((k) => p[k] === check.groups[i][k]))));
const listed = check.pairs.slice(0, 2000);
table('pairs-table', ['triangle A', 'solid/face A', 'triangle B', 'solid/face B', 'beyond tol.'],
  listed.map((p) => ({ bad: p.penetrating, cells: [p.a, `${p.solid_a}/${p.face_a}`, p.b, `${p.solid_b}/${p.face_b}`, p.penetrating ? 'yes' : 'contact'] })),
  (i) => flyTo([listed[i]]));

// ---------------------------------------------------------------- 3-D view
const renderer = openRenderer($('view3d'));
if (!renderer) $('webgl-error').hidden = false;
const canvas = renderer ? renderer.domElement : $('view3d');
const scene = new THREE.Scene();
addLights(scene);
const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e6);
camera.up.set(0, 0, 1);
const controls = renderer ? new OrbitControls(camera, canvas) : null;

function geometry(m, only = null) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(decode(m.positions, Float32Array), 3));
  const index = decode(m.indices, Uint32Array);
  if (only) {
    const picked = new Uint32Array(3 * only.length);
    only.forEach((t, k) => picked.set(index.subarray(3 * t, 3 * t + 3), 3 * k));
    g.setIndex(new THREE.BufferAttribute(picked, 1));
  } else g.setIndex(new THREE.BufferAttribute(index, 1));
  g.computeVertexNormals();
  return g;
}
// Lambert: its shaders compile several times faster than the standard material's in software WebGL.
const surface = (color, opacity) => new THREE.MeshLambertMaterial({ color, transparent: opacity < 1, opacity, depthWrite: opacity >= 1, side: THREE.DoubleSide });
const hits = (which, penetrating) => [...new Set(check.pairs.filter((p) => p.penetrating === penetrating).map((p) => p[which]))];
const layers = {};
function layer(key, label, objects) {
  const group = new THREE.Group();
  for (const o of objects) group.add(o);
  scene.add(group);
  const box = el('input', { type: 'checkbox', id: `layer-${key}` });
  box.checked = true;
  box.addEventListener('change', () => { group.visible = box.checked; render(); });
  $('layers').append(el('label', {}, [box, ` ${label}`]));
  layers[key] = group;
}
layer('a', 'A', [new THREE.Mesh(geometry(data.a.mesh), surface(0x9aa3b2, 0.35))]);
layer('b', 'B', [new THREE.Mesh(geometry(data.b.mesh), surface(0x4f8fd6, 0.35))]);
layer('interfering', 'interfering triangles', [
  new THREE.Mesh(geometry(data.a.mesh, hits('a', true)), surface(0xc62828, 1)),
  new THREE.Mesh(geometry(data.b.mesh, hits('b', true)), surface(0xe53935, 1))]);
layer('contact', 'contact triangles', [
  new THREE.Mesh(geometry(data.a.mesh, hits('a', false)), surface(0xf2c200, 1)),
  new THREE.Mesh(geometry(data.b.mesh, hits('b', false)), surface(0xf2c200, 1))]);
{
  const points = check.pairs.flatMap((p) => p.segment.flat());
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(points), 3));
  layer('segments', 'intersection segments', [new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x111111 }))]);
}
$('legend').append(...[['#9aa3b2', 'A'], ['#4f8fd6', 'B'], ['#c62828', 'interfering'], ['#f2c200', 'contact'], ['#111', 'intersection']].map(([c, t]) =>
  el('div', { class: 'row' }, [el('span', { class: 'swatch', style: `background:${c}` }), t])));
$('view-title').textContent = `${verdict}: ${check.pair_count} triangle pairs`;

const all = new THREE.Box3().setFromObject(scene);
function view(box) {
  const centre = box.getCenter(new THREE.Vector3()), d = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-6);
  camera.position.copy(centre).add(new THREE.Vector3(0.5 * d, -1.0 * d, 0.7 * d));
  camera.near = d / 200; camera.far = d * 100;
  camera.updateProjectionMatrix();
  if (controls) { controls.target.copy(centre); controls.update(); }
  render();
}
function flyTo(pairs) {
  const box = new THREE.Box3();
  for (const p of pairs) for (const q of p.segment) box.expandByPoint(new THREE.Vector3(...q));
  if (!box.isEmpty()) box.expandByScalar(0.05 * all.getSize(new THREE.Vector3()).length());
  view(box.isEmpty() ? all : box);
}
let frames = 0;
function render() {
  if (!renderer) return;
  renderer.render(scene, camera);
  frames += 1;
}
function resize() {
  if (renderer && fitToCanvas(renderer, camera)) render();
}
if (controls) {
  controls.addEventListener('change', render);
  controls.listenToKeyEvents(canvas);
}
canvas.addEventListener('keydown', (e) => { if (e.key === 'r' || e.key === 'R') view(all); });
$('reset-view').addEventListener('click', () => view(all));
new ResizeObserver(resize).observe(canvas);
// First view: the smaller component (a pin in a plate, a figure on a gear) and where they meet.
const focus = [layers.a, layers.b].map((g) => new THREE.Box3().setFromObject(g))
  .sort((p, q) => p.getSize(new THREE.Vector3()).length() - q.getSize(new THREE.Vector3()).length())[0];
resize();
view(focus.union(new THREE.Box3().setFromObject(layers.segments)));
// For a page that embeds this one (mtcs serve): the camera as a viewpoint (BCF's names, the
// meshes' units) and back, exactly; a group framed as its table row does.
function viewpoint() {
  const dir = new THREE.Vector3();
  camera.getWorldDirection(dir);
  return {
    camera_view_point: camera.position.toArray(), camera_direction: dir.toArray(), camera_up_vector: camera.up.toArray(),
    field_of_view: camera.fov, aspect_ratio: camera.aspect, target: controls ? controls.target.toArray() : null,
  };
}
function setViewpoint(v) {
  camera.position.fromArray(v.camera_view_point);
  camera.up.fromArray(v.camera_up_vector);
  if (v.field_of_view) camera.fov = v.field_of_view;
  const target = v.target ? new THREE.Vector3().fromArray(v.target)
    : camera.position.clone().add(new THREE.Vector3().fromArray(v.camera_direction));
  camera.lookAt(target);
  camera.updateProjectionMatrix();
  if (controls) { controls.target.copy(target); controls.update(); }
  render();
}
function showGroup(i) {
  const g = check.groups[i];
  flyTo(check.pairs.filter((p) => ['solid_a', 'face_a', 'solid_b', 'face_b'].every((k) => p[k] === g[k])));
}
window.mtcsInterference = { data, frames: () => frames, viewpoint, setViewpoint, showGroup };
document.body.dataset.ready = '1';
