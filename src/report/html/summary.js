// The batch summary page (meshdiff batch-summary --html): sorts the table by
// the clicked column (numbers numerically, empty cells last) and plots each
// measure over the pairs as inline SVG. The table itself is in the page.
(function () {
  'use strict';
  const records = JSON.parse(document.getElementById('meshdiff-summary').textContent);
  const meta = JSON.parse(document.getElementById('meshdiff-meta').textContent);
  const table = document.getElementById('pairs');
  const body = table.tBodies[0];
  const SVG = 'http://www.w3.org/2000/svg';
  const state = { key: null, dir: 1 };

  function cellOf(tr, key) { return tr.querySelector('td[data-key="' + key + '"]'); }

  // Sorts the rows by the column \p key, in \p dir (1 ascending, -1 descending); empty cells last either way.
  function sortBy(key, dir) {
    const th = table.querySelector('th[data-key="' + key + '"]');
    const numeric = th.dataset.type === 'num';
    const rows = [...body.rows].map(tr => {
      const td = cellOf(tr, key);
      let v = null;
      if (numeric) v = td && td.dataset.value !== undefined ? Number(td.dataset.value) : null;
      else v = td && td.textContent !== '' ? td.textContent : null;
      return { tr, v, i: Number(tr.dataset.index) };
    });
    rows.sort((a, b) => {
      if (a.v === null || b.v === null) return a.v === null && b.v === null ? a.i - b.i : a.v === null ? 1 : -1;
      const c = numeric ? a.v - b.v : a.v.localeCompare(b.v);
      return c !== 0 ? dir * c : a.i - b.i;
    });
    for (const r of rows) body.appendChild(r.tr);
    for (const h of table.tHead.rows[0].cells) h.classList.remove('asc', 'desc');
    th.classList.add(dir > 0 ? 'asc' : 'desc');
    state.key = key;
    state.dir = dir;
  }

  for (const th of table.tHead.rows[0].cells) {
    if (!th.dataset.type) continue;
    th.addEventListener('click', () => sortBy(th.dataset.key, state.key === th.dataset.key ? -state.dir : 1));
  }

  function svg(tag, attrs, text) {
    const e = document.createElementNS(SVG, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function fmt(x) { return Number(x.toPrecision(4)).toString(); }

  // One measure over the pairs (in the records' order): a bar per pair with a value, its id on hover.
  function plot(p) {
    const ids = [], ys = [];
    for (const tr of [...body.rows].sort((a, b) => a.dataset.index - b.dataset.index)) {
      const td = cellOf(tr, p.key);
      ids.push(cellOf(tr, 'id').textContent);
      ys.push(td && td.dataset.value !== undefined ? Number(td.dataset.value) : null);
    }
    const have = ys.filter(y => y !== null && isFinite(y));
    if (!have.length) return null;
    const W = 360, H = 200, L = 56, R = 10, T = 24, B = 22;
    let lo = Math.min(0, ...have), hi = Math.max(0, ...have);
    if (hi === lo) hi = lo + 1;
    const X = i => L + (i + 0.5) * (W - L - R) / ys.length;
    const Y = y => T + (hi - y) / (hi - lo) * (H - T - B);
    const s = svg('svg', { width: W, height: H, class: 'plot', id: 'plot-' + p.key, viewBox: '0 0 ' + W + ' ' + H });
    s.appendChild(svg('text', { x: W / 2, y: 15, 'text-anchor': 'middle', 'font-weight': 'bold' }, p.label));
    for (let k = 0; k <= 4; ++k) {
      const y = lo + (hi - lo) * k / 4;
      s.appendChild(svg('line', { x1: L, x2: W - R, y1: Y(y), y2: Y(y), stroke: '#eee' }));
      s.appendChild(svg('text', { x: L - 4, y: Y(y) + 4, 'text-anchor': 'end' }, fmt(y)));
    }
    s.appendChild(svg('line', { x1: L, x2: W - R, y1: Y(0), y2: Y(0), stroke: '#999' }));
    s.appendChild(svg('text', { x: (L + W - R) / 2, y: H - 6, 'text-anchor': 'middle' }, 'pairs (' + ys.length + ')'));
    const bw = Math.max(1, 0.8 * (W - L - R) / ys.length);
    ys.forEach((y, i) => {
      if (y === null || !isFinite(y)) return;
      const r = svg('rect', { x: X(i) - bw / 2, y: Math.min(Y(y), Y(0)), width: bw, height: Math.max(1, Math.abs(Y(y) - Y(0))), fill: '#3a6ea5', class: 'bar' });
      r.appendChild(svg('title', {}, ids[i] + ': ' + fmt(y)));
      s.appendChild(r);
    });
    const box = document.createElement('div');
    box.appendChild(s);
    const t = document.createElement('div');
    t.className = 'sub';
    t.textContent = p.title;
    t.style.maxWidth = W + 'px';
    box.appendChild(t);
    return box;
  }

  const plots = document.getElementById('plots');
  for (const p of meta.plots) {
    const e = plot(p);
    if (e) plots.appendChild(e);
  }

  window.meshdiffSummary = { records, meta, sortBy, state };
})();
