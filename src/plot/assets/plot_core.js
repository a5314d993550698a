// skipnc plot page, part 1 of 4: data, helpers, markers. The page's script
// is src/plot/assets/plot_*.js inlined in this order (core, views, scope,
// page); each part adds its functions to window.SkipncPlot.
//
// The page draws the model in #plot-data (written by src/plot/html.cpp)
// into canvases. Plain script, no libraries, no network.
//
// Views: wheel zooms, drag pans, double-click resets, hover reads a point,
// click selects its block. Timeline: the same along time. Keys: left/right
// step block by block, Escape shows all blocks again.
// URL hash: #zoom=N zooms on skip N's latch, #step=N selects block N
// (both 1-based).
// After each drawing, every view canvas carries data-frame="u0 u1 v0 v1 x y w h":
// its world window (mm) and the page rectangle (CSS px) it is drawn in.
(function () {
  'use strict';

  var K = window.SkipncPlot = {};
  var D = K.D = JSON.parse(document.getElementById('plot-data').textContent);
  var FONT = K.FONT = 'DejaVu Sans, Verdana, Arial, sans-serif';
  var S = K.S = {block: -1, hoverT: null, views: [], tl: null, tip: null};

  // ---- helpers ------------------------------------------------------------
  function el(tag, attrs, kids) {
    var e = document.createElement(tag);
    if (attrs) {
      Object.keys(attrs).forEach(function (k) {
        if (k === 'text') e.textContent = attrs[k];
        else if (k === 'cls') e.className = attrs[k];
        else if (k.slice(0, 2) === 'on') e.addEventListener(k.slice(2), attrs[k]);
        else e.setAttribute(k, attrs[k]);
      });
    }
    (kids || []).forEach(function (c) { if (c) e.appendChild(c); });
    return e;
  }
  function num(v, d) {
    if (d === undefined) d = 4;
    var s = Number(v).toFixed(d);
    return /^-0(\.0*)?$/.test(s) ? s.slice(1) : s;
  }
  function niceStep(span, target) {
    if (!(span > 0) || !isFinite(span)) return 1;
    var raw = span / Math.max(1, target);
    var p = Math.pow(10, Math.floor(Math.log10(raw)));
    var m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }
  // The next larger round step: 1 -> 2 -> 5 -> 10 (x 10^n).
  function nextNiceStep(step) {
    if (!(step > 0) || !isFinite(step)) return 1;
    var p = Math.pow(10, Math.floor(Math.log10(step) + 1e-9)), m = step / p;
    return (m < 1.5 ? 2 : m < 3.5 ? 5 : 10) * p;
  }
  function decimals(step) { return step < 1 ? Math.ceil(-Math.log10(step)) : 0; }
  function dot(p, u) { return p[0] * u[0] + p[1] * u[1] + p[2] * u[2]; }
  function samplePt(i) { return [D.px[i], D.py[i], D.pz[i]]; }
  function ink(name) { return D.inks[name]; }
  // A block is (ctx, line): its call context names the file the line is in.
  function fileOf(ctx) { var c = D.contexts[ctx]; return c ? c.file : 0; }
  function sourceLine(ctx, line) {
    var src = (D.files[fileOf(ctx)] || {source: []}).source;
    return line > 0 && line <= src.length ? src[line - 1].trim() : '';
  }
  // "line 12" in the main program, "O9810.nc:12 (O9810) called from ..." in a call.
  function place(ctx, line) {
    var c = D.contexts[ctx];
    if (!ctx || !c) return 'line ' + line;
    var name = D.files[c.file].name;
    return name + ':' + line + c.where.slice(name.length);
  }
  // "L12" in the main program's file, "O9810.nc:12" in another.
  function placeShort(ctx, line) {
    var f = fileOf(ctx);
    return f === 0 ? 'L' + line : D.files[f].name + ':' + line;
  }
  function axisText(vals, axes) {
    var out = [];
    axes.forEach(function (a) { out.push(D.meta.axes[a] + num(vals[a])); });
    return out.join(' ');
  }
  function allAxes() { return D.meta.axes.map(function (_, i) { return i; }); }
  function lowerBound(arr, x) {
    var lo = 0, hi = arr.length;
    while (lo < hi) { var mid = (lo + hi) >> 1; if (arr[mid] < x) lo = mid + 1; else hi = mid; }
    return lo;
  }
  function blockAt(t) {
    for (var i = 0; i < D.blocks.length; i++) {
      var b = D.blocks[i];
      var next = i + 1 < D.blocks.length ? D.blocks[i + 1].t0 : Infinity;
      if (t >= b.t0 && t < next) return i;
    }
    return D.blocks.length - 1;
  }
  function channel(id) {
    for (var i = 0; i < D.channels.length; i++) if (D.channels[i].id === id) return D.channels[i];
    return null;
  }
  function latchWindow(s) {
    var d = Math.max(s.stopT - s.latchT, 0.004);
    return [s.latchT - Math.max(0.25 * d, 0.004), s.stopT + 0.1 * d];
  }
  function setupCanvas(c, w, h) {
    var r = window.devicePixelRatio || 1;
    c.style.width = w + 'px';
    c.style.height = h + 'px';
    c.width = Math.round(w * r);
    c.height = Math.round(h * r);
    var ctx = c.getContext('2d');
    ctx.setTransform(r, 0, 0, r, 0, 0);
    return ctx;
  }
  function pageRect(c) {
    var b = c.getBoundingClientRect();
    return {x: b.left + window.scrollX, y: b.top + window.scrollY};
  }
  function stroke(ctx, st, width) {
    ctx.strokeStyle = st.stroke;
    ctx.lineWidth = width || st.width;
    ctx.setLineDash(st.dash);
  }

  // Greedy label placement: beside the anchor, then on rings with a leader.
  // Greedy label placement: beside the anchor, then on rings with a leader
  // line; a place that covers no other label and no drawn line wins, then one
  // that covers no label. Lines are kept in a grid of 6 px cells.
  var CELL = 6;
  function Placer(clip) {
    this.clip = clip;
    this.used = [];
    this.cols = Math.max(1, Math.ceil(clip.w / CELL));
    this.rows = Math.max(1, Math.ceil(clip.h / CELL));
    this.grid = new Uint8Array(this.cols * this.rows);
  }
  Placer.prototype.block = function (b) { this.used.push(b); };
  Placer.prototype.mark = function (x, y) {
    var cx = Math.floor((x - this.clip.x) / CELL), cy = Math.floor((y - this.clip.y) / CELL);
    if (cx >= 0 && cy >= 0 && cx < this.cols && cy < this.rows) this.grid[cy * this.cols + cx] = 1;
  };
  Placer.prototype.line = function (a, b) {
    var n = Math.min(2000, Math.ceil(Math.hypot(b.x - a.x, b.y - a.y) / (CELL / 2)));
    for (var i = 0; i <= n; i++) {
      var f = n ? i / n : 0;
      this.mark(a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f);
    }
  };
  Placer.prototype.onLine = function (b) {
    var x0 = Math.max(0, Math.floor((b.x - this.clip.x) / CELL)), x1 = Math.min(this.cols - 1, Math.floor((b.x + b.w - this.clip.x) / CELL));
    var y0 = Math.max(0, Math.floor((b.y - this.clip.y) / CELL)), y1 = Math.min(this.rows - 1, Math.floor((b.y + b.h - this.clip.y) / CELL));
    for (var y = y0; y <= y1; y++) for (var x = x0; x <= x1; x++) if (this.grid[y * this.cols + x]) return true;
    return false;
  };
  Placer.prototype.place = function (ax, ay, w, h) {
    var c = this.clip, used = this.used, self = this;
    var cands = [[8, -h / 2], [-8 - w, -h / 2], [6, -6 - h], [6, 6], [-6 - w, -6 - h], [-6 - w, 6]];
    var near = cands.length;
    [26, 42, 58, 76, 96].forEach(function (r) {
      for (var k = 0; k < 12; k++) {
        var a = k * Math.PI / 6, dx = r * Math.cos(a), dy = -r * Math.sin(a);
        cands.push([dx + (Math.cos(a) >= 0 ? 0 : -w), dy - h / 2]);
      }
    });
    function clampBox(b) {
      b.x = Math.min(Math.max(b.x, c.x + 2), Math.max(c.x + 2, c.x + c.w - b.w - 2));
      b.y = Math.min(Math.max(b.y, c.y + 2), Math.max(c.y + 2, c.y + c.h - b.h - 2));
      return b;
    }
    function overlaps(a, b) { return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h; }
    for (var pass = 0; pass < 2; pass++) {
      for (var i = 0; i < cands.length; i++) {
        var b = clampBox({x: ax + cands[i][0], y: ay + cands[i][1], w: w, h: h});
        if (used.some(function (u) { return overlaps(u, b); })) continue;
        if (pass === 0 && self.onLine(b)) continue;
        used.push(b);
        b.leader = i >= near;
        return b;
      }
    }
    // The free place of the view nearest to the anchor (as view.cpp); none:
    // no label (labels never stack).
    var best = null, bestD = 0, step = Math.max(4, h / 2);
    for (var y = c.y + 2; y + h <= c.y + c.h - 2; y += step) {
      for (var x = c.x + 2; x + w <= c.x + c.w - 2; x += step) {
        var q = {x: x, y: y, w: w, h: h};
        if (used.some(function (u) { return overlaps(u, q); })) continue;
        var d = Math.hypot(x + w / 2 - ax, y + h / 2 - ay);
        if (!best || d < bestD) { best = q; bestD = d; }
      }
    }
    if (!best) return null;
    best.leader = true;
    used.push(best);
    return best;
  };

  function haloText(ctx, text, x, y, colour) {
    ctx.lineWidth = 3;
    ctx.strokeStyle = 'rgba(255,255,255,0.85)';
    ctx.setLineDash([]);
    ctx.strokeText(text, x, y);
    ctx.fillStyle = colour;
    ctx.fillText(text, x, y);
  }

  // ---- markers ----------------------------------------------------------
  function drawLatch(ctx, x, y, triggered) {
    var st = ink(triggered ? 'latch' : 'miss');
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.arc(x, y, 6.5, 0, 2 * Math.PI);
    ctx.fillStyle = '#ffffff';
    ctx.fill();
    ctx.beginPath();
    ctx.arc(x, y, 5, 0, 2 * Math.PI);
    ctx.fillStyle = st.fill;
    ctx.fill();
    ctx.lineWidth = st.width;
    ctx.strokeStyle = st.stroke;
    ctx.stroke();
  }
  function drawRest(ctx, x, y) {
    var st = ink('rest');
    ctx.setLineDash([]);
    ctx.fillStyle = st.fill;
    ctx.fillRect(x - 4, y - 4, 8, 8);
    ctx.lineWidth = st.width;
    ctx.strokeStyle = st.stroke;
    ctx.strokeRect(x - 4, y - 4, 8, 8);
  }
  // A crash, collision or protection alarm: a red cross in a circle.
  function drawAlarm(ctx, x, y) {
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.arc(x, y, 7, 0, 2 * Math.PI);
    ctx.fillStyle = '#ffffff';
    ctx.fill();
    ctx.lineWidth = 2;
    ctx.strokeStyle = '#c00000';
    ctx.stroke();
    ctx.beginPath();
    ctx.moveTo(x - 4, y - 4); ctx.lineTo(x + 4, y + 4);
    ctx.moveTo(x + 4, y - 4); ctx.lineTo(x - 4, y + 4);
    ctx.stroke();
  }
  function drawStart(ctx, x, y) {
    var st = ink('start');
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(x, y - 6);
    ctx.lineTo(x + 6, y + 4);
    ctx.lineTo(x - 6, y + 4);
    ctx.closePath();
    ctx.fillStyle = st.fill;
    ctx.fill();
    ctx.lineWidth = st.width;
    ctx.strokeStyle = st.stroke;
    ctx.stroke();
  }

  K.el = el;
  K.num = num;
  K.niceStep = niceStep;
  K.nextNiceStep = nextNiceStep;
  K.decimals = decimals;
  K.dot = dot;
  K.samplePt = samplePt;
  K.ink = ink;
  K.sourceLine = sourceLine;
  K.fileOf = fileOf;
  K.place = place;
  K.placeShort = placeShort;
  K.axisText = axisText;
  K.allAxes = allAxes;
  K.lowerBound = lowerBound;
  K.blockAt = blockAt;
  K.channel = channel;
  K.latchWindow = latchWindow;
  K.setupCanvas = setupCanvas;
  K.pageRect = pageRect;
  K.stroke = stroke;
  K.Placer = Placer;
  K.haloText = haloText;
  K.drawLatch = drawLatch;
  K.drawRest = drawRest;
  K.drawStart = drawStart;
  K.drawAlarm = drawAlarm;
})();
