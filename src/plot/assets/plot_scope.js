// skipnc plot page, part 3 of 4: the timeline, drawn like a scope.
(function (K) {
  'use strict';

  var D = K.D, S = K.S, FONT = K.FONT;

  // ---- timeline -----------------------------------------------------------
  function stripHeight(c) {
    return c.digital ? 26 : c.flat ? 30 : c.id.slice(0, 4) === 'pos_' ? 70 : c.id === 'following_error' ? 100 : 80;
  }
  // Linear value of a series at time t.
  function valueAt(v, t) {
    var i = K.lowerBound(D.t, t);
    if (i <= 0) return v[0];
    if (i >= D.t.length) return v[D.t.length - 1];
    var t0 = D.t[i - 1], t1 = D.t[i];
    return v[i - 1] + (v[i] - v[i - 1]) * (t1 > t0 ? (t - t0) / (t1 - t0) : 0);
  }
  // Range of a K.channel over [t0, t1] (values at both ends included), with
  // room at the top for the strip's title. A K.channel that barely moves gets
  // a fixed span, so that noise is not blown up to full height.
  function valueRange(c, t0, t1) {
    var lo = Infinity, hi = -Infinity;
    var i0 = K.lowerBound(D.t, t0), i1 = K.lowerBound(D.t, t1);
    c.series.forEach(function (s) {
      if (!D.t.length) return;
      var a = valueAt(s.v, t0), b = valueAt(s.v, t1);
      lo = Math.min(lo, a, b); hi = Math.max(hi, a, b);
      for (var i = i0; i < i1; i++) { lo = Math.min(lo, s.v[i]); hi = Math.max(hi, s.v[i]); }
    });
    if (lo > hi) return [-1, 1];
    var minSpan = c.minSpan;
    if (hi - lo < minSpan) {
      var pad = Math.max(Math.abs(hi) * 0.1, minSpan), mid = (hi + lo) / 2;
      return [mid - pad, mid + pad];
    }
    var p = 0.08 * (hi - lo);
    return [lo - p, hi + 2.5 * p];
  }
  function fullTime() { return [0, Math.max(D.meta.time, D.t.length ? D.t[D.t.length - 1] : 1e-3)]; }

  function makeTimeline() {
    var canvas = K.el('canvas', {cls: 'timeline', id: 'timeline'});
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
      if (x < tl.px0 || x > tl.px0 + tl.pw || !D.t.length) { S.hoverT = null; K.hideTip(); K.redrawAll(); return; }
      S.hoverT = x2t(x);
      var i = Math.min(Math.max(K.lowerBound(D.t, S.hoverT), 0), D.t.length - 1);
      K.showTip(K.sampleLines(i), ev.clientX, ev.clientY);
      K.redrawAll();
    });
    canvas.addEventListener('mouseleave', function () { S.hoverT = null; K.hideTip(); K.redrawAll(); });
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
    var i0 = Math.max(0, K.lowerBound(D.t, tl.t0) - 1), i1 = Math.min(D.t.length, K.lowerBound(D.t, tl.t1) + 1);
    var y = 30, strips = [];
    ctx.font = 'bold 14px ' + FONT; ctx.fillStyle = '#222'; ctx.textAlign = 'left';
    ctx.fillText('Timeline (scope)', 4, 16);
    ctx.font = '11px ' + FONT; ctx.fillStyle = '#666';
    ctx.fillText('wheel: zoom \u00b7 drag: pan \u00b7 double-click: whole run \u00b7 latch instants in magenta, rest instants dashed',
                 150, 16);
    if (S.block >= 0) {
      var b = D.blocks[S.block];
      ctx.fillStyle = 'rgba(240,140,0,0.12)';
      var xa = Math.max(tl.px0, t2x(b.t0)), xb = Math.min(tl.px0 + tl.pw, t2x(b.t1));
      if (xb >= xa) ctx.fillRect(xa, 30, Math.max(1, xb - xa), tl.h - 60);
    }
    D.channels.forEach(function (c) {
      var h = stripHeight(c);
      var rg = c.digital ? [-0.15, 1.25] : valueRange(c, tl.t0, tl.t1);
      var Y = function (v) { return y + (rg[1] - v) / (rg[1] - rg[0]) * h; };
      strips.push({id: c.id, y: y, h: h, lo: rg[0], hi: rg[1]});
      ctx.fillStyle = '#ffffff'; ctx.fillRect(tl.px0, y, tl.pw, h);
      ctx.strokeStyle = '#d0d0d0'; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.strokeRect(tl.px0 + 0.5, y + 0.5, tl.pw - 1, h - 1);
      if (c.flat) {
        ctx.font = '10px ' + FONT; ctx.textAlign = 'right'; ctx.fillStyle = '#666';
        ctx.fillText(K.num((rg[0] + rg[1]) / 2, c.unit === 'mm' ? 4 : 1), tl.px0 - 4, Y((rg[0] + rg[1]) / 2) + 3);
      } else if (!c.digital) {
        var step = K.niceStep(rg[1] - rg[0], 3);  // tick labels at least 20 px apart
        for (var g = 0; g < 40 && step / (rg[1] - rg[0]) * h < 20; g++) step = K.nextNiceStep(step);
        ctx.font = '10px ' + FONT; ctx.textAlign = 'right'; ctx.fillStyle = '#666';
        ctx.strokeStyle = '#f0f0f0';
        ctx.beginPath();
        for (var v = Math.ceil(rg[0] / step) * step; v <= rg[1]; v += step) {
          ctx.moveTo(tl.px0, Y(v)); ctx.lineTo(tl.px0 + tl.pw, Y(v));
          ctx.fillText(K.num(Math.abs(v) < step * 1e-6 ? 0 : v, K.decimals(step)), tl.px0 - 4, Y(v) + 3);
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
      var title = c.title + (c.unit ? ' (' + c.unit + ')' : '') + (c.flat ? ': constant' : '');
      K.haloText(ctx, title, tl.px0 + 6, y + 12, '#333');
      var tx = tl.px0 + 6 + ctx.measureText(title).width + 10;
      if (c.series.length > 1) {
        c.series.forEach(function (s) { K.haloText(ctx, s.name, tx, y + 12, s.colour); tx += ctx.measureText(s.name).width + 8; });
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
      ctx.fillText(K.placeShort(s.ctx, s.line), xl, 27);
    });
    if (S.hoverT !== null) {
      var hx = t2x(S.hoverT);
      ctx.strokeStyle = '#000'; ctx.lineWidth = 1; ctx.setLineDash([2, 2]);
      ctx.beginPath(); ctx.moveTo(hx, top); ctx.lineTo(hx, bottom); ctx.stroke();
    }
    ctx.restore();
    var step = K.niceStep(tl.t1 - tl.t0, 10);
    ctx.font = '10px ' + FONT; ctx.fillStyle = '#666'; ctx.textAlign = 'center'; ctx.setLineDash([]);
    ctx.strokeStyle = '#666';
    for (var t = Math.ceil(tl.t0 / step) * step; t <= tl.t1 + step * 1e-9; t += step) {
      var x = t2x(t);
      ctx.beginPath(); ctx.moveTo(x, bottom); ctx.lineTo(x, bottom + 4); ctx.stroke();
      ctx.fillText(K.num(t, K.decimals(step)), x, bottom + 15);
    }
    ctx.textAlign = 'left'; ctx.fillStyle = '#444'; ctx.font = '11px ' + FONT;
    ctx.fillText('time (s)', 4, bottom + 15);
    var pr = K.pageRect(tl.canvas);
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

  K.stripHeight = stripHeight;
  K.valueAt = valueAt;
  K.valueRange = valueRange;
  K.fullTime = fullTime;
  K.makeTimeline = makeTimeline;
  K.t2x = t2x;
  K.x2t = x2t;
  K.drawTimeline = drawTimeline;
  K.timelineHeight = timelineHeight;
})(window.SkipncPlot);
