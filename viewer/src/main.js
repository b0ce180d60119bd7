// SPDX-License-Identifier: MIT
// The page of `cgogn view`: reads the mesh that cgogn embedded in the page
// (base64 typed arrays and a JSON description, see src/render/viewer.cpp),
// and draws it with three.js. Every scalar was computed and normalized to
// [0, 1] by cgogn; the page only maps it to colours.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

// flags per triangle, as written by cgogn (viewer.cpp)
const EDGE_AB = 1, EDGE_BC = 2, EDGE_CA = 4; // polygon edges to draw
const BOUNDARY_AB = 8, BOUNDARY_BC = 16, BOUNDARY_CA = 32; // boundary edges
const ON_BOUNDARY = 64; // the face is on the boundary of the volume mesh
const NO_VALUE = 255; // quantities: 0..254 over their range

function showNoWebGL(reason) {
  const m = document.getElementById('no-webgl');
  m.hidden = false;
  if (reason) document.getElementById('no-webgl-reason').textContent = reason;
  document.getElementById('ui').hidden = true;
  document.body.dataset.state = 'no-webgl';
}

function webgl2Available() {
  try {
    const c = document.createElement('canvas');
    return !!(window.WebGL2RenderingContext && c.getContext('webgl2'));
  } catch (e) {
    return false;
  }
}

