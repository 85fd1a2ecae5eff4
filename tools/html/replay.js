// plastic-sim --html: replays a run from the data element "plascap-data" (docs/replay.md).
// three.js draws the bodies and the joints, Chart.js the energy ledger and the joints' dissipation.
// The page reports its state in #plascap-status's data-* attributes, for people and for tests:
// data-state (loading, ready, done, error), data-frames, data-frames-drawn, data-broken-end,
// data-broken-shown, data-errors, data-fps, data-render-ms, data-message.
// URL fragments: #autoplay draws every frame once as fast as it can, then reports data-state
// "done" (tests, and the frame rate); #frame=N shows frame N; #end the last frame.
(function () {
  'use strict';

  const STATE = { elastic: 0, yielding: 1, broken: 2, notEngaged: 3 };
  // Joint colours: elastic joints from blue (unloaded) through green to orange (at the capacity or
  // surface), red while yielding, magenta once broken, grey before they engage.
  const RAMP = [[43, 131, 186], [171, 221, 164], [253, 174, 97]];
  const YIELDING = [215, 25, 28];
  const BROKEN = [255, 0, 255];
  const NOT_ENGAGED = [150, 150, 150];

  const page = window.plascapPage, report = page.report, check = page.check, si = page.si, element = page.element;
  function fail(message) { page.fail('This replay cannot be shown: ' + message); }

  function bytesOf(text, what, expected) {
    check(typeof text === 'string', what + ' is missing');
    let binary;
    try {
      binary = atob(text);
    } catch (e) {
      throw new Error(what + ' is not base64 data');
    }
    check(binary.length === expected, what + ' holds ' + binary.length + ' bytes where the frames need ' + expected);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }

  // uint16, little-endian, times scale: one value per joint and frame.
  function quantised(q, what, count) {
    check(q && typeof q.scale === 'number' && isFinite(q.scale), what + '.scale is missing');
    const bytes = bytesOf(q.data, what, count * 2);
    const view = new DataView(bytes.buffer);
    const out = new Float32Array(count);
    for (let i = 0; i < count; i++) out[i] = view.getUint16(2 * i, true) * q.scale;
    return out;
  }

  // Reads and checks everything the page draws; throws an Error that says what is wrong.
  function readReplay() {
    const d = page.readData('plascap-replay', 'a plastic-sim replay');
    check(Array.isArray(d.bodies) && Array.isArray(d.joints), 'its data lists no bodies or no joints');
    const f = d.frames;
    check(f && Number.isInteger(f.count) && f.count >= 1, 'its data has no frames');
    check(Array.isArray(f.time) && f.time.length === f.count, 'its frame times do not match the frame count ' + f.count);
    for (let k = 0; k < f.count; k++) {
      check(typeof f.time[k] === 'number' && isFinite(f.time[k]) && (k === 0 || f.time[k] >= f.time[k - 1]),
            'frame ' + k + ' has a bad time (' + f.time[k] + ')');
    }
    const nb = d.bodies.length, nj = d.joints.length, n = f.count;
    for (let i = 0; i < nb; i++) {
      const b = d.bodies[i];
      check(b && Array.isArray(b.size) && b.size.length === 3 && b.size.every(isFinite), 'body ' + i + ' has no size');
      check(b.outline === null || (Number.isInteger(b.outline) && b.outline >= 0 && b.outline < (d.outlines || []).length),
            'body ' + i + ' (' + b.name + ') names an outline that is not there');
    }
    for (let j = 0; j < nj; j++) {
      const joint = d.joints[j];
      check(joint && Number.isInteger(joint.b) && joint.b >= 0 && joint.b < nb, 'joint ' + j + ' names no body b');
      check(Array.isArray(joint.anchor_in_b) && joint.anchor_in_b.length === 3, 'joint ' + j + ' has no anchor');
    }
    const p = f.poses;
    check(p && Array.isArray(p.centre) && Array.isArray(p.scale), 'its body poses are missing');
    const poseBytes = bytesOf(p.data, 'the body poses', n * nb * 14);
    const view = new DataView(poseBytes.buffer);
    const positions = new Float32Array(n * nb * 3), quaternions = new Float32Array(n * nb * 4);
    for (let k = 0; k < n * nb; k++) {
      for (let c = 0; c < 3; c++) positions[3 * k + c] = p.centre[c] + view.getInt16(14 * k + 2 * c, true) * p.scale[c];
      for (let c = 0; c < 4; c++) quaternions[4 * k + c] = view.getInt16(14 * k + 6 + 2 * c, true) * p.quaternion_scale;
    }
    const energy = d.energy || {};
    for (const key of ['kinetic', 'gravitational', 'elastic', 'dissipated', 'external_work', 'remainder']) {
      check(Array.isArray(energy[key]) && energy[key].length === n, 'its energy ledger (' + key + ') does not match the frames');
    }
    return {
      data: d,
      frames: n,
      time: f.time,
      positions: positions,
      quaternions: quaternions,
      states: bytesOf(f.joint_states, 'the joint states', n * nj),
      utilisation: bytesOf(f.joint_utilisation, 'the joint utilisation', n * nj),
      dissipated: quantised(f.joint_dissipated, 'the joints\' dissipated energy', n * nj),
      plasticDisplacement: quantised(f.joint_plastic_displacement, 'the joints\' plastic displacement', n * nj),
      plasticRotation: quantised(f.joint_plastic_rotation, 'the joints\' plastic rotation', n * nj),
    };
  }

  function colourOf(state, u) {
    if (state === STATE.broken) return BROKEN;
    if (state === STATE.yielding) return YIELDING;
    if (state === STATE.notEngaged) return NOT_ENGAGED;
    const t = Math.min(Math.max(u, 0), 1) * (RAMP.length - 1);
    const i = Math.min(Math.floor(t), RAMP.length - 2), s = t - i;
    return [0, 1, 2].map(function (c) { return RAMP[i][c] + s * (RAMP[i + 1][c] - RAMP[i][c]); });
  }
  const css = function (rgb) { return 'rgb(' + rgb.map(Math.round).join(',') + ')'; };

  function buildLayout(r) {
    const d = r.data;
    document.body.className = 'replay';
    const header = element('header', {}, document.body);
    element('h1', { text: d.title }, header);
    const broken = d.joints.filter(function (j) { return d.summary && d.summary.joints[j.name] && d.summary.joints[j.name].broken; }).length;
    element('div', { class: 'meta', text: d.engine + ' · ' + d.scene.steps + ' steps of ' + si(d.scene.dt, 's') + ' · ' +
      d.bodies.length + ' bodies, ' + d.joints.length + ' joints (' + broken + ' broken by the end) · ' + r.frames +
      ' frames' }, header);
    const view = element('div', { id: 'view' }, document.body);
    const legend = element('div', { id: 'legend' }, view);
    const ramp = element('div', {}, legend);
    element('span', { class: 'ramp', style: 'background: linear-gradient(to right,' + RAMP.map(css).join(',') + ')' }, ramp);
    element('span', { text: 'elastic: load / capacity 0 → 1' }, ramp);
    for (const [rgb, label] of [[YIELDING, 'yielding'], [BROKEN, 'broken'], [NOT_ENGAGED, 'not engaged yet']]) {
      const row = element('div', {}, legend);
      element('span', { class: 'swatch', style: 'background:' + css(rgb) }, row);
      element('span', { text: label }, row);
    }
    const panels = element('aside', { id: 'panels' }, document.body);
    const energySection = element('section', {}, panels);
    element('h2', { text: 'Energy ledger [J]' }, energySection);
    const energyCanvas = element('canvas', { id: 'energy-chart' }, element('div', { class: 'chart' }, energySection));
    const jointSection = element('section', {}, panels);
    element('h2', { text: 'Dissipated energy by joint (largest ten) [J]' }, jointSection);
    const jointCanvas = element('canvas', { id: 'joint-chart' }, element('div', { class: 'chart' }, jointSection));
    const info = element('section', { id: 'info' }, panels);
    const controls = element('footer', { id: 'controls' }, document.body);
    return { view: view, legend: legend, energyCanvas: energyCanvas, jointCanvas: jointCanvas, info: info, controls: controls };
  }

  // Bodies: boxes, or a structure segment's section extruded along its y.
  function bodyGeometry(body, outlines, cache) {
    const key = body.outline === null ? 'box ' + body.size.join(' ') : 'outline ' + body.outline + ' ' + body.size[1];
    if (cache.has(key)) return cache.get(key);
    let geometry;
    if (body.outline === null) {
      geometry = new THREE.BoxBufferGeometry(body.size[0], body.size[1], body.size[2]);
    } else {
      const shapes = outlines[body.outline].map(function (part) {
        const shape = new THREE.Shape(part.outer.map(function (p) { return new THREE.Vector2(p[0], p[1]); }));
        for (const hole of part.holes) shape.holes.push(new THREE.Path(hole.map(function (p) { return new THREE.Vector2(p[0], p[1]); })));
        return shape;
      });
      const length = body.size[1];
      geometry = new THREE.ExtrudeBufferGeometry(shapes, { depth: length, bevelEnabled: false, steps: 1, curveSegments: 4 });
      geometry.translate(0, 0, -length / 2);
      geometry.rotateX(Math.PI / 2);  // section (x, z) in the shape's (x, y); the extrusion along the body's y
    }
    cache.set(key, geometry);
    return geometry;
  }

  function start() {
    report({ startMs: performance.now().toFixed(0) });
    let r;
    try {
      r = readReplay();
    } catch (e) {
      fail(e.message);
      return;
    }
    const d = r.data, nb = d.bodies.length, nj = d.joints.length;
    report({ readMs: performance.now().toFixed(0) });
    const layout = buildLayout(r);

    let renderer;
    try {
      // Antialiasing costs a software renderer (a browser without a GPU) half its frame rate:
      // large scenes go without it.
      renderer = new THREE.WebGLRenderer({ antialias: nb + nj <= 400, preserveDrawingBuffer: true });
    } catch (e) {
      fail('this browser gives it no WebGL (' + e.message + ')');
      return;
    }
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    layout.view.appendChild(renderer.domElement);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xeef1f4);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f99, 0.75));
    const sun = new THREE.DirectionalLight(0xffffff, 0.55);
    scene.add(sun);

    const g = d.scene.gravity || [0, -9.81, 0];
    const gn = Math.hypot(g[0], g[1], g[2]);
    const up = gn > 0 ? new THREE.Vector3(-g[0] / gn, -g[1] / gn, -g[2] / gn) : new THREE.Vector3(0, 1, 0);

    // The bodies, and the box around where they start (the camera's first view).
    const cache = new Map();
    const materials = {
      dynamic: new THREE.MeshLambertMaterial({ color: 0xc3ccd6 }),
      structure: new THREE.MeshLambertMaterial({ color: 0xa9b6c4 }),
      fixed: new THREE.MeshLambertMaterial({ color: 0x7b8794 }),
    };
    // One instanced mesh per shape and material: a thousand segments are a few draw calls.
    const groups = new Map(), slot = [];  // slot[i]: body i's [group, instance]
    for (let i = 0; i < nb; i++) {
      const b = d.bodies[i];
      const geometry = bodyGeometry(b, d.outlines || [], cache);
      const material = b.static ? materials.fixed : b.outline !== null ? materials.structure : materials.dynamic;
      const key = geometry.uuid + ' ' + material.uuid;
      if (!groups.has(key)) groups.set(key, { geometry: geometry, material: material, bodies: [] });
      const group = groups.get(key);
      slot.push([group, group.bodies.length]);
      group.bodies.push(i);
    }
    for (const group of groups.values()) {
      group.mesh = new THREE.InstancedMesh(group.geometry, group.material, group.bodies.length);
      group.mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
      group.mesh.frustumCulled = false;  // its bounds are the geometry's, not the instances'
      scene.add(group.mesh);
    }
    const bodyMatrix = new THREE.Matrix4(), bodyPosition = new THREE.Vector3(), bodyRotation = new THREE.Quaternion();
    const unit = new THREE.Vector3(1, 1, 1);
    const bounds = new THREE.Box3();
    // The camera frames the moving bodies where they start and where they end (a ground plane
    // would dwarf them), or every body if none moves.
    const framed = d.bodies.some(function (b) { return !b.static; });
    for (const k of [0, r.frames - 1]) {
      for (let i = 0; i < nb; i++) {
        const b = d.bodies[i], at = k * nb + i;
        if (framed && b.static) continue;
        const c = new THREE.Vector3(r.positions[3 * at], r.positions[3 * at + 1], r.positions[3 * at + 2]);
        const h = 0.5 * Math.hypot(b.size[0], b.size[1], b.size[2]);
        bounds.expandByPoint(c.clone().addScalar(-h)).expandByPoint(c.clone().addScalar(h));
      }
    }
    if (bounds.isEmpty()) bounds.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
    const centre = bounds.getCenter(new THREE.Vector3());
    const radius = Math.max(bounds.getSize(new THREE.Vector3()).length() / 2, 1e-3);

    // The joints: one point each, drawn over the bodies so none hides.
    const jointPositions = new Float32Array(3 * Math.max(nj, 1));
    const jointColours = new Float32Array(3 * Math.max(nj, 1));
    const jointGeometry = new THREE.BufferGeometry();
    jointGeometry.setAttribute('position', new THREE.BufferAttribute(jointPositions, 3));
    jointGeometry.setAttribute('color', new THREE.BufferAttribute(jointColours, 3));
    jointGeometry.setDrawRange(0, nj);
    const jointPoints = new THREE.Points(jointGeometry, new THREE.PointsMaterial({
      size: 9, sizeAttenuation: false, vertexColors: THREE.VertexColors, depthTest: false, transparent: true }));
    jointPoints.renderOrder = 2;
    scene.add(jointPoints);
    const selection = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 12, 8),
                                      new THREE.MeshBasicMaterial({ color: 0x111111, wireframe: true, depthTest: false }));
    selection.visible = false;
    selection.renderOrder = 3;
    scene.add(selection);

    const camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 100);
    camera.up.copy(up);
    const side = Math.abs(up.y) > 0.9 ? new THREE.Vector3(0.8, 0, 1.3) : new THREE.Vector3(1.3, 0.8, 0);
    side.addScaledVector(up, 0.55).normalize();
    camera.position.copy(centre).addScaledVector(side, radius * 2.6);
    sun.position.copy(camera.position).addScaledVector(up, radius * 2);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.copy(centre);
    controls.update();

    // Frames are drawn on demand: while playing, or once after a change (the camera, a frame, a
    // resize); an idle page costs nothing.
    let needsRender = true, ticking = false;
    function wake() {
      needsRender = true;
      if (!ticking) {
        ticking = true;
        requestAnimationFrame(tick);
      }
    }
    controls.addEventListener('change', wake);
    function resize() {
      const w = Math.max(layout.view.clientWidth, 100), h = Math.max(layout.view.clientHeight, 100);
      renderer.setSize(w, h);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
      wake();
      const box = function (el) {
        const rect = el.getBoundingClientRect();
        return [rect.left, rect.top, rect.width, rect.height].map(Math.round).join(',');
      };
      report({ view: box(renderer.domElement), legend: box(layout.legend) });
    }
    window.addEventListener('resize', resize);

    // The charts.
    const energyKeys = [['kinetic', 'kinetic', '#2b6cb0'], ['gravitational', 'gravitational', '#38a169'],
      ['elastic', 'elastic', '#d69e2e'], ['dissipated', 'dissipated', '#c53030'],
      ['external_work', 'external work', '#6b46c1'], ['remainder', 'remainder (contacts, solver)', '#4a5568'],
      ['contacts', 'of it: contacts', '#dd6b20'], ['joints_unbooked', 'of it: joints\' rows unbooked', '#319795']]
      .filter(function (k) { return Array.isArray(d.energy[k[0]]) && d.energy[k[0]].length === r.frames; });  // older files lack the parts
    let cursorTime = 0;
    const cursor = {
      id: 'plascapCursor',
      afterDatasetsDraw: function (chart) {
        const x = chart.scales.x.getPixelForValue(cursorTime), area = chart.chartArea;
        const ctx = chart.ctx;
        ctx.save();
        ctx.strokeStyle = 'rgba(0,0,0,0.55)';
        ctx.lineWidth = 1;
        ctx.beginPath();
        ctx.moveTo(x, area.top);
        ctx.lineTo(x, area.bottom);
        ctx.stroke();
        ctx.restore();
      },
    };
    const energyChart = new Chart(layout.energyCanvas, {
      type: 'line',
      data: {
        datasets: energyKeys.map(function (k) {
          return { label: k[1], borderColor: k[2], backgroundColor: k[2], borderWidth: 1.5, pointRadius: 0,
                   data: r.time.map(function (t, i) { return { x: t, y: d.energy[k[0]][i] }; }) };
        }),
      },
      options: {
        animation: false, responsive: true, maintainAspectRatio: false, parsing: false, normalized: true,
        scales: { x: { type: 'linear', title: { display: true, text: 'time [s]' } }, y: { ticks: { maxTicksLimit: 6 } } },
        plugins: { legend: { position: 'bottom', labels: { boxWidth: 10, font: { size: 11 } } } },
      },
      plugins: [cursor],
    });
    const jointChart = new Chart(layout.jointCanvas, {
      type: 'bar',
      data: { labels: [], datasets: [{ label: 'dissipated [J]', data: [], backgroundColor: css(YIELDING) }] },
      options: {
        indexAxis: 'y', animation: false, responsive: true, maintainAspectRatio: false,
        plugins: { legend: { display: false } }, scales: { y: { ticks: { font: { size: 10 } } } },
      },
    });

    // The state of frame k.
    let frame = -1, selected = -1;
    const q = new THREE.Quaternion(), v = new THREE.Vector3();
    function jointWorld(j, k, out) {
      const joint = d.joints[j], b = joint.b, at = k * nb + b;
      q.set(r.quaternions[4 * at + 1], r.quaternions[4 * at + 2], r.quaternions[4 * at + 3], r.quaternions[4 * at]).normalize();
      out.set(joint.anchor_in_b[0], joint.anchor_in_b[1], joint.anchor_in_b[2]).applyQuaternion(q);
      return out.add(v.set(r.positions[3 * at], r.positions[3 * at + 1], r.positions[3 * at + 2]));
    }
    const w = new THREE.Vector3();
    function brokenIn(k) {
      let n = 0;
      for (let j = 0; j < nj; j++) if (r.states[k * nj + j] === STATE.broken) n++;
      return n;
    }
    function showFrame(k) {
      frame = k;
      for (let i = 0; i < nb; i++) {
        const at = k * nb + i;
        bodyPosition.set(r.positions[3 * at], r.positions[3 * at + 1], r.positions[3 * at + 2]);
        bodyRotation.set(r.quaternions[4 * at + 1], r.quaternions[4 * at + 2], r.quaternions[4 * at + 3], r.quaternions[4 * at]).normalize();
        slot[i][0].mesh.setMatrixAt(slot[i][1], bodyMatrix.compose(bodyPosition, bodyRotation, unit));
      }
      for (const group of groups.values()) group.mesh.instanceMatrix.needsUpdate = true;
      for (let j = 0; j < nj; j++) {
        jointWorld(j, k, w);
        jointPositions[3 * j] = w.x;
        jointPositions[3 * j + 1] = w.y;
        jointPositions[3 * j + 2] = w.z;
        const rgb = colourOf(r.states[k * nj + j], r.utilisation[k * nj + j] / 100);
        for (let c = 0; c < 3; c++) jointColours[3 * j + c] = rgb[c] / 255;
      }
      jointGeometry.attributes.position.needsUpdate = true;
      jointGeometry.attributes.color.needsUpdate = true;
      jointGeometry.computeBoundingSphere();
      if (selected >= 0) {
        selection.position.copy(jointWorld(selected, k, w));
        showInfo(selected);
      }
      slider.value = String(k);
      timeLabel.textContent = 't = ' + r.time[k].toFixed(4) + ' s  (' + (k + 1) + ' / ' + r.frames + ')';
      report({ frame: k, brokenShown: brokenIn(k) });
      if (!autoplaying) wake();
    }
    let lastChartUpdate = -Infinity;
    function updateCharts(force) {
      const now = performance.now();
      if (!force && now - lastChartUpdate < 250) return;
      lastChartUpdate = now;
      cursorTime = r.time[frame];
      energyChart.draw();
      const order = [];
      for (let j = 0; j < nj; j++) if (r.dissipated[frame * nj + j] > 0) order.push(j);
      order.sort(function (a, b) { return r.dissipated[frame * nj + b] - r.dissipated[frame * nj + a]; });
      const top = order.slice(0, 10);
      jointChart.data.labels = top.map(function (j) { return d.joints[j].name; });
      jointChart.data.datasets[0].data = top.map(function (j) { return r.dissipated[frame * nj + j]; });
      jointChart.data.datasets[0].backgroundColor = top.map(function (j) {
        return css(colourOf(r.states[frame * nj + j], r.utilisation[frame * nj + j] / 100));
      });
      jointChart.update('none');
    }

    // What a click on a joint shows: its dofs and laws, and its state now and at the end.
    function showInfo(j) {
      const joint = d.joints[j], at = frame * nj + j;
      const end = (d.summary && d.summary.joints[joint.name]) || {};
      const names = ['elastic', 'yielding', 'broken', 'not engaged'];  // by STATE
      const info = layout.info;
      info.textContent = '';
      element('h2', { text: 'Joint ' + joint.name }, info);
      const bodyName = function (i) { return i === null ? 'the world' : d.bodies[i].name; };
      const rows = [
        ['bodies', bodyName(joint.a) + ' – ' + bodyName(joint.b)],
        ['now', names[r.states[at]] + (r.states[at] === STATE.elastic || r.states[at] === STATE.yielding
          ? ', load / capacity ' + (r.utilisation[at] / 100).toFixed(2) + (joint.coupled ? ' (coupled surface U)' : '') : '')],
        ['plastic displacement', si(r.plasticDisplacement[at], 'm') + ' (breaks at ' + si(joint.max_plastic_displacement, 'm') + ')'],
        ['plastic rotation', si(r.plasticRotation[at], 'rad') + ' (breaks at ' + si(joint.max_plastic_rotation, 'rad') + ')'],
        ['dissipated', si(r.dissipated[at], 'J')],
        ['at the end', end.broken ? 'broken at t = ' + end.broken_at.toFixed(4) + ' s' : 'not broken'],
      ];
      const table = element('table', {}, info);
      for (const [k, value] of rows) {
        const tr = element('tr', {}, table);
        element('th', { class: 'name', text: k }, tr);
        element('td', { class: 'name', text: value }, tr);
      }
      const dofs = element('table', {}, info);
      const head = element('tr', {}, dofs);
      for (const h of ['dof', 'mode', 'capacity +', 'capacity −', 'stiffness', 'regime at the end']) element('th', { text: h }, head);
      for (const dof of joint.dofs) {
        const tr = element('tr', {}, dofs);
        const rotation = dof.dof[0] === 'M';
        const regime = end.dofs && end.dofs[dof.dof] ? (end.dofs[dof.dof].regime || end.dofs[dof.dof].mode) : '';
        element('td', { class: 'name', text: dof.dof }, tr);
        element('td', { class: 'name', text: dof.mode }, tr);
        element('td', { text: dof.mode === 'plastic' ? si(dof.capacity_positive, rotation ? 'N·m' : 'N') : '' }, tr);
        element('td', { text: dof.mode === 'plastic' ? si(dof.capacity_negative, rotation ? 'N·m' : 'N') : '' }, tr);
        element('td', { text: dof.mode === 'plastic' ? (dof.stiffness === null ? 'rigid-plastic' : si(dof.stiffness, rotation ? 'N·m/rad' : 'N/m')) : '' }, tr);
        element('td', { class: 'name', text: regime }, tr);
      }
    }
    layout.info.appendChild(element('h2', { text: 'Joint' }));
    element('div', { class: 'hint', text: nj ? 'Click a joint (a coloured point) to see its dofs, capacities, plastic deformation and energy.'
                                             : 'This scene has no joints.' }, layout.info);

    const raycaster = new THREE.Raycaster();
    raycaster.params.Points.threshold = radius / 60;
    let downAt = null;
    renderer.domElement.addEventListener('pointerdown', function (e) { downAt = [e.clientX, e.clientY]; });
    renderer.domElement.addEventListener('pointerup', function (e) {
      if (!downAt || Math.hypot(e.clientX - downAt[0], e.clientY - downAt[1]) > 4) return;  // a drag orbits
      const rect = renderer.domElement.getBoundingClientRect();
      const mouse = new THREE.Vector2(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
      raycaster.setFromCamera(mouse, camera);
      const hits = raycaster.intersectObject(jointPoints);
      if (!hits.length) return;
      hits.sort(function (a, b) { return a.distanceToRay - b.distanceToRay; });
      selected = hits[0].index;
      selection.scale.setScalar(radius / 80);
      selection.visible = true;
      showFrame(frame);
      report({ selected: d.joints[selected].name });
    });

    // Playback: the simulated time runs at `speed` times the wall clock.
    const play = element('button', { id: 'play', text: 'Play' }, layout.controls);
    const slider = element('input', { id: 'timeline', type: 'range', min: '0', max: String(r.frames - 1), step: '1', value: '0' }, layout.controls);
    const timeLabel = element('span', { class: 'time' }, layout.controls);
    const speed = element('select', { id: 'speed', title: 'simulated seconds per second' }, layout.controls);
    const duration = Math.max(r.time[r.frames - 1] - r.time[0], 1e-9);
    const speeds = [];
    for (let e = -5; e <= 1; e++) for (const m of [1, 2, 5]) speeds.push(m * Math.pow(10, e));
    let preferred = speeds[0];
    for (const s of speeds) if (s <= duration / 8) preferred = s;  // the whole run in 8 s or a little more
    for (const s of speeds) element('option', { value: String(s), text: s.toPrecision(1) + '× real time' }, speed);
    speed.value = String(preferred);
    const fpsLabel = element('span', { class: 'fps' }, layout.controls);
    let playing = false, simTime = r.time[0], lastTick = null;
    function setPlaying(on) {
      playing = on;
      play.textContent = on ? 'Pause' : 'Play';
      lastTick = null;
      if (on && frame >= r.frames - 1) simTime = r.time[0];
      if (on) wake();
    }
    play.addEventListener('click', function () { setPlaying(!playing); });
    slider.addEventListener('input', function () {
      setPlaying(false);
      showFrame(Number(slider.value));
      simTime = r.time[frame];
      updateCharts(true);
    });
    window.addEventListener('keydown', function (e) {
      if (e.code === 'Space' && e.target === document.body) { e.preventDefault(); setPlaying(!playing); }
    });
    function frameAt(t) {
      let lo = 0, hi = r.frames - 1;
      while (lo < hi) {
        const mid = (lo + hi + 1) >> 1;
        if (r.time[mid] <= t) lo = mid; else hi = mid - 1;
      }
      return lo;
    }

    // The page's own frame rate (#autoplay): the wall time of showing and drawing a frame, to the
    // end of the GPU's work (a one-pixel read waits for it).
    let drawn = 0, drawMs = 0, drawnTimed = 0;
    const gl = renderer.getContext(), pixel = new Uint8Array(4);
    function draw() {
      renderer.render(scene, camera);
      drawn += 1;
      needsRender = false;
      report({ framesDrawn: drawn });
    }
    let fpsFrames = 0, fpsSince = performance.now(), autoplaying = false;
    function tick(now) {
      if (playing) {
        if (lastTick !== null) simTime += ((now - lastTick) / 1000) * Number(speed.value);
        lastTick = now;
        const k = frameAt(simTime);
        if (k !== frame) showFrame(k);
        if (simTime >= r.time[r.frames - 1]) setPlaying(false);
        updateCharts(!playing);
      }
      if (needsRender) {
        draw();
        fpsFrames += 1;
      }
      if (now - fpsSince > 1000) {
        fpsLabel.textContent = playing ? Math.round((fpsFrames * 1000) / (now - fpsSince)) + ' fps' : '';
        fpsFrames = 0;
        fpsSince = now;
      }
      if (playing || needsRender) {
        requestAnimationFrame(tick);
      } else {
        ticking = false;
        fpsLabel.textContent = '';
      }
    }

    resize();
    report({ state: 'ready', frames: r.frames, bodies: nb, joints: nj, brokenEnd: brokenIn(r.frames - 1),
             errors: page.errors(), message: '', readyMs: performance.now().toFixed(0) });
    const hash = window.location.hash;
    const at = /frame=(\d+)/.exec(hash);
    showFrame(hash.indexOf('end') >= 0 ? r.frames - 1 : at ? Math.min(Number(at[1]), r.frames - 1) : 0);
    updateCharts(true);
    if (hash.indexOf('autoplay') >= 0) {
      // Every frame once, as fast as the browser draws (a timer, not animation frames, so that a
      // headless browser's virtual time runs it too).
      let k = 0, started = performance.now();
      const next = function () {
        const t0 = performance.now();
        showFrame(k);
        draw();
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        drawMs += performance.now() - t0;
        drawnTimed += 1;
        // The charts are not timed: a person's replay redraws them 4 times a second.
        if (k % 25 === 0 || k === r.frames - 1) updateCharts(true);
        k += 1;
        if (k < r.frames) {
          setTimeout(next, 0);
          return;
        }
        const mean = drawMs / Math.max(drawnTimed, 1);
        autoplaying = false;
        report({ state: 'done', renderMs: mean.toFixed(2), fps: (1000 / mean).toFixed(1),
                 autoplayMs: (performance.now() - started).toFixed(0) });
      };
      autoplaying = true;
      setTimeout(next, 0);
    } else {
      setPlaying(hash.indexOf('frame=') < 0 && hash.indexOf('end') < 0);
      wake();
    }
  }

  page.run('replay', start);
})();
