// skipnc plot page: draws the model in #plot-data (written by
// src/plot/html.cpp) into canvases. Plain script, no libraries, no network.
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

  var D = JSON.parse(document.getElementById('plot-data').textContent);
  var FONT = 'DejaVu Sans, Verdana, Arial, sans-serif';
  var S = {block: -1, hoverT: null, views: [], tl: null, tip: null};

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
  function decimals(step) { return step < 1 ? Math.ceil(-Math.log10(step)) : 0; }
  function dot(p, u) { return p[0] * u[0] + p[1] * u[1] + p[2] * u[2]; }
  function samplePt(i) { return [D.px[i], D.py[i], D.pz[i]]; }
  function ink(name) { return D.inks[name]; }
  function sourceLine(line) {
    return line > 0 && line <= D.source.length ? D.source[line - 1].trim() : '';
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
  function Placer(clip) { this.clip = clip; this.used = []; }
  Placer.prototype.block = function (b) { this.used.push(b); };
  Placer.prototype.place = function (ax, ay, w, h) {
    var c = this.clip, used = this.used;
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
    for (var i = 0; i < cands.length; i++) {
      var b = clampBox({x: ax + cands[i][0], y: ay + cands[i][1], w: w, h: h});
      if (!used.some(function (u) { return overlaps(u, b); })) {
        used.push(b);
        b.leader = i >= near;
        return b;
      }
    }
    var f = clampBox({x: ax + 8, y: ay - h / 2, w: w, h: h});
    used.push(f);
    return f;
  }

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

  // ---- views --------------------------------------------------------------
  function fitFrame(def, rect) {
    var e = D.extent, u0 = Infinity, u1 = -Infinity, v0 = Infinity, v1 = -Infinity;
    for (var c = 0; c < 8; c++) {
      var p = [c & 1 ? e.hi[0] : e.lo[0], c & 2 ? e.hi[1] : e.lo[1], c & 4 ? e.hi[2] : e.lo[2]];
      var pu = dot(p, def.u), pv = dot(p, def.v);
      u0 = Math.min(u0, pu); u1 = Math.max(u1, pu); v0 = Math.min(v0, pv); v1 = Math.max(v1, pv);
    }
    return frameAround(rect, (u0 + u1) / 2, (v0 + v1) / 2,
                       Math.max((u1 - u0) / Math.max(1, rect.w - 44), (v1 - v0) / Math.max(1, rect.h - 44), 1e-9));
  }
  function frameAround(rect, cu, cv, mmPerPx) {
    return {u0: cu - rect.w * mmPerPx / 2, u1: cu + rect.w * mmPerPx / 2,
            v0: cv - rect.h * mmPerPx / 2, v1: cv + rect.h * mmPerPx / 2};
  }
  function makeView(def) {
    var canvas = el('canvas', {cls: 'view', 'data-view': def.id});
    var vs = {def: def, canvas: canvas, frame: null, rect: null, drag: null};
    canvas.addEventListener('wheel', function (ev) {
      ev.preventDefault();
      var p = viewPoint(vs, ev), f = vs.frame, k = Math.pow(1.2, ev.deltaY / 100);
      var u = px2u(vs, p.x), v = py2v(vs, p.y);
      vs.frame = {u0: u + (f.u0 - u) * k, u1: u + (f.u1 - u) * k, v0: v + (f.v0 - v) * k, v1: v + (f.v1 - v) * k};
      drawView(vs);
    }, {passive: false});
    canvas.addEventListener('mousedown', function (ev) {
      vs.drag = {x: ev.clientX, y: ev.clientY, f: Object.assign({}, vs.frame), moved: false};
    });
    window.addEventListener('mouseup', function () { setTimeout(function () { vs.drag = null; }, 0); });
    canvas.addEventListener('mousemove', function (ev) {
      if (vs.drag && (ev.buttons & 1)) {
        var f = vs.drag.f, sx = (f.u1 - f.u0) / vs.rect.w, sy = (f.v1 - f.v0) / vs.rect.h;
        var dx = (ev.clientX - vs.drag.x) * sx, dy = (ev.clientY - vs.drag.y) * sy;
        if (Math.abs(ev.clientX - vs.drag.x) + Math.abs(ev.clientY - vs.drag.y) > 2) vs.drag.moved = true;
        vs.frame = {u0: f.u0 - dx, u1: f.u1 - dx, v0: f.v0 + dy, v1: f.v1 + dy};
        drawView(vs);
        return;
      }
      hoverView(vs, ev);
    });
    canvas.addEventListener('mouseleave', function () { hideTip(); S.hoverT = null; drawTimeline(); });
    canvas.addEventListener('dblclick', function () { vs.frame = fitFrame(def, vs.rect); drawView(vs); });
    canvas.addEventListener('click', function (ev) {
      if (vs.drag && vs.drag.moved) return;
      var hit = nearest(vs, viewPoint(vs, ev));
      if (hit && hit.t !== undefined) selectBlock(blockAt(hit.t));
    });
    return vs;
  }
  function viewPoint(vs, ev) {
    var b = vs.canvas.getBoundingClientRect();
    return {x: ev.clientX - b.left, y: ev.clientY - b.top};
  }
  function u2px(vs, u) { return vs.rect.x + (u - vs.frame.u0) / (vs.frame.u1 - vs.frame.u0) * vs.rect.w; }
  function v2py(vs, v) { return vs.rect.y + (vs.frame.v1 - v) / (vs.frame.v1 - vs.frame.v0) * vs.rect.h; }
  function px2u(vs, x) { return vs.frame.u0 + (x - vs.rect.x) / vs.rect.w * (vs.frame.u1 - vs.frame.u0); }
  function py2v(vs, y) { return vs.frame.v1 - (y - vs.rect.y) / vs.rect.h * (vs.frame.v1 - vs.frame.v0); }
  function P(vs, p) { return {x: u2px(vs, dot(p, vs.def.u)), y: v2py(vs, dot(p, vs.def.v))}; }

  function drawGrid(ctx, vs) {
    var f = vs.frame, r = vs.rect, def = vs.def;
    ctx.font = '10px ' + FONT;
    ctx.fillStyle = '#666';
    if (def.look < 0) {
      var mmPerPx = (f.u1 - f.u0) / r.w, len = niceStep(mmPerPx * 90, 1), px = len / mmPerPx;
      var x0 = r.x + 12, y0 = r.y + r.h - 14;
      ctx.strokeStyle = '#444'; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x0 + px, y0);
      ctx.moveTo(x0, y0 - 3); ctx.lineTo(x0, y0 + 3); ctx.moveTo(x0 + px, y0 - 3); ctx.lineTo(x0 + px, y0 + 3);
      ctx.stroke();
      ctx.fillText(num(len, len < 1 ? 3 : 0) + ' mm', x0 + px + 6, y0 + 4);
      var cx = r.x + r.w - 44, cy = r.y + r.h - 34;
      ['X', 'Y', 'Z'].forEach(function (n, k) {
        var e = [0, 0, 0]; e[k] = 1;
        var dx = dot(e, def.u) * 24, dy = -dot(e, def.v) * 24;
        ctx.strokeStyle = axisColour(k); ctx.lineWidth = 1.5;
        ctx.beginPath(); ctx.moveTo(cx, cy); ctx.lineTo(cx + dx, cy + dy); ctx.stroke();
        ctx.fillStyle = axisColour(k);
        ctx.fillText(n, cx + dx * 1.3 - 3, cy + dy * 1.3 + 4);
      });
      return;
    }
    var su = niceStep(f.u1 - f.u0, 6), sv = niceStep(f.v1 - f.v0, 5);
    ctx.strokeStyle = '#ececec'; ctx.lineWidth = 1; ctx.setLineDash([]);
    ctx.beginPath();
    var u, v, x, y;
    ctx.textAlign = 'center';
    for (u = Math.ceil(f.u0 / su) * su; u <= f.u1; u += su) {
      x = u2px(vs, u);
      ctx.moveTo(x, r.y); ctx.lineTo(x, r.y + r.h);
      ctx.fillText(num(u, decimals(su)), x, r.y + r.h + 12);
    }
    ctx.textAlign = 'right';
    for (v = Math.ceil(f.v0 / sv) * sv; v <= f.v1; v += sv) {
      y = v2py(vs, v);
      ctx.moveTo(r.x, y); ctx.lineTo(r.x + r.w, y);
      ctx.fillText(num(v, decimals(sv)), r.x - 4, y + 3);
    }
    ctx.stroke();
    ctx.textAlign = 'left';
    ctx.font = 'bold 11px ' + FONT;
    ctx.fillStyle = '#444';
    ctx.fillText(def.uName + ' \u2192  ' + def.vName + ' \u2191  (mm, machine)', r.x - 44, r.y + r.h + 26);
  }
  function axisColour(k) {
    var idx = D.meta.xyz[k], pos = idx >= 0 ? channel('pos_' + D.meta.axes[idx]) : null;
    return pos ? pos.series[0].colour : '#444';
  }

  function drawShapes(ctx, vs, notes, placer) {
    D.shapes.forEach(function (s) {
      if (s.normal >= 0 && s.normal === vs.def.look) {
        if (s.note) notes.push(s.note);
        return;
      }
      var iso = vs.def.look < 0;
      if (iso && !s.inIso) return;
      var st = ink(s.ink);
      var pts = s.pts.map(function (p) { return P(vs, p); });
      ctx.setLineDash([]);
      ctx.beginPath();
      if (s.kind === 'segments') {
        for (var i = 0; i + 1 < pts.length; i += 2) { ctx.moveTo(pts[i].x, pts[i].y); ctx.lineTo(pts[i + 1].x, pts[i + 1].y); }
        ctx.strokeStyle = st.stroke; ctx.lineWidth = 1; ctx.stroke();
      } else {
        pts.forEach(function (p, k) { if (k === 0) ctx.moveTo(p.x, p.y); else ctx.lineTo(p.x, p.y); });
        if (s.kind === 'polygon') {
          ctx.closePath();
          ctx.globalAlpha = iso ? 0.05 : 0.10; ctx.fillStyle = st.fill; ctx.fill();
        }
        ctx.globalAlpha = iso ? 0.6 : 1;
        ctx.strokeStyle = st.stroke; ctx.lineWidth = st.width; ctx.stroke();
        ctx.globalAlpha = 1;
      }
      if (s.label && pts.length) {
        var r = pts[0];
        pts.forEach(function (p) { if (p.x > r.x + 0.5 || (Math.abs(p.x - r.x) <= 0.5 && p.y < r.y)) r = p; });
        ctx.font = '11px ' + FONT;
        var w = ctx.measureText(s.label).width, R = vs.rect;
        var b = placer.place(Math.min(r.x, R.x + R.w - 4), Math.min(Math.max(r.y, R.y + 8), R.y + R.h - 8), w, 13);
        var lx = b.x, ly = b.y + 10.5;
        haloText(ctx, s.label, lx, ly, st.stroke);
      }
    });
  }

  function blockInk(b) {
    return b.kind === 'rapid' ? 'rapid' : b.kind === 'skip' ? 'skip' : 'feed';
  }
  function drawBlock(ctx, vs, b, width, alpha) {
    if (b.kind === 'none' || b.kind === 'dwell') return;
    var st = ink(blockInk(b));
    stroke(ctx, st, width);
    ctx.globalAlpha = alpha;
    ctx.beginPath();
    var p = P(vs, b.from);
    ctx.moveTo(p.x, p.y);
    for (var i = b.s0; i < b.s1 && i < D.t.length; i++) { p = P(vs, samplePt(i)); ctx.lineTo(p.x, p.y); }
    p = P(vs, b.to);
    ctx.lineTo(p.x, p.y);
    ctx.stroke();
    ctx.globalAlpha = 1;
  }

  function drawView(vs) {
    var c = vs.canvas, ctx = vs.ctx, r = vs.rect, def = vs.def;
    ctx.clearRect(0, 0, vs.w, vs.h);
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, vs.w, vs.h);
    ctx.font = 'bold 13px ' + FONT;
    ctx.fillStyle = '#222';
    ctx.textAlign = 'left';
    ctx.fillText(def.title, 8, 17);
    drawGrid(ctx, vs);
    ctx.save();
    ctx.beginPath();
    ctx.rect(r.x, r.y, r.w, r.h);
    ctx.clip();
    var notes = [];
    var placer = new Placer(r);
    D.skips.forEach(function (s) {
      [s.latch, s.rest].forEach(function (q) { var a = P(vs, q); placer.block({x: a.x - 6, y: a.y - 6, w: 12, h: 12}); });
    });
    drawShapes(ctx, vs, notes, placer);
    var dim = S.block >= 0 ? 0.28 : 1;
    ['rapid', 'feed', 'skip'].forEach(function (kind) {
      D.blocks.forEach(function (b) { if (blockInk(b) === kind) drawBlock(ctx, vs, b, null, dim); });
    });
    if (S.block >= 0) drawBlock(ctx, vs, D.blocks[S.block], 4, 1);
    // Programmed skip end points not reached.
    D.skips.forEach(function (s) {
      if (!s.hasTarget || !s.triggered) return;
      var a = P(vs, s.rest), b = P(vs, s.target);
      if (Math.hypot(a.x - b.x, a.y - b.y) < 1) return;
      stroke(ctx, ink('target'));
      ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y);
      ctx.moveTo(b.x - 3, b.y - 3); ctx.lineTo(b.x + 3, b.y + 3); ctx.moveTo(b.x + 3, b.y - 3); ctx.lineTo(b.x - 3, b.y + 3);
      ctx.stroke();
    });
    if (D.t.length) { var s0 = P(vs, samplePt(0)); drawStart(ctx, s0.x, s0.y); }
    D.skips.forEach(function (s) { var b = P(vs, s.rest); drawRest(ctx, b.x, b.y); });
    D.skips.forEach(function (s) { var a = P(vs, s.latch); drawLatch(ctx, a.x, a.y, s.triggered); });
    if (S.hoverT !== null && D.t.length) {
      var h = P(vs, pathAt(S.hoverT));
      ctx.strokeStyle = '#000'; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.beginPath(); ctx.arc(h.x, h.y, 7, 0, 2 * Math.PI);
      ctx.moveTo(h.x - 11, h.y); ctx.lineTo(h.x + 11, h.y); ctx.moveTo(h.x, h.y - 11); ctx.lineTo(h.x, h.y + 11);
      ctx.stroke();
    }
    ctx.font = '11px ' + FONT;
    function label(p, text, colour) {
      var w = ctx.measureText(text).width, b = placer.place(p.x, p.y, w, 13);
      if (b.leader) {
        ctx.strokeStyle = colour; ctx.lineWidth = 0.8; ctx.setLineDash([]);
        ctx.beginPath(); ctx.moveTo(p.x, p.y);
        ctx.lineTo(Math.min(Math.max(p.x, b.x), b.x + b.w), Math.min(Math.max(p.y, b.y), b.y + b.h));
        ctx.stroke();
      }
      haloText(ctx, text, b.x, b.y + 10.5, colour);
    }
    function inside(p) { return p.x >= r.x && p.x <= r.x + r.w && p.y >= r.y && p.y <= r.y + r.h; }
    D.skips.forEach(function (s) { var p = P(vs, s.latch); if (inside(p)) label(p, s.label, '#b0005f'); });
    D.skips.forEach(function (s) { var p = P(vs, s.rest); if (inside(p)) label(p, s.restLabel, '#111'); });
    ctx.restore();
    ctx.strokeStyle = '#c8c8c8'; ctx.lineWidth = 1; ctx.setLineDash([]);
    ctx.strokeRect(0.5, 0.5, vs.w - 1, vs.h - 1);
    ctx.font = '11px ' + FONT;
    ctx.textAlign = 'right';
    ctx.fillStyle = '#2e7d46';
    if (notes.length) {
      // One line in the title row: planes this view looks straight at.
      ctx.font = 'bold 13px ' + FONT;
      var room = vs.w - ctx.measureText(def.title).width - 30;
      ctx.font = '11px ' + FONT;
      var text = 'face-on: ' + notes.join(', ');
      while (text.length > 4 && ctx.measureText(text).width > room) text = text.slice(0, -4) + '...';
      ctx.fillText(text, vs.w - 8, 17);
    }
    ctx.textAlign = 'left';
    var pr = pageRect(c), f = vs.frame;
    c.setAttribute('data-frame', [f.u0, f.u1, f.v0, f.v1, pr.x + r.x, pr.y + r.y, r.w, r.h].join(' '));
  }

  // Actual position at time t (linear between drawn samples).
  function pathAt(t) {
    var i = lowerBound(D.t, t);
    if (i <= 0) return samplePt(0);
    if (i >= D.t.length) return samplePt(D.t.length - 1);
    var t0 = D.t[i - 1], t1 = D.t[i], k = t1 > t0 ? (t - t0) / (t1 - t0) : 0;
    var a = samplePt(i - 1), b = samplePt(i);
    return [a[0] + (b[0] - a[0]) * k, a[1] + (b[1] - a[1]) * k, a[2] + (b[2] - a[2]) * k];
  }

  function nearest(vs, p) {
    var best = null, bd = 9;
    D.skips.forEach(function (s) {
      [['latch', s.latch], ['rest', s.rest]].forEach(function (m) {
        var q = P(vs, m[1]), d = Math.hypot(q.x - p.x, q.y - p.y);
        if (d < bd) { bd = d; best = {marker: m[0], skip: s}; }
      });
    });
    if (best) return best;
    bd = 12;
    for (var i = 0; i < D.t.length; i++) {
      var q = P(vs, samplePt(i)), d = Math.hypot(q.x - p.x, q.y - p.y);
      if (d < bd) { bd = d; best = {i: i, t: D.t[i]}; }
    }
    return best;
  }

  // The skip variables in force at time t: from the last skip that ended before it.
  function varsAt(t) {
    var last = null;
    D.skips.forEach(function (s) { if (s.stopT <= t) last = s; });
    return last;
  }

  function hoverView(vs, ev) {
    var p = viewPoint(vs, ev), hit = nearest(vs, p);
    if (!hit) { hideTip(); if (S.hoverT !== null) { S.hoverT = null; drawTimeline(); } return; }
    var lines = [];
    if (hit.marker) {
      var s = hit.skip;
      lines = skipLines(s, hit.marker);
      S.hoverT = hit.marker === 'latch' ? s.latchT : s.stopT;
    } else {
      lines = sampleLines(hit.i);
      S.hoverT = hit.t;
    }
    showTip(lines, ev.clientX, ev.clientY);
    drawTimeline();
  }

  function skipLines(s, which) {
    var lines = [['b', 'Skip ' + (s.index + 1) + ' \u00b7 line ' + s.line + ': ' + s.block]];
    var axes = allAxes();
    if (which === 'latch') {
      lines.push(['m', s.triggered ? 'latch: ' + s.signal + ' at ' + num(s.latchT, 6) + ' s'
                                   : 'no signal: the block ran to its end point']);
      s.vars.forEach(function (v) { lines.push(['m', v.name + ' = ' + num(v.value)]); });
      lines.push(['', 'work ' + axisText(s.position, axes)]);
      lines.push(['', 'machine ' + axisText(s.latchMachine, axes)]);
    } else {
      lines.push(['', 'rest at ' + num(s.stopT, 6) + ' s, ' + num(s.overtravel) + ' mm past the latch']);
      lines.push(['', 'work ' + axisText(s.endPosition, axes)]);
      lines.push(['', 'machine ' + axisText(s.restMachine, axes)]);
    }
    return lines;
  }

  function sampleLines(i) {
    var t = D.t[i], line = D.line[i], b = D.blocks[blockAt(t)];
    var lines = [['b', 't = ' + num(t, 6) + ' s \u00b7 line ' + line + (sourceLine(line) ? ': ' + sourceLine(line) : '')]];
    lines.push(['', (b ? b.kind : '') + ' \u00b7 machine (actual) ' + D.meta.axes.map(function (a) {
      var c = channel('pos_' + a);
      return c ? a + num(c.series[0].v[i]) : '';
    }).join(' ')]);
    lines.push(['', 'F ' + num(channel('speed').series[0].v[i], 1) + ' mm/min \u00b7 following error ' +
                channelText('following_error', i, 4)]);
    var sig = D.signals.map(function (n) {
      var c = channel('signal_' + n);
      return n + (c && c.series[0].v[i] > 0.5 ? ' on' : ' off');
    });
    if (sig.length) lines.push(['', 'inputs: ' + sig.join(', ')]);
    var s = varsAt(t);
    if (s) {
      lines.push(['m', s.vars.map(function (v) { return v.name + ' = ' + num(v.value); }).join(', ') +
                  ' (from line ' + s.line + ')']);
    }
    return lines;
  }
  function channelText(id, i, d) {
    var c = channel(id);
    if (!c) return '';
    return c.series.map(function (s) { return s.name + num(s.v[i], d); }).join(' ');
  }

  function showTip(lines, x, y) {
    var tip = S.tip;
    tip.textContent = '';
    lines.forEach(function (l) { tip.appendChild(el('div', {cls: l[0] === 'b' ? 'tb' : l[0] === 'm' ? 'tm' : '', text: l[1]})); });
    tip.style.display = 'block';
    var w = tip.offsetWidth, h = tip.offsetHeight;
    var left = x + 16 + w > window.innerWidth ? x - w - 12 : x + 16;
    var top = y + 16 + h > window.innerHeight ? y - h - 12 : y + 16;
    tip.style.left = (left + window.scrollX) + 'px';
    tip.style.top = (top + window.scrollY) + 'px';
  }
  function hideTip() { if (S.tip) S.tip.style.display = 'none'; }

  // ---- timeline -----------------------------------------------------------
  function stripHeight(c) {
    return c.digital ? 26 : c.id.slice(0, 4) === 'pos_' ? 70 : c.id === 'following_error' ? 100 : 80;
  }
  // Linear value of a series at time t.
  function valueAt(v, t) {
    var i = lowerBound(D.t, t);
    if (i <= 0) return v[0];
    if (i >= D.t.length) return v[D.t.length - 1];
    var t0 = D.t[i - 1], t1 = D.t[i];
    return v[i - 1] + (v[i] - v[i - 1]) * (t1 > t0 ? (t - t0) / (t1 - t0) : 0);
  }
  // Range of a channel over [t0, t1] (values at both ends included), with
  // room at the top for the strip's title. A channel that barely moves gets
  // a fixed span, so that noise is not blown up to full height.
  function valueRange(c, t0, t1) {
    var lo = Infinity, hi = -Infinity;
    var i0 = lowerBound(D.t, t0), i1 = lowerBound(D.t, t1);
    c.series.forEach(function (s) {
      if (!D.t.length) return;
      var a = valueAt(s.v, t0), b = valueAt(s.v, t1);
      lo = Math.min(lo, a, b); hi = Math.max(hi, a, b);
      for (var i = i0; i < i1; i++) { lo = Math.min(lo, s.v[i]); hi = Math.max(hi, s.v[i]); }
    });
    if (lo > hi) return [-1, 1];
    var minSpan = c.unit === 'mm' ? (c.id === 'following_error' ? 0.001 : 0.01) : 1;
    if (hi - lo < minSpan) {
      var pad = Math.max(Math.abs(hi) * 0.1, minSpan), mid = (hi + lo) / 2;
      return [mid - pad, mid + pad];
    }
    var p = 0.08 * (hi - lo);
    return [lo - p, hi + 2.5 * p];
  }
  function fullTime() { return [0, Math.max(D.meta.time, D.t.length ? D.t[D.t.length - 1] : 1e-3)]; }

  function makeTimeline() {
    var canvas = el('canvas', {cls: 'timeline', id: 'timeline'});
    var ft = fullTime();
    var tl = {canvas: canvas, t0: ft[0], t1: ft[1], drag: null};
    canvas.addEventListener('wheel', function (ev) {
      ev.preventDefault();
      var x = ev.clientX - canvas.getBoundingClientRect().left, t = x2t(x), k = Math.pow(1.2, ev.deltaY / 100);
      tl.t0 = t + (tl.t0 - t) * k; tl.t1 = t + (tl.t1 - t) * k;
      drawTimeline();
    }, {passive: false});
    canvas.addEventListener('mousedown', function (ev) { tl.drag = {x: ev.clientX, t0: tl.t0, t1: tl.t1}; });
    window.addEventListener('mouseup', function () { tl.drag = null; });
    canvas.addEventListener('mousemove', function (ev) {
      var x = ev.clientX - canvas.getBoundingClientRect().left;
      if (tl.drag && (ev.buttons & 1)) {
        var dt = (ev.clientX - tl.drag.x) / tl.pw * (tl.drag.t1 - tl.drag.t0);
        tl.t0 = tl.drag.t0 - dt; tl.t1 = tl.drag.t1 - dt;
        drawTimeline();
        return;
      }
      if (x < tl.px0 || x > tl.px0 + tl.pw || !D.t.length) { S.hoverT = null; hideTip(); redrawAll(); return; }
      S.hoverT = x2t(x);
      var i = Math.min(Math.max(lowerBound(D.t, S.hoverT), 0), D.t.length - 1);
      showTip(sampleLines(i), ev.clientX, ev.clientY);
      redrawAll();
    });
    canvas.addEventListener('mouseleave', function () { S.hoverT = null; hideTip(); redrawAll(); });
    canvas.addEventListener('dblclick', function () { var f = fullTime(); tl.t0 = f[0]; tl.t1 = f[1]; drawTimeline(); });
    return tl;
  }
  function t2x(t) { var tl = S.tl; return tl.px0 + (t - tl.t0) / (tl.t1 - tl.t0) * tl.pw; }
  function x2t(x) { var tl = S.tl; return tl.t0 + (x - tl.px0) / tl.pw * (tl.t1 - tl.t0); }

  function drawTimeline() {
    var tl = S.tl;
    if (!tl) return;
    var ctx = tl.ctx, w = tl.w;
    ctx.clearRect(0, 0, w, tl.h);
    ctx.fillStyle = '#f7f7f5';
    ctx.fillRect(0, 0, w, tl.h);
    var i0 = Math.max(0, lowerBound(D.t, tl.t0) - 1), i1 = Math.min(D.t.length, lowerBound(D.t, tl.t1) + 1);
    var y = 30, strips = [];
    ctx.font = 'bold 14px ' + FONT; ctx.fillStyle = '#222'; ctx.textAlign = 'left';
    ctx.fillText('Timeline (scope)', 4, 16);
    ctx.font = '11px ' + FONT; ctx.fillStyle = '#666';
    ctx.fillText('wheel: zoom \u00b7 drag: pan \u00b7 double-click: whole run \u00b7 latch instants in magenta, rest instants dashed',
                 150, 16);
    if (S.block >= 0) {
      var b = D.blocks[S.block];
      ctx.fillStyle = 'rgba(240,140,0,0.12)';
      ctx.fillRect(t2x(b.t0), 30, Math.max(1, t2x(b.t1) - t2x(b.t0)), tl.h - 60);
    }
    D.channels.forEach(function (c) {
      var h = stripHeight(c);
      var rg = c.digital ? [-0.15, 1.25] : valueRange(c, tl.t0, tl.t1);
      var Y = function (v) { return y + (rg[1] - v) / (rg[1] - rg[0]) * h; };
      strips.push({id: c.id, y: y, h: h, lo: rg[0], hi: rg[1]});
      ctx.fillStyle = '#ffffff'; ctx.fillRect(tl.px0, y, tl.pw, h);
      ctx.strokeStyle = '#d0d0d0'; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.strokeRect(tl.px0 + 0.5, y + 0.5, tl.pw - 1, h - 1);
      if (!c.digital) {
        var step = niceStep(rg[1] - rg[0], 3);
        ctx.font = '10px ' + FONT; ctx.textAlign = 'right'; ctx.fillStyle = '#666';
        ctx.strokeStyle = '#f0f0f0';
        ctx.beginPath();
        for (var v = Math.ceil(rg[0] / step) * step; v <= rg[1]; v += step) {
          ctx.moveTo(tl.px0, Y(v)); ctx.lineTo(tl.px0 + tl.pw, Y(v));
          ctx.fillText(num(Math.abs(v) < step * 1e-6 ? 0 : v, decimals(step)), tl.px0 - 4, Y(v) + 3);
        }
        ctx.stroke();
      }
      ctx.save();
      ctx.beginPath(); ctx.rect(tl.px0, y, tl.pw, h); ctx.clip();
      c.series.forEach(function (s) {
        ctx.strokeStyle = s.colour; ctx.lineWidth = c.digital ? 1.5 : 1.3; ctx.setLineDash([]);
        ctx.beginPath();
        for (var i = i0; i < i1; i++) {
          var x = t2x(D.t[i]);
          if (c.digital) {
            var yy = Y(s.v[i] > 0.5 ? 1 : 0);
            if (i === i0) ctx.moveTo(x, yy); else { ctx.lineTo(x, Y(s.v[i - 1] > 0.5 ? 1 : 0)); ctx.lineTo(x, yy); }
          } else if (i === i0) ctx.moveTo(x, Y(s.v[i])); else ctx.lineTo(x, Y(s.v[i]));
        }
        if (c.digital && i1 > i0) ctx.lineTo(tl.px0 + tl.pw, Y(s.v[i1 - 1] > 0.5 ? 1 : 0));
        ctx.stroke();
      });
      ctx.restore();
      ctx.font = 'bold 11px ' + FONT; ctx.textAlign = 'left';
      var title = c.title + (c.unit ? ' (' + c.unit + ')' : '');
      haloText(ctx, title, tl.px0 + 6, y + 12, '#333');
      var tx = tl.px0 + 6 + ctx.measureText(title).width + 10;
      if (c.series.length > 1) {
        c.series.forEach(function (s) { haloText(ctx, s.name, tx, y + 12, s.colour); tx += ctx.measureText(s.name).width + 8; });
      }
      y += h + 6;
    });
    var top = 30, bottom = y - 6;
    ctx.save();
    ctx.beginPath(); ctx.rect(tl.px0, 18, tl.pw, bottom - 18); ctx.clip();
    D.skips.forEach(function (s) {
      var xr = t2x(s.stopT), xl = t2x(s.latchT);
      ctx.strokeStyle = '#111'; ctx.lineWidth = 1; ctx.setLineDash([4, 3]);
      ctx.beginPath(); ctx.moveTo(xr, top); ctx.lineTo(xr, bottom); ctx.stroke();
      ctx.strokeStyle = '#e0007a'; ctx.lineWidth = 1.5; ctx.setLineDash([]);
      ctx.beginPath(); ctx.moveTo(xl, top); ctx.lineTo(xl, bottom); ctx.stroke();
      ctx.font = '10px ' + FONT; ctx.fillStyle = '#b0005f'; ctx.textAlign = 'center';
      ctx.fillText('L' + s.line, xl, 27);
    });
    if (S.hoverT !== null) {
      var hx = t2x(S.hoverT);
      ctx.strokeStyle = '#000'; ctx.lineWidth = 1; ctx.setLineDash([2, 2]);
      ctx.beginPath(); ctx.moveTo(hx, top); ctx.lineTo(hx, bottom); ctx.stroke();
    }
    ctx.restore();
    var step = niceStep(tl.t1 - tl.t0, 10);
    ctx.font = '10px ' + FONT; ctx.fillStyle = '#666'; ctx.textAlign = 'center'; ctx.setLineDash([]);
    ctx.strokeStyle = '#666';
    for (var t = Math.ceil(tl.t0 / step) * step; t <= tl.t1 + step * 1e-9; t += step) {
      var x = t2x(t);
      ctx.beginPath(); ctx.moveTo(x, bottom); ctx.lineTo(x, bottom + 4); ctx.stroke();
      ctx.fillText(num(t, decimals(step)), x, bottom + 15);
    }
    ctx.textAlign = 'left'; ctx.fillStyle = '#444'; ctx.font = '11px ' + FONT;
    ctx.fillText('time (s)', 4, bottom + 15);
    var pr = pageRect(tl.canvas);
    tl.canvas.setAttribute('data-frame', [tl.t0, tl.t1, pr.x + tl.px0, tl.pw].join(' '));
    tl.canvas.setAttribute('data-strips', JSON.stringify(strips.map(function (s) {
      return {id: s.id, y: pr.y + s.y, h: s.h, lo: s.lo, hi: s.hi};
    })));
  }
  function timelineHeight() {
    var h = 30;
    D.channels.forEach(function (c) { h += stripHeight(c) + 6; });
    return h + 24;
  }

  // ---- blocks, skips, zoom -----------------------------------------------
  function selectBlock(i) {
    S.block = i;
    var info = document.getElementById('block-info');
    if (i < 0) {
      info.textContent = 'All blocks shown. Step with \u2190 \u2192 or the buttons; click the path to pick a block.';
    } else {
      var b = D.blocks[i], axes = allAxes();
      info.textContent = 'Block ' + (i + 1) + ' of ' + D.blocks.length + ' \u00b7 line ' + b.line +
        (sourceLine(b.line) ? ': ' + sourceLine(b.line) : '') + ' \u00b7 ' + b.kind + ' \u00b7 ' +
        num(b.t0, 3) + '\u2013' + num(b.t1, 3) + ' s \u00b7 ends at ' + axisText(b.end, axes) + ' (machine)';
    }
    document.querySelectorAll('#listing .src').forEach(function (n) {
      var on = i >= 0 && +n.getAttribute('data-line') === D.blocks[i].line;
      n.classList.toggle('current', on);
      if (on && n.scrollIntoView) n.scrollIntoView({block: 'nearest'});
    });
    redrawAll();
  }
  function stepBlock(d) {
    var i = S.block;
    for (var k = 0; k < D.blocks.length; k++) {
      i = i < 0 ? (d > 0 ? 0 : D.blocks.length - 1) : i + d;
      if (i < 0 || i >= D.blocks.length) return;
      if (D.blocks[i].kind !== 'none') { selectBlock(i); return; }
    }
  }
  function zoomSkip(k) {
    var s = D.skips[k];
    if (!s) return;
    S.views.forEach(function (vs) {
      var a = [dot(s.latch, vs.def.u), dot(s.latch, vs.def.v)], b = [dot(s.rest, vs.def.u), dot(s.rest, vs.def.v)];
      var span = Math.max(Math.hypot(a[0] - b[0], a[1] - b[1]) * 6, 0.05);
      var mmPerPx = span / Math.min(vs.rect.w, vs.rect.h);
      vs.frame = frameAround(vs.rect, (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, mmPerPx);
    });
    var w = latchWindow(s);
    S.tl.t0 = w[0]; S.tl.t1 = w[1];
    redrawAll();
  }
  function resetZoom() {
    S.views.forEach(function (vs) { vs.frame = fitFrame(vs.def, vs.rect); });
    var f = fullTime(); S.tl.t0 = f[0]; S.tl.t1 = f[1];
    redrawAll();
  }
  function redrawAll() { S.views.forEach(drawView); drawTimeline(); }

  // ---- page -------------------------------------------------------------
  function legend() {
    var box = el('div', {cls: 'legend'});
    var used = ['rapid', 'feed', 'skip'];
    if (D.skips.some(function (s) { return s.hasTarget && s.triggered; })) used.push('target');
    if (D.skips.length) used.push('latch');
    if (D.skips.some(function (s) { return !s.triggered; })) used.push('miss');
    if (D.skips.length) used.push('rest');
    used.push('start');
    ['trigger', 'stop', 'part'].forEach(function (n) {
      if (D.shapes.some(function (s) { return s.ink === n; })) used.push(n);
    });
    used.forEach(function (name) {
      var c = el('canvas'), ctx = setupCanvas(c, 34, 14), st = ink(name);
      if (name === 'latch' || name === 'miss') drawLatch(ctx, 17, 7, name === 'latch');
      else if (name === 'rest') drawRest(ctx, 17, 7);
      else if (name === 'start') drawStart(ctx, 17, 8);
      else if (name === 'trigger' || name === 'stop' || name === 'part') {
        ctx.globalAlpha = 0.15; ctx.fillStyle = st.fill; ctx.fillRect(2, 3, 30, 8); ctx.globalAlpha = 1;
        ctx.strokeStyle = st.stroke; ctx.lineWidth = 1; ctx.strokeRect(2.5, 3.5, 29, 7);
      } else {
        stroke(ctx, st); ctx.beginPath(); ctx.moveTo(2, 7); ctx.lineTo(32, 7); ctx.stroke();
      }
      box.appendChild(el('div', {cls: 'item'}, [c, el('span', {text: st.legend})]));
    });
    return box;
  }
  function skipCards() {
    var box = el('div', {cls: 'skips'});
    box.appendChild(el('h2', {text: 'Skips (' + D.skips.length + ')'}));
    if (!D.skips.length) box.appendChild(el('p', {cls: 'muted', text: 'No skip block ran.'}));
    D.skips.forEach(function (s) {
      var vars = s.vars.map(function (v) { return v.name + ' = ' + num(v.value); }).join(', ');
      var rest = s.moved.map(function (a) { return D.meta.axes[a] + num(s.endPosition[a]); }).join(' ');
      box.appendChild(el('div', {cls: 'card', 'data-skip': s.index}, [
        el('div', {cls: 'head', text: (s.index + 1) + '. line ' + s.line + ': ' + s.block}),
        el('div', {cls: 'latch', text: s.triggered ? s.signal + ' at ' + num(s.latchT, 6) + ' s: stored ' + vars
                                                   : 'no signal: ran to its end point, stored ' + vars}),
        el('div', {text: 'rest ' + rest + ' (work) at ' + num(s.stopT, 4) + ' s, ' + num(s.overtravel) + ' mm past the latch'}),
        el('button', {text: 'zoom on this latch', onclick: function () { zoomSkip(s.index); }})
      ]));
    });
    return box;
  }
  function variables() {
    var box = el('div', {cls: 'vars'});
    if (D.variables.length) {
      box.appendChild(el('h2', {text: 'Variables at the end'}));
      D.variables.forEach(function (v) {
        box.appendChild(el('div', {text: '#' + v[0] + ' = ' + (v[1] === null ? '<vacant>' : num(v[1]))}));
      });
    }
    if (D.messages.length) {
      box.appendChild(el('h2', {text: 'Messages'}));
      D.messages.forEach(function (m) { box.appendChild(el('div', {text: m})); });
    }
    return box;
  }
  function listing() {
    var box = el('div', {id: 'listing'});
    if (!D.source.length) return box;
    var ran = {};
    D.blocks.forEach(function (b) { ran[b.line] = true; });
    D.skips.forEach(function (s) { ran[s.line] = 'skip'; });
    D.source.forEach(function (text, k) {
      var line = k + 1;
      var row = el('div', {cls: 'src' + (ran[line] ? ' ran' : '') + (ran[line] === 'skip' ? ' skipline' : ''), 'data-line': line,
                           onclick: function () {
                             for (var i = 0; i < D.blocks.length; i++) if (D.blocks[i].line === line) { selectBlock(i); return; }
                           }},
                   [el('span', {cls: 'no', text: String(line)}), el('span', {text: text})]);
      box.appendChild(row);
    });
    return box;
  }

  function layout() {
    var grid = document.getElementById('views');
    var gw = grid.clientWidth;
    var cols = D.views.length > 1 && gw > 700 ? 2 : 1;
    var cw = Math.floor((gw - (cols - 1) * 12) / cols), ch = Math.round(cw * 0.74);
    S.views.forEach(function (vs) {
      vs.w = cw; vs.h = ch;
      vs.ctx = setupCanvas(vs.canvas, cw, ch);
      var iso = vs.def.look < 0;
      var rect = {x: iso ? 8 : 52, y: 26, w: cw - (iso ? 8 : 52) - 10, h: ch - 26 - (iso ? 8 : 30)};
      if (vs.rect && vs.frame) {
        // Keep the scale and centre across a resize.
        var mmPerPx = (vs.frame.u1 - vs.frame.u0) / vs.rect.w;
        vs.frame = frameAround(rect, (vs.frame.u0 + vs.frame.u1) / 2, (vs.frame.v0 + vs.frame.v1) / 2, mmPerPx);
      }
      vs.rect = rect;
      if (!vs.frame) vs.frame = fitFrame(vs.def, rect);
    });
    var tl = S.tl, tw = document.getElementById('scope').clientWidth;
    tl.w = tw; tl.h = timelineHeight();
    tl.ctx = setupCanvas(tl.canvas, tw, tl.h);
    tl.px0 = 74; tl.pw = tw - 74 - 8;
    redrawAll();
  }

  function build() {
    var m = D.meta;
    var header = el('header', {}, [
      el('h1', {text: 'skipnc plot: ' + m.program}),
      el('div', {cls: 'meta', text: 'machine ' + m.machine + ' \u00b7 dialect ' + m.dialect + ' \u00b7 ' + m.status +
                 ' after ' + num(m.time, 3) + ' s of machine time \u00b7 ' + D.skips.length + ' skip' +
                 (D.skips.length === 1 ? '' : 's') + ' \u00b7 ' + m.periods + ' servo periods, ' + D.t.length + ' drawn'}),
      m.alarm ? el('div', {cls: 'alarm', text: 'ALARM ' + m.alarm}) : null
    ]);
    var toolbar = el('div', {cls: 'toolbar'}, [
      el('button', {text: '\u25c0 previous block', onclick: function () { stepBlock(-1); }}),
      el('button', {text: 'next block \u25b6', onclick: function () { stepBlock(1); }}),
      el('button', {text: 'all blocks', onclick: function () { selectBlock(-1); }}),
      el('button', {text: 'reset zoom', onclick: resetZoom}),
      el('span', {id: 'block-info'})
    ]);
    var grid = el('div', {id: 'views'});
    S.views = D.views.map(makeView);
    S.views.forEach(function (vs) { grid.appendChild(vs.canvas); });
    var aside = el('aside', {}, [el('h2', {text: 'Legend'}), legend(), skipCards(), variables(),
                                 D.source.length ? el('h2', {text: 'Program'}) : null, listing()]);
    S.tl = makeTimeline();
    var scope = el('div', {id: 'scope'}, [S.tl.canvas]);
    S.tip = el('div', {id: 'tip'});
    var app = document.getElementById('app');
    app.appendChild(header);
    app.appendChild(toolbar);
    app.appendChild(el('div', {cls: 'main'}, [grid, aside]));
    app.appendChild(scope);
    document.body.appendChild(S.tip);
    document.addEventListener('keydown', function (ev) {
      if (ev.key === 'ArrowRight') { stepBlock(1); ev.preventDefault(); }
      else if (ev.key === 'ArrowLeft') { stepBlock(-1); ev.preventDefault(); }
      else if (ev.key === 'Escape') selectBlock(-1);
    });
    var resizeTimer = null;
    window.addEventListener('resize', function () {
      clearTimeout(resizeTimer);
      resizeTimer = setTimeout(layout, 100);
    });
    layout();
    selectBlock(-1);
    applyHash();
    window.addEventListener('hashchange', applyHash);
  }
  function applyHash() {
    var h = window.location.hash.replace(/^#/, '');
    h.split('&').forEach(function (kv) {
      var p = kv.split('='), n = parseInt(p[1], 10);
      if (p[0] === 'zoom' && n >= 1) zoomSkip(n - 1);
      if (p[0] === 'step' && n >= 1 && n <= D.blocks.length) selectBlock(n - 1);
    });
  }

  window.addEventListener('error', function () {
    var b = document.body;
    b.setAttribute('data-errors', String((+b.getAttribute('data-errors') || 0) + 1));
  });
  build();
  document.body.setAttribute('data-ready', '1');
})();
