// drillflex report.html: draws the job's results.json (inlined as #results-json, in the case's output
// units) and the report's own data (#report-json: components, hole centres, mode shapes, time
// series) with Chart.js (plots) and three.js (the 3-D view), both inlined from Debian's packages.
// After drawing, <body> carries data-report-status ("ok" or "error") and every plot data-points
// (its number of drawn points): tests/report reads them from the rendered page.
(function () {
  'use strict';

  const errors = [];
  function recordError(message) {
    errors.push(String(message));
    document.body.dataset.reportStatus = 'error';
    document.body.dataset.reportErrors = errors.join(' | ');
    let banner = document.getElementById('report-errors');
    if (!banner) {
      banner = el('div', {id: 'report-errors', class: 'errors'});
      document.body.insertBefore(banner, document.body.firstChild);
    }
    banner.textContent = 'The report could not draw everything: ' + errors.join('; ');
  }
  window.addEventListener('error', (event) => recordError(event.message));

  const R = JSON.parse(document.getElementById('results-json').textContent);
  const D = JSON.parse(document.getElementById('report-json').textContent);
  const RUN = JSON.parse(document.getElementById('run-json').textContent);
  const U = D.units || RUN.units || {};
  const root = document.getElementById('report');
  const COLORS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf'];

  // ---- small helpers ----------------------------------------------------------------------------
  function el(tag, attrs, children) {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attrs || {})) {
      if (key === 'text') node.textContent = value;
      else if (key === 'html') node.innerHTML = value;
      else node.setAttribute(key, value);
    }
    for (const child of children || []) node.appendChild(typeof child === 'string' ? document.createTextNode(child) : child);
    return node;
  }
  // A number as an engineer reads it: `digits` significant figures, no "-0", thousands grouped.
  function num(x, digits) {
    if (x === null || x === undefined || !isFinite(x)) return '–';
    let v = Number(Number(x).toPrecision(digits || 4));
    if (v === 0) v = 0;  // -0 → 0
    return v.toLocaleString('en-US', {maximumSignificantDigits: digits || 4});
  }
  // A value the test compares with results.json: data-key names its path there.
  function value(x, unit, key, digits) {
    const span = el('span', {class: 'value', text: num(x, digits || 5) + (unit ? ' ' + unit : '')});
    if (key) span.dataset.key = key;
    return span;
  }
  function section(id, title) {
    const s = el('section', {id: id, class: 'report-section'}, [el('h2', {text: title})]);
    root.appendChild(s);
    return s;
  }
  function facts(parent, rows) {
    const table = el('table', {class: 'facts'});
    for (const [label, content] of rows) {
      const cell = el('td');
      if (content instanceof Node) cell.appendChild(content); else cell.textContent = content;
      table.appendChild(el('tr', {}, [el('th', {text: label}), cell]));
    }
    parent.appendChild(table);
    return table;
  }
  function first(array, fallback) { return array && array.length ? array[0] : fallback; }

  // ---- plots -------------------------------------------------------------------------------------
  // Shaded x-ranges, horizontal and vertical lines with labels, and drag-to-zoom (double-click resets):
  // one plugin, configured per chart through options.plugins.marks.
  const marksPlugin = {
    id: 'marks',
    beforeDatasetsDraw(chart, args, options) {
      const {ctx, chartArea: area, scales: {x, y}} = chart;
      ctx.save();
      for (const band of options.xBands || []) {
        const left = Math.max(x.getPixelForValue(band.from), area.left);
        const right = Math.min(x.getPixelForValue(band.to), area.right);
        if (right <= left) continue;
        ctx.fillStyle = band.color || 'rgba(44,160,44,0.15)';
        ctx.fillRect(left, area.top, right - left, area.bottom - area.top);
      }
      ctx.restore();
    },
    afterDatasetsDraw(chart, args, options) {
      const {ctx, chartArea: area, scales: {x, y}} = chart;
      ctx.save();
      ctx.font = '11px sans-serif';
      for (const line of options.hLines || []) {
        const py = y.getPixelForValue(line.y);
        if (py < area.top || py > area.bottom) continue;
        ctx.strokeStyle = line.color || '#d62728';
        ctx.setLineDash([6, 4]);
        ctx.beginPath(); ctx.moveTo(area.left, py); ctx.lineTo(area.right, py); ctx.stroke();
        ctx.fillStyle = line.color || '#d62728';
        ctx.fillText(line.label || '', area.left + 4, py - 4);
      }
      for (const line of options.vLines || []) {
        const px = x.getPixelForValue(line.x);
        if (px < area.left || px > area.right) continue;
        ctx.strokeStyle = line.color || '#555';
        ctx.setLineDash([3, 3]);
        ctx.beginPath(); ctx.moveTo(px, area.top); ctx.lineTo(px, area.bottom); ctx.stroke();
        ctx.fillStyle = line.color || '#555';
        ctx.save(); ctx.translate(px + 3, area.top + 4); ctx.rotate(Math.PI / 2);
        ctx.fillText(line.label || '', 0, 0); ctx.restore();
      }
      const drag = chart.$drag;
      if (drag && drag.to !== undefined) {
        ctx.fillStyle = 'rgba(31,119,180,0.15)';
        ctx.fillRect(Math.min(drag.from, drag.to), area.top, Math.abs(drag.to - drag.from), area.bottom - area.top);
      }
      ctx.restore();
    },
  };
  Chart.register(marksPlugin);

  function enableZoom(chart, canvas) {
    canvas.addEventListener('mousedown', (e) => { chart.$drag = {from: e.offsetX}; });
    canvas.addEventListener('mousemove', (e) => { if (chart.$drag) { chart.$drag.to = e.offsetX; chart.draw(); } });
    canvas.addEventListener('mouseup', (e) => {
      const drag = chart.$drag;
      chart.$drag = null;
      if (drag && Math.abs(e.offsetX - drag.from) > 5) {
        const a = chart.scales.x.getValueForPixel(drag.from), b = chart.scales.x.getValueForPixel(e.offsetX);
        chart.options.scales.x.min = Math.min(a, b);
        chart.options.scales.x.max = Math.max(a, b);
      }
      chart.update('none');
    });
    canvas.addEventListener('dblclick', () => {
      delete chart.options.scales.x.min; delete chart.options.scales.x.max; chart.update('none');
    });
  }

  // A plot of {x, y} series. spec: {title, x, y (axis titles), series: [{label, x: [], y: [], color,
  // line (default true), dash, fill, points}], xBands, hLines, vLines, yMin, yMax, logY, xReverse,
  // xNice (the x axis ends on ticks), xFromZero, depthDown (y is a depth: drawn downwards, the tooltip
  // reads x at that depth)}.
  function plot(parent, spec) {
    const figure = el('figure', {class: 'plot'});
    figure.appendChild(el('figcaption', {text: spec.title}));
    const holder = el('div', {class: 'canvas-holder'});
    const canvas = el('canvas');
    holder.appendChild(canvas);
    figure.appendChild(holder);
    parent.appendChild(figure);
    let points = 0;
    const datasets = spec.series.map((s, i) => {
      const data = [];
      for (let k = 0; k < s.x.length; ++k) {
        if (isFinite(s.x[k]) && isFinite(s.y[k])) data.push({x: s.x[k], y: s.y[k]});
      }
      if (!s.hidden) points += data.length;
      const color = s.color || COLORS[i % COLORS.length];
      return {
        label: s.label, data: data, showLine: s.line !== false, borderColor: color, backgroundColor: s.fillColor || color,
        borderWidth: s.width || 1.5, pointRadius: s.points ? (s.pointRadius || 3) : 0, pointHoverRadius: 4,
        pointStyle: s.pointStyle || 'circle', borderDash: s.dash || [], fill: s.fill || false, hidden: !!s.hidden,
        order: s.order || 0, tension: 0,
      };
    });
    figure.dataset.points = String(points);
    if (points === 0) figure.classList.add('empty');
    // A series that barely changes (a held WOB, 1e-6 of its value) is drawn against a span of 1 % of
    // its value, not stretched over the plot as if its round-off were a signal.
    let yMin = spec.yMin, yMax = spec.yMax;
    if (yMin === undefined && yMax === undefined && !spec.logY && points > 0) {
      const ys = datasets.flatMap((d) => d.data.map((p) => p.y));
      const lo = Math.min(...ys), hi = Math.max(...ys), size = Math.max(Math.abs(lo), Math.abs(hi));
      if (size > 0 && hi - lo < 1e-3 * size) { yMin = (lo + hi) / 2 - 0.01 * size; yMax = (lo + hi) / 2 + 0.01 * size; }
    }
    // Chart.js takes `normalized` data's x range from its first and last points (data sorted by x):
    // a depth-down plot's x is not sorted, so the whole range is suggested.
    const xs = datasets.flatMap((d) => d.data.map((p) => p.x));
    const xLow = xs.length ? Math.min(...xs) : undefined, xHigh = xs.length ? Math.max(...xs) : undefined;
    if (spec.square) holder.classList.add('square');
    const chart = new Chart(canvas, {
      type: 'scatter',
      data: {datasets: datasets},
      options: {
        animation: false, responsive: true, maintainAspectRatio: false, parsing: false, normalized: true,
        interaction: {mode: 'nearest', intersect: false, axis: spec.depthDown ? 'y' : 'x'},
        scales: {
          x: {type: 'linear', title: {display: true, text: spec.x}, reverse: !!spec.xReverse, min: spec.xMin, max: spec.xMax,
              suggestedMin: xLow, suggestedMax: xHigh,
              bounds: spec.xNice ? 'ticks' : 'data', beginAtZero: !!spec.xFromZero, ticks: {callback: (v) => num(v, 6)}},
          y: {type: spec.logY ? 'logarithmic' : 'linear', title: {display: true, text: spec.y}, min: yMin, max: yMax,
              reverse: !!spec.depthDown,
              ticks: {callback: (v) => num(v, 4)}},
        },
        plugins: {
          legend: {display: spec.series.length > 1, labels: {filter: (item) => !spec.series[item.datasetIndex].noLegend}},
          tooltip: {callbacks: {label: (c) => spec.depthDown
            ? `${c.dataset.label || ''}: ${num(c.parsed.x, 5)} at ${num(c.parsed.y, 5)}`
            : `${c.dataset.label || ''}: ${num(c.parsed.y, 5)} at ${num(c.parsed.x, 5)}`}},
          marks: {xBands: spec.xBands || [], hLines: spec.hLines || [], vLines: spec.vLines || []},
        },
      },
    });
    enableZoom(chart, canvas);
    return chart;
  }
  function column(rows, key) { return rows.map((r) => r[key]); }
  function where(s, md) { return s === undefined ? '' : (md !== undefined ? `MD ${num(md, 6)} ${U.length}` : `${num(s, 5)} ${U.length} from the bit`); }

  // ---- header ------------------------------------------------------------------------------------
  function header() {
    const s = el('header', {id: 'header', class: 'report-section'});
    root.appendChild(s);
    s.appendChild(el('h1', {text: R.case || 'drillflex case'}));
    const model = R.model;
    facts(s, [
      ['job', `drillflex ${RUN.command} (version ${RUN.version}), written ${RUN.written}, run time ${num(RUN.run_seconds, 3)} s`],
      ...(model ? [['model', `${model.bodies} bodies, ${model.coordinates} coordinates, ${model.contacts} wall contacts, ${model.elements_per_body} elements and ${model.modes_per_body} modes a body`]] : []),
      ['units', `${R.units}: lengths in ${U.length}, diameters in ${U.diameter}, forces in ${U.force}, stresses in ${U.stress}`],
    ]);
    if (R.operation) {
      const op = R.operation;
      const hook = op.hook_load !== undefined ? ` from the hook load ${num(op.hook_load, 5)} ${U.force} (the pipe above the model weighs ${num(op.string_above_weight, 5)} ${U.force})` : '';
      facts(s, [['operation', `WOB ${num(op.weight_on_bit, 5)} ${U.wob}${hook}, ${num(op.rpm, 4)} ${U.rpm}, torque on bit ${num(op.torque_on_bit, 5)} ${U.moment}`]]);
    }
    const warnings = [];
    if (R.static) {
      for (const w of R.static.warnings || []) warnings.push(w);
      // Into the wall by more than 5 % of the radial clearance there: the contact stiffness is low
      // for its force (a penetration is the penalty's compliance, normal force / stiffness). Only
      // where the string has a clearance: the bit cuts its hole (its stations are held at the centre).
      const into = (R.static.nodes || []).filter((n) => n.clearance !== undefined && n.clearance + n.hole_offset > 0 &&
                                                       n.clearance < -0.05 * (n.clearance + n.hole_offset));
      if (into.length) {
        const deepest = into.reduce((a, b) => (b.clearance < a.clearance ? b : a));
        warnings.push(`${into.length} stations lie into the wall by more than 5 % of their clearance (deepest ${num(-deepest.clearance, 3)} ${U.diameter} at ${where(deepest.s, deepest.md)}): raise model.contact.stiffness or lower model.contact.penetration_fraction`);
      }
    }
    if (R.vibration && R.vibration.max_clearance_ratio) {
      const beyond = R.vibration.rpm.filter((_, i) => R.vibration.max_clearance_ratio[i] > 1);
      if (beyond.length) warnings.push(`the linear vibration response exceeds the clearance at ${beyond.length} of ${R.vibration.rpm.length} rotary speeds: the wall would limit it there (the linear model does not)`);
    }
    if (R.modes) {
      const negative = R.modes.filter((m) => m.negative_stiffness).length;
      if (negative) warnings.push(`${negative === 1 ? 'one of the modes has' : negative + ' of the modes have'} negative stiffness (ω² < 0): not vibration modes; with wall friction they come from its tangent (docs/validation.md)`);
    }
    const list = el('ul', {class: 'warnings'});
    for (const w of warnings) list.appendChild(el('li', {text: w}));
    if (warnings.length) s.appendChild(el('div', {class: 'warning-box'}, [el('strong', {text: 'Warnings'}), list]));
    const nav = el('nav');
    s.appendChild(nav);
    return nav;
  }

  // ---- static ------------------------------------------------------------------------------------
  // The string to scale between s = 0 and sTop (from the bit; all of it without sTop).
  function bhaSchematic(parent, nodes, allContacts, sTop, caption) {
    const comps = (D.components || []).filter((c) => sTop === undefined || c.from < sTop);
    if (!comps.length) return;
    const contacts = allContacts.filter((c) => sTop === undefined || c.s <= sTop);
    const mdOf = mdMapping(nodes);
    const width = 1000, height = 120, mid = 60;
    const md = comps.flatMap((c) => [mdOf(c.from), mdOf(sTop === undefined ? c.to : Math.min(c.to, sTop))]);
    const lo = Math.min(...md), hi = Math.max(...md);
    const largest = Math.max(...comps.map((c) => c.blade_od || c.joint_od || c.od), ...nodes.map((n) => n.hole_diameter || 0));
    const sx = (m) => 10 + (width - 20) * (m - lo) / (hi - lo || 1);
    const sy = (d) => (height - 30) * d / largest / 2;
    const svg = ['<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ' + width + ' ' + height + '" class="schematic">'];
    const hole = nodes.filter((n) => n.hole_diameter && (sTop === undefined || n.s <= sTop));
    if (hole.length) {
      const top = hole.map((n) => `${sx(n.md).toFixed(1)},${(mid - sy(n.hole_diameter)).toFixed(1)}`).join(' ');
      const bottom = hole.map((n) => `${sx(n.md).toFixed(1)},${(mid + sy(n.hole_diameter)).toFixed(1)}`).join(' ');
      svg.push(`<polyline points="${top}" class="wall"/><polyline points="${bottom}" class="wall"/>`);
    }
    comps.forEach((c, i) => {
      const a = sx(mdOf(c.from)), b = sx(mdOf(sTop === undefined ? c.to : Math.min(c.to, sTop)));
      const x = Math.min(a, b), w = Math.max(Math.abs(b - a), 0.8);
      const title = `${c.name} (${c.type}): OD ${num(c.od, 4)} ${U.diameter}, ${num(Math.abs(c.to - c.from), 4)} ${U.length}${c.count > 1 ? ', ' + c.count + ' joints' : ''}`;
      svg.push(`<rect x="${x.toFixed(1)}" y="${(mid - sy(c.od)).toFixed(1)}" width="${w.toFixed(1)}" height="${(2 * sy(c.od)).toFixed(1)}" class="comp comp-${c.type}" fill="${COLORS[i % COLORS.length]}"><title>${escapeXml(title)}</title></rect>`);
      if (c.blade_od) {
        const centre = (a + b) / 2, bw = Math.max(w * 0.3, 2);
        svg.push(`<rect x="${(centre - bw / 2).toFixed(1)}" y="${(mid - sy(c.blade_od)).toFixed(1)}" width="${bw.toFixed(1)}" height="${(2 * sy(c.blade_od)).toFixed(1)}" class="blade"><title>${escapeXml(c.name + ': blades ' + num(c.blade_od, 4) + ' ' + U.diameter)}</title></rect>`);
      }
    });
    for (const c of contacts) {
      const x = sx(c.md);
      svg.push(`<path d="M ${x.toFixed(1)} ${height - 14} l -5 10 l 10 0 z" class="contact"><title>${escapeXml(`${c.component}: ${num(c.normal_force, 4)} ${U.force} at MD ${num(c.md, 6)} ${U.length}`)}</title></path>`);
    }
    svg.push(`<text x="${sx(mdOf(0)) - 4}" y="12" text-anchor="end" class="label">bit</text>`);
    svg.push('</svg>');
    const figure = el('figure', {class: 'plot schematic-figure'});
    figure.appendChild(el('figcaption', {text: caption}));
    const holder = el('div', {html: svg.join('')});
    figure.appendChild(holder);
    figure.dataset.points = String(comps.length);
    parent.appendChild(figure);
  }
  function escapeXml(t) { return String(t).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;'); }
  // MD of a distance s from the bit, from the static stations (md = md_bit − s); s itself without a well.
  function mdMapping(nodes) {
    const n = (nodes || []).find((x) => x.md !== undefined);
    if (!n || !R.static || !(R.static.nodes || []).some((x) => x.hole_diameter !== undefined)) return (s) => s;
    const bit = n.md + n.s;
    return (s) => bit - s;
  }

  // The casing wear run's groove and remaining wall along the casing (results.json static.casing_wear.stations,
  // casing_wear.csv's columns).
  function casingWearPlot(parent, wear) {
    const st = wear.stations || {};
    const md = st.md || [];
    if (!md.length) return;
    const rows = md.map((m, i) => ({groove_depth: st.groove_depth[i], wall: st.wall[i], remaining_wall: st.remaining_wall[i], side_force_per_length: st.side_force_per_length[i]}));
    const grid = el('div', {class: 'grid'});
    parent.appendChild(grid);
    plot(grid, {title: `Casing wear over ${num(wear.rotating_time / 3600, 4)} h rotating at ${num(wear.rpm, 4)} rpm`,
      x: `MD (${U.length})`, y: `depth (${U.diameter})`,
      series: [{label: 'groove depth', x: md, y: rows.map((r) => r.groove_depth), color: COLORS[1], width: 2},
               {label: 'remaining wall', x: md, y: rows.map((r) => (r.wall ? r.remaining_wall : NaN)), color: COLORS[0], width: 1.5}]});
    plot(grid, {title: 'Side force per length on the casing (the largest over the run)', x: `MD (${U.length})`, y: `side force per length (${U.force_per_length || U.force + '/' + U.length})`,
      series: [{label: 'side force per length', x: md, y: rows.map((r) => r.side_force_per_length), color: COLORS[2]}]});
  }

  function staticSection(nav) {
    const st = R.static;
    const s = section('static', 'Static equilibrium');
    nav.appendChild(el('a', {href: '#static', text: 'static'}));
    const nodes = st.nodes || [];
    const contacts = st.contacts || [];
    const inHole = nodes.some((n) => n.hole_diameter !== undefined);
    const x = inHole ? column(nodes, 'md') : column(nodes, 's');
    const xTitle = inHole ? `MD (${U.length})` : `distance from the bit (${U.length})`;
    const peak = nodes.reduce((a, b) => (b.von_mises_stress > a.von_mises_stress ? b : a), nodes[0] || {});
    const rows = [
      ['solution', `${st.converged ? 'converged' : 'NOT converged'} (${st.method_used || 'newton'}), ${st.iterations} iterations, |R| = ${num(st.residual_norm, 3)} ${U.force}`],
    ];
    if (st.bit) {
      const b = st.bit;
      const t = b.tendency || {};
      const words = `${t.inclination === 'hold' ? 'holds angle' : t.inclination === 'build' ? 'builds' : 'drops'}` +
        (t.azimuth && t.azimuth !== 'none' ? `, walks ${t.azimuth}` : ', no walk');
      const span = el('span');
      span.append(value(b.side_force, U.force, 'static.bit.side_force'), ` (build ${num(b.build_force, 4)} ${U.force}, walk ${num(b.walk_force, 4)} ${U.force})`);
      rows.push(['bit side force', span]);
      rows.push(['bit tilt', value(b.tilt, 'deg', 'static.bit.tilt')]);
      rows.push(['tendency', `the bit ${words} (a side force counts above ${num(t.threshold, 3)} ${U.force})`]);
    }
    if (contacts.length) {
      const largest = contacts.reduce((a, b) => (b.normal_force > a.normal_force ? b : a));
      const span = el('span');
      span.append(value(largest.normal_force, U.force, 'static.contacts.max_normal_force'), ` at ${where(largest.s, largest.md)} (${largest.component}); ${contacts.length} contacts carry force`);
      rows.push(['largest wall contact', span]);
    } else if (inHole) {
      rows.push(['wall contacts', 'none carries force']);
    }
    if (peak) {
      const span = el('span');
      span.append(value(peak.von_mises_stress, U.stress, 'static.nodes.max_von_mises_stress'), ` at ${where(peak.s, peak.md)}`);
      rows.push(['peak von Mises stress', span]);
    }
    // The string's limits (results.json static.limits, static.casing_wear): each limit's largest
    // utilisation and where, in a table, and a warning for any at or above 1.
    const lim = st.limits;
    const beyond = [];
    const utilisations = [];
    if (lim && lim.summary) {
      const names = {yield: 'yield (von Mises / (yield / design factor))', makeup_torque: 'make-up torque (|T| / make-up torque)',
        helical_buckling: 'helical buckling (compression / F_hel)', fatigue: 'fatigue (bending stress / RP 7G endurance limit)'};
      for (const key of ['yield', 'makeup_torque', 'helical_buckling', 'fatigue']) {
        const u = lim.summary[key];
        let detail = '';
        if (key === 'fatigue' && u) {
          detail = `bending ${num(u.bending_stress, 4)} ${U.stress} against ${num(u.allowable_bending_stress, 4)} ${U.stress}; dogleg ${num(u.dogleg_severity, 3)} ${U.dogleg || 'deg/100ft'}` +
            (u.max_dogleg_severity !== undefined ? `, Lubinski's permissible ${num(u.max_dogleg_severity, 3)}` : '');
        }
        const none = key === 'makeup_torque' ? 'no make-up torque given' : key === 'fatigue' ? 'not rotating' : 'does not apply';
        utilisations.push([names[key], u ? u.utilisation : undefined, u ? `${where(u.s, u.md)} (${u.component})` : none, detail]);
        if (u && u.utilisation >= 1) beyond.push(`${names[key]} ${num(u.utilisation, 3)} at ${where(u.s, u.md)}`);
      }
    }
    const wear = st.casing_wear;
    if (wear) {
      const g = wear.deepest_groove;
      const name = 'casing wear (groove depth / casing wall)';
      if (g && g.utilisation !== undefined) {
        utilisations.push([name, g.utilisation, `MD ${num(g.md, 6)} ${U.length}`,
          `groove ${num(g.groove_depth, 3)} ${U.diameter} of a ${num(g.wall, 3)} ${U.diameter} wall, ${num(g.remaining_wall, 3)} ${U.diameter} left`]);
        if (g.utilisation >= 1) beyond.push(`${name} ${num(g.utilisation, 3)} at MD ${num(g.md, 6)} ${U.length}`);
      } else {
        utilisations.push([name, undefined, g ? `MD ${num(g.md, 6)} ${U.length}` : 'no groove', g ? `groove ${num(g.groove_depth, 3)} ${U.diameter} (no casing wall given)` : '']);
      }
    }
    if (lim && lim.summary) {
      const closest = lim.summary.closest;
      if (closest) rows.push(['closest limit', `${closest.limit.replace('_', ' ')}: ${num(closest.utilisation, 3)} (design factor ${num(lim.design_factor, 3)})`]);
      if (lim.buckled_zones && lim.buckled_zones.length) {
        rows.push(['buckled', lim.buckled_zones.map((z) => `${z.kind} MD ${num(z.md_from, 6)}–${num(z.md_to, 6)} ${U.length}`).join('; ')]);
      }
      for (const note of lim.notes || []) rows.push(['limits note', note]);
    }
    facts(s, rows);
    if (utilisations.length) {
      const table = el('table', {class: 'data utilisations'});
      table.appendChild(el('tr', {}, ['limit', 'largest utilisation', 'where', ''].map((t) => el('th', {text: t}))));
      for (const [name, u, at, detail] of utilisations) {
        const cell = el('td', {text: u === undefined ? '–' : num(u, 3)});
        if (u !== undefined && u >= 1) cell.setAttribute('class', 'beyond');
        table.appendChild(el('tr', {}, [el('td', {text: name}), cell, el('td', {text: at}), el('td', {text: detail})]));
      }
      s.appendChild(table);
    }
    if (beyond.length) {
      const list = el('ul', {class: 'warnings'});
      for (const b of beyond) list.appendChild(el('li', {text: b}));
      s.appendChild(el('div', {class: 'warning-box'}, [el('strong', {text: 'Beyond a limit (utilisation above 1)'}), list]));
    }
    if (wear) casingWearPlot(s, wear);
    const ln = lim && lim.nodes ? lim.nodes : null;
    // The whole string, and the BHA alone (up to the first drill pipe or HWDP) when pipe is above it.
    const pipes = (D.components || []).filter((c) => c.type === 'pipe' || c.type === 'hwdp');
    const bhaTop = pipes.length ? Math.min(...pipes.map((c) => c.from)) : undefined;
    bhaSchematic(s, nodes, contacts, undefined, 'The string to scale along MD (diameters to the hole\'s scale, the hole\'s wall drawn; blades dark; ▲ wall contacts carrying force). Hover a component for its name and size.');
    if (bhaTop !== undefined && bhaTop > 0) bhaSchematic(s, nodes, contacts, bhaTop, 'The BHA below the pipe, to scale along MD.');
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    if (inHole) {
      const available = nodes.map((n) => n.hole_offset + n.clearance);
      plot(grid, {
        title: 'Lateral offset from the hole axis, inside the clearance', x: xTitle, y: `offset (${U.diameter})`,
        series: [
          {label: 'clearance (the wall)', x: x, y: available, color: 'rgba(120,120,120,0.6)', fill: 'origin', fillColor: 'rgba(150,150,150,0.2)', width: 0.5},
          {label: 'string axis offset', x: x, y: column(nodes, 'hole_offset'), color: COLORS[0], width: 2},
        ],
      });
      if (contacts.length) {
        plot(grid, {
          title: 'Wall contact force', x: xTitle, y: `normal force (${U.force})`,
          series: [
            {label: 'normal force', x: column(contacts, 'md'), y: column(contacts, 'normal_force'), line: false, points: true, pointStyle: 'triangle', pointRadius: 5, color: COLORS[1]},
            {label: 'friction force', x: column(contacts, 'md'), y: column(contacts, 'friction_force'), line: false, points: true, pointRadius: 3, color: COLORS[3]},
          ],
        });
      } else {
        s.appendChild(el('p', {class: 'note', text: 'No wall contact carries force: the string hangs free of the wall.'}));
      }
    } else {
      plot(grid, {title: 'Lateral displacement', x: xTitle, y: `displacement (${U.diameter})`,
        series: [{label: 'lateral', x: x, y: column(nodes, 'lateral_offset')}]});
    }
    const stressSeries = [
      {label: 'von Mises', x: x, y: column(nodes, 'von_mises_stress'), color: COLORS[1], width: 2},
      {label: 'bending', x: x, y: column(nodes, 'bending_stress'), color: COLORS[0]},
    ];
    // The limit: each component's yield / design factor (E-75's where no grade is given).
    if (ln) stressSeries.push({label: `yield / design factor ${num(lim.design_factor, 3)}`, x: x, y: ln.allowable_stress.map((v) => (v ? v : NaN)), color: '#d62728', dash: [6, 3], width: 1.5});
    plot(grid, {title: 'Bending and von Mises stress, and the allowable stress', x: xTitle, y: `stress (${U.stress})`, series: stressSeries});
    const axial = column(nodes, 'axial_force');
    const neutral = [];
    for (let i = 1; i < axial.length; ++i) {
      if ((axial[i - 1] < 0) !== (axial[i] < 0)) {
        const f = axial[i - 1] / (axial[i - 1] - axial[i]);
        neutral.push({x: x[i - 1] + f * (x[i] - x[i - 1]), label: 'neutral point', color: '#2ca02c'});
      }
    }
    const axialSeries = [{label: 'axial force', x: x, y: axial, color: COLORS[0], width: 2}];
    // Compression beyond −F_sin buckles the string sinusoidally, beyond −F_hel helically (in a well).
    if (ln && ln.helical_load.some((v) => v)) {
      axialSeries.push({label: '−F_sin (Dawson–Paslay)', x: x, y: ln.sinusoidal_load.map((v) => (v ? -v : NaN)), color: '#ff7f0e', dash: [6, 3], width: 1.2});
      axialSeries.push({label: '−F_hel (Chen)', x: x, y: ln.helical_load.map((v) => (v ? -v : NaN)), color: '#d62728', dash: [2, 3], width: 1.2});
    }
    plot(grid, {
      title: 'Axial force (tension positive) and the buckling loads', x: xTitle, y: `axial force (${U.force})`,
      series: axialSeries, hLines: [{y: 0, label: '', color: '#999'}], vLines: neutral,
    });
    const torqueSeries = [{label: 'torque', x: x, y: column(nodes, 'torque'), color: COLORS[4], width: 2}];
    if (ln && ln.makeup_torque.some((v) => v)) {
      torqueSeries.push({label: 'make-up torque', x: x, y: ln.makeup_torque.map((v) => (v ? v : NaN)), color: '#d62728', dash: [6, 3], width: 1.5});
    }
    plot(grid, {title: 'Torque', x: xTitle, y: `torque (${U.moment})`, series: torqueSeries});
    if (neutral.length) {
      s.appendChild(el('p', {text: `Neutral point (axial force zero) at ${neutral.map((n) => `${inHole ? 'MD ' : ''}${num(n.x, 6)} ${U.length}`).join(', ')}.`}));
    }
  }

  // ---- 3-D view ----------------------------------------------------------------------------------
  function threeSection(nav) {
    const nodes = R.static.nodes;
    const centres = D.hole_centre;
    const s = section('view3d', '3-D view of the string in the hole');
    nav.appendChild(el('a', {href: '#view3d', text: '3-D view'}));
    const controls = el('div', {class: 'controls'});
    const slider = el('input', {type: 'range', min: '0', max: '3', step: '0.01', value: '2'});
    const label = el('span');
    controls.append('lateral scale ', slider, ' ', label, ' — drag to turn, scroll to zoom; contacts coloured by normal force (blue low, red high)');
    s.appendChild(controls);
    const holder = el('div', {class: 'view3d'});
    s.appendChild(holder);
    const canvas = document.createElement('canvas');
    const gl = canvas.getContext('webgl') || canvas.getContext('experimental-webgl');
    if (!gl) {
      holder.appendChild(el('p', {class: 'note', text: 'This browser has no WebGL: the 3-D view cannot be drawn (the plots above hold the same results).'}));
      s.dataset.points = '0';
      s.dataset.webgl = 'none';
      return;
    }
    const renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true});
    const width = holder.clientWidth || 900, height = 520;
    renderer.setSize(width, height);
    renderer.setClearColor(0xffffff);
    holder.appendChild(canvas);
    const scene = new THREE.Scene();
    scene.add(new THREE.AmbientLight(0xffffff, 0.6));
    const sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.set(1, 2, 1);
    scene.add(sun);
    // Global frame x north, y east, z down → three.js (east, up, south): a proper rotation.
    const toScene = (p) => new THREE.Vector3(p[1], -p[2], -p[0]);
    const origin = toScene(centres[Math.floor(centres.length / 2)]);
    const length = Math.abs(nodes[nodes.length - 1].s - nodes[0].s) || 1;
    const group = new THREE.Group();
    scene.add(group);
    const camera = new THREE.PerspectiveCamera(40, width / height, length * 1e-4, length * 100);
    const orbit = new THREE.OrbitControls(camera, canvas);
    const forces = (R.static.contacts || []).map((c) => c.normal_force);
    const maxForce = Math.max(1e-30, ...forces);
    const meanHole = nodes.reduce((a, n) => a + (n.hole_diameter || 0), 0) / nodes.length;
    // The default scale: the hole's diameter drawn as a twentieth of the string's length.
    const defaultScale = Math.max(1, length / 20 / (meanHole * lengthPerDiameter()));
    let points = 0;
    function lengthPerDiameter() { return U.length === 'ft' ? 1 / 12 : 1; }  // diameters in in or m → lengths
    function build(scale) {
      while (group.children.length) {
        const child = group.children.pop();
        if (child.geometry) child.geometry.dispose();
      }
      const k = scale;
      const dl = lengthPerDiameter();
      const display = nodes.map((n, i) => {
        const c = toScene(centres[i]), p = toScene(n.position);
        return c.clone().add(p.clone().sub(c).multiplyScalar(k)).sub(origin);
      });
      const curve = new THREE.CatmullRomCurve3(display);
      const od = (D.components || []).length ? Math.min(...D.components.map((c) => c.od)) : meanHole / 2;
      const tubeRadius = Math.max(k * od * dl / 2, length * 1e-4);
      const tube = new THREE.TubeGeometry(curve, Math.min(2000, display.length * 4), tubeRadius, 10, false);
      group.add(new THREE.Mesh(tube, new THREE.MeshLambertMaterial({color: 0x4a6fa5})));
      // The hole: a transparent tube of its mean diameter about the centreline, and rings of its
      // diameter at stations along it (sections of another size show there).
      const centreLine = centres.map((c) => toScene(c).sub(origin));
      const holeCurve = new THREE.CatmullRomCurve3(centreLine);
      const holeTube = new THREE.TubeGeometry(holeCurve, Math.min(1000, centreLine.length * 2), k * meanHole * dl / 2, 24, false);
      group.add(new THREE.Mesh(holeTube, new THREE.MeshLambertMaterial({color: 0xc8a060, transparent: true, opacity: 0.18, depthWrite: false, side: THREE.DoubleSide})));
      group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(centreLine), new THREE.LineBasicMaterial({color: 0x999999})));
      const step = Math.max(1, Math.floor(nodes.length / 40));
      for (let i = 0; i < nodes.length; i += step) {
        if (!nodes[i].hole_diameter) continue;
        const j = Math.min(i + 1, nodes.length - 1), h = Math.max(i - 1, 0);
        const tangent = centreLine[j].clone().sub(centreLine[h]).normalize();
        const radius = k * nodes[i].hole_diameter * dl / 2;
        const ring = new THREE.RingGeometry(radius * 0.95, radius, 48);
        const mesh = new THREE.Mesh(ring, new THREE.MeshBasicMaterial({color: 0x8a6d3b, side: THREE.DoubleSide, transparent: true, opacity: 0.6}));
        mesh.position.copy(centreLine[i]);
        mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), tangent);
        group.add(mesh);
      }
      // Contacts: spheres where the string meets the wall (its station nearest each, on the side
      // away from the hole's axis), coloured by normal force.
      points = display.length;
      for (const c of R.static.contacts || []) {
        let best = 0;
        for (let i = 1; i < nodes.length; ++i) if (Math.abs(nodes[i].s - c.s) < Math.abs(nodes[best].s - c.s)) best = i;
        const f = Math.sqrt(c.normal_force / maxForce);
        const color = new THREE.Color().setHSL(0.66 * (1 - f), 0.9, 0.45);
        const sphere = new THREE.Mesh(new THREE.SphereGeometry(tubeRadius * 0.8, 12, 8), new THREE.MeshLambertMaterial({color: color}));
        const outward = display[best].clone().sub(centreLine[best]);
        if (outward.lengthSq() > 0) outward.normalize();
        sphere.position.copy(display[best]).add(outward.multiplyScalar(tubeRadius));
        group.add(sphere);
        ++points;
      }
      label.textContent = `× ${num(k, 3)}`;
    }
    const display0 = (i) => toScene(nodes[i].position);
    const scaleOf = (v) => Math.pow(10, Number(v)) * defaultScale / 100;
    build(scaleOf(slider.value));
    const box = new THREE.Box3().setFromObject(group);
    const size = box.getSize(new THREE.Vector3()).length() || length;
    const centre = box.getCenter(new THREE.Vector3());
    // Looking from the side of the well (across its overall direction, slightly from above).
    const axis = display0(nodes.length - 1).sub(display0(0)).normalize();
    let across = new THREE.Vector3().crossVectors(axis, new THREE.Vector3(0, 1, 0));
    if (across.lengthSq() < 1e-6) across = new THREE.Vector3(1, 0, 0);
    across.normalize();
    camera.position.copy(centre.clone().add(across.multiplyScalar(size * 1.6)).add(new THREE.Vector3(0, size * 0.25, 0)));
    orbit.target.copy(centre);
    orbit.update();
    slider.addEventListener('input', () => { build(scaleOf(slider.value)); render(); });
    function render() { renderer.render(scene, camera); }
    orbit.addEventListener('change', render);
    render();
    s.dataset.points = String(points);
  }

  // ---- modes -------------------------------------------------------------------------------------
  function modesSection(nav) {
    const s = section('modes', 'Natural frequencies and mode shapes');
    nav.appendChild(el('a', {href: '#modes', text: 'modes'}));
    const table = el('table', {class: 'data'});
    table.appendChild(el('tr', {}, ['#', 'f (Hz)', 'RPM at 1×', 'kind', 'damping', 'axial', 'torsional', 'lateral', ''].map((t) => el('th', {text: t}))));
    const firstReal = R.modes.findIndex((m) => !m.rigid_body && !m.negative_stiffness && !m.near_zero);
    R.modes.forEach((m, i) => {
      const note = m.rigid_body ? 'rigid body' : m.negative_stiffness ? 'negative stiffness' : m.near_zero ? 'near zero' : (m.whirl ? m.whirl + ' whirl' : '');
      const f = value(m.frequency_hz, '', i === firstReal ? 'modes.first_frequency_hz' : null, 5);
      const cells = [String(i + 1), f, num(60 * m.frequency_hz, 5), m.kind, num(m.damping_ratio, 3), num(m.axial_fraction, 3),
                     num(m.torsional_fraction, 3), num(m.lateral_fraction, 3), note];
      table.appendChild(el('tr', {}, cells.map((c) => { const td = el('td'); if (c instanceof Node) td.appendChild(c); else td.textContent = c; return td; })));
    });
    s.appendChild(table);
    if (R.critical_rpm) {
      const cr = R.critical_rpm;
      const p = el('p');
      if (cr.first_lateral !== undefined) p.append('First lateral critical RPM ', value(cr.first_lateral, 'rpm', 'critical_rpm.first_lateral'), '; ');
      p.append(`rule of thumb 33055·√(OD²+ID²)/L² ${num(cr.rule_of_thumb, 4)} rpm over ${num(cr.rule_of_thumb_span, 4)} ${U.length} (±15 %).`);
      s.appendChild(p);
    }
    const shapes = D.mode_shapes;
    if (shapes && shapes.modes.length) {
      const grid = el('div', {class: 'grid'});
      s.appendChild(grid);
      const series = [];
      shapes.modes.slice(0, 8).forEach((m, i) => {
        const mode = R.modes[i];
        if (mode.rigid_body || mode.negative_stiffness || series.length >= 6) return;
        // The lateral component of the larger amplitude, largest = 1.
        const ay = Math.max(...m.y.map(Math.abs)), az = Math.max(...m.z.map(Math.abs)), ax = Math.max(...m.axial.map(Math.abs));
        const [values, which] = mode.kind === 'axial' ? [m.axial, 'axial'] : ay >= az ? [m.y, 'y'] : [m.z, 'z'];
        const scale = Math.max(ax, ay, az) || 1;
        series.push({label: `${i + 1}: ${num(mode.frequency_hz, 4)} Hz (${which})`, x: shapes.s, y: values.map((v) => v / scale)});
      });
      plot(grid, {title: 'Mode shapes (each scaled to its largest displacement)', x: `distance from the bit (${U.length})`, y: 'displacement (–)', series: series});
    }
  }

  // ---- vibration ---------------------------------------------------------------------------------
  function vibrationSection(nav) {
    const v = R.vibration;
    const s = section('vibration', 'Critical speeds: forced response against RPM');
    nav.appendChild(el('a', {href: '#vibration', text: 'vibration'}));
    const names = D.excitations || [];
    const critical = (v.critical_speeds || []).slice().sort((a, b) => a.rpm - b.rpm);
    const bands = (v.safe_windows || []).map((w) => ({from: w.from, to: w.to}));
    const lines = critical.map((c) => ({x: c.rpm, label: `${num(c.rpm, 4)} rpm ${names[c.excitation] || ''}`, color: '#d62728'}));
    const ratio = v.max_clearance_ratio !== undefined;
    const p = el('p');
    const firstCritical = critical.length ? critical[0].rpm : undefined;
    if (firstCritical !== undefined) p.append('Lowest critical RPM ', value(firstCritical, 'rpm', 'vibration.critical_rpm.0'), '. ');
    p.append(`Safe windows (green: displacement below ${num(v.clearance_fraction, 3)} of the clearance and bending-stress amplitude below ${num(v.stress_limit, 3)} ${U.stress}): ` +
             (bands.length ? bands.map((b) => `${num(b.from, 4)}–${num(b.to, 4)} rpm`).join(', ') : 'none') + '.');
    s.appendChild(p);
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    plot(grid, {
      title: ratio ? 'Lateral amplitude / radial clearance (all excitations)' : `Lateral amplitude (${U.diameter})`,
      x: 'rotary speed (rpm)', y: ratio ? 'amplitude / clearance (–)' : `amplitude (${U.diameter})`,
      series: [{label: ratio ? 'amplitude / clearance' : 'amplitude', x: v.rpm, y: ratio ? v.max_clearance_ratio : v.max_lateral_displacement, width: 2}],
      xBands: bands, vLines: lines, hLines: ratio ? [{y: v.clearance_fraction, label: 'limit', color: '#ff7f0e'}] : [], logY: true,
    });
    if (v.excitation_displacement && v.excitation_displacement.length > 1) {
      plot(grid, {
        title: 'Lateral amplitude of each excitation\'s own response', x: 'rotary speed (rpm)', y: `amplitude (${U.diameter})`,
        series: v.excitation_displacement.map((curve, e) => ({label: names[e] || `excitation ${e + 1}`, x: v.rpm, y: curve})),
        xBands: bands, logY: true,
      });
    }
    plot(grid, {
      title: 'Bending-stress amplitude', x: 'rotary speed (rpm)', y: `stress (${U.stress})`,
      series: [{label: 'bending stress', x: v.rpm, y: v.max_bending_stress, color: COLORS[1], width: 2}],
      xBands: bands, vLines: lines, hLines: [{y: v.stress_limit, label: 'limit', color: '#ff7f0e'}], logY: true,
    });
    if (v.max_contact_force && v.max_contact_force.some((f) => f > 0)) {
      plot(grid, {title: 'Largest dynamic contact force amplitude', x: 'rotary speed (rpm)', y: `force (${U.force})`,
        series: [{label: 'contact force', x: v.rpm, y: v.max_contact_force, color: COLORS[3]}], xBands: bands, logY: true});
    }
    const table = el('table', {class: 'data'});
    table.appendChild(el('tr', {}, ['critical RPM', 'excitation', 'severity', `amplitude (${U.diameter})`, `bending (${U.stress})`, 'frequency (Hz)'].map((t) => el('th', {text: t}))));
    for (const c of v.critical_speeds || []) {
      table.appendChild(el('tr', {}, [num(c.rpm, 5), names[c.excitation] || String(c.excitation), num(c.severity, 3), num(c.max_lateral_displacement, 3),
                                      num(c.max_bending_stress, 3), num(c.frequency_hz, 4)].map((t) => el('td', {text: t}))));
    }
    s.appendChild(table);
  }

  function campbellSection(nav) {
    const c = R.campbell;
    const s = section('campbell', 'Campbell diagram');
    nav.appendChild(el('a', {href: '#campbell', text: 'Campbell'}));
    const branches = [];
    c.modes.forEach((atSpeed) => atSpeed.forEach((m, j) => { (branches[j] = branches[j] || []).push(m.frequency_hz); }));
    const series = branches.map((f, j) => ({label: `mode ${j + 1}`, x: c.rpm, y: f}));
    const top = Math.max(...c.rpm);
    series.push({label: '1× (synchronous)', x: [0, top], y: [0, top / 60], color: '#000', dash: [6, 4]});
    plot(s, {title: 'Whirl frequencies against rotary speed', x: 'rotary speed (rpm)', y: 'frequency (Hz)', series: series,
      vLines: (c.synchronous || []).map((x) => ({x: x.rpm, label: `${num(x.rpm, 4)} rpm (${x.whirl})`}))});
  }

  // ---- buckling ----------------------------------------------------------------------------------
  function bucklingSection(nav) {
    const b = R.buckling;
    const s = section('buckling', 'Buckling');
    nav.appendChild(el('a', {href: '#buckling', text: 'buckling'}));
    const p = el('p');
    const scaled = b.scaled === 'wob' ? 'the WOB' : 'every load';
    if (b.lower_bound) {
      // No onset up to the largest multiplier sampled (every equilibrium stable, the frequency rising).
      p.append(`No buckling up to ${scaled} × `, value(b.load_factor, '', 'buckling.load_factor', 6), ': a largest compression of ',
               value(b.critical_load, U.force, 'buckling.critical_load'), ` (now ${num(b.reference_compression, 5)} ${U.force})`);
      if (b.critical_wob !== undefined) p.append(', a WOB of ', value(b.critical_wob, U.force, 'buckling.critical_wob'));
      p.append(': the lowest lateral frequency rises with the load and every equilibrium is stable (the compression presses the string onto the wall).');
    } else {
      p.append(`Critical multiplier of ${scaled} `, value(b.load_factor, '', 'buckling.load_factor', 6), ': a largest compression of ',
               value(b.critical_load, U.force, 'buckling.critical_load'), ` (now ${num(b.reference_compression, 5)} ${U.force})`);
      if (b.critical_wob !== undefined) p.append(', a critical WOB of ', value(b.critical_wob, U.force, 'buckling.critical_wob'));
      p.append(b.method ? ` (${b.method}).` : '.');
      if (b.onset_above_model) p.append(' The pipe above the modelled string buckles first: its compression at the model\'s top reaches Dawson–Paslay\'s sinusoidal load there.');
      if (b.buckled_at_case_loads) p.append(' The string lies buckled at the case\'s loads: the onset was found below them, on a path of equilibria from a fraction of them.');
    }
    s.appendChild(p);
    if (b.frequency_method && !b.frequency_method.converged && !b.lower_bound) {
      s.appendChild(el('p', {class: 'note', text: 'The frequency extrapolation did not settle: read the multiplier with its samples below.'}));
    }
    if (b.dawson_paslay) {
      const d = b.dawson_paslay;
      const text = d.sinusoidal_load === 0
        ? `Dawson–Paslay: at MD ${num(d.md, 6)} ${U.length} the hole is vertical and the string compressed (${num(d.compression, 5)} ${U.force}): no weight holds it to the wall (Lubinski\'s case).`
        : d.load_factor < 1
          ? `Dawson–Paslay: at MD ${num(d.md, 6)} ${U.length} the compression ${num(d.compression, 5)} ${U.force} exceeds the sinusoidal buckling load ${num(d.sinusoidal_load, 5)} ${U.force} (helical ${num(d.helical_load, 5)} ${U.force}): the string lies buckled there.`
          : `Dawson–Paslay: sinusoidal buckling first at ${scaled} × ${num(d.load_factor, 4)}, at MD ${num(d.md, 6)} ${U.length} (compression ${num(d.compression, 5)} ${U.force} against ${num(d.sinusoidal_load, 5)} ${U.force} now; helical ${num(d.helical_load, 5)} ${U.force}).`;
      s.appendChild(el('p', {text: text}));
      if (!R.model.pipe_above) {
        // model.top: free (or the case's supports): nothing holds the top across the hole.
        s.appendChild(el('p', {class: 'note', text: 'In an inclined hole the modelled string\'s top is free sideways and may buckle first (Hetényi\'s end mode, about half the Dawson–Paslay load): docs/validation.md, V2 inclined holes.'}));
      }
    }
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    const table = (b.frequency_method || {}).table || [];
    if (table.length) {
      plot(grid, {title: 'Lowest frequency against the load multiplier', x: 'load multiplier (–)', y: 'frequency (Hz)',
        series: [{label: 'lowest frequency', x: column(table, 'load_factor'), y: column(table, 'frequency_hz'), points: true, width: 2}],
        vLines: b.lower_bound ? [] : [{x: b.load_factor, label: `critical ${num(b.load_factor, 4)}`, color: '#d62728'}]});
    }
    if (b.mode && b.mode.s.length) {
      const d = b.mode.displacement;
      plot(grid, {title: b.lower_bound ? `Lowest lateral mode at × ${num(b.load_factor, 4)} (largest = 1)` : 'Buckled shape (largest = 1)', x: `distance from the bit (${U.length})`, y: 'displacement (–)',
        series: [{label: 'y (right)', x: b.mode.s, y: d.map((u) => u[1])}, {label: 'z (high side)', x: b.mode.s, y: d.map((u) => u[2])}]});
    }
  }

  // ---- tendency ----------------------------------------------------------------------------------
  function tendencySection(nav) {
    const t = R.tendency;
    const s = section('tendency', 'Directional tendency');
    nav.appendChild(el('a', {href: '#tendency', text: 'tendency'}));
    const p = el('p');
    const verb = (rate, up, down) => (rate >= 0 ? up : down);
    p.append(`The steady curvature, where the bit drills along the hole it is in (bit steerability ${num(t.steerability, 3)}, WOB ${num(t.weight_on_bit, 4)} ${U.wob}, at ${num(t.inclination, 4)}° inclination): `,
             verb(t.build_rate, 'builds ', 'drops '), value(Math.abs(t.build_rate), U.dogleg, 'tendency.build_rate'), ' and ',
             verb(t.turn_rate, 'turns right ', 'turns left '), value(Math.abs(t.turn_rate), U.dogleg, 'tendency.turn_rate'),
             ` (dogleg ${num(t.dogleg_severity, 4)} ${U.dogleg}; ${t.statics} statics). There the bit pushes the formation with ${num(t.bit.side_force, 4)} ${U.force} (build ${num(t.bit.build_force, 4)}, walk ${num(t.bit.walk_force, 4)}) and tilts ${num(t.bit.tilt, 3)}° toward the high side.`);
    s.appendChild(p);
    const steering = t.steering;
    if (steering) {
      // A rotary steerable system: its rates at 0 % and 100 % steer and the yield per unit of steer.
      const system = steering.type === 'point'
        ? `A point-the-bit system (the bit's axis ${num(steering.offset, 3)}° off the tool's toward toolface ${num(steering.toolface, 4)}°)`
        : `A push-the-bit system (pads pushing ${num(steering.force, 4)} ${U.force} toward toolface ${num(steering.toolface, 4)}°)`;
      const rates = (r) => `build ${num(r.build_rate, 4)}, turn ${num(r.turn_rate, 4)} ${U.dogleg}`;
      s.appendChild(el('p', {text: `${system} steering ${num(100 * steering.steer, 3)} % of the time: natural tendency (0 %) ${rates(steering.natural)}; full steer ${rates(steering.full)}; per unit of steer ${rates(steering.yield_per_steer)}.`}));
    }
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    const trace = t.trace || [];
    if (trace.length) {
      plot(grid, {title: 'The search: the bit\'s sideways penetration against the hole\'s build', x: `build curvature (${U.dogleg})`, y: 'deviation toward the high side (deg)',
        series: [{label: 'statics', x: column(trace, 'build_curvature'), y: column(trace, 'deviation_build'), points: true, width: 0}],
        vLines: [{x: t.build_rate, label: `steady ${num(t.build_rate, 4)}`, color: '#d62728'}]});
    }
    const sens = t.sensitivities;
    if (sens) {
      const rates = (curve, label) => [{label: 'build rate', x: curve.values, y: curve.build_rate, points: true, width: 2, color: COLORS[0]},
                                      {label: 'turn rate', x: curve.values, y: curve.turn_rate, points: true, width: 2, color: COLORS[1]}];
      plot(grid, {title: 'Against the weight on bit', x: `WOB (${U.wob})`, y: `rate (${U.dogleg})`, series: rates(sens.weight_on_bit)});
      plot(grid, {title: 'Against the inclination', x: 'inclination at the bit (deg)', y: `rate (${U.dogleg})`, series: rates(sens.inclination)});
      plot(grid, {title: 'Against the stabilizers\' gauge', x: `every blade's OD less (${U.diameter})`, y: `rate (${U.dogleg})`, series: rates(sens.gauge_reduction)});
    }
  }

  // ---- transient ---------------------------------------------------------------------------------
  function transientSection(nav) {
    const t = D.transient;
    const s = section('transient', 'Transient: drilling in time');
    nav.appendChild(el('a', {href: '#transient', text: 'transient'}));
    // Stick-slip severity over the second half of the run (after the start-up): (max − min) / mean bit RPM.
    const half = t.time.length >> 1;
    const late = t.bit_rpm.slice(half);
    const mean = late.reduce((a, b) => a + b, 0) / (late.length || 1);
    const severity = mean !== 0 ? (Math.max(...late) - Math.min(...late)) / Math.abs(mean) : NaN;
    const words = !isFinite(severity) ? '' : severity < 0.2 ? 'smooth drilling' : severity < 1 ? 'torsional oscillation' : 'stick-slip (the bit stops)';
    const p = el('p');
    p.append(`${num(t.time[t.time.length - 1], 4)} s simulated. Stick-slip severity (max − min) / mean bit RPM over the second half: `,
             el('strong', {text: num(severity, 3)}), ` — ${words}.`);
    s.appendChild(p);
    // The string's limits at every output sample (results.json transient.limits): each limit's largest
    // utilisation, where and when, and a warning for any at or above 1; their history is plotted below.
    const tl = R.transient && R.transient.limits;
    const names = {yield: 'yield', makeup_torque: 'make-up torque', helical_buckling: 'helical buckling', fatigue: 'fatigue'};
    if (tl && tl.summary) {
      const table = el('table', {class: 'data utilisations'});
      table.appendChild(el('tr', {}, ['limit', `largest over ${tl.samples || tl.frames} samples`, 'where', 'when (s)'].map((x) => el('th', {text: x}))));
      const over = [];
      for (const key of ['yield', 'makeup_torque', 'helical_buckling', 'fatigue']) {
        const u = tl.summary[key];
        if (!u) continue;
        const cell = el('td', {text: num(u.utilisation, 3)});
        if (u.utilisation >= 1) { cell.setAttribute('class', 'beyond'); over.push(`${names[key]} ${num(u.utilisation, 3)} at ${where(u.s, u.md)}, t = ${num(u.time, 4)} s`); }
        table.appendChild(el('tr', {}, [el('td', {text: names[key]}), cell, el('td', {text: `${where(u.s, u.md)} (${u.component})`}), el('td', {text: num(u.time, 4)})]));
      }
      s.appendChild(table);
      if (over.length) {
        const list = el('ul', {class: 'warnings'});
        for (const b of over) list.appendChild(el('li', {text: b}));
        s.appendChild(el('div', {class: 'warning-box'}, [el('strong', {text: 'Beyond a limit during the run (utilisation above 1)'}), list]));
      }
    }
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    plot(grid, {title: 'Rotary speed', x: 'time (s)', y: 'rpm', series: [
      {label: 'surface', x: t.time, y: t.surface_rpm, color: COLORS[0]}, {label: 'bit', x: t.time, y: t.bit_rpm, color: COLORS[1]}]});
    plot(grid, {title: 'Torque', x: 'time (s)', y: `torque (${U.moment})`, series: [
      {label: 'surface', x: t.time, y: t.surface_torque, color: COLORS[0]}, {label: 'on bit', x: t.time, y: t.torque_on_bit, color: COLORS[1]}]});
    plot(grid, {title: 'Weight on bit', x: 'time (s)', y: `WOB (${U.wob})`, series: [{label: 'WOB', x: t.time, y: t.wob, color: COLORS[2]}]});
    plot(grid, {title: 'Tension at the top of the modelled string', x: 'time (s)', y: `force (${U.force})`,
      series: [{label: 'top tension', x: t.time, y: t.hook_load, color: COLORS[4]}]});
    const th = tl && tl.history;
    if (th && th.time && th.closest) {
      const series = ['yield', 'makeup_torque', 'helical_buckling', 'fatigue'].filter((k) => th[k]).map((k, i) => ({
        label: names[k] + (k === th.closest ? ' (the closest)' : ''), x: th.time, y: th[k], color: COLORS[i], width: k === th.closest ? 2.5 : 1.5}));
      plot(grid, {title: 'String limits: the largest utilisation along the string', x: 'time (s)', y: 'utilisation (load / limit)',
        series: series, hLines: [{y: 1, label: 'limit', color: '#d62728'}]});
    }
    t.probes.forEach((probe, i) => {
      const circle = [];
      if (probe.clearance !== undefined) {
        for (let a = 0; a <= 64; ++a) circle.push([probe.clearance * Math.cos(2 * Math.PI * a / 64), probe.clearance * Math.sin(2 * Math.PI * a / 64)]);
      }
      const reach = 1.1 * Math.max(probe.clearance || 0, ...probe.y.map(Math.abs), ...probe.z.map(Math.abs));
      plot(grid, {title: `Whirl orbit at ${num(probe.s, 4)} ${U.length} from the bit (looking down-hole)`, x: `right (${U.diameter})`, y: `high side (${U.diameter})`,
        square: true, xMin: -reach, xMax: reach, yMin: -reach, yMax: reach,
        series: [{label: 'orbit', x: probe.y, y: probe.z, color: COLORS[i % COLORS.length]},
                 {label: 'the wall (radial clearance)', x: circle.map((c) => c[0]), y: circle.map((c) => c[1]), color: '#999', dash: [4, 3]}]});
      plot(grid, {title: `Wall contact force at ${num(probe.s, 4)} ${U.length} from the bit`, x: 'time (s)', y: `force (${U.force})`,
        series: [{label: 'contact force', x: t.time, y: probe.contact_force, color: COLORS[1]}]});
    });
  }

  // ---- roadmap -----------------------------------------------------------------------------------
  // Torque and drag against bit depth in the field's usual look: depth down, a colour per friction
  // factor, pick-up solid, slack-off dashed, rotating off bottom dotted; torque off bottom solid, on
  // bottom dashed.
  function roadmapSection(nav) {
    const r = R.roadmap;
    const ru = r.units;
    const s = section('roadmap', 'Torque-and-drag roadmap');
    nav.appendChild(el('a', {href: '#roadmap', text: 'roadmap'}));
    facts(s, [
      ['model', r.model === 'soft' ? 'soft string (Johancsik)' : r.model === 'both'
        ? 'stiff string (markers) and soft string (Johancsik: thin lines)' : 'stiff string'],
      ['bit depths', `${num(r.from, 6)} to ${num(r.bit_md, 6)} ${ru.bit_md}, every ${num(r.step, 5)} ${ru.bit_md}`],
      ['friction factors', r.friction.map((f) => num(f, 3)).join(', ')],
      ['motion', `tripping at ${num(r.trip_speed, 3)} ${U.length}/s; rotating at ${num(r.rpm, 4)} ${U.rpm}; on bottom WOB ${num(r.weight_on_bit, 4)} ${U.wob}, torque on bit ${num(r.torque_on_bit, 5)} ${ru.on_bottom_torque}`],
    ]);
    // A point whose message leaves its values whole carries a warning; one with an empty value failed.
    const values = ['pick_up', 'slack_off', 'rotating', 'off_bottom_torque', 'on_bottom_torque'];
    const noted = r.points.filter((p) => p.message);
    const failed = noted.filter((p) => values.some((v) => p[v] === null)).length;
    if (noted.length) {
      const list = el('ul', {class: 'warnings'});
      for (const p of noted) list.appendChild(el('li', {text: `${num(p.bit_md, 6)} ${ru.bit_md}, friction ${num(p.friction, 3)}: ${p.message}`}));
      s.appendChild(el('div', {class: 'warning-box'}, [el('strong', {text: `${failed} of ${r.points.length} points failed, ${noted.length - failed} answered with a warning`}), list]));
    }
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    const hook = [], torque = [];
    r.friction.forEach((mu, i) => {
      const rows = r.points.filter((p) => p.friction === mu);
      const depth = column(rows, 'bit_md'), color = COLORS[i % COLORS.length], m = `μ ${num(mu, 3)}`;
      hook.push({label: `pick-up, ${m}`, x: column(rows, 'pick_up'), y: depth, color: color, points: true, width: 2});
      hook.push({label: `slack-off, ${m}`, x: column(rows, 'slack_off'), y: depth, color: color, dash: [7, 4], points: true, width: 2});
      hook.push({label: `rotating, ${m}`, x: column(rows, 'rotating'), y: depth, color: color, dash: [2, 3], width: 1.5});
      torque.push({label: `off bottom, ${m}`, x: column(rows, 'off_bottom_torque'), y: depth, color: color, points: true, width: 2});
      torque.push({label: `on bottom, ${m}`, x: column(rows, 'on_bottom_torque'), y: depth, color: color, dash: [7, 4], points: true, width: 2});
      // With `--model both` the soft string (Johancsik) beside it, thin lines without markers.
      if (r.soft_points) {
        const soft = r.soft_points.filter((p) => p.friction === mu), sd = column(soft, 'bit_md');
        hook.push({label: `soft pick-up, ${m}`, x: column(soft, 'pick_up'), y: sd, color: color, width: 0.8});
        hook.push({label: `soft slack-off, ${m}`, x: column(soft, 'slack_off'), y: sd, color: color, dash: [7, 4], width: 0.8});
        torque.push({label: `soft off bottom, ${m}`, x: column(soft, 'off_bottom_torque'), y: sd, color: color, width: 0.8});
        torque.push({label: `soft on bottom, ${m}`, x: column(soft, 'on_bottom_torque'), y: sd, color: color, dash: [7, 4], width: 0.8});
      }
    });
    // The limits (roadmap.json points' hook_load_limit, helical_slack_off, torque_limit): thin dark-red
    // lines, once, at the largest friction factor (its torque lowers the yield's hook load most; the
    // helical slack-off hardly moves with it), so that they do not crowd the legend.
    {
      const mu = Math.max(...r.friction), rows = r.points.filter((p) => p.friction === mu), depth = column(rows, 'bit_md');
      const given = (key) => rows.some((p) => p[key] !== null && p[key] !== undefined);
      if (given('hook_load_limit')) {
        hook.push({label: `hook load at yield (μ ${num(mu, 3)})`, x: column(rows, 'hook_load_limit'), y: depth, color: '#8b0000', dash: [12, 3, 2, 3], width: 1});
      }
      if (given('helical_slack_off')) {
        hook.push({label: `slack-off at helical buckling (μ ${num(mu, 3)})`, x: column(rows, 'helical_slack_off'), y: depth, color: '#8b0000', dash: [1, 3], width: 1.5});
      }
    }
    if (r.points.some((p) => p.torque_limit !== null && p.torque_limit !== undefined)) {
      torque.push({label: 'make-up torque (weakest)', x: column(r.points, 'torque_limit'), y: column(r.points, 'bit_md'), color: '#d62728', dash: [12, 3, 2, 3], width: 1});
    }
    // The rig's readings (`--readings`): markers by activity over the curves, and through the drilling
    // readings the on-bottom hook load each friction factor gives at their own WOB.
    if (r.readings) readingsSeries(r.readings, hook, torque, r.friction);
    plot(grid, {title: 'Hook load: pick-up (solid), slack-off (dashed), rotating off bottom (dotted)', x: `hook load (${ru.pick_up})`,
      y: `bit MD (${ru.bit_md})`, depthDown: true, yMin: 0, xNice: true, xFromZero: true, series: hook});
    // A vertical stretch turns free of the wall: its torque's round-off (1e-20) is drawn as the zero it is.
    const torques = torque.flatMap((t) => t.x).filter(isFinite);
    const largest = Math.max(0, ...torques.map(Math.abs));
    plot(grid, {title: 'Surface torque: off bottom (solid), on bottom (dashed)', x: `torque (${ru.off_bottom_torque})`,
      y: `bit MD (${ru.bit_md})`, depthDown: true, yMin: 0, xNice: true, xFromZero: true,
      xMin: Math.min(...torques) > -1e-9 * largest ? 0 : undefined, series: torque});
    roadmapLimitsTable(s, r);
  }

  // The roadmap points' screens (roadmap.json points' buckled_zones, fatigue, wear_*): a row a point that
  // buckles, turns through a dogleg or wears the casing, each zone's ends and each worst utilisation a
  // value the report test compares with roadmap.json; a warning line for any utilisation at or above 1.
  const ROADMAP_RUNS = {pick_up: 'pick-up', slack_off: 'slack-off', rotating: 'rotating', on_bottom: 'on bottom'};
  function roadmapLimitsTable(s, r) {
    const ru = r.units, len = ru.bit_md;
    const rows = [], beyond = [];
    r.points.forEach((p, i) => {
      const zones = p.buckled_zones || [], fatigue = p.fatigue || {};
      const worst = Object.keys(ROADMAP_RUNS).filter((run) => fatigue[run] && fatigue[run].worst && fatigue[run].worst.utilisation > 0);
      const wears = p.wear_groove_depth !== null && p.wear_groove_depth !== undefined;
      if (!zones.length && !worst.length && !wears) return;
      const key = `roadmap.points.${i}`;
      const zoneCell = el('td');
      zones.forEach((z, k) => {
        if (k) zoneCell.appendChild(document.createTextNode('; '));
        zoneCell.appendChild(document.createTextNode(`${ROADMAP_RUNS[z.run] || z.run}: ${z.kind} MD `));
        zoneCell.appendChild(value(z.md_from, '', `${key}.buckled_zones.${k}.md_from`, 6));
        zoneCell.appendChild(document.createTextNode('–'));
        zoneCell.appendChild(value(z.md_to, len, `${key}.buckled_zones.${k}.md_to`, 6));
      });
      if (!zones.length) zoneCell.textContent = 'none';
      const fatigueCell = el('td');
      worst.forEach((run, k) => {
        const w = fatigue[run].worst, doglegs = fatigue[run].doglegs.length;
        if (k) fatigueCell.appendChild(document.createTextNode('; '));
        fatigueCell.appendChild(document.createTextNode(`${ROADMAP_RUNS[run]}: `));
        fatigueCell.appendChild(value(w.utilisation, '', `${key}.fatigue.${run}.worst.utilisation`));
        fatigueCell.appendChild(document.createTextNode(` at MD ${num(w.md, 6)} ${len} (${doglegs} dogleg${doglegs === 1 ? '' : 's'})`));
        if (w.utilisation >= 1) beyond.push(`fatigue ${ROADMAP_RUNS[run]} ${num(w.utilisation, 3)} at MD ${num(w.md, 6)} ${len} (bit ${num(p.bit_md, 6)} ${len}, μ ${num(p.friction, 3)})`);
      });
      if (!worst.length) fatigueCell.textContent = '–';
      const wearCell = el('td');
      if (wears) {
        wearCell.appendChild(value(p.wear_groove_depth, ru.wear_groove_depth, `${key}.wear_groove_depth`));
        wearCell.appendChild(document.createTextNode(` at MD ${num(p.wear_md, 6)} ${len}`));
        if (p.wear_utilisation !== null && p.wear_utilisation !== undefined) {
          wearCell.appendChild(document.createTextNode(' (utilisation '));
          wearCell.appendChild(value(p.wear_utilisation, '', `${key}.wear_utilisation`));
          wearCell.appendChild(document.createTextNode(' of the wall)'));
          if (p.wear_utilisation >= 1) beyond.push(`casing wear ${num(p.wear_utilisation, 3)} at MD ${num(p.wear_md, 6)} ${len} (bit ${num(p.bit_md, 6)} ${len}, μ ${num(p.friction, 3)})`);
        }
      } else {
        wearCell.textContent = '–';
      }
      for (const cell of [zoneCell, fatigueCell, wearCell]) cell.setAttribute('style', 'text-align: left');
      rows.push(el('tr', {}, [el('td', {text: `${num(p.bit_md, 6)} ${len}`}), el('td', {text: num(p.friction, 3)}), zoneCell, fatigueCell, wearCell]));
    });
    if (!rows.length) return;
    const by = r.points.some((p) => p.screened_by === 'stiff') ? 'the stiff string\'s own runs (the pipe above its part by the soft string)' : 'the soft string (Johancsik)';
    s.appendChild(el('h3', {text: 'Limits along the roadmap'}));
    s.appendChild(el('p', {text: `Buckled zones (compression beyond Dawson–Paslay's sinusoidal and Chen's helical loads) and the bending stress's fatigue utilisation (API RP 7G) of the rotating runs, from ${by}; ` +
      'the casing\'s deepest wear groove drilling down to each depth (White & Dawson, the soft string rotating on bottom).'}));
    if (beyond.length) {
      const list = el('ul', {class: 'warnings'});
      for (const b of beyond) list.appendChild(el('li', {text: b}));
      s.appendChild(el('div', {class: 'warning-box'}, [el('strong', {text: 'At or beyond a limit'}), list]));
    }
    const table = el('table', {class: 'data utilisations'});
    table.appendChild(el('tr', {}, ['bit MD', 'friction', 'buckled zones', 'fatigue (worst)', 'casing wear groove'].map((t) => el('th', {text: t}))));
    for (const row of rows) table.appendChild(row);
    s.appendChild(table);
  }

  // The readings as marker series by activity, and each model's on-bottom hook load through the drilling
  // readings (their own WOB), appended to a hook-load and a torque plot's series.
  const ACTIVITY_MARKERS = {drilling: 'circle', rotating: 'triangle', pick_up: 'rect', slack_off: 'rectRot'};
  function readingsSeries(g, hook, torque, frictions) {
    const rows = g.bit_md.map((md, i) => i);
    for (const [activity, style] of Object.entries(ACTIVITY_MARKERS)) {
      const at = rows.filter((i) => g.activity[i] === activity);
      if (!at.length) continue;
      hook.push({label: `read: ${activity.replace('_', '-')}`, x: at.map((i) => g.hook_load[i]), y: at.map((i) => g.bit_md[i]),
                 color: '#000', line: false, points: true, pointStyle: style, pointRadius: 3});
      const turning = at.filter((i) => g.surface_torque[i] !== null);
      if (turning.length) {
        torque.push({label: `read: ${activity.replace('_', '-')}`, x: turning.map((i) => g.surface_torque[i]),
                     y: turning.map((i) => g.bit_md[i]), color: '#000', line: false, points: true, pointStyle: style, pointRadius: 3});
      }
    }
    const drilling = rows.filter((i) => g.activity[i] === 'drilling').sort((a, b) => g.bit_md[a] - g.bit_md[b]);
    g.models.forEach((m, k) => {
      const color = frictions ? COLORS[frictions.indexOf(m.friction) % COLORS.length] : COLORS[k % COLORS.length];
      if (drilling.length) {
        hook.push({label: `on bottom at the readings' WOB, ${m.label}`, x: drilling.map((i) => m.hook_load[i]),
                   y: drilling.map((i) => g.bit_md[i]), color: color, dash: [1, 2], width: 1.5});
      }
    });
  }

  // ---- calibration -------------------------------------------------------------------------------
  // The fitted values with their 95 % intervals, the fitted broomstick (the readings and the model at the
  // fitted values, against depth) and the residuals against depth.
  function calibrationSection(nav) {
    const c = R.calibration;
    const g = c.readings, gu = g.units;
    const s = section('calibration', 'Calibration to the rig\'s readings');
    nav.appendChild(el('a', {href: '#calibration', text: 'calibration'}));
    s.appendChild(el('p', {text: `${g.bit_md.length} readings of ${g.file} fitted by the ${c.model} string model ` +
      `(Levenberg–Marquardt, each channel weighted by its scatter): ${c.iterations} iterations, ${c.evaluations} evaluations of the model${c.converged ? '' : ', not converged'}.`}));
    const table = el('table', {class: 'facts'});
    table.appendChild(el('tr', {}, ['parameter', 'value', '95 % interval', ''].map((h) => el('th', {text: h}))));
    for (const [name, p] of Object.entries(c.parameters)) {
      const unit = p.unit === '-' ? '' : ` ${p.unit}`;
      table.appendChild(el('tr', {}, [name.replace(/_/g, ' '), p.value === null ? '–' : `${num(p.value, 4)}${unit}`,
        p.fitted ? `${num(p.low, 4)} to ${num(p.high, 4)}${unit}` : '', p.fitted ? '' : `held: ${p.note}`].map((t) => el('td', {text: t}))));
    }
    s.appendChild(table);
    facts(s, [['residual RMS', `hook load ${num(c.rms.hook_load, 4)} ${gu.hook_load} (${c.counts.hook_load} readings), ` +
      `surface torque ${num(c.rms.surface_torque, 4)} ${gu.surface_torque} (${c.counts.surface_torque})`]]);
    if (c.warnings.length) {
      const list = el('ul', {class: 'warnings'});
      for (const w of c.warnings) list.appendChild(el('li', {text: w}));
      s.appendChild(el('div', {class: 'warning-box'}, [el('strong', {text: 'What the readings cannot tell'}), list]));
    }
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    const hook = [], torque = [];
    readingsSeries(g, hook, torque, null);
    const m = g.models[0], rows = g.bit_md.map((md, i) => i).sort((a, b) => g.bit_md[a] - g.bit_md[b]);
    for (const activity of Object.keys(ACTIVITY_MARKERS)) {
      const at = rows.filter((i) => g.activity[i] === activity);
      if (!at.length || activity === 'drilling') continue;
      hook.push({label: `fitted: ${activity.replace('_', '-')}`, x: at.map((i) => m.hook_load[i]), y: at.map((i) => g.bit_md[i]), color: COLORS[1], width: 1.5});
    }
    const turning = rows.filter((i) => g.surface_torque[i] !== null);
    torque.push({label: 'fitted', x: turning.map((i) => m.surface_torque[i]), y: turning.map((i) => g.bit_md[i]), color: COLORS[0], width: 1.5});
    plot(grid, {title: 'Hook load: read (markers) and fitted', x: `hook load (${gu.hook_load})`, y: `bit MD (${gu.bit_md})`,
      depthDown: true, xNice: true, series: hook});
    plot(grid, {title: 'Surface torque: read (markers) and fitted', x: `torque (${gu.surface_torque})`, y: `bit MD (${gu.bit_md})`,
      depthDown: true, xNice: true, series: torque});
    plot(grid, {title: 'Hook-load residual (model − reading)', x: `residual (${gu.hook_load})`, y: `bit MD (${gu.bit_md})`, depthDown: true, xNice: true,
      series: [{label: 'hook load', x: rows.map((i) => m.hook_load_residual[i]), y: rows.map((i) => g.bit_md[i]), color: COLORS[1], line: false, points: true}]});
    plot(grid, {title: 'Torque residual (model − reading)', x: `residual (${gu.surface_torque})`, y: `bit MD (${gu.bit_md})`, depthDown: true, xNice: true,
      series: [{label: 'surface torque', x: turning.map((i) => m.torque_residual[i]), y: turning.map((i) => g.bit_md[i]), color: COLORS[0], line: false, points: true}]});
  }

  // ---- stability map -----------------------------------------------------------------------------
  // Each run a square at its RPM and WOB, coloured by its regime (pipeline/drilling_regime.hpp), and
  // the stick-slip severity against RPM, a line per WOB.
  function stabilitySection(nav) {
    const m = R.stability;
    const s = section('stability', 'Stability map: RPM × WOB');
    nav.appendChild(el('a', {href: '#stability', text: 'stability map'}));
    const [oscillation, stickSlip] = m.severity_limits;
    s.appendChild(el('p', {text: `Each run is the case's transient at its top-drive RPM and WOB, read over its second half: ` +
      `stick-slip when (max − min) / mean bit RPM ≥ ${num(stickSlip, 2)} (the bit stops), torsional oscillation from ${num(oscillation, 2)}; ` +
      `whirl when a probe orbits at least once round, never nearer the hole's axis than ${num(100 * m.whirl_radius_fraction, 2)} % of its clearance, ` +
      `forward with the string's rotation, backward against it. Hover a square for its regime.`}));
    const classes = [['smooth', '#2ca02c'], ['torsional oscillation', '#bcbd22'], ['forward whirl', '#ff7f0e'],
                     ['stick-slip', '#d62728'], ['backward whirl', '#9467bd'], ['failed', '#7f7f7f']];
    const grid = el('div', {class: 'grid'});
    s.appendChild(grid);
    const series = classes.map(([name, color]) => {
      const runs = m.points.filter((p) => p.class === name);
      return {label: name, x: column(runs, 'rpm'), y: column(runs, 'wob'), color: color, line: false, points: true,
              pointStyle: 'rect', pointRadius: 11, noLegend: runs.length === 0};
    }).filter((entry) => entry.x.length > 0);
    // The squares whole inside the frame: a tenth of the span (or of the value) beyond the outer runs.
    const padded = (values) => {
      const lo = Math.min(...values), hi = Math.max(...values), pad = 0.1 * (hi - lo || Math.abs(hi) || 1);
      return [lo - pad, hi + pad];
    };
    const [xMin, xMax] = padded(column(m.points, 'rpm')), [yMin, yMax] = padded(column(m.points, 'wob'));
    plot(grid, {title: 'Drilling regime', x: `top-drive speed (${U.rpm})`, y: `WOB (${U.wob})`, series: series,
      xMin: xMin, xMax: xMax, yMin: yMin, yMax: yMax});
    const wobs = [...new Set(m.points.map((p) => p.wob))].sort((a, b) => a - b);
    plot(grid, {title: 'Stick-slip severity (max − min) / mean bit RPM', x: `top-drive speed (${U.rpm})`, y: 'severity (–)',
      hLines: [{y: stickSlip, label: 'the bit stops', color: '#d62728'}, {y: oscillation, label: 'torsional oscillation', color: '#bcbd22'}],
      series: wobs.map((wob, i) => {
        const runs = m.points.filter((p) => p.wob === wob).sort((a, b) => a.rpm - b.rpm);
        return {label: `WOB ${num(wob, 4)} ${U.wob}`, x: column(runs, 'rpm'), y: column(runs, 'stick_slip_severity'),
                color: COLORS[i % COLORS.length], points: true};
      })});
    const table = el('table', {class: 'facts'});
    table.appendChild(el('tr', {}, ['run', `RPM (${U.rpm})`, `WOB (${U.wob})`, 'regime', 'severity', `whirl (${U.rpm})`].map((h) => el('th', {text: h}))));
    for (const p of m.points) {
      table.appendChild(el('tr', {}, [String(p.run), num(p.rpm, 4), num(p.wob, 4), p.message ? `failed: ${p.message}` : p.regime,
        p.stick_slip_severity === null ? '' : num(p.stick_slip_severity, 3), p.whirl === 'none' || !p.whirl ? '' : num(p.whirl_speed, 4)].map((t) => el('td', {text: t}))));
    }
    s.appendChild(table);
  }

  // ---- compose -----------------------------------------------------------------------------------
  function guarded(name, f) {
    try { f(); } catch (e) { recordError(`${name}: ${e && e.message ? e.message : e}`); }
  }
  // An analysis of a run that kept what finished (`drillflex run --keep-finished`) and did not finish:
  // its section says so, with the solver's reason, where the results would be.
  function failedSection(nav, failure) {
    const s = section(failure.analysis, `${failure.analysis[0].toUpperCase()}${failure.analysis.slice(1)}: failed`);
    nav.appendChild(el('a', {href: `#${failure.analysis}`, text: `${failure.analysis} (failed)`}));
    s.appendChild(el('div', {class: 'failure-box'}, [el('strong', {text: 'This analysis did not finish. '}),
      el('span', {text: failure.message})]));
  }
  const failed = (name) => (R.failures || []).find((f) => f.analysis === name);
  function part(name, present, f) {
    if (present) guarded(name, f);
    else if (failed(name)) guarded(name, () => failedSection(nav, failed(name)));
  }
  const nav = header();
  part('static', R.static, () => staticSection(nav));
  if (R.static && D.hole_centre) guarded('3-D view', () => threeSection(nav));
  part('modes', R.modes, () => modesSection(nav));
  if (R.campbell) guarded('Campbell', () => campbellSection(nav));
  part('vibration', R.vibration, () => vibrationSection(nav));
  part('buckling', R.buckling, () => bucklingSection(nav));
  part('tendency', R.tendency, () => tendencySection(nav));
  part('transient', D.transient, () => transientSection(nav));
  if (R.roadmap) guarded('roadmap', () => roadmapSection(nav));
  if (R.stability) guarded('stability map', () => stabilitySection(nav));
  if (R.calibration) guarded('calibration', () => calibrationSection(nav));
  // report.html?only=static shows the header and that section alone (to print or capture one part).
  const only = new URLSearchParams(window.location.search).get('only');
  if (only) {
    for (const part of root.querySelectorAll('section.report-section')) if (part.id !== only) part.style.display = 'none';
  }
  root.appendChild(el('footer', {text: 'drillflex: flexible multibody drill-string mechanics. The tables behind every plot are in results.json and the CSV files beside this report.'}));
  if (!errors.length) document.body.dataset.reportStatus = 'ok';
})();
