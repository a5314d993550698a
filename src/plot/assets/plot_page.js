// skipnc plot page, part 4 of 4: the page around the drawings, block
// stepping, zoom on a latch, the URL hash.
(function (K) {
  'use strict';

  var D = K.D, S = K.S, FONT = K.FONT;

  // ---- blocks, skips, zoom -----------------------------------------------
  function selectBlock(i) {
    S.block = i;
    var info = document.getElementById('block-info');
    if (i < 0) {
      info.textContent = 'All blocks shown. Step with \u2190 \u2192 or the buttons; click the path to pick a block.';
    } else {
      var b = D.blocks[i], axes = K.allAxes();
      info.textContent = 'Block ' + (i + 1) + ' of ' + D.blocks.length + ' \u00b7 ' + K.place(b.ctx, b.line) +
        (K.sourceLine(b.ctx, b.line) ? ': ' + K.sourceLine(b.ctx, b.line) : '') + ' \u00b7 ' + b.kind + ' \u00b7 ' +
        K.num(b.t0, 3) + '\u2013' + K.num(b.t1, 3) + ' s \u00b7 ends at ' + K.axisText(b.end, axes) + ' (machine)';
    }
    document.querySelectorAll('#listing .src').forEach(function (n) {
      var on = i >= 0 && +n.getAttribute('data-line') === D.blocks[i].line &&
               +n.getAttribute('data-file') === K.fileOf(D.blocks[i].ctx);
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
      var a = [K.dot(s.latch, vs.def.u), K.dot(s.latch, vs.def.v)], b = [K.dot(s.rest, vs.def.u), K.dot(s.rest, vs.def.v)];
      var span = Math.max(Math.hypot(a[0] - b[0], a[1] - b[1]) * 6, 0.05);
      var mmPerPx = span / Math.min(vs.rect.w, vs.rect.h);
      vs.frame = K.frameAround(vs.rect, (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, mmPerPx);
    });
    var w = K.latchWindow(s);
    S.tl.t0 = w[0]; S.tl.t1 = w[1];
    redrawAll();
  }
  function resetZoom() {
    S.views.forEach(function (vs) { vs.frame = K.fitFrame(vs.def, vs.rect); });
    var f = K.fullTime(); S.tl.t0 = f[0]; S.tl.t1 = f[1];
    redrawAll();
  }
  function wholeScene() {
    S.views.forEach(function (vs) { vs.frame = K.fitFrame(vs.def, vs.rect, true); });
    var f = K.fullTime(); S.tl.t0 = f[0]; S.tl.t1 = f[1];
    redrawAll();
  }
  function redrawAll() { S.views.forEach(K.drawView); K.drawTimeline(); }

  // ---- page -------------------------------------------------------------
  function legend() {
    var box = K.el('div', {cls: 'legend'});
    var used = ['rapid', 'feed', 'skip'];
    if (D.skips.some(function (s) { return s.hasTarget && s.triggered; })) used.push('target');
    if (D.skips.length) used.push('latch');
    if (D.skips.some(function (s) { return !s.triggered; })) used.push('miss');
    if (D.skips.length) used.push('rest');
    used.push('start');
    ['trigger', 'stop', 'part', 'hole', 'setter'].forEach(function (n) {
      if (D.shapes.some(function (s) { return s.ink === n; })) used.push(n);
    });
    used.forEach(function (name) {
      var c = K.el('canvas'), ctx = K.setupCanvas(c, 34, 14), st = K.ink(name);
      if (name === 'latch' || name === 'miss') K.drawLatch(ctx, 17, 7, name === 'latch');
      else if (name === 'rest') K.drawRest(ctx, 17, 7);
      else if (name === 'start') K.drawStart(ctx, 17, 8);
      else if (['trigger', 'stop', 'part', 'hole', 'setter'].indexOf(name) >= 0) {
        if (st.fill !== 'none') { ctx.globalAlpha = 0.15; ctx.fillStyle = st.fill; ctx.fillRect(2, 3, 30, 8); ctx.globalAlpha = 1; }
        ctx.strokeStyle = st.stroke; ctx.lineWidth = 1; ctx.setLineDash(st.dash); ctx.strokeRect(2.5, 3.5, 29, 7);
        ctx.setLineDash([]);
      } else {
        K.stroke(ctx, st); ctx.beginPath(); ctx.moveTo(2, 7); ctx.lineTo(32, 7); ctx.stroke();
      }
      var text = name === 'skip' && D.meta.skipLegend ? D.meta.skipLegend : st.legend;
      box.appendChild(K.el('div', {cls: 'item'}, [c, K.el('span', {text: text})]));
    });
    if (D.meta.alarmAt) {
      var ac = K.el('canvas'), actx = K.setupCanvas(ac, 34, 16);
      K.drawAlarm(actx, 17, 8);
      box.appendChild(K.el('div', {cls: 'item'}, [ac, K.el('span', {text: D.meta.alarmLegend})]));
    }
    return box;
  }
  function skipCards() {
    var box = K.el('div', {cls: 'skips'});
    box.appendChild(K.el('h2', {text: 'Skips (' + D.skips.length + ')'}));
    if (!D.skips.length) box.appendChild(K.el('p', {cls: 'muted', text: 'No skip block ran.'}));
    D.skips.forEach(function (s) {
      var vars = s.vars.map(function (v) { return v.name + ' = ' + K.num(v.value); }).join(', ');
      var rest = s.moved.map(function (a) { return D.meta.axes[a] + K.num(s.endPosition[a]); }).join(' ');
      box.appendChild(K.el('div', {cls: 'card', 'data-skip': s.index}, [
        K.el('div', {cls: 'head', text: (s.index + 1) + '. ' + K.place(s.ctx, s.line) + ': ' + s.block}),
        K.el('div', {cls: 'latch', text: s.triggered ? s.signal + ' at ' + K.num(s.latchT, 6) + ' s: stored ' + vars
                                                   : 'no signal: ran to its end point, stored ' + vars}),
        K.el('div', {cls: s.endedByAlarm ? 'alarm' : '',
                     text: (s.endedByAlarm ? 'cut short by the alarm: stopped at ' : 'rest ') + rest + ' (work) at ' +
                           K.num(s.stopT, 4) + ' s, ' + K.num(s.overtravel) + ' mm past the latch'}),
        K.el('button', {text: 'zoom on this latch', onclick: function () { zoomSkip(s.index); }})
      ]));
    });
    return box;
  }
  function variables() {
    var box = K.el('div', {cls: 'vars'});
    if (D.variables.length) {
      box.appendChild(K.el('h2', {text: 'Variables at the end'}));
      D.variables.forEach(function (v) {
        box.appendChild(K.el('div', {text: '#' + v[0] + ' = ' + (v[1] === null ? '<vacant>' : K.num(v[1]))}));
      });
    }
    if (D.messages.length) {
      box.appendChild(K.el('h2', {text: 'Messages'}));
      D.messages.forEach(function (m) { box.appendChild(K.el('div', {text: m})); });
    }
    return box;
  }
  // One section per file the run executed (the main program first, then
  // each macro or subprogram file), its lines marked where blocks ran.
  function listing() {
    var box = K.el('div', {id: 'listing'});
    var ran = {};
    function key(ctx, line) { return K.fileOf(ctx) + ':' + line; }
    D.blocks.forEach(function (b) { ran[key(b.ctx, b.line)] = true; });
    D.skips.forEach(function (s) { ran[key(s.ctx, s.line)] = 'skip'; });
    D.files.forEach(function (file, f) {
      if (!file.source.length) return;
      if (D.files.length > 1) box.appendChild(K.el('div', {cls: 'file', 'data-file': f, text: file.name}));
      file.source.forEach(function (text, k) {
        var line = k + 1, mark = ran[f + ':' + line];
        var row = K.el('div', {cls: 'src' + (mark ? ' ran' : '') + (mark === 'skip' ? ' skipline' : ''),
                             'data-line': line, 'data-file': f,
                             onclick: function () {
                               for (var i = 0; i < D.blocks.length; i++) {
                                 if (D.blocks[i].line === line && K.fileOf(D.blocks[i].ctx) === f) { selectBlock(i); return; }
                               }
                             }},
                     [K.el('span', {cls: 'no', text: String(line)}), K.el('span', {text: text})]);
        box.appendChild(row);
      });
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
      vs.ctx = K.setupCanvas(vs.canvas, cw, ch);
      var iso = vs.def.look < 0;
      var rect = {x: iso ? 8 : 52, y: 26, w: cw - (iso ? 8 : 52) - 10, h: ch - 26 - (iso ? 8 : 30)};
      if (vs.rect && vs.frame) {
        // Keep the scale and centre across a resize.
        var mmPerPx = (vs.frame.u1 - vs.frame.u0) / vs.rect.w;
        vs.frame = K.frameAround(rect, (vs.frame.u0 + vs.frame.u1) / 2, (vs.frame.v0 + vs.frame.v1) / 2, mmPerPx);
      }
      vs.rect = rect;
      if (!vs.frame) vs.frame = K.fitFrame(vs.def, rect);
    });
    var tl = S.tl, tw = document.getElementById('scope').clientWidth;
    tl.w = tw; tl.h = K.timelineHeight();
    tl.ctx = K.setupCanvas(tl.canvas, tw, tl.h);
    tl.px0 = 74; tl.pw = tw - 74 - 8;
    redrawAll();
  }

  function build() {
    var m = D.meta;
    var header = K.el('header', {}, [
      K.el('h1', {text: 'skipnc plot: ' + m.program}),
      K.el('div', {cls: 'meta', text: 'machine ' + m.machine + ' \u00b7 dialect ' + m.dialect + ' \u00b7 ' + m.status +
                 ' after ' + K.num(m.time, 3) + ' s of machine time \u00b7 ' + D.skips.length + ' skip' +
                 (D.skips.length === 1 ? '' : 's') + ' \u00b7 ' + m.periods + ' servo periods, ' + D.t.length + ' drawn' +
                 (m.tipNote ? ' \u00b7 ' + m.tipNote : '')}),
      m.alarm ? K.el('div', {cls: 'alarm', text: 'ALARM ' + m.alarm}) : null
    ]);
    var toolbar = K.el('div', {cls: 'toolbar'}, [
      K.el('button', {text: '\u25c0 previous block', onclick: function () { stepBlock(-1); }}),
      K.el('button', {text: 'next block \u25b6', onclick: function () { stepBlock(1); }}),
      K.el('button', {text: 'all blocks', onclick: function () { selectBlock(-1); }}),
      K.el('button', {text: 'reset zoom', onclick: resetZoom}),
      K.el('button', {text: 'whole scene', onclick: wholeScene}),
      K.el('span', {id: 'block-info'})
    ]);
    var grid = K.el('div', {id: 'views'});
    S.views = D.views.map(K.makeView);
    S.views.forEach(function (vs) { grid.appendChild(vs.canvas); });
    var aside = K.el('aside', {}, [K.el('h2', {text: 'Legend'}), legend(), skipCards(), variables(),
                                 D.files.some(function (f) { return f.source.length; }) ? K.el('h2', {text: 'Program'}) : null, listing()]);
    S.tl = K.makeTimeline();
    var scope = K.el('div', {id: 'scope'}, [S.tl.canvas]);
    S.tip = K.el('div', {id: 'tip'});
    var app = document.getElementById('app');
    app.appendChild(header);
    app.appendChild(toolbar);
    app.appendChild(K.el('div', {cls: 'main'}, [grid, aside]));
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

  K.selectBlock = selectBlock;
  K.stepBlock = stepBlock;
  K.zoomSkip = zoomSkip;
  K.resetZoom = resetZoom;
  K.redrawAll = redrawAll;
  K.legend = legend;
  K.skipCards = skipCards;
  K.variables = variables;
  K.listing = listing;
  K.layout = layout;
  K.build = build;
  K.applyHash = applyHash;
})(window.SkipncPlot);