function decode(meta, name) {
  const a = meta.arrays[name];
  const text = document.getElementById('cgogn-' + name).textContent.trim();
  const bin = atob(text);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
  const types = { Float32: Float32Array, Uint32: Uint32Array, Uint16: Uint16Array, Uint8: Uint8Array };
  const out = new types[a.type](bytes.buffer);
  if (out.length !== a.length) throw new Error('array ' + name + ': ' + out.length + ' values, ' + a.length + ' expected');
  return out;
}

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'text') e.textContent = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function main() {
  const t0 = performance.now();
  const meta = JSON.parse(document.getElementById('cgogn-meta').textContent);
  document.title = meta.title;
  document.getElementById('title').textContent = meta.title;
  if (!webgl2Available()) {
    showNoWebGL('');
    return;
  }
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true });
  } catch (e) {
    showNoWebGL(String(e && e.message ? e.message : e));
    return;
  }
  THREE.ColorManagement.enabled = false; // colours as cgogn computed them
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.setClearColor(0xffffff);
  document.getElementById('view').append(renderer.domElement);

  const pos = decode(meta, 'positions');
  const tri = decode(meta, 'triangles');
  const flags = decode(meta, 'flags');
  const split = decode(meta, 'split_vertices');
  const cellOffsets = meta.dimension === 3 ? decode(meta, 'cell_offsets') : null;
  const nt = tri.length / 3, nv = pos.length / 3;

  // ---- the triangles, one vertex per corner (face scalars are per triangle)
  const cornerPos = new Float32Array(9 * nt);
  const flatNormal = new Float32Array(9 * nt);
  const smoothNormal = new Float32Array(9 * nt);
  const vn = new Float32Array(3 * nv);
  for (let t = 0; t < nt; ++t) {
    const a = 3 * tri[3 * t], b = 3 * tri[3 * t + 1], c = 3 * tri[3 * t + 2];
    const ux = pos[b] - pos[a], uy = pos[b + 1] - pos[a + 1], uz = pos[b + 2] - pos[a + 2];
    const wx = pos[c] - pos[a], wy = pos[c + 1] - pos[a + 1], wz = pos[c + 2] - pos[a + 2];
    const nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx; // twice the area
    const l = Math.hypot(nx, ny, nz) || 1;
    for (const v of [a, b, c]) {
      vn[v] += nx; vn[v + 1] += ny; vn[v + 2] += nz;
    }
    for (let k = 0; k < 3; ++k) {
      const v = 3 * tri[3 * t + k], o = 9 * t + 3 * k;
      cornerPos[o] = pos[v]; cornerPos[o + 1] = pos[v + 1]; cornerPos[o + 2] = pos[v + 2];
      flatNormal[o] = nx / l; flatNormal[o + 1] = ny / l; flatNormal[o + 2] = nz / l;
    }
  }
  for (let v = 0; v < nv; ++v) {
    const l = Math.hypot(vn[3 * v], vn[3 * v + 1], vn[3 * v + 2]) || 1;
    vn[3 * v] /= l; vn[3 * v + 1] /= l; vn[3 * v + 2] /= l;
  }
  for (let i = 0; i < 3 * nt; ++i) {
    const v = 3 * tri[i];
    smoothNormal[3 * i] = vn[v]; smoothNormal[3 * i + 1] = vn[v + 1]; smoothNormal[3 * i + 2] = vn[v + 2];
  }
  const colors = new Uint8Array(9 * nt);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(cornerPos, 3));
  const flatAttr = new THREE.BufferAttribute(flatNormal, 3), smoothAttr = new THREE.BufferAttribute(smoothNormal, 3);
  geometry.setAttribute('normal', meta.dimension === 3 ? flatAttr : smoothAttr);
  const colorAttr = new THREE.BufferAttribute(colors, 3, true);
  geometry.setAttribute('color', colorAttr);
  let drawn = new Uint32Array(3 * nt); // corner numbers of the drawn triangles
  for (let i = 0; i < 3 * nt; ++i) drawn[i] = i;
  geometry.setIndex(new THREE.BufferAttribute(drawn, 1));
  geometry.computeBoundingSphere();

  const material = new THREE.MeshLambertMaterial({
    vertexColors: true, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  });
  const mesh = new THREE.Mesh(geometry, material);
  const scene = new THREE.Scene();
  scene.add(mesh);

  // ---- camera: looking at the centre of the bounding box, iso direction
  const lo = new THREE.Vector3(...meta.bbox.slice(0, 3)), hi = new THREE.Vector3(...meta.bbox.slice(3, 6));
  const centre = lo.clone().add(hi).multiplyScalar(0.5);
  const radius = Math.max(hi.clone().sub(lo).length() / 2, 1e-9);
  const camera = new THREE.PerspectiveCamera(30, window.innerWidth / window.innerHeight, radius / 100, radius * 100);
  const home = () => {
    // the bounding sphere of the box fits the narrower field of view
    const half = Math.min(THREE.MathUtils.degToRad(camera.fov / 2), Math.atan(Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)) * camera.aspect));
    const d = radius / Math.sin(half);
    camera.position.copy(centre).add(new THREE.Vector3(1, 1, 1).normalize().multiplyScalar(d));
    camera.up.set(0, 1, 0);
    camera.lookAt(centre);
  };
  home();
  scene.add(camera);
  // as cgogn render: 0.2 + 0.8 |n.l| of the colour (three's Lambert divides by pi)
  scene.add(new THREE.AmbientLight(0xffffff, 0.2 * Math.PI));
  const light = new THREE.DirectionalLight(0xffffff, 0.8 * Math.PI);
  light.position.set(0, 0, 0);
  light.target.position.set(0, 0, -1);
  camera.add(light, light.target); // a headlight
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.screenSpacePanning = true;
  controls.update();

  // ---- which triangles are drawn (volume meshes: the clipping plane)
  const shown = new Uint8Array(nt).fill(1);
  let cellMin = null, cellMax = null;
  const clip = { on: false, axis: 0, at: 0.5, flip: false };
  if (meta.dimension === 3) {
    const nc = cellOffsets.length - 1;
    cellMin = new Float32Array(3 * nc).fill(Infinity);
    cellMax = new Float32Array(3 * nc).fill(-Infinity);
    for (let c = 0; c < nc; ++c)
      for (let t = cellOffsets[c]; t < cellOffsets[c + 1]; ++t)
        for (let k = 0; k < 3; ++k) {
          const v = 3 * tri[3 * t + k];
          for (let a = 0; a < 3; ++a) {
            cellMin[3 * c + a] = Math.min(cellMin[3 * c + a], pos[v + a]);
            cellMax[3 * c + a] = Math.max(cellMax[3 * c + a], pos[v + a]);
          }
        }
  }
  function updateShown() {
    if (meta.dimension !== 3) return;
    const nc = cellOffsets.length - 1, a = clip.axis;
    const x = lo.getComponent(a) + clip.at * (hi.getComponent(a) - lo.getComponent(a));
    let n = 0;
    for (let c = 0; c < nc; ++c) {
      // kept side: coordinate <= x (or >= x when flipped)
      const mn = clip.flip ? -cellMax[3 * c + a] : cellMin[3 * c + a];
      const mx = clip.flip ? -cellMin[3 * c + a] : cellMax[3 * c + a];
      const p = clip.flip ? -x : x;
      const far = clip.on && mn > p, crossed = clip.on && mn <= p && mx > p;
      for (let t = cellOffsets[c]; t < cellOffsets[c + 1]; ++t) {
        const s = far ? 0 : crossed ? 1 : (flags[t] & ON_BOUNDARY ? 1 : 0);
        shown[t] = s;
        n += s;
      }
    }
    drawn = new Uint32Array(3 * n);
    let k = 0;
    for (let t = 0; t < nt; ++t)
      if (shown[t]) { drawn[k++] = 3 * t; drawn[k++] = 3 * t + 1; drawn[k++] = 3 * t + 2; }
    geometry.setIndex(new THREE.BufferAttribute(drawn, 1));
    document.getElementById('clip-count').textContent = n + ' of ' + nt + ' triangles';
  }

  // ---- overlays: edges, boundary edges, split vertices
  function segments(mask) {
    const out = [];
    const pairs = [[0, 1, EDGE_AB | BOUNDARY_AB], [1, 2, EDGE_BC | BOUNDARY_BC], [2, 0, EDGE_CA | BOUNDARY_CA]];
    for (let t = 0; t < nt; ++t) {
      if (!shown[t] || !(flags[t] & mask)) continue;
      for (const [i, j, bits] of pairs)
        if (flags[t] & bits & mask) out.push(tri[3 * t + i], tri[3 * t + j]);
    }
    return new Uint32Array(out);
  }
  const pointsAttr = new THREE.BufferAttribute(pos, 3);
  function lineObject(mask, color, hiddenOpacity) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', pointsAttr);
    g.setIndex(new THREE.BufferAttribute(segments(mask), 1));
    const group = new THREE.Group();
    if (hiddenOpacity > 0) {
      const faint = new THREE.LineSegments(g, new THREE.LineBasicMaterial({
        color, transparent: true, opacity: hiddenOpacity, depthTest: false, depthWrite: false }));
      faint.renderOrder = 1;
      group.add(faint);
    }
    const full = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color }));
    full.renderOrder = 2;
    group.add(full);
    group.userData.geometry = g;
    return group;
  }
  const edges = lineObject(EDGE_AB | EDGE_BC | EDGE_CA, 0x232328, 0);
  const boundary = lineObject(BOUNDARY_AB | BOUNDARY_BC | BOUNDARY_CA, 0xe61919, 0.25);
  const splitGeometry = new THREE.BufferGeometry();
  splitGeometry.setAttribute('position', pointsAttr);
  splitGeometry.setIndex(new THREE.BufferAttribute(split, 1));
  const defects = new THREE.Group();
  defects.add(boundary);
  const splitFaint = new THREE.Points(splitGeometry, new THREE.PointsMaterial({
    color: 0xff8c00, size: 7, sizeAttenuation: false, transparent: true, opacity: 0.25, depthTest: false }));
  splitFaint.renderOrder = 3;
  const splitFull = new THREE.Points(splitGeometry, new THREE.PointsMaterial({ color: 0xff8c00, size: 7, sizeAttenuation: false }));
  splitFull.renderOrder = 4;
  defects.add(splitFaint, splitFull);
  scene.add(edges, defects);
  function updateLines() {
    for (const [obj, mask] of [[edges, EDGE_AB | EDGE_BC | EDGE_CA], [boundary, BOUNDARY_AB | BOUNDARY_BC | BOUNDARY_CA]])
      if (obj.visible) obj.userData.geometry.setIndex(new THREE.BufferAttribute(segments(mask), 1));
  }

  // ---- colours
  const viridis = meta.viridis;
  const uniform = meta.surface_color;
  const scalarArrays = {};
  function setColors(q) {
    if (!q.array) {
      for (let i = 0; i < 3 * nt; ++i) colors.set(uniform, 3 * i);
    } else {
      const s = scalarArrays[q.array] || (scalarArrays[q.array] = decode(meta, q.array));
      const rgb = (u) => (u === NO_VALUE ? [128, 128, 128] : viridis[Math.min(255, Math.round(u / 254 * 255))]);
      for (let i = 0; i < 3 * nt; ++i) colors.set(rgb(q.on === 'vertices' ? s[tri[i]] : s[Math.floor(i / 3)]), 3 * i);
    }
    colorAttr.needsUpdate = true;
    const legend = document.getElementById('legend');
    legend.hidden = !q.array;
    if (q.array) {
      document.getElementById('legend-name').textContent = q.label;
      document.getElementById('legend-hi').textContent = (q.above ? '≥ ' : '') + q.hi.toPrecision(4);
      document.getElementById('legend-lo').textContent = (q.below ? '≤ ' : '') + q.lo.toPrecision(4);
    }
  }
  const stops = [];
  for (let i = 0; i <= 16; ++i) {
    const c = viridis[Math.round((16 - i) / 16 * 255)];
    stops.push('rgb(' + c.join(',') + ') ' + (i / 16 * 100).toFixed(1) + '%');
  }
  document.getElementById('legend-bar').style.background = 'linear-gradient(' + stops.join(',') + ')';

  // ---- the panel
  const ui = document.getElementById('controls');
  const check = (label, on, change) => {
    const box = el('input', { type: 'checkbox' });
    box.checked = on;
    box.addEventListener('change', () => { change(box.checked); redraw(); });
    ui.append(el('label', {}, box, ' ' + label));
    change(on);
    return box;
  };
  const select = el('select', { id: 'color' });
  meta.quantities.forEach((q, i) => select.append(el('option', { value: String(i), text: q.label })));
  select.value = String(meta.initial.color);
  select.addEventListener('change', () => { setColors(meta.quantities[Number(select.value)]); redraw(); });
  ui.append(el('label', {}, 'colour ', select));
  check('edges', meta.initial.edges, (on) => { edges.visible = on; updateLines(); });
  check('boundary edges', meta.initial.defects, (on) => { boundary.visible = on; updateLines(); });
  check('split vertices', meta.initial.defects, (on) => { splitFaint.visible = on; splitFull.visible = on; });
  check('smooth shading', meta.dimension === 2, (on) => { geometry.setAttribute('normal', on ? smoothAttr : flatAttr); });
  if (meta.dimension === 3) {
    const axis = el('select', { id: 'clip-axis' });
    for (const a of ['x', 'y', 'z']) axis.append(el('option', { value: a, text: a }));
    const slider = el('input', { id: 'clip-at', type: 'range', min: '0', max: '1000', value: '500' });
    const refresh = () => { updateShown(); updateLines(); redraw(); };
    axis.addEventListener('change', () => { clip.axis = 'xyz'.indexOf(axis.value); refresh(); });
    slider.addEventListener('input', () => { clip.at = Number(slider.value) / 1000; refresh(); });
    const onBox = el('input', { type: 'checkbox', id: 'clip-on' });
    onBox.addEventListener('change', () => { clip.on = onBox.checked; refresh(); });
    const flipBox = el('input', { type: 'checkbox' });
    flipBox.addEventListener('change', () => { clip.flip = flipBox.checked; refresh(); });
    ui.append(el('div', { class: 'group' }, el('label', {}, onBox, ' clip'), ' axis ', axis, ' ', el('label', {}, flipBox, ' keep the other side'),
      el('div', {}, slider), el('div', { id: 'clip-count', class: 'small' })));
    // a link can open the page clipped: #clip=AXIS:AT[:flip], AT in [0, 1]
    const wanted = /clip=([xyz]):([0-9.]+)(:flip)?/.exec(window.location.hash);
    if (wanted) {
      clip.on = onBox.checked = true;
      axis.value = wanted[1];
      clip.axis = 'xyz'.indexOf(wanted[1]);
      clip.at = Math.min(1, Math.max(0, Number(wanted[2]) || 0));
      slider.value = String(Math.round(clip.at * 1000));
      clip.flip = flipBox.checked = !!wanted[3];
    }
  }
  const homeButton = el('button', { text: 'reset view' });
  homeButton.addEventListener('click', () => { home(); controls.target.copy(centre); controls.update(); redraw(); });
  ui.append(homeButton);
  document.getElementById('counts').textContent = meta.counts;

  setColors(meta.quantities[meta.initial.color]);
  updateShown();
  updateLines();

  let pending = false;
  function redraw() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; renderer.render(scene, camera); });
  }
  controls.addEventListener('change', redraw);
  window.addEventListener('resize', () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    redraw();
  });
  renderer.render(scene, camera);
  document.body.dataset.state = 'ready';
  // milliseconds spent in this script, and since the page started loading
  document.body.dataset.scriptMs = String(Math.round(performance.now() - t0));
  document.body.dataset.readyMs = String(Math.round(performance.now()));
}

try {
  main();
} catch (e) {
  const m = document.getElementById('error');
  m.hidden = false;
  m.textContent = 'The page could not show the mesh: ' + (e && e.message ? e.message : e);
  document.body.dataset.state = 'error';
}
