// Draws report.html's figures with uPlot (embedded before this file): each
// <figure class="evidence"> holds its data as JSON (rig/results/figure_data.hpp) in a
// <script type="application/json" class="figure-data">; every chart of it becomes one uPlot.
// After drawing, each chart's box says which marks landed on its canvas (data-expected,
// data-limits), so a test reads what the reader sees.
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
      if (chart.labels && b.label) text(ctx, b.label, (x0 + x1) / 2, bbox.top + px(10), '#1a7f37', bbox);
    }
    // Bands of values (an expected rate), across the plot; their words at their left.
    for (const b of chart.hbands || []) {
      const y0 = Math.max(u.valToPos(b.to, 'y', true), bbox.top);
      const y1 = Math.min(u.valToPos(b.from, 'y', true), bbox.top + bbox.height);
      if (y1 < y0) continue;
      ctx.fillStyle = b.colour;
      ctx.fillRect(bbox.left, y0, bbox.width, Math.max(y1 - y0, px(1)));
      if (b.cls === 'expected' && y0 > bbox.top - px(1) && y1 < bbox.top + bbox.height + px(1)) seen.rate++;
      if (b.label) {
        ctx.font = px(10) + 'px sans-serif';
        ctx.fillStyle = '#bf3989';
        ctx.fillText(b.label, bbox.left + px(4), Math.max(y0 - px(3), bbox.top + px(10)));
      }
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

  // A mark's words beside its line (to its right, or its left near the plot's right edge).
  function beside(ctx, s, x, y, colour, bbox) {
    ctx.font = px(10) + 'px sans-serif';
    const w = ctx.measureText(s).width;
    text(ctx, s, x + px(4) + w > bbox.left + bbox.width ? x - px(4) - w / 2 : x + px(4) + w / 2, y, colour, bbox);
  }

  // The marks over the series: instants and limits, their words, the probes' numbers.
  function drawMarks(u, chart, seen) {
    const {ctx, bbox} = u;
    const inside = (v, lo, hi) => v >= lo - px(1) && v <= hi + px(1);
    ctx.save();
    ctx.lineWidth = px(1.5);
    let row = 0;
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
      if (chart.labels && l.label) beside(ctx, l.label, x, bbox.top + px(22 + 11 * row++), l.colour, bbox);
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
      if (chart.labels && l.label) text(ctx, l.label, bbox.left + bbox.width, y - px(3), l.colour, bbox);
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
    const opts = {
      width: WIDTH,
      height: chart.height + (bottom ? 60 : 0),
      legend: {show: chart.series.length > 1 && !chart.lane, live: false},
      padding: [6, 24, 0, 0], // fixed: stacked lanes keep one time axis
      cursor: {show: true, drag: {x: false, y: false}},
      scales, axes,
      series: [{}].concat(chart.series.map(series)),
      hooks: {
        drawClear: [u => { seen.expected = 0; seen.limits = 0; seen.rate = 0; seen.profile = 0; drawBands(u, chart, seen); }],
        draw: [u => {
          drawMarks(u, chart, seen);
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
