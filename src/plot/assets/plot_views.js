// skipnc plot page, part 2 of 4: the XY/XZ/YZ/isometric views (zoom, pan,
// hover, pick a block).
(function (K) {
  'use strict';

  var D = K.D, S = K.S, FONT = K.FONT;

  // ---- views --------------------------------------------------------------
  // Fits a view to where the run worked (D.extent), or with `all` to the
  // whole path and scene (D.fullExtent).
  function fitFrame(def, rect, all) {
    var e = all ? D.fullExtent : D.extent, u0 = Infinity, u1 = -Infinity, v0 = Infinity, v1 = -Infinity;
    for (var c = 0; c < 8; c++) {
      var p = [c & 1 ? e.hi[0] : e.lo[0], c & 2 ? e.hi[1] : e.lo[1], c & 4 ? e.hi[2] : e.lo[2]];
      var pu = K.dot(p, def.u), pv = K.dot(p, def.v);
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
    var canvas = K.el('canvas', {cls: 'view', 'data-view': def.id});
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
    canvas.addEventListener('mouseleave', function () { hideTip(); S.hoverT = null; K.drawTimeline(); });
    canvas.addEventListener('dblclick', function () { vs.frame = fitFrame(def, vs.rect); drawView(vs); });
    canvas.addEventListener('click', function (ev) {
      if (vs.drag && vs.drag.moved) return;
      var hit = nearest(vs, viewPoint(vs, ev));
      if (hit && hit.t !== undefined) K.selectBlock(K.blockAt(hit.t));
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
  function P(vs, p) { return {x: u2px(vs, K.dot(p, vs.def.u)), y: v2py(vs, K.dot(p, vs.def.v))}; }

  function drawGrid(ctx, vs) {
    var f = vs.frame, r = vs.rect, def = vs.def;
    ctx.font = '10px ' + FONT;
    ctx.fillStyle = '#666';
    if (def.look < 0) {
      var mmPerPx = (f.u1 - f.u0) / r.w, len = K.niceStep(mmPerPx * 90, 1), px = len / mmPerPx;
      var x0 = r.x + 12, y0 = r.y + r.h - 14;
      ctx.strokeStyle = '#444'; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x0 + px, y0);
      ctx.moveTo(x0, y0 - 3); ctx.lineTo(x0, y0 + 3); ctx.moveTo(x0 + px, y0 - 3); ctx.lineTo(x0 + px, y0 + 3);
      ctx.stroke();
      ctx.fillText(K.num(len, len < 1 ? 3 : 0) + ' mm', x0 + px + 6, y0 + 4);
      var cx = r.x + r.w - 44, cy = r.y + r.h - 34;
      ['X', 'Y', 'Z'].forEach(function (n, k) {
        var e = [0, 0, 0]; e[k] = 1;
        var dx = K.dot(e, def.u) * 24, dy = -K.dot(e, def.v) * 24;
        ctx.strokeStyle = axisColour(k); ctx.lineWidth = 1.5;
        ctx.beginPath(); ctx.moveTo(cx, cy); ctx.lineTo(cx + dx, cy + dy); ctx.stroke();
        ctx.fillStyle = axisColour(k);
        ctx.fillText(n, cx + dx * 1.3 - 3, cy + dy * 1.3 + 4);
      });
      return;
    }
    var vk = def.vScale || 1;
    var su = K.niceStep(f.u1 - f.u0, 6), sv = K.niceStep((f.v1 - f.v0) * vk, 5) / vk;
    ctx.strokeStyle = '#ececec'; ctx.lineWidth = 1; ctx.setLineDash([]);
    ctx.beginPath();
    var u, v, x, y;
    ctx.textAlign = 'center';
    for (u = Math.ceil(f.u0 / su) * su; u <= f.u1; u += su) {
      x = u2px(vs, u);
      ctx.moveTo(x, r.y); ctx.lineTo(x, r.y + r.h);
      ctx.fillText(K.num(u, K.decimals(su)), x, r.y + r.h + 12);
    }
    ctx.textAlign = 'right';
    for (v = Math.ceil(f.v0 / sv) * sv; v <= f.v1; v += sv) {
      y = v2py(vs, v);
      ctx.moveTo(r.x, y); ctx.lineTo(r.x + r.w, y);
      ctx.fillText(K.num(v * vk, K.decimals(sv * vk)), r.x - 4, y + 3);
    }
    ctx.stroke();
    ctx.textAlign = 'left';
    ctx.font = 'bold 11px ' + FONT;
    ctx.fillStyle = '#444';
    ctx.fillText(def.uName + ' \u2192  ' + def.vName + ' \u2191  (mm, machine' + (def.note ? ', ' + def.note : '') +
                 '; labels in work coordinates)', r.x - 44, r.y + r.h + 26);
  }
  function axisColour(k) {
    var idx = D.meta.xyz[k], pos = idx >= 0 ? K.channel('pos_' + D.meta.axes[idx]) : null;
    return pos ? pos.series[0].colour : '#444';
  }

  // The part of segment a-b inside rectangle R (Liang-Barsky), or null.
  function clipSegment(a, b, R) {
    var t0 = 0, t1 = 1, dx = b.x - a.x, dy = b.y - a.y;
    var p = [-dx, dx, -dy, dy], q = [a.x - R.x, R.x + R.w - a.x, a.y - R.y, R.y + R.h - a.y];
    for (var i = 0; i < 4; i++) {
      if (p[i] === 0) { if (q[i] < 0) return null; continue; }
      var t = q[i] / p[i];
      if (p[i] < 0) t0 = Math.max(t0, t); else t1 = Math.min(t1, t);
      if (t0 > t1) return null;
    }
    return [{x: a.x + t0 * dx, y: a.y + t0 * dy}, {x: a.x + t1 * dx, y: a.y + t1 * dy}];
  }

  function drawShapes(ctx, vs, notes, placer, labels) {
    D.shapes.forEach(function (s) {
      if (s.normal >= 0 && s.normal === vs.def.look) {
        if (s.note) notes.push(s.note);
        return;
      }
      var iso = vs.def.look < 0;
      if (iso ? !s.inIso : s.onlyIso) return;
      var st = K.ink(s.ink);
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
          if (st.fill !== 'none') { ctx.globalAlpha = iso ? 0.05 : 0.10; ctx.fillStyle = st.fill; ctx.fill(); }
        }
        ctx.globalAlpha = iso ? 0.6 : 1;
        ctx.strokeStyle = st.stroke; ctx.lineWidth = st.width; ctx.setLineDash(st.dash); ctx.stroke();
        ctx.setLineDash([]);
        ctx.globalAlpha = 1;
      }
      if (s.label && pts.length) {
        // Beside the right-most visible point of the outline (the top one of
        // equals); a shape wholly outside the view gets no label.
        var R = vs.rect, r = null;
        var n = s.kind === 'polygon' ? pts.length : pts.length - 1;
        for (var e = 0; e < n; e++) {
          var seg = clipSegment(pts[e], pts[(e + 1) % pts.length], R);
          if (!seg) continue;
          seg.forEach(function (p) {
            if (!r || p.x > r.x + 0.5 || (Math.abs(p.x - r.x) <= 0.5 && p.y < r.y)) r = p;
          });
        }
      }
      if (s.label && r) {
        labels.push({p: {x: Math.min(r.x, R.x + R.w - 4), y: Math.min(Math.max(r.y, R.y + 8), R.y + R.h - 8)},
                     text: s.label, colour: st.stroke});
      }
      if (s.kind === 'segments') {
        for (var k = 0; k + 1 < pts.length; k += 2) placer.line(pts[k], pts[k + 1]);
      } else {
        for (var j = 1; j < pts.length; j++) placer.line(pts[j - 1], pts[j]);
        if (s.kind === 'polygon' && pts.length > 2) placer.line(pts[pts.length - 1], pts[0]);
      }
    });
  }

  function blockInk(b) {
    return b.kind === 'rapid' ? 'rapid' : b.kind === 'skip' ? 'skip' : 'feed';
  }
  function drawBlock(ctx, vs, b, width, alpha, placer) {
    if (b.kind === 'none' || b.kind === 'dwell') return;
    var st = K.ink(blockInk(b));
    K.stroke(ctx, st, width);
    ctx.globalAlpha = alpha;
    ctx.beginPath();
    var p = P(vs, b.from), q;
    ctx.moveTo(p.x, p.y);
    for (var i = b.s0; i <= b.s1 && i <= D.t.length; i++) {
      q = P(vs, i < b.s1 && i < D.t.length ? K.samplePt(i) : b.to);
      ctx.lineTo(q.x, q.y);
      if (placer) placer.line(p, q);
      p = q;
    }
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
    var notes = [], shapeLabels = [];
    var placer = new K.Placer(r);
    D.skips.forEach(function (s) {
      [s.latch, s.rest].forEach(function (q) { var a = P(vs, q); placer.block({x: a.x - 6, y: a.y - 6, w: 12, h: 12}); });
    });
    if (D.meta.alarmAt) { var am = P(vs, D.meta.alarmAt); placer.block({x: am.x - 8, y: am.y - 8, w: 16, h: 16}); }
    drawShapes(ctx, vs, notes, placer, shapeLabels);
    var dim = S.block >= 0 ? 0.28 : 1;
    ['rapid', 'feed', 'skip'].forEach(function (kind) {
      D.blocks.forEach(function (b) { if (blockInk(b) === kind) drawBlock(ctx, vs, b, null, dim, placer); });
    });
    if (S.block >= 0) drawBlock(ctx, vs, D.blocks[S.block], 4, 1, null);
    // Programmed skip end points not reached.
    D.skips.forEach(function (s) {
      if (!s.hasTarget || !s.triggered) return;
      var a = P(vs, s.rest), b = P(vs, s.target);
      if (Math.hypot(a.x - b.x, a.y - b.y) < 1) return;
      K.stroke(ctx, K.ink('target'));
      ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y);
      ctx.moveTo(b.x - 3, b.y - 3); ctx.lineTo(b.x + 3, b.y + 3); ctx.moveTo(b.x + 3, b.y - 3); ctx.lineTo(b.x - 3, b.y + 3);
      ctx.stroke();
      placer.line(a, b);
    });
    // Labels: the skip points first, then the scene's; markers go on top.
    ctx.font = '11px ' + FONT;
    function label(p, text, colour) {
      var w = ctx.measureText(text).width, b = placer.place(p.x, p.y, w, 13);
      if (!b) return;  // no room left in the view
      if (b.leader) {
        ctx.strokeStyle = colour; ctx.lineWidth = 0.8; ctx.setLineDash([]);
        ctx.beginPath(); ctx.moveTo(p.x, p.y);
        ctx.lineTo(Math.min(Math.max(p.x, b.x), b.x + b.w), Math.min(Math.max(p.y, b.y), b.y + b.h));
        ctx.stroke();
      }
      K.haloText(ctx, text, b.x, b.y + 10.5, colour);
    }
    function inside(p) { return p.x >= r.x && p.x <= r.x + r.w && p.y >= r.y && p.y <= r.y + r.h; }
    D.skips.forEach(function (s) { var p = P(vs, s.latch); if (inside(p)) label(p, s.label, '#b0005f'); });
    D.skips.forEach(function (s) { var p = P(vs, s.rest); if (inside(p)) label(p, s.restLabel, '#111'); });
    shapeLabels.forEach(function (l) { label(l.p, l.text, l.colour); });
    if (D.t.length) { var s0 = P(vs, K.samplePt(0)); K.drawStart(ctx, s0.x, s0.y); }
    D.skips.forEach(function (s) { var b = P(vs, s.rest); K.drawRest(ctx, b.x, b.y); });
    D.skips.forEach(function (s) { var a = P(vs, s.latch); K.drawLatch(ctx, a.x, a.y, s.triggered); });
    if (D.meta.alarmAt) { var q = P(vs, D.meta.alarmAt); K.drawAlarm(ctx, q.x, q.y); }
    if (S.hoverT !== null && D.t.length) {
      var h = P(vs, pathAt(S.hoverT));
      ctx.strokeStyle = '#000'; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.beginPath(); ctx.arc(h.x, h.y, 7, 0, 2 * Math.PI);
      ctx.moveTo(h.x - 11, h.y); ctx.lineTo(h.x + 11, h.y); ctx.moveTo(h.x, h.y - 11); ctx.lineTo(h.x, h.y + 11);
      ctx.stroke();
    }
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
    var pr = K.pageRect(c), f = vs.frame;
    c.setAttribute('data-frame', [f.u0, f.u1, f.v0, f.v1, pr.x + r.x, pr.y + r.y, r.w, r.h].join(' '));
  }

  // Actual position at time t (linear between drawn samples).
  function pathAt(t) {
    var i = K.lowerBound(D.t, t);
    if (i <= 0) return K.samplePt(0);
    if (i >= D.t.length) return K.samplePt(D.t.length - 1);
    var t0 = D.t[i - 1], t1 = D.t[i], k = t1 > t0 ? (t - t0) / (t1 - t0) : 0;
    var a = K.samplePt(i - 1), b = K.samplePt(i);
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
      var q = P(vs, K.samplePt(i)), d = Math.hypot(q.x - p.x, q.y - p.y);
      if (d < bd) { bd = d; best = {i: i, t: D.t[i]}; }
    }
    return best;
  }

  // The skip K.variables in force at time t: from the last skip that ended before it.
  function varsAt(t) {
    var last = null;
    D.skips.forEach(function (s) { if (s.stopT <= t) last = s; });
    return last;
  }

  function hoverView(vs, ev) {
    var p = viewPoint(vs, ev), hit = nearest(vs, p);
    if (!hit) { hideTip(); if (S.hoverT !== null) { S.hoverT = null; K.drawTimeline(); } return; }
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
    K.drawTimeline();
  }

  function skipLines(s, which) {
    var lines = [['b', 'Skip ' + (s.index + 1) + ' \u00b7 ' + K.place(s.ctx, s.line) + ': ' + s.block]];
    var axes = K.allAxes();
    if (which === 'latch') {
      lines.push(['m', s.triggered ? 'latch: ' + s.signal + ' at ' + K.num(s.latchT, 6) + ' s'
                                   : 'no signal: the block ran to its end point']);
      s.vars.forEach(function (v) { lines.push(['m', v.name + ' = ' + K.num(v.value)]); });
      lines.push(['', 'work ' + K.axisText(s.position, axes)]);
      lines.push(['', 'machine ' + K.axisText(s.latchMachine, axes)]);
    } else {
      lines.push(['', 'rest at ' + K.num(s.stopT, 6) + ' s, ' + K.num(s.overtravel) + ' mm past the latch']);
      lines.push(['', 'work ' + K.axisText(s.endPosition, axes)]);
      lines.push(['', 'machine ' + K.axisText(s.restMachine, axes)]);
    }
    return lines;
  }

  function sampleLines(i) {
    var t = D.t[i], line = D.line[i], ctx = D.ctx[i], b = D.blocks[K.blockAt(t)];
    var lines = [['b', 't = ' + K.num(t, 6) + ' s \u00b7 ' + K.place(ctx, line) +
                  (K.sourceLine(ctx, line) ? ': ' + K.sourceLine(ctx, line) : '')]];
    lines.push(['', (b ? b.kind : '') + ' \u00b7 machine (actual) ' + D.meta.axes.map(function (a) {
      var c = K.channel('pos_' + a);
      return c ? a + K.num(c.series[0].v[i]) : '';
    }).join(' ')]);
    lines.push(['', 'F ' + K.num(K.channel('speed').series[0].v[i], 1) + ' mm/min \u00b7 following error ' +
                channelText('following_error', i, 4)]);
    var sig = D.signals.map(function (n) {
      var c = K.channel('signal_' + n);
      return n + (c && c.series[0].v[i] > 0.5 ? ' on' : ' off');
    });
    if (sig.length) lines.push(['', 'inputs: ' + sig.join(', ')]);
    var s = varsAt(t);
    if (s) {
      lines.push(['m', s.vars.map(function (v) { return v.name + ' = ' + K.num(v.value); }).join(', ') +
                  ' (from ' + K.place(s.ctx, s.line) + ')']);
    }
    return lines;
  }
  function channelText(id, i, d) {
    var c = K.channel(id);
    if (!c) return '';
    return c.series.map(function (s) { return s.name + K.num(s.v[i], d); }).join(' ');
  }

  function showTip(lines, x, y) {
    var tip = S.tip;
    tip.textContent = '';
    lines.forEach(function (l) { tip.appendChild(K.el('div', {cls: l[0] === 'b' ? 'tb' : l[0] === 'm' ? 'tm' : '', text: l[1]})); });
    tip.style.display = 'block';
    var w = tip.offsetWidth, h = tip.offsetHeight;
    var left = x + 16 + w > window.innerWidth ? x - w - 12 : x + 16;
    var top = y + 16 + h > window.innerHeight ? y - h - 12 : y + 16;
    tip.style.left = (left + window.scrollX) + 'px';
    tip.style.top = (top + window.scrollY) + 'px';
  }
  function hideTip() { if (S.tip) S.tip.style.display = 'none'; }

  K.fitFrame = fitFrame;
  K.frameAround = frameAround;
  K.makeView = makeView;
  K.viewPoint = viewPoint;
  K.u2px = u2px;
  K.v2py = v2py;
  K.px2u = px2u;
  K.py2v = py2v;
  K.P = P;
  K.drawGrid = drawGrid;
  K.axisColour = axisColour;
  K.drawShapes = drawShapes;
  K.blockInk = blockInk;
  K.drawBlock = drawBlock;
  K.drawView = drawView;
  K.pathAt = pathAt;
  K.nearest = nearest;
  K.varsAt = varsAt;
  K.hoverView = hoverView;
  K.skipLines = skipLines;
  K.sampleLines = sampleLines;
  K.channelText = channelText;
  K.showTip = showTip;
  K.hideTip = hideTip;
})(window.SkipncPlot);
