// Draws report.html's figures with uPlot (embedded before this file): each
// <figure class="evidence"> holds its data as JSON (rig/results/figure_data.hpp) in a
// <script type="application/json" class="figure-data">; every chart of it becomes one uPlot.
// After drawing, each chart's box says which marks landed on its canvas (data-expected,
// data-limits) and where their words went (data-labels), so a test reads what the reader sees.
(function () {
  'use strict';
  const WIDTH = 640;
  const AXIS = 70; // every chart's y axis the same width: stacked lanes share one time axis
  const px = n => n * uPlot.pxRatio;

  // Tick labels in `per` units, with the decimals the tick step needs (100.0005 next to 100.001).
  const ticks = per => (u, splits, axis, space, incr) => {
    const decimals = Math.min(Math.max(0, -Math.floor(Math.log10(incr / per) + 1e-9)), 9);
    return splits.map(v => String(Number((v / per).toFixed(decimals))));
  };
  // The unit a time span in ns reads in.
  const timeUnit = span => span < 2e3 ? ['ns', 1] : span < 2e6 ? ['\u00b5s', 1e3] : span < 2e9 ? ['ms', 1e6] : ['s', 1e9];

  function xAxis(chart, bottom) {
    const x = chart.x;
    const axis = {show: bottom, size: 40, gap: 4};
    if (x.time) {
      const [unit, per] = timeUnit(Math.max(Math.abs(x.min), Math.abs(x.max), x.max - x.min));
      axis.label = x.label ? x.label + ' (' + unit + ')' : unit;
      axis.values = ticks(per);
    } else if (x.names) {
      axis.label = x.label;
      axis.incrs = [1, 2, 5, 10, 20, 50, 100, 200, 500];
      axis.values = (u, splits) => splits.map(v => (Number.isInteger(v) && x.names[v] !== undefined ? x.names[v] : ''));
    } else {
      axis.label = x.label;
      axis.values = ticks(1);
    }
    axis.labelSize = 18;
    return axis;
  }

  function yAxis(chart, y, scale, side) {
    const label = y.label; // a lane's name is its title above it
    const axis = {scale, side, size: AXIS, label, labelSize: 16, show: !y.hidden, values: ticks(1)};
    if (y.logic) {
      axis.splits = () => [0, 1];
      axis.values = (u, s) => s.map(String);
    } else if (y.integer) {
      axis.incrs = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1e3, 2e3, 5e3, 1e4, 2e4, 5e4, 1e5, 1e6, 1e7];
    } else if (y.ticks) {
      axis.splits = () => y.ticks.map((_, i) => i);
      axis.values = (u, s) => s.map(v => y.ticks[v]);
    }
    return axis;
  }

  function range(y) {
    if (y.logic) return () => [-0.3, 1.3];
    return (u, lo, hi) => {
      const auto = lo == null ? [0, 1] : uPlot.rangeNum(lo, hi, 0.1, true);
      return [y.min ?? auto[0], y.max ?? auto[1]];
    };
  }

  function series(s) {
    const out = {label: s.label, stroke: s.colour, width: 1.5, scale: s.scale || 'y', points: {show: false}};
    if (s.dashed) out.dash = [px(6), px(4)];
    if (s.draw === 'step') out.paths = uPlot.paths.stepped({align: 1});
    if (s.draw === 'bars') {
      out.paths = uPlot.paths.stepped({align: 1});
      out.fill = s.colour + '99';
    }
    if (s.draw === 'points') {
      out.paths = () => null;
      out.points = {show: true, size: 9, width: 1.5, stroke: s.colour, fill: s.colour};
    }
    return out;
  }

  // The marks behind the series: the expected window(s) shaded.
  function drawBands(u, chart, seen) {
    const {ctx, bbox} = u;
    const right = bbox.left + bbox.width;
    ctx.save();
    for (const b of chart.bands || []) {
      const x0 = Math.max(u.valToPos(b.from, 'x', true), bbox.left);
      const x1 = Math.min(u.valToPos(b.to, 'x', true), right);
      if (x1 < x0) continue;
      ctx.fillStyle = b.colour;
      ctx.fillRect(x0, bbox.top, Math.max(x1 - x0, px(1)), bbox.height);
      if (b.cls === 'expected' && x0 >= bbox.left && x1 <= right) seen.expected++;
    }
    // Bands of values (an expected rate), across the plot.
    for (const b of chart.hbands || []) {
      const y0 = Math.max(u.valToPos(b.to, 'y', true), bbox.top);
      const y1 = Math.min(u.valToPos(b.from, 'y', true), bbox.top + bbox.height);
      if (y1 < y0) continue;
      ctx.fillStyle = b.colour;
      ctx.fillRect(bbox.left, y0, bbox.width, Math.max(y1 - y0, px(1)));
      if (b.cls === 'expected' && y0 > bbox.top - px(1) && y1 < bbox.top + bbox.height + px(1)) seen.rate++;
    }
    ctx.restore();
  }

  function text(ctx, s, x, y, colour, bbox) {
    ctx.font = px(10) + 'px sans-serif';
    const w = ctx.measureText(s).width;
    ctx.fillStyle = colour;
    ctx.textAlign = 'left';
    ctx.fillText(s, Math.min(Math.max(x - w / 2, bbox.left + px(2)), bbox.left + bbox.width - w - px(2)), y);
  }

  // The marks' words (limits, expected windows, edges, an expected rate) are drawn in a band
  // reserved above the plot, never inside it: no trace crosses them. Each line's words sit
  // beside it (right, else left), the line drawn on up to them; a window's words centred over
  // it; the words of a band or line across the plot (an expected rate, a trend's limit) at the
  // plot's left or right end. Words that would collide go on another row, placed greedily
  // (measured on the canvas): a row's words neither touch each other nor a line drawn up
  // through the row to words above it.
  const ROW = 13; // CSS px per row of words (10 px text)
  const PAD_TOP = 6; // the plot's top padding with no words
  const bandHeight = rows => (rows ? rows * ROW + 3 : PAD_TOP);
  const FONT = () => px(10) + 'px sans-serif';

  function labelsOf(chart) {
    const out = [];
    if (chart.labels) {
      for (const b of chart.bands || []) if (b.label) out.push({s: b.label, colour: '#1a7f37', from: b.from, to: b.to});
      for (const l of chart.vlines || []) if (l.label) out.push({s: l.label, colour: l.colour, at: l.at, dashed: l.dashed});
      for (const l of chart.hlines || []) if (l.label) out.push({s: l.label, colour: l.colour, end: 'right'});
    }
    for (const b of chart.hbands || []) if (b.label) out.push({s: b.label, colour: '#bf3989', end: 'left'});
    return out;
  }

  // Where each of the words goes (canvas px): {l, a (left), w, row, lead (the x of its line)}.
  function layOut(u, labels) {
    const {ctx, bbox} = u;
    const left = bbox.left + px(2), right = bbox.left + bbox.width - px(2), gap = px(8);
    ctx.save();
    ctx.font = FONT();
    const wants = [];
    for (const l of labels) {
      const w = ctx.measureText(l.s).width;
      const clamp = a => Math.max(Math.min(a, right - w), left);
      let options, lead = null;
      if (l.at != null) {
        const x = u.valToPos(l.at, 'x', true);
        if (x < bbox.left - px(1) || x > bbox.left + bbox.width + px(1)) continue;
        lead = x;
        options = [x + px(4), x - px(4) - w].filter(a => a >= left && a + w <= right);
        if (!options.length) options = [clamp(x + px(4))];
      } else if (l.from != null) {
        const x0 = Math.max(u.valToPos(l.from, 'x', true), bbox.left);
        const x1 = Math.min(u.valToPos(l.to, 'x', true), bbox.left + bbox.width);
        if (x1 < x0) continue;
        options = [clamp((x0 + x1) / 2 - w / 2)];
      } else {
        options = [l.end === 'left' ? left : clamp(right - w)];
      }
      wants.push({l, w, options, lead});
    }
    // Lines' words first, from the right: words beside a line (to its right) then never cover
    // the line of words placed after them; then the rest, clear of every line drawn up.
    wants.sort((p, q) => (p.lead == null) - (q.lead == null) || (q.lead ?? 0) - (p.lead ?? 0) || p.options[0] - q.options[0]);
    const rows = []; // per row: the spans [a, b] of its words
    const leads = []; // {x, row}: a line drawn up to its words in that row
    const overlaps = (a, b, c, d) => a < d + gap && c < b + gap;
    const free = (r, a, b, lead) =>
      !(rows[r] || []).some(([c, d]) => overlaps(a, b, c, d)) &&
      !leads.some(t => t.row >= r && t.x > a - gap / 2 && t.x < b + gap / 2) &&
      (lead == null || !rows.slice(0, r).some(spans => spans.some(([c, d]) => lead > c - gap / 2 && lead < d + gap / 2)));
    const placed = [];
    for (const want of wants) {
      let r = 0, a;
      for (; r < rows.length; r++) {
        a = want.options.find(o => free(r, o, o + want.w, want.lead));
        if (a !== undefined) break;
      }
      // A new row on top always takes the words; its line, if words below would cross it, not.
      if (a === undefined) {
        a = want.options[0];
        if (!free(r, a, a + want.w, want.lead)) want.lead = null;
      }
      (rows[r] = rows[r] || []).push([a, a + want.w]);
      if (want.lead != null) leads.push({x: want.lead, row: r});
      placed.push({...want, a, row: r});
    }
    ctx.restore();
    return {placed, rows: rows.length};
  }

  // The words laid out, drawn in the band above the plot (a line's drawn on up to them); what
  // was drawn where (CSS px on the canvas) returned for the page's tests.
  function drawLabels(u, lay) {
    const {ctx, bbox} = u;
    const drawn = [];
    ctx.save();
    ctx.font = FONT();
    ctx.textAlign = 'left';
    ctx.textBaseline = 'alphabetic';
    for (const p of lay.placed) {
      const base = bbox.top - px(4) - px(ROW) * p.row;
      const top = base - px(9);
      const entry = {text: p.l.s, x: p.a / uPlot.pxRatio, y: top / uPlot.pxRatio, w: p.w / uPlot.pxRatio, h: px(12) / uPlot.pxRatio};
      if (p.lead != null) {
        ctx.strokeStyle = p.l.colour;
        ctx.lineWidth = px(1.5);
        ctx.setLineDash(p.l.dashed ? [px(5), px(4)] : []);
        ctx.beginPath();
        ctx.moveTo(p.lead, bbox.top);
        ctx.lineTo(p.lead, top);
        ctx.stroke();
        entry.leader = [p.lead / uPlot.pxRatio, top / uPlot.pxRatio, bbox.top / uPlot.pxRatio];
      }
      ctx.fillStyle = p.l.colour;
      ctx.fillText(p.l.s, p.a, base);
      drawn.push(entry);
    }
    ctx.restore();
    return drawn;
  }

  // The marks over the series: instants and limits, their words, the probes' numbers.
  function drawMarks(u, chart, seen) {
    const {ctx, bbox} = u;
    const inside = (v, lo, hi) => v >= lo - px(1) && v <= hi + px(1);
    ctx.save();
    ctx.lineWidth = px(1.5);
    for (const l of chart.vlines || []) {
      const x = u.valToPos(l.at, 'x', true);
      if (!inside(x, bbox.left, bbox.left + bbox.width)) continue;
      if (l.cls === 'limit') seen.limits++;
      ctx.strokeStyle = l.colour;
      ctx.setLineDash(l.dashed ? [px(5), px(4)] : []);
      ctx.beginPath();
      ctx.moveTo(x, bbox.top);
      ctx.lineTo(x, bbox.top + bbox.height);
      ctx.stroke();
    }
    for (const l of chart.hlines || []) {
      const y = u.valToPos(l.at, l.scale || 'y', true);
      if (!inside(y, bbox.top, bbox.top + bbox.height)) continue;
      if (l.cls === 'limit') seen.limits++;
      ctx.strokeStyle = l.colour;
      ctx.setLineDash([px(5), px(4)]);
      ctx.beginPath();
      ctx.moveTo(bbox.left, y);
      ctx.lineTo(bbox.left + bbox.width, y);
      ctx.stroke();
    }
    // An expected series (a move's profile over its step rate): its points inside the plot.
    chart.series.forEach((s, i) => {
      if (s.cls !== 'expected') return;
      u.data[0].forEach((xv, j) => {
        const yv = u.data[i + 1][j];
        if (yv == null) return;
        const x = u.valToPos(xv, 'x', true), y = u.valToPos(yv, s.scale || 'y', true);
        if (inside(x, bbox.left, bbox.left + bbox.width) && inside(y, bbox.top, bbox.top + bbox.height)) seen.profile++;
      });
    });
    chart.series.forEach((s, i) => {
      if (!s.numbers) return;
      u.data[0].forEach((xv, j) => {
        const yv = u.data[i + 1][j];
        if (yv == null) return;
        text(ctx, s.numbers[j], u.valToPos(xv, 'x', true), u.valToPos(yv, 'y', true) - px(8), '#57606a', bbox);
      });
    });
    ctx.restore();
  }

  function drawChart(chart, bottom, into) {
    const box = document.createElement('div');
    box.className = 'chart' + (chart.role ? ' lane ' + chart.role : '');
    // An analog lane (a resolver stator): a line through its samples, not steps.
    if (chart.role && chart.series[0].draw === 'line') box.classList.add('analog');
    if (chart.lane) box.dataset.lane = chart.lane;
    if (chart.measurement) box.dataset.measurement = chart.measurement;
    if (chart.lane) {
      const title = document.createElement('p');
      title.className = 'lane-title';
      title.textContent = chart.lane;
      box.appendChild(title);
    }
    into.appendChild(box);
    const seen = {expected: 0, limits: 0, rate: 0, profile: 0};
    const scales = {x: {time: false, range: () => [chart.x.min, chart.x.max]}, y: {range: range(chart.y)}};
    const axes = [xAxis(chart, bottom), yAxis(chart, chart.y, 'y', 3)];
    if (chart.y2) {
      scales.y2 = {range: range(chart.y2)};
      axes.push(yAxis(chart, chart.y2, 'y2', 1));
    }
    // The band for the marks' words: as many rows as their layout takes once the plot's x
    // positions are known (only the plot's top padding and height change, not its x axis).
    const labels = labelsOf(chart);
    const height = chart.height + (bottom ? 60 : 0);
    let rows = 0, lay = {placed: [], rows: 0};
    const opts = {
      width: WIDTH,
      height,
      legend: {show: chart.series.length > 1 && !chart.lane, live: false},
      padding: [() => bandHeight(rows), 24, 0, 0], // left, right fixed: stacked lanes keep one time axis
      cursor: {show: true, drag: {x: false, y: false}},
      scales, axes,
      series: [{}].concat(chart.series.map(series)),
      hooks: {
        drawClear: [u => {
          seen.expected = 0; seen.limits = 0; seen.rate = 0; seen.profile = 0;
          lay = layOut(u, labels);
          if (lay.rows !== rows) {
            rows = lay.rows;
            queueMicrotask(() => u.setSize({width: WIDTH, height: height - PAD_TOP + bandHeight(rows)}));
          }
          drawBands(u, chart, seen);
        }],
        draw: [u => {
          drawMarks(u, chart, seen);
          box.dataset.labels = JSON.stringify(drawLabels(u, lay));
          box.dataset.expected = seen.expected;
          box.dataset.limits = seen.limits;
          box.dataset.rateExpected = seen.rate;
          box.dataset.profile = seen.profile;
        }],
      },
    };
    new uPlot(opts, chart.data, box);
  }

  function drawFigure(fig) {
    const spec = JSON.parse(fig.querySelector('script.figure-data').textContent);
    const plot = fig.querySelector('.plot');
    spec.charts.forEach((chart, i) => drawChart(chart, i === spec.charts.length - 1 || !chart.lane, plot));
    if (spec.notes) {
      const p = document.createElement('p');
      p.className = 'notes';
      p.textContent = spec.notes;
      plot.appendChild(p);
    }
    fig.dataset.drawn = spec.charts.length;
  }

  for (const fig of document.querySelectorAll('figure.evidence')) {
    if (!fig.querySelector('script.figure-data')) continue;
    try {
      drawFigure(fig);
    } catch (e) {
      // The other figures are still drawn; the error still reaches the page (and its tests).
      fig.dataset.error = String(e);
      setTimeout(() => { throw e; });
    }
  }
})();
