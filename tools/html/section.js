// section-calc --html: the section drawing, its capacities and the interaction diagrams of the
// exact yield surface, from the data element "plascap-data" (docs/replay.md, "The section page").
// #plascap-status reports data-state (ready, error), data-rows (table rows), data-charts and
// data-curve-points (points drawn over the three diagrams), data-errors.
(function () {
  'use strict';
  const page = window.plascapPage, check = page.check, si = page.si, element = page.element;

  // The table's rows: the JSON key, what it is, its unit (SI).
  const ROWS = [
    ['N', 'N, axial (tension)', 'N'], ['N_neg', 'N_neg, axial (compression)', 'N'],
    ['Qx', 'Qx, shear along x', 'N'], ['Qz', 'Qz, shear along z', 'N'],
    ['Mx', 'Mx, bending about x (strong axis of shapes)', 'N·m'], ['Mx_neg', 'Mx_neg, the other way', 'N·m'],
    ['Mz', 'Mz, bending about z', 'N·m'], ['Mz_neg', 'Mz_neg, the other way', 'N·m'],
    ['My', 'My, torsion (paper eq. 2.14)', 'N·m'], ['My_plastic_torsion', 'T_p, fully plastic torque', 'N·m'],
    ['area', 'area A', 'm²'], ['Ixx', 'Ixx', 'm⁴'], ['Izz', 'Izz', 'm⁴'], ['Wx', 'Wx, elastic modulus', 'm³'],
    ['Wz', 'Wz, elastic modulus', 'm³'], ['J', 'J, Saint-Venant', 'm⁴'], ['EA', 'EA', 'N'], ['EIxx', 'EIxx', 'N·m²'],
    ['EIzz', 'EIzz', 'N·m²'], ['GJ', 'GJ', 'N·m²'], ['utilisation', 'utilisation of the load', ''],
  ];

  function closed(points) {
    return points.length ? points.concat([points[0]]) : points;
  }

  // One diagram: the exact curve, the box of independent limits, the load's point if any.
  function diagram(canvas, title, xName, yName, curve, box, load) {
    const datasets = [
      { label: 'exact surface', data: closed(curve).map(function (p) { return { x: p[0], y: p[1] }; }),
        showLine: true, borderColor: '#2b6cb0', backgroundColor: '#2b6cb0', pointRadius: 0, borderWidth: 2 },
      { label: 'independent limits', data: [
        { x: box[0], y: box[2] }, { x: box[1], y: box[2] }, { x: box[1], y: box[3] }, { x: box[0], y: box[3] }, { x: box[0], y: box[2] }],
        showLine: true, borderColor: '#a0aec0', backgroundColor: '#a0aec0', borderDash: [5, 4], pointRadius: 0, borderWidth: 1 },
    ];
    if (load) datasets.push({ label: 'load', data: [{ x: load[0], y: load[1] }], borderColor: '#c53030', backgroundColor: '#c53030', pointRadius: 5 });
    return new Chart(canvas, {
      type: 'scatter',
      data: { datasets: datasets },
      options: {
        animation: false, responsive: true, maintainAspectRatio: false,
        plugins: { title: { display: true, text: title }, legend: { position: 'bottom', labels: { boxWidth: 10 } } },
        scales: { x: { title: { display: true, text: xName } }, y: { title: { display: true, text: yName } } },
      },
    });
  }

  function build() {
    const d = page.readData('plascap-section', 'a section-calc report');
    const r = d.report;
    check(r && typeof r === 'object' && typeof r.N === 'number', 'its report holds no capacities');
    document.body.className = 'section-page';
    const header = element('header', {}, document.body);
    element('h1', { text: d.title }, header);
    element('div', { class: 'meta', text: d.version_of_tool + ' · ' + r.method + ' route · shear ' + (r.shear || '') + ' · ' +
      r.parts + ' part(s), ' + r.vertices + ' vertices' }, header);
    const cards = element('div', { class: 'cards' }, document.body);
    const drawing = element('div', { class: 'card', id: 'drawing' }, cards);
    element('h2', { text: 'Section' }, drawing);
    const svgHolder = element('div', {}, drawing);
    svgHolder.innerHTML = d.svg;  // section-calc's own drawing
    const svg = svgHolder.querySelector('svg');
    check(svg, 'its drawing is not SVG');
    if (!svg.getAttribute('viewBox')) {  // scale the drawing to the card instead of cropping it
      svg.setAttribute('viewBox', '0 0 ' + svg.getAttribute('width') + ' ' + svg.getAttribute('height'));
      svg.removeAttribute('height');
      svg.setAttribute('width', '100%');
    }

    const card = element('div', { class: 'card', id: 'capacities' }, cards);
    element('h2', { text: 'Capacities and properties' }, card);
    const table = element('table', {}, card);
    let rows = 0;
    for (const [key, label, unit] of ROWS) {
      if (typeof r[key] !== 'number') continue;
      const tr = element('tr', {}, table);
      element('th', { class: 'name', text: label }, tr);
      element('td', { text: unit ? si(r[key], unit) : r[key].toFixed(4) }, tr);
      element('td', { class: 'name note', text: key }, tr);
      rows += 1;
    }
    element('p', { class: 'note', text: 'Capacities by the definitions of “Handling of plasticity in physics engine” ' +
      '(eqs. 2.10–2.14); the JSON keys are those of section-calc --json.' }, card);

    const diagrams = element('div', { class: 'diagrams' }, document.body);
    let charts = 0, points = 0;
    const c = r.interaction;
    const load = r.load_check ? r.load_check.load : null;
    if (c) {
      check(Array.isArray(c.N_Mx) && Array.isArray(c.N_Mz) && c.Mx_Mz && Array.isArray(c.Mx_Mz.points),
            'its interaction curves are incomplete');
      const kilo = function (pts) { return pts.map(function (p) { return [p[1] / 1e3, p[0] / 1e3]; }); };  // (moment, N) in k
      const specs = [
        ['N – Mx', 'Mx [kN·m]', 'N [kN]', kilo(c.N_Mx), [-r.Mx_neg, r.Mx, -r.N_neg, r.N], load ? [load.Mx, load.N] : null],
        ['N – Mz', 'Mz [kN·m]', 'N [kN]', kilo(c.N_Mz), [-r.Mz_neg, r.Mz, -r.N_neg, r.N], load ? [load.Mz, load.N] : null],
        ['Mx – Mz at N = ' + si(c.Mx_Mz.N, 'N'), 'Mx [kN·m]', 'Mz [kN·m]',
         c.Mx_Mz.points.map(function (p) { return [p[0] / 1e3, p[1] / 1e3]; }), [-r.Mx_neg, r.Mx, -r.Mz_neg, r.Mz],
         load ? [load.Mx, load.Mz] : null],
      ];
      for (const [title, xName, yName, curve, box, at] of specs) {
        const holder = element('div', { class: 'card' }, diagrams);
        const canvas = element('canvas', {}, element('div', { class: 'chart' }, holder));
        diagram(canvas, title, xName, yName, curve, box.map(function (v) { return v / 1e3; }),
                at ? [at[0] / 1e3, at[1] / 1e3] : null);
        charts += 1;
        points += curve.length;
      }
    }
    if (d.note) element('p', { class: 'note', style: 'padding: 0 14px', text: d.note }, document.body);
    page.report({ state: 'ready', rows: rows, charts: charts, curvePoints: points, errors: page.errors(), message: '' });
  }

  page.run('section report', build);
})();
