// Viewer of a denoising comparison report: one canvas per mesh, drawn flat
// shaded with three.js, all canvases sharing one orbit camera, an optional
// per-face normal-error heat map, and the table of E_n / E_v / seconds.
//
// Inlined by support/include/denoising_support/comparison_report.h into every
// report (together with three's module build) and used by render.mjs for the
// figures. Page data (JSON, element #report-data):
//   { title, heatMax (degrees), view: {dir: [x,y,z], up: [x,y,z]},
//     faceLists: [base64 Uint32 triangle indices, ...],
//     meshes: [{label, positions: base64 Float32 xyz, faces: index into faceLists,
//               errors: base64 Uint16 per-face hundredths of a degree, or null}],
//     table: [{label, E_n, E_v, seconds}] }
// URL hash options (used by render.mjs): tile=PIXELS, cols=N, heat=1, static=1.
/* exported DenoisingViewer */
var DenoisingViewer = (function () {
  'use strict';

  function decode(b64, Type) {
    const bin = atob(b64);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    return new Type(bytes.buffer);
  }

  // 0 degrees: light blue-grey, heatMax and above: red, through yellow
  function heatColour(t) {
    t = Math.max(0, Math.min(1, t));
    if (t < 0.5) {
      const s = t / 0.5;
      return [0.55 + 0.45 * s, 0.7 + 0.25 * s, 0.95 - 0.75 * s];
    }
    const s = (t - 0.5) / 0.5;
    return [1.0, 0.95 - 0.8 * s, 0.2 - 0.15 * s];
  }

  function hashOptions() {
    const out = {};
    for (const part of location.hash.replace(/^#/, '').split('&')) {
      if (!part) continue;
      const [k, v] = part.split('=');
      out[k] = v === undefined ? '1' : v;
    }
    return out;
  }

  function formatNumber(x, kind) {
    if (x === null || x === undefined || !isFinite(x)) return '';
    if (kind === 'E_v') return x.toExponential(3);
    if (kind === 'seconds') return x.toFixed(2);
    return x.toFixed(3);
  }

  function buildTable(data, parent) {
    if (!data.table || data.table.length === 0) return;
    const table = document.createElement('table');
    table.id = 'error-table';
    const head = table.createTHead().insertRow();
    for (const h of ['mesh', 'E_n (degrees)', 'E_v', 'seconds']) {
      const th = document.createElement('th');
      th.textContent = h;
      head.appendChild(th);
    }
    const body = table.createTBody();
    for (const row of data.table) {
      const tr = body.insertRow();
      tr.insertCell().textContent = row.label;
      for (const kind of ['E_n', 'E_v', 'seconds']) {
        const td = tr.insertCell();
        td.textContent = formatNumber(row[kind], kind);
        td.dataset.kind = kind;
      }
    }
    parent.appendChild(table);
  }

  function start(THREE, data) {
    const opts = hashOptions();
    const tile = parseInt(opts.tile || '320', 10);
    const isStatic = opts.static === '1';
    const heatMax = data.heatMax || 15;
    document.title = data.title || 'denoising report';
    if (isStatic) document.body.classList.add('static');

    const faceLists = data.faceLists.map((b) => decode(b, Uint32Array));
    const grid = document.getElementById('grid');
    grid.style.gridTemplateColumns = 'repeat(' + (opts.cols || 'auto-fill') + ', ' + tile + 'px)';

    // bounding box of all meshes: one camera frames them all
    const box = new THREE.Box3();
    const tiles = [];
    for (const m of data.meshes) {
      const pos = decode(m.positions, Float32Array);
      const tri = faceLists[m.faces];
      const errors = m.errors ? Float32Array.from(decode(m.errors, Uint16Array), (c) => c / 100) : null;
      // non-indexed: each face its own three vertices, so normals are flat
      const nf = pos.length > 0 ? tri.length / 3 : 0;
      const p = new Float32Array(nf * 9);
      for (let f = 0; f < nf; ++f)
        for (let c = 0; c < 3; ++c) {
          const v = tri[3 * f + c];
          p[9 * f + 3 * c] = pos[3 * v];
          p[9 * f + 3 * c + 1] = pos[3 * v + 1];
          p[9 * f + 3 * c + 2] = pos[3 * v + 2];
        }
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(p, 3));
      geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(nf * 9), 3));
      geometry.computeVertexNormals();
      geometry.computeBoundingBox();
      if (nf > 0) box.union(geometry.boundingBox);

      const div = document.createElement('div');
      div.className = 'tile';
      const canvas = document.createElement('canvas');
      canvas.width = tile;
      canvas.height = tile;
      canvas.style.width = tile + 'px';
      canvas.style.height = tile + 'px';
      canvas.dataset.label = m.label;
      const label = document.createElement('div');
      label.className = 'label';
      label.textContent = m.label;
      div.appendChild(canvas);
      div.appendChild(label);
      grid.appendChild(div);

      const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
      renderer.setPixelRatio(1);
      renderer.setSize(tile, tile, false);
      renderer.setClearColor(0xffffff, 1);
      const scene = new THREE.Scene();
      const material = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide });
      scene.add(new THREE.Mesh(geometry, material));
      scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 1.2));
      const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 100);
      const light = new THREE.DirectionalLight(0xffffff, 1.8);
      camera.add(light);
      light.position.set(0.3, 0.5, 1);
      scene.add(camera);
      tiles.push({ label: m.label, canvas, renderer, scene, camera, geometry, errors, nf });
    }

    function setColours(heat) {
      for (const t of tiles) {
        const col = t.geometry.getAttribute('color');
        for (let f = 0; f < t.nf; ++f) {
          const c = heat && t.errors ? heatColour(t.errors[f] / heatMax) : [0.78, 0.8, 0.84];
          for (let k = 0; k < 3; ++k) col.setXYZ(3 * f + k, c[0], c[1], c[2]);
        }
        col.needsUpdate = true;
      }
    }

    // shared orbit camera: spherical coordinates around the box centre
    const centre = box.getCenter(new THREE.Vector3());
    const radius = Math.max(1e-12, box.getSize(new THREE.Vector3()).length() / 2);
    const view = data.view || { dir: [1, 0.6, 1.4], up: [0, 1, 0] };
    const up = new THREE.Vector3().fromArray(view.up).normalize();
    const dir0 = new THREE.Vector3().fromArray(view.dir).normalize();
    // the closest distance at which the box's corners fit the 30-degree field of view, 5% margin
    const right0 = new THREE.Vector3().crossVectors(up, dir0).normalize();
    const up0 = new THREE.Vector3().crossVectors(dir0, right0);
    const t = Math.tan((15 * Math.PI) / 180) * 0.95;
    let distance = radius * 1e-3;
    for (let k = 0; k < 8; ++k) {
      const c = new THREE.Vector3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z).sub(centre);
      const z = c.dot(dir0);
      distance = Math.max(distance, z + Math.abs(c.dot(right0)) / t, z + Math.abs(c.dot(up0)) / t);
    }
    if (box.isEmpty()) distance = 1;
    const orbit = { q: new THREE.Quaternion(), distance };

    function renderAll() {
      const dir = dir0.clone().applyQuaternion(orbit.q);
      const u = up.clone().applyQuaternion(orbit.q);
      for (const t of tiles) {
        t.camera.position.copy(centre).addScaledVector(dir, orbit.distance);
        t.camera.up.copy(u);
        t.camera.lookAt(centre);
        t.camera.near = orbit.distance / 100;
        t.camera.far = orbit.distance * 10;
        t.camera.updateProjectionMatrix();
        t.renderer.render(t.scene, t.camera);
      }
    }

    // dragging any canvas turns the shared camera; the wheel zooms
    let drag = null;
    for (const t of tiles) {
      t.canvas.addEventListener('pointerdown', (e) => {
        drag = { x: e.clientX, y: e.clientY };
        t.canvas.setPointerCapture(e.pointerId);
      });
      t.canvas.addEventListener('pointermove', (e) => {
        if (!drag) return;
        const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
        drag = { x: e.clientX, y: e.clientY };
        const dir = dir0.clone().applyQuaternion(orbit.q);
        const u = up.clone().applyQuaternion(orbit.q);
        const right = new THREE.Vector3().crossVectors(u, dir).normalize();
        const qx = new THREE.Quaternion().setFromAxisAngle(u, -dx * 0.01);
        const qy = new THREE.Quaternion().setFromAxisAngle(right, dy * 0.01);
        orbit.q.premultiply(qx).premultiply(qy);
        renderAll();
      });
      t.canvas.addEventListener('pointerup', () => { drag = null; });
      t.canvas.addEventListener('wheel', (e) => {
        e.preventDefault();
        orbit.distance *= Math.exp(e.deltaY * 0.001);
        renderAll();
      }, { passive: false });
    }

    const heatBox = document.getElementById('heat');
    const heatAvailable = tiles.some((t) => t.errors);
    heatBox.disabled = !heatAvailable;
    heatBox.checked = heatAvailable && opts.heat === '1';
    heatBox.addEventListener('change', () => { setColours(heatBox.checked); renderAll(); });
    document.getElementById('heat-max').textContent = heatMax;
    buildTable(data, document.getElementById('table'));
    document.getElementById('title').textContent = data.title || '';

    setColours(heatBox.checked);
    renderAll();
    window.denoisingViewer = {
      tiles: tiles.map((t) => t.label),
      setHeat(on) { heatBox.checked = on; setColours(on); renderAll(); },
      rotate(angleX, angleY) {
        orbit.q.premultiply(new THREE.Quaternion().setFromAxisAngle(up, angleX));
        renderAll();
      },
      ready: true,
    };
  }

  return { start, decode };
})();
