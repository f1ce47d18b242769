// The script of meshdiff's HTML report (src/report/html.cpp inlines it after
// three.js and OrbitControls). It reads three JSON elements of the page:
// meshdiff-report (the JSON report, as `--json` writes it), meshdiff-meta
// (version, command) and meshdiff-view (the meshes as drawn and their
// per-vertex fields), and builds the tables, the plots (inline SVG) and the
// 3D view. window.meshdiffReport exposes the state for scripts and tests.
// Each part of the page is one function; main() at the bottom calls them in
// the order of the page.
(function () {
  'use strict';
  const byId = (id) => document.getElementById(id);
  const readJson = (id) => JSON.parse(byId(id).textContent);
  const report = readJson('meshdiff-report');
  const meta = readJson('meshdiff-meta');
  const view = readJson('meshdiff-view');
  const app = byId('app');
  // A comparison's page shows two meshes; a profile's (meshdiff.profile/1) one, its keys at the top level.
  const isProfile = String(report.schema || '').startsWith('meshdiff.profile');
  const NAMES = view.meshes.map((m) => m.role);
  const PREFIX = isProfile ? [''] : ['original.', 'processed.'];

  // ---- formatting and elements -------------------------------------------------
  function fmt(x) {
    if (x === null || x === undefined) return '\u2014';
    if (typeof x === 'boolean') return x ? 'yes' : 'no';
    if (typeof x !== 'number') return String(x);
    if (Number.isInteger(x)) return String(x);
    return x.toPrecision(6);
  }
  function el(tag, attrs, children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'text') e.textContent = v;
      else if (k === 'cls') e.className = v;
      else e.setAttribute(k, v);
    }
    for (const c of children || []) e.appendChild(typeof c === 'string' ? document.createTextNode(c) : c);
    return e;
  }
  function get(path) {
    let x = report;
    for (const k of path.split('.')) {
      if (x === null || x === undefined) return undefined;
      x = x[k];
    }
    return x;
  }
  // A table cell showing the report's value at `path`; data-key lets a script check it against the JSON.
  function cell(path) {
    const v = get(path);
    const td = el('td', { text: fmt(v), 'data-key': path });
    if (typeof v === 'number') td.setAttribute('data-value', String(v));
    return td;
  }
  function table(head, rows) {
    const t = el('table');
    t.appendChild(el('tr', {}, head.map((h, i) => el('th', { text: h, cls: i === 0 ? 'l' : '' }))));
    for (const r of rows) t.appendChild(el('tr', {}, r));
    return t;
  }
  const section = (title) => app.appendChild(el('h2', { text: title }));
  // A row's first cell: its label, left-aligned.
  const labelCell = (text) => el('td', { cls: 'l', text: text });
  const sigmaOf = (m) => get(m + '.sigma');

  // ---- header and meshes ------------------------------------------------------------
  function headerSection() {
    app.appendChild(el('h1', { text: isProfile ? 'meshdiff profile: ' + get('mesh.path') :
      'meshdiff: ' + get('original.mesh.path') + ' vs ' + get('processed.mesh.path') }));
    app.appendChild(el('p', { cls: 'sub', text: 'meshdiff ' + meta.version + ', report schema ' + report.schema }));
    app.appendChild(el('code', { cls: 'cmd', id: 'command', text: meta.command }));
  }
  function meshesSection() {
    section(isProfile ? 'Mesh' : 'Meshes');
    const meshRows = [
      ['file', 'path'], ['vertices', 'vertices'], ['faces', 'faces'], ['components', 'components'],
      ['closed', 'closed'], ['boundary loops', 'boundary_loops'], ['area', 'area'], ['bounding-box diagonal', 'bbox.diagonal'],
    ];
    app.appendChild(table([''].concat(NAMES), meshRows.map(([label, key]) =>
      [labelCell(label)].concat(PREFIX.map((m) => cell(m + 'mesh.' + key))))));
    PREFIX.forEach((m, k) => {
      const w = get(m + 'warnings') || [];
      if (w.length) {
        app.appendChild(el('p', { cls: 'warn', text: NAMES[k] + ': ' + w.length + ' warning' + (w.length > 1 ? 's' : '') }));
        app.appendChild(el('ul', { cls: 'warn' }, w.map((s) => el('li', { text: s }))));
      }
    });
  }

  // ---- surface distance ---------------------------------------------------------------
  // The certified bounds and where they are attained, or (without them) the sampled maximum.
  function hausdorffTable(sd) {
    const h = sd.hausdorff;
    if (h && h.lower !== undefined) {
      app.appendChild(table(['Hausdorff', 'lower', 'upper', 'lower / diagonal', 'upper / diagonal'], [[
        labelCell(h.certified ? 'certified' : h.method),
        cell('surface_distance.hausdorff.lower'), cell('surface_distance.hausdorff.upper'),
        cell('surface_distance.hausdorff.relative.lower'), cell('surface_distance.hausdorff.relative.upper')]]));
      const at = sd[h.attained] && sd[h.attained].hausdorff && sd[h.attained].hausdorff.location;
      if (at) {
        app.appendChild(el('p', { text: 'Attained ' + h.attained + ' (' + (h.attained === 'forward' ?
          'original \u2192 processed' : 'processed \u2192 original') + ') at (' + at.point.map(fmt).join(', ') +
          ') on face ' + at.face + ', closest point (' + at.closest_point.map(fmt).join(', ') + '): the magenta marker.' }));
      }
    } else {
      app.appendChild(table(['Hausdorff (sampled)', 'value', '/ diagonal'], [[labelCell('sampled maximum'),
        cell('surface_distance.sampled_hausdorff'), cell('surface_distance.sampled_hausdorff_relative')]]));
    }
  }
  function distanceSection(sd) {
    if (!sd) return;
    section('Surface distance');
    app.appendChild(el('p', { text: 'Relative values are relative to the ' + sd.diagonal_of + ' (' + fmt(sd.diagonal) + ').' }));
    hausdorffTable(sd);
    const stats = ['min', 'max', 'mean', 'rms', 'std', 'p50', 'p95', 'p99', 'p999'];
    const dirs = ['forward', 'backward'];
    app.appendChild(table(['', 'forward', 'backward', 'forward / diagonal', 'backward / diagonal'], stats.map((s) =>
      [labelCell(s)].concat(dirs.map((d) => cell('surface_distance.' + d + '.' + s)),
        dirs.map((d) => cell('surface_distance.' + d + '.relative.' + s))))));
    app.appendChild(el('p', { text: 'forward: ' + sd.forward_is + '; ' + fmt(get('surface_distance.forward.samples')) +
      ' and ' + fmt(get('surface_distance.backward.samples')) + ' samples.' }));
  }

  // ---- roughness ------------------------------------------------------------------------
  // A comparison's ring levels: sigma of both meshes, the relative change, d_L and, when computed, the local
  // roughness difference (each original vertex's D_L against the processed mesh's at the closest point):
  // its column is the one that ranks decimations (reference/README.md).
  function ringRoughnessSection(rd) {
    section('Roughness profile');
    app.appendChild(el('p', { text: rd.formula + ', k = ' + rd.k }));
    const local = rd.local;
    const localCell = (L) => {
      const j = local ? local.levels.indexOf(L) : -1;
      return j < 0 ? el('td', { text: fmt(null) }) : cell('roughness_distance.local.rms.' + j);
    };
    const rows = rd.levels.map((L, i) => [labelCell(String(L)),
      cell('original.sigma.' + i), cell('processed.sigma.' + i),
      cell('roughness_distance.relative_change.' + i), cell('roughness_distance.distance.' + i)]
      .concat(local ? [localCell(L)] : []));
    if (rd.global) rows.push([labelCell('global'), cell('original.sigma_global'), cell('processed.sigma_global'),
      cell('roughness_distance.global.relative_change'), cell('roughness_distance.global.distance')]
      .concat(local ? [local.global === undefined ? el('td', { text: fmt(null) }) : cell('roughness_distance.local.global')] : []));
    app.appendChild(table(['level', 'sigma original', 'sigma processed', 'relative change', 'd_L']
      .concat(local ? ['local RMS'] : []), rows));
    if (local) {
      app.appendChild(el('p', { id: 'local-definition', text: 'local RMS: ' + local.definition +
        (local.trim > 0 ? '; without the ' + fmt(100 * local.trim) + '% largest differences' : '') + '.' }));
    }
  }
  // A profile's ring levels: sigma, the vertices used and the share of the worst 0.1%.
  function profileRoughnessSection() {
    section('Roughness profile');
    app.appendChild(el('p', { text: String(get('neighborhood') || '') }));
    const rows = get('levels').map((L, i) => [labelCell(String(L)), cell('sigma.' + i),
      cell('level_details.' + i + '.vertices_used'), cell('level_details.' + i + '.top_share')]);
    if (get('global')) rows.push([labelCell('global'), cell('sigma_global'), cell('global.vertices_used'), cell('global.top_share')]);
    app.appendChild(table(['level', 'sigma', 'vertices used', 'share of the worst 0.1%'], rows));
  }
  // --measure corsini: Corsini et al.'s dihedral-angle roughness per level, globally and multi-scale.
  function corsiniSection(cd) {
    section('Corsini roughness');
    app.appendChild(el('p', { text: cd.formula + ', k = ' + cd.k }));
    app.appendChild(el('p', { text: get('original.corsini.definition') }));
    const rows = cd.levels.map((L, i) => [labelCell(String(L)),
      cell('original.corsini.roughness.' + i), cell('processed.corsini.roughness.' + i),
      cell('corsini_distance.relative_change.' + i), cell('corsini_distance.distance.' + i)]);
    if (cd.global) rows.push([labelCell('global'), cell('original.corsini.global.roughness'),
      cell('processed.corsini.global.roughness'), cell('corsini_distance.global.relative_change'),
      cell('corsini_distance.global.distance')]);
    if (cd.multiscale) rows.push([labelCell('multi-scale'), cell('original.corsini.multiscale'),
      cell('processed.corsini.multiscale'), cell('corsini_distance.multiscale.relative_change'),
      cell('corsini_distance.multiscale.distance')]);
    app.appendChild(table(['level', 'R original', 'R processed', 'relative change', 'R(M, M\')'], rows));
  }
  // One roughness section at most: the comparison's ring levels, a profile's, Corsini's, or why there is none.
  function roughnessSection(rd) {
    if (rd && sigmaOf('original')) {
      ringRoughnessSection(rd);
    } else if (isProfile && get('sigma')) {
      profileRoughnessSection();
    } else if (report.corsini_distance && get('original.corsini')) {
      corsiniSection(report.corsini_distance);
    } else if (report.roughness_unavailable) {
      section('Roughness profile');
      app.appendChild(el('p', { text: 'unavailable: ' + report.roughness_unavailable }));
    }
  }

  // ---- plots (inline SVG) -----------------------------------------------------------------
  const SVG = 'http://www.w3.org/2000/svg';
  function svg(tag, attrs, text) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  const PLOT = { W: 560, H: 260, L: 62, R: 12, T: 24, B: 34 };
  // Series n of `count` ({name, color, ys, bars}) into the plot `s`, its points at X(i), Y(y), and its legend.
  function plotSeries(s, xs, q, n, count, X, Y) {
    const { W, L, R, T } = PLOT;
    if (q.bars) {
      const bw = Math.max(1, (W - L - R) / Math.max(xs.length, 1) * 0.8 / count);
      q.ys.forEach((y, i) => {
        if (!Number.isFinite(y)) return;
        const r = svg('rect', { x: X(i) - bw * count / 2 + n * bw, y: Math.min(Y(y), Y(0)), width: bw, height: Math.abs(Y(y) - Y(0)), fill: q.color });
        r.appendChild(svg('title', {}, q.name + ' ' + xs[i] + ': ' + fmt(y)));
        s.appendChild(r);
      });
    } else {
      const pts = q.ys.map((y, i) => Number.isFinite(y) ? X(i) + ',' + Y(y) : null).filter((p) => p);
      s.appendChild(svg('polyline', { points: pts.join(' '), fill: 'none', stroke: q.color, 'stroke-width': 2 }));
      q.ys.forEach((y, i) => {
        if (!Number.isFinite(y)) return;
        const c = svg('circle', { cx: X(i), cy: Y(y), r: 3, fill: q.color });
        c.appendChild(svg('title', {}, q.name + ' ' + xs[i] + ': ' + fmt(y)));
        s.appendChild(c);
      });
    }
    s.appendChild(svg('text', { x: W - R - 4, y: T + 14 + 14 * n, 'text-anchor': 'end', fill: q.color }, q.name));
  }
  // A plot of `series` ({name, color, ys, bars}) over the category labels `xs`.
  function plot(id, title, xs, series, ylabel) {
    const { W, H, L, R, T, B } = PLOT;
    const s = svg('svg', { width: W, height: H, class: 'plot', id: id, viewBox: '0 0 ' + W + ' ' + H });
    const all = [].concat(...series.map((q) => q.ys)).filter((y) => Number.isFinite(y));
    let lo = Math.min(0, ...all), hi = Math.max(...all, 0);
    if (!(hi > lo)) hi = lo + 1;
    const X = (i) => L + (xs.length > 1 ? i * (W - L - R) / (xs.length - 1) : (W - L - R) / 2);
    const Y = (y) => T + (hi - y) * (H - T - B) / (hi - lo);
    s.appendChild(svg('text', { x: W / 2, y: 15, 'text-anchor': 'middle', 'font-weight': 'bold' }, title));
    for (let k = 0; k <= 4; ++k) {
      const y = lo + k * (hi - lo) / 4;
      s.appendChild(svg('line', { x1: L, x2: W - R, y1: Y(y), y2: Y(y), stroke: '#eee' }));
      s.appendChild(svg('text', { x: L - 4, y: Y(y) + 4, 'text-anchor': 'end' }, Number(y.toPrecision(3)).toString()));
    }
    const every = Math.ceil(xs.length / 12);
    xs.forEach((x, i) => {
      if (i % every === 0 || i === xs.length - 1) s.appendChild(svg('text', { x: X(i), y: H - B + 14, 'text-anchor': 'middle' }, x));
    });
    s.appendChild(svg('text', { x: 12, y: T + (H - T - B) / 2, transform: 'rotate(-90 12 ' + (T + (H - T - B) / 2) + ')', 'text-anchor': 'middle' }, ylabel));
    series.forEach((q, n) => plotSeries(s, xs, q, n, series.length, X, Y));
    return s;
  }
  // A comparison's roughness: sigma of both meshes per ring level, d_L per level, sigma per radius.
  function ringPlots(rd) {
    const xs = rd.levels.map(String).concat(rd.global ? ['global'] : []);
    const sig = (m) => sigmaOf(m).concat(rd.global ? [get(m + '.sigma_global')] : []);
    const out = [plot('plot-sigma', 'sigma per ring level', xs, [
      { name: 'original', color: '#1f77b4', ys: sig('original') }, { name: 'processed', color: '#d62728', ys: sig('processed') }], 'sigma_L'),
    plot('plot-dl', 'roughness distance d_L per level', xs, [
      { name: 'd_L', color: '#555', bars: true, ys: rd.distance.concat(rd.global ? [rd.global.distance] : []) }], 'd_L')];
    if (get('original.radii') && get('processed.radii')) {
      out.push(plot('plot-sigma-radii', 'sigma per radius (unit-scaled mesh)', get('original.radii').map(String), [
        { name: 'original', color: '#1f77b4', ys: get('original.sigma_radii') },
        { name: 'processed', color: '#d62728', ys: get('processed.sigma_radii') }], 'sigma_r'));
    }
    return out;
  }
  // A profile's roughness: sigma per ring level and per radius.
  function profilePlots() {
    const xs = get('levels').map(String).concat(get('global') ? ['global'] : []);
    const out = [plot('plot-sigma', 'sigma per ring level', xs, [
      { name: 'sigma', color: '#1f77b4', ys: get('sigma').concat(get('global') ? [get('sigma_global')] : []) }], 'sigma_L')];
    if (get('radii')) out.push(plot('plot-sigma-radii', 'sigma per radius (unit-scaled mesh)', get('radii').map(String),
      [{ name: 'sigma', color: '#1f77b4', ys: get('sigma_radii') }], 'sigma_r'));
    return out;
  }
  // The histogram of each direction's distances that the report has.
  function histogramPlots(sd) {
    const out = [];
    for (const d of ['forward', 'backward']) {
      const hist = sd && sd[d] && sd[d].histogram;
      if (!hist) continue;
      const xs = hist.counts.map((_, i) => Number(((hist.edges[i] + hist.edges[i + 1]) / 2).toPrecision(3)).toString());
      out.push(plot('plot-hist-' + d, d + ' distance histogram (' + hist.counts.length + ' bins)', xs,
        [{ name: d, color: d === 'forward' ? '#1f77b4' : '#d62728', bars: true, ys: hist.counts }], 'samples'));
    }
    return out;
  }
  function plotsSection(sd, rd) {
    const plots = el('div', { cls: 'row' });
    if (rd && sigmaOf('original')) plots.append(...ringPlots(rd));
    if (isProfile && get('sigma')) plots.append(...profilePlots());
    plots.append(...histogramPlots(sd));
    if (plots.childNodes.length) {
      section('Plots');
      app.appendChild(plots);
    }
  }

  // ---- colour maps: the PLY maps' ramps (src/report/colormap.cpp), value for value ----------
  const toByte = (x) => Math.round(Math.min(Math.max(x, 0), 1) * 255);
  function sequential(v, lo, hi) {
    if (Number.isNaN(v)) return [128, 128, 128];
    const span = hi > lo ? hi - lo : 1.0;
    const t = Math.min(Math.max((v - lo) / span, 0.0), 1.0) * 4.0;
    let r, g, b;
    if (t < 1) { r = 0; g = t; b = 1; } else if (t < 2) { r = 0; g = 1; b = 2 - t; } else if (t < 3) { r = t - 2; g = 1; b = 0; } else { r = 1; g = 4 - t; b = 0; }
    return [toByte(r), toByte(g), toByte(b)];
  }
  function diverging(v, range) {
    if (Number.isNaN(v)) return [128, 128, 128];
    if (!(range > 0.0)) range = 1.0;
    const t = Math.min(Math.max(v / range, -1.0), 1.0);
    const r = t < 0 ? 1.0 + t * (1.0 - 0.23) : 1.0 - t * (1.0 - 0.71);
    const g = t < 0 ? 1.0 + t * (1.0 - 0.30) : 1.0 - t * (1.0 - 0.02);
    const b = t < 0 ? 1.0 + t * (1.0 - 0.75) : 1.0 - t * (1.0 - 0.15);
    return [toByte(r), toByte(g), toByte(b)];
  }
  const colorOf = (f, v) => f.map === 'sequential' ? sequential(v, f.range[0], f.range[1]) : diverging(v, f.range[1]);
  const fieldNamed = (name) => view.fields.find((q) => q.name === name);

  // ---- decoding the meshes ----------------------------------------------------------------
  function bytes(b64) {
    const s = atob(b64);
    const out = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
    return out.buffer;
  }
  function decodeField(f) {
    if (f.encoding === 'float64') return new Float64Array(bytes(f.data));
    const q = new Uint16Array(bytes(f.data));
    const out = new Float64Array(q.length);
    for (let i = 0; i < q.length; ++i) out[i] = q[i] === 65535 ? NaN : f.lo + q[i] * f.step;
    return out;
  }
  // The meshes as drawn; their fields' values and colours are decoded when first asked for.
  function decodeMeshes() {
    return view.meshes.map((m) => ({
      positions: new Float32Array(bytes(m.positions)), indices: new Uint32Array(bytes(m.indices)), info: m, values: {}, colors: {},
    }));
  }
  function meshValues(m, name) {
    if (!m.values[name]) m.values[name] = decodeField(m.info.fields[name]);
    return m.values[name];
  }
  function meshColors(m, name) {
    if (!m.colors[name]) {
      const f = fieldNamed(name), v = meshValues(m, name), c = new Uint8Array(3 * v.length);
      for (let i = 0; i < v.length; ++i) c.set(colorOf(f, v[i]), 3 * i);
      m.colors[name] = c;
    }
    return m.colors[name];
  }

  // ---- the coarse mesh drawn while the camera moves -------------------------------------------
  // A software renderer (no GPU) takes about a second per frame of 200,000 faces: while the user drags or
  // zooms, a mesh drawn with more than lodFaces faces is replaced by a coarser clustering of what is drawn
  // (as html_mesh.cpp reduces: a uniform grid, a cluster at its vertices' mean, carrying per field the value
  // of largest magnitude of its vertices, so its colours are the colour map's), and the full drawn mesh
  // comes back LOD_SETTLE_MS after the interaction ends (a wheel's ticks each start and end one).
  const LOD_FACES = 20000;
  const LOD_SETTLE_MS = 250;
  // One clustering of m's drawn vertices on a grid of `cells` cells along the longest side of their box.
  function clusterOnce(m, lo, side, cells) {
    const p = m.positions, n = p.length / 3, h = side / cells, stride = Math.floor(cells) + 2;
    const cluster = new Uint32Array(n), ids = new Map();
    const cell = (x) => Math.min(Math.max(Math.floor(x / h), 0), stride - 1);
    for (let i = 0; i < n; ++i) {
      const key = cell(p[3 * i] - lo[0]) + stride * (cell(p[3 * i + 1] - lo[1]) + stride * cell(p[3 * i + 2] - lo[2]));
      let id = ids.get(key);
      if (id === undefined) { id = ids.size; ids.set(key, id); }
      cluster[i] = id;
    }
    const idx = m.indices, faces = [];
    for (let f = 0; f < idx.length; f += 3) {
      const a = cluster[idx[f]], b = cluster[idx[f + 1]], c = cluster[idx[f + 2]];
      if (a !== b && b !== c && a !== c) faces.push(a, b, c);
    }
    return { cluster, count: ids.size, indices: faces };
  }
  // m's coarse version of at most `budget` faces ({positions, indices, cluster, values, colors}), or null when
  // m draws at most `budget` faces (or none).
  function coarsen(m, budget) {
    if (m.indices.length / 3 <= budget) return null;
    const p = m.positions, lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < p.length; ++i) {
      lo[i % 3] = Math.min(lo[i % 3], p[i]);
      hi[i % 3] = Math.max(hi[i % 3], p[i]);
    }
    const side = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-30);
    // As html_mesh.cpp: a closed surface on an N^3 grid keeps about 12 N^2 faces; coarsen by 15% until within budget.
    let cells = Math.sqrt(budget / 4), c = clusterOnce(m, lo, side, cells);
    while (c.indices.length / 3 > budget && cells > 2) {
      cells *= 0.85;
      c = clusterOnce(m, lo, side, cells);
    }
    const sum = new Float64Array(3 * c.count), count = new Uint32Array(c.count);
    for (let i = 0; i < c.cluster.length; ++i) {
      const k = c.cluster[i];
      for (let a = 0; a < 3; ++a) sum[3 * k + a] += p[3 * i + a];
      ++count[k];
    }
    const positions = new Float32Array(3 * c.count);
    for (let i = 0; i < positions.length; ++i) positions[i] = sum[i] / count[Math.floor(i / 3)];
    return { positions, indices: new Uint32Array(c.indices), cluster: c.cluster, values: {}, colors: {} };
  }
  // The coarse mesh's values of a field: per cluster, the value of largest magnitude of its vertices (NaN: none).
  function coarseColors(m, name) {
    const c = m.coarse;
    if (!c.colors[name]) {
      const fine = meshValues(m, name), v = new Float64Array(c.positions.length / 3).fill(NaN);
      for (let i = 0; i < fine.length; ++i) {
        const x = fine[i], k = c.cluster[i];
        if (!Number.isNaN(x) && (Number.isNaN(v[k]) || Math.abs(x) > Math.abs(v[k]))) v[k] = x;
      }
      const f = fieldNamed(name), out = new Uint8Array(3 * v.length);
      for (let i = 0; i < v.length; ++i) out.set(colorOf(f, v[i]), 3 * i);
      c.values[name] = v;
      c.colors[name] = out;
    }
    return c.colors[name];
  }

  // ---- the 3D view: its elements ------------------------------------------------------------
  function reducedNote(meshes) {
    if (!meshes.some((m) => m.info.reduced)) return;
    app.appendChild(el('p', { cls: 'note', id: 'reduced-note', text: 'Drawn reduced above ' + view.face_budget.toLocaleString('en') +
      ' faces per mesh (vertex clustering; a cluster shows the largest value of its vertices): ' +
      meshes.map((m, k) => NAMES[k] + ' ' + m.info.faces.toLocaleString('en') + ' of ' + m.info.full_faces.toLocaleString('en') + ' faces').join(', ') +
      '. Every number of this report is of the full meshes.' }));
  }
  // Said when a mesh has a coarse version for interaction (its budget, LOD_FACES, is the page's).
  function lodNote(meshes) {
    if (!meshes.some((m) => m.indices.length / 3 > LOD_FACES)) return;
    app.appendChild(el('p', { cls: 'note', id: 'lod-note', text: 'While the view turns or zooms, a mesh drawn with more than ' +
      LOD_FACES.toLocaleString('en') + ' faces is drawn coarser (clustered again to at most that many faces, same colours); ' +
      'the drawn mesh comes back when the view stops.' }));
  }
  // The field and mode selects and the shading checkbox, with the mouse's help.
  function buildControls(meshes, dom) {
    dom.fieldSelect = el('select', { id: 'field' }, view.fields.map((f) => el('option', { value: f.name,
      text: f.name === 'distance' ? 'distance to the other mesh' : f.name === 'H' ? 'mean curvature H' : f.name })));
    dom.modeSelect = el('select', { id: 'mode' }, [['side', 'side by side'], ['original', 'original only'], ['processed', 'processed only']].map(([v, t]) => el('option', { value: v, text: t })));
    dom.shading = el('input', { type: 'checkbox', id: 'shading', checked: '' });
    const controlsBox = el('div', { id: 'controls' });
    controlsBox.append(el('label', {}, ['colour by ', dom.fieldSelect]));
    if (meshes.length > 1) controlsBox.append(el('label', {}, ['show ', dom.modeSelect]));
    controlsBox.append(el('label', {}, [dom.shading, ' shading']),
      el('span', { cls: 'sub', text: 'drag: rotate, wheel: zoom, right-drag: pan' + (meshes.length > 1 ? ' (both views share one camera)' : '') + '; click the surface for its value' }));
    app.appendChild(controlsBox);
  }
  // The section's elements, in the page's order: note, controls, colour bar, canvas with labels and tooltip, probe.
  function buildViewDom(meshes) {
    section('3D view');
    reducedNote(meshes);
    lodNote(meshes);
    const dom = {};
    buildControls(meshes, dom);
    dom.barCanvas = el('canvas', { width: 256, height: 14, id: 'colorbar-ramp' });
    dom.barLo = el('span', { id: 'colorbar-lo' });
    dom.barHi = el('span', { id: 'colorbar-hi' });
    dom.barLabel = el('span', { id: 'colorbar-label' });
    app.appendChild(el('div', { id: 'colorbar' }, [dom.barLo, dom.barCanvas, dom.barHi, dom.barLabel]));
    dom.box = el('div', { id: 'view-box' });
    dom.canvas = el('canvas', { id: 'view' });
    dom.labels = NAMES.map((n) => el('span', { cls: 'view-label', text: n }));
    dom.tooltip = el('div', { id: 'tooltip' });
    dom.box.append(dom.canvas, ...dom.labels, dom.tooltip);
    app.appendChild(dom.box);
    dom.probe = el('div', { id: 'probe' });
    app.appendChild(dom.probe);
    return dom;
  }

  // ---- the 3D view: renderer, camera, scenes ------------------------------------------------
  // The WebGL renderer, or null (and a warning in place of the view) without WebGL.
  function createRenderer(dom, state) {
    try {
      return new THREE.WebGLRenderer({ canvas: dom.canvas, antialias: true, preserveDrawingBuffer: true });
    } catch (e) {
      state.error = 'WebGL is not available: ' + e.message;
      dom.box.replaceWith(el('p', { cls: 'warn', text: state.error + '. The numbers above are complete.' }));
      return null;
    }
  }
  // The centre and diagonal of the bounding box of all meshes.
  function meshBounds(meshes) {
    const lo3 = new THREE.Vector3(Infinity, Infinity, Infinity), hi3 = new THREE.Vector3(-Infinity, -Infinity, -Infinity);
    for (const m of meshes)
      for (let i = 0; i < m.positions.length; i += 3) {
        lo3.min(new THREE.Vector3(m.positions[i], m.positions[i + 1], m.positions[i + 2]));
        hi3.max(new THREE.Vector3(m.positions[i], m.positions[i + 1], m.positions[i + 2]));
      }
    return { center: lo3.clone().add(hi3).multiplyScalar(0.5), diag: Math.max(lo3.distanceTo(hi3), 1e-30) };
  }
  function createCamera(center, diag) {
    const camera = new THREE.PerspectiveCamera(35, 1, diag * 0.01, diag * 20);
    camera.position.copy(center).add(new THREE.Vector3(0, 0, 1.5 * diag));
    camera.lookAt(center);
    return camera;
  }
  // Mesh m's scene: the surface (points when it has no face) in grey until a field colours it, and its lights.
  function createScene(m, diag) {
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xffffff);
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(m.positions, 3));
    const empty = m.indices.length === 0;
    if (!empty) g.setIndex(new THREE.BufferAttribute(m.indices, 1));
    g.setAttribute('color', new THREE.BufferAttribute(new Uint8Array(m.positions.length).fill(128), 3, true));
    if (!empty) g.computeVertexNormals();
    const lit = new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide });
    const flat = new THREE.MeshBasicMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide });
    const object = empty ? new THREE.Points(g, new THREE.PointsMaterial({ vertexColors: THREE.VertexColors, size: diag * 0.004 }))
      : new THREE.Mesh(g, lit);
    scene.add(object);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const light = new THREE.DirectionalLight(0xffffff, 0.5);
    scene.add(light);
    m.geometry = g;
    return { scene, object, light, lit, flat, empty, markers: [] };
  }
  // Everything the view's functions share: the meshes, the elements, the state, renderer, camera and scenes.
  function createScenes(meshes, dom) {
    const state = { field: view.fields.length ? view.fields[0].name : null, mode: 'side', shading: true, frames: 0, error: null,
      interacting: false, lod: 'full', drawnFaces: 0, lodFaces: LOD_FACES };
    const renderer = createRenderer(dom, state);
    const { center, diag } = meshBounds(meshes);
    const camera = createCamera(center, diag);
    const scenes = meshes.map((m) => createScene(m, diag));
    const v = { meshes, dom, state, renderer, center, diag, camera, scenes, controls: null, pending: false, settle: null };
    buildCoarse(v, LOD_FACES);
    return v;
  }
  // Each scene's coarse object (hidden but while the camera moves) for meshes drawn with more than `budget` faces.
  function buildCoarse(v, budget) {
    v.state.lodFaces = budget;
    v.meshes.forEach((m, k) => {
      const s = v.scenes[k];
      if (s.coarse) {
        s.scene.remove(s.coarse);
        s.coarse.geometry.dispose();
        s.coarse = null;
      }
      m.coarse = s.empty ? null : coarsen(m, budget);
      if (!m.coarse) return;
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(m.coarse.positions, 3));
      g.setIndex(new THREE.BufferAttribute(m.coarse.indices, 1));
      g.setAttribute('color', new THREE.BufferAttribute(v.state.field ? coarseColors(m, v.state.field).slice()
        : new Uint8Array(m.coarse.positions.length).fill(128), 3, true));
      g.computeVertexNormals();
      s.coarse = new THREE.Mesh(g, s.object.material);
      s.coarse.visible = false;
      s.scene.add(s.coarse);
    });
  }

  // The certified Hausdorff distance: where it is attained (on the mesh whose samples reach it) and its closest point.
  function addMarker(v, k, p, r, what) {
    const s = new THREE.Mesh(new THREE.SphereGeometry(r, 24, 16), new THREE.MeshBasicMaterial({ color: 0xff00ff, depthTest: false }));
    s.renderOrder = 10;
    s.position.set(p[0], p[1], p[2]);
    s.userData.what = what;
    v.scenes[k].scene.add(s);
    v.scenes[k].markers.push(s);
  }
  function addHausdorffMarkers(v, sd) {
    const marker = { point: null, closest: null, on: null };
    const hd = sd && sd.hausdorff;
    if (hd && hd.attained && sd[hd.attained].hausdorff && sd[hd.attained].hausdorff.location) {
      const loc = sd[hd.attained].hausdorff.location, on = hd.attained === 'forward' ? 0 : 1;
      Object.assign(marker, { point: loc.point, closest: loc.closest_point, on: on, lower: hd.lower, upper: hd.upper, direction: hd.attained });
      addMarker(v, on, loc.point, v.diag * 0.012, 'certified Hausdorff distance in [' + fmt(hd.lower) + ', ' + fmt(hd.upper) + '], attained here (' + hd.attained + ') at (' + loc.point.map(fmt).join(', ') + ')');
      addMarker(v, 1 - on, loc.closest_point, v.diag * 0.007, 'closest point (' + loc.closest_point.map(fmt).join(', ') + ') of the certified Hausdorff distance in [' + fmt(hd.lower) + ', ' + fmt(hd.upper) + ']');
    }
    return marker;
  }

  // ---- the 3D view: viewports and drawing ---------------------------------------------------
  // The viewports: [scene index, x, width] in CSS pixels.
  function viewports(v) {
    const w = v.dom.canvas.clientWidth;
    if (v.meshes.length === 1) return [[0, 0, w]];
    if (v.state.mode === 'side') return [[0, 0, w / 2], [1, w / 2, w - w / 2]];
    return [[v.state.mode === 'original' ? 0 : 1, 0, w]];
  }
  function requestRender(v) {
    if (v.pending || !v.renderer) return;
    v.pending = true;
    requestAnimationFrame(() => render(v));
  }
  function render(v) {
    v.pending = false;
    const { renderer, camera, dom } = v;
    const w = dom.canvas.clientWidth, h = dom.canvas.clientHeight;
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(w, h, false);
    renderer.setScissorTest(true);
    const vps = viewports(v);
    dom.labels.forEach((l) => { l.style.display = 'none'; });
    // While the camera moves, the coarse objects stand in for the full ones (shown again after the frame, so
    // that picking always hits the drawn full mesh).
    const coarse = v.state.interacting && vps.some(([k]) => v.scenes[k].coarse);
    let drawn = 0;
    for (const [k, x, vw] of vps) {
      renderer.setViewport(x, 0, vw, h);
      renderer.setScissor(x, 0, vw, h);
      camera.aspect = vw / h;
      camera.updateProjectionMatrix();
      const s = v.scenes[k], swap = coarse && s.coarse;
      s.light.position.copy(camera.position);
      if (swap) [s.object.visible, s.coarse.visible] = [false, true];
      renderer.render(s.scene, camera);
      if (swap) [s.object.visible, s.coarse.visible] = [true, false];
      drawn += (swap ? v.meshes[k].coarse.indices.length : v.meshes[k].indices.length) / 3;
      dom.labels[k].style.display = '';
      dom.labels[k].style.left = (x + 6) + 'px';
    }
    v.state.lod = coarse ? 'coarse' : 'full';
    v.state.drawnFaces = drawn;
    dom.canvas.dataset.lod = v.state.lod;
    dom.canvas.dataset.drawnFaces = String(drawn);
    v.state.frames++;
  }
  // Where a point of scene k's space is drawn, in CSS pixels of the canvas (for scripts and tests).
  function project(v, k, p) {
    const vp = viewports(v).find(([s]) => s === k);
    if (!vp) return null;
    const [, vx, vw] = vp, h = v.dom.canvas.clientHeight;
    v.camera.aspect = vw / h;
    v.camera.updateProjectionMatrix();
    const q = new THREE.Vector3(p[0], p[1], p[2]).project(v.camera);
    return { x: vx + (q.x + 1) / 2 * vw, y: (1 - q.y) / 2 * h };
  }

  // ---- the 3D view: field, mode and shading -------------------------------------------------
  function drawColorbar(dom, f) {
    const ctx = dom.barCanvas.getContext('2d');
    for (let i = 0; i < 256; ++i) {
      const v = f.range[0] + (f.range[1] - f.range[0]) * i / 255;
      const c = colorOf(f, v);
      ctx.fillStyle = 'rgb(' + c.join(',') + ')';
      ctx.fillRect(i, 0, 1, 14);
    }
    dom.barLo.textContent = fmt(f.range[0]);
    dom.barHi.textContent = fmt(f.range[1]);
    dom.barLabel.textContent = f.label + (f.name === 'distance' ? ' (units of the meshes)' : '') + '; range: ' + f.rule + '; grey: undefined';
  }
  function setField(v, name) {
    const f = fieldNamed(name);
    if (!f) throw new Error('no field ' + name);
    v.state.field = name;
    v.dom.fieldSelect.value = name;
    v.meshes.forEach((m, k) => {
      const attr = m.geometry.getAttribute('color');
      attr.array.set(meshColors(m, name));
      attr.needsUpdate = true;
      if (m.coarse) {
        const ca = v.scenes[k].coarse.geometry.getAttribute('color');
        ca.array.set(coarseColors(m, name));
        ca.needsUpdate = true;
      }
    });
    drawColorbar(v.dom, f);
    requestRender(v);
  }
  function setMode(v, mode) {
    v.state.mode = mode;
    v.dom.modeSelect.value = mode;
    requestRender(v);
  }
  function setShading(v, on) {
    v.state.shading = on;
    v.dom.shading.checked = on;
    for (const s of v.scenes) {
      if (!s.empty) s.object.material = on ? s.lit : s.flat;
      if (s.coarse) s.coarse.material = s.object.material;
    }
    requestRender(v);
  }

  // ---- the 3D view: interaction -------------------------------------------------------------
  // The orbit controls (one camera for both views), when there is a renderer.
  function createControls(v) {
    if (!v.renderer) return;
    v.controls = new THREE.OrbitControls(v.camera, v.dom.canvas);
    v.controls.target.copy(v.center);
    v.controls.update();
    v.controls.addEventListener('change', () => requestRender(v));
    // The coarse meshes from a drag's (or a wheel tick's) start until LOD_SETTLE_MS after its end.
    v.controls.addEventListener('start', () => {
      clearTimeout(v.settle);
      v.state.interacting = true;
    });
    v.controls.addEventListener('end', () => {
      clearTimeout(v.settle);
      v.settle = setTimeout(() => {
        v.state.interacting = false;
        if (v.state.lod === 'coarse') requestRender(v);
      }, LOD_SETTLE_MS);
    });
  }
  // The hit nearest the viewer among objects(k) of the viewport k under the pointer: {k, hit}, or null.
  function pick(v, raycaster, ev, objects) {
    const r = v.dom.canvas.getBoundingClientRect(), x = ev.clientX - r.left, y = ev.clientY - r.top;
    const vp = viewports(v).find(([, vx, vw]) => x >= vx && x < vx + vw);
    if (!vp) return null;
    const [k, vx, vw] = vp;
    v.camera.aspect = vw / r.height;
    v.camera.updateProjectionMatrix();
    raycaster.setFromCamera(new THREE.Vector2((x - vx) / vw * 2 - 1, -(y / r.height) * 2 + 1), v.camera);
    const hits = raycaster.intersectObjects(objects(k));
    return hits.length ? { k, hit: hits[0] } : null;
  }
  // The probe's text for a hit on a surface: the nearest corner of the face hit and the field's value there.
  function surfaceProbe(v, p) {
    const m = v.meshes[p.k], f = p.hit.face, pt = p.hit.point;
    let best = f.a, bd = Infinity;
    for (const i of [f.a, f.b, f.c]) {
      const d = pt.distanceToSquared(new THREE.Vector3(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]));
      if (d < bd) { bd = d; best = i; }
    }
    return NAMES[p.k] + (m.info.reduced ? ' (reduced) cluster ' : ' vertex ') + best + ' at (' +
      [pt.x, pt.y, pt.z].map(fmt).join(', ') + '): ' + v.state.field + ' = ' + fmt(meshValues(m, v.state.field)[best]);
  }
  // Picking: the viewport under the pointer, then a ray into its scene. Hovering a marker shows its tooltip;
  // a click shows the marker's text or the surface's value in the probe.
  function installPicking(v) {
    const { canvas, tooltip, probe } = v.dom;
    const raycaster = new THREE.Raycaster();
    canvas.addEventListener('mousemove', (ev) => {
      const p = pick(v, raycaster, ev, (k) => v.scenes[k].markers);
      if (!p) { tooltip.style.display = 'none'; return; }
      const r = canvas.getBoundingClientRect();
      tooltip.textContent = p.hit.object.userData.what;
      tooltip.style.left = (ev.clientX - r.left + 12) + 'px';
      tooltip.style.top = (ev.clientY - r.top + 12) + 'px';
      tooltip.style.display = 'block';
    });
    canvas.addEventListener('click', (ev) => {
      const p = pick(v, raycaster, ev, (k) => v.scenes[k].markers.concat(v.scenes[k].empty ? [] : [v.scenes[k].object]));
      if (!p) { probe.textContent = ''; return; }
      if (p.hit.object.userData.what) { probe.textContent = p.hit.object.userData.what; return; }
      probe.textContent = surfaceProbe(v, p);
    });
  }
  function installInteraction(v) {
    createControls(v);
    const { fieldSelect, modeSelect, shading } = v.dom;
    fieldSelect.addEventListener('change', () => setField(v, fieldSelect.value));
    modeSelect.addEventListener('change', () => setMode(v, modeSelect.value));
    shading.addEventListener('change', () => setShading(v, shading.checked));
    window.addEventListener('resize', () => requestRender(v));
    installPicking(v);
  }

  // ---- window.meshdiffReport ----------------------------------------------------------------
  function exposeApi(v, marker) {
    const state = v.state;
    window.meshdiffReport = {
      report, meta, view, state, marker,
      setField: (name) => setField(v, name),
      setMode: (mode) => setMode(v, mode),
      setShading: (on) => setShading(v, on),
      project: (k, p) => project(v, k, p),
      colors: (k, name) => meshColors(v.meshes[k], name || state.field),
      values: (k, name) => meshValues(v.meshes[k], name || state.field),
      markerPositions: () => v.scenes.map((s) => s.markers.map((o) => o.position.toArray())),
      colorOf: (name, value) => colorOf(fieldNamed(name), value),
      // The coarse mesh drawn while the camera moves: its size, and its per-vertex values and colours.
      coarseFaces: (k) => (v.meshes[k].coarse ? v.meshes[k].coarse.indices.length / 3 : null),
      coarseValues: (k, name) => (coarseColors(v.meshes[k], name || state.field), v.meshes[k].coarse.values[name || state.field]),
      coarseColors: (k, name) => coarseColors(v.meshes[k], name || state.field),
      coarseCluster: (k) => v.meshes[k].coarse.cluster,
      setInteractionFaces: (n) => {
        buildCoarse(v, n);
        requestRender(v);
      },
      ready: true,
    };
  }

  function main() {
    const sd = report.surface_distance, rd = report.roughness_distance;
    headerSection();
    meshesSection();
    distanceSection(sd);
    roughnessSection(rd);
    plotsSection(sd, rd);
    const meshes = decodeMeshes();
    const v = createScenes(meshes, buildViewDom(meshes));
    const marker = addHausdorffMarkers(v, sd);
    installInteraction(v);
    if (v.state.field && v.renderer) setField(v, v.state.field);
    setShading(v, true);
    exposeApi(v, marker);
    requestRender(v);
  }
  main();
})();
