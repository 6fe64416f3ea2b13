// The script of ochre-regress HTML reports (docs/tools.md, "HTML report"). A plain script that requests
// nothing (no modules, no network or file requests): pages work from a file:// URL. The index gets a "failed scenes only" filter; a scene
// page gets the image viewer (side by side, slider, flip; zoom to single pixels; failing pixels marked),
// the readout of the pixel under the cursor and its spectrum, from window.ochreSceneData (the scene's
// <name>.data.js, tools/regress/scene_data.h).
(function () {
  'use strict';

  document.documentElement.classList.add('js');

  // ------------------------------------------------------------------ formatting

  function formatNumber(v) {
    if (Number.isNaN(v)) return 'NaN';
    if (!Number.isFinite(v)) return v > 0 ? '+Inf' : '-Inf';
    if (v === 0) return '0';
    const a = Math.abs(v);
    if (a >= 1e-3 && a < 1e5) return String(Number(v.toPrecision(4)));
    return v.toExponential(3);
  }

  function formatList(values) {
    return values.map(formatNumber).join(', ');
  }

  function formatPValue(nlp) {
    if (!(nlp < 299.5)) return '< 1e-300';
    return formatNumber(Math.pow(10, -nlp));
  }

  // ------------------------------------------------------------------ index page

  function setupIndex() {
    const box = document.getElementById('failed-only');
    if (!box) return;
    const apply = function () {
      document.body.classList.toggle('failed-only', box.checked);
    };
    box.addEventListener('change', apply);
    apply();
  }

  // ------------------------------------------------------------------ scene data

  // Base64 of little-endian float32 values (scene_data.h) to a Float32Array.
  function decodeFloats(text) {
    const bytes = atob(text);
    const buffer = new ArrayBuffer(bytes.length);
    const view = new Uint8Array(buffer);
    for (let i = 0; i < bytes.length; ++i) view[i] = bytes.charCodeAt(i);
    const floats = new Float32Array(buffer.byteLength / 4);
    const data = new DataView(buffer);
    for (let i = 0; i < floats.length; ++i) floats[i] = data.getFloat32(4 * i, true);
    return floats;
  }

  function decodeLayer(layer) {
    return layer ? { components: layer.components, values: decodeFloats(layer.data), wavelengths: layer.wavelengths } : null;
  }

  function cellValues(layer, cell) {
    if (!layer) return null;
    const n = layer.components;
    return Array.prototype.slice.call(layer.values, cell * n, cell * n + n);
  }

  function multiply(matrix, v) {
    return [0, 1, 2].map(function (row) {
      return matrix[3 * row] * v[0] + matrix[3 * row + 1] * v[1] + matrix[3 * row + 2] * v[2];
    });
  }

  // ------------------------------------------------------------------ scene viewer

  function SceneViewer(data) {
    this.data = data;
    this.width = data.width;
    this.height = data.height;
    this.layers = {};
    for (const name in data.layers) this.layers[name] = decodeLayer(data.layers[name]);
    this.spectral = {};
    for (const side in data.spectral) this.spectral[side] = decodeLayer(data.spectral[side]);
    this.zoom = 1; // relative to "fit"
    this.center = { x: this.width / 2, y: this.height / 2 };
    this.mode = 'side';
    this.split = 0.5;
    this.flipShowsNew = false;
    this.markFailing = true;
    this.pinned = null; // a cell index
    this.hover = null;
    this.failingCells = [];
    const failing = this.layers.failing;
    for (let c = 0; failing && c < failing.values.length; ++c) if (failing.values[c] > 0) this.failingCells.push(c);
    this.images = {};
    this.views = [];
    this.setupViews();
    this.setupControls();
    this.readHash();
    this.drawAll();
    this.updateReadout();
  }

  SceneViewer.prototype.setupViews = function () {
    const self = this;
    document.querySelectorAll('figure.panel').forEach(function (figure) {
      const key = figure.dataset.image;
      const img = figure.querySelector('img');
      self.images[key] = img;
      self.addView(figure.querySelector('.viewport'), key);
    });
    const compare = document.querySelector('.viewport.compare');
    if (compare) this.compareView = this.addView(compare, 'compare');
    Object.keys(this.images).forEach(function (key) {
      const img = self.images[key];
      img.addEventListener('load', function () {
        self.drawAll();
      });
    });
    window.addEventListener('resize', function () {
      self.drawAll();
    });
  };

  SceneViewer.prototype.addView = function (viewport, key) {
    const canvas = document.createElement('canvas');
    canvas.tabIndex = 0;
    canvas.dataset.view = key;
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', key + ' image; arrow keys move the selected pixel, + and - zoom');
    viewport.appendChild(canvas);
    const view = { key: key, canvas: canvas, viewport: viewport };
    this.views.push(view);
    this.attachPointer(view);
    return view;
  };

  // CSS pixels per image pixel in a view.
  SceneViewer.prototype.scale = function (view) {
    const w = view.canvas.clientWidth;
    const h = view.canvas.clientHeight;
    return Math.min(w / this.width, h / this.height) * this.zoom;
  };

  SceneViewer.prototype.toImage = function (view, clientX, clientY) {
    const rect = view.canvas.getBoundingClientRect();
    const s = this.scale(view);
    return {
      x: (clientX - rect.left - rect.width / 2) / s + this.center.x,
      y: (clientY - rect.top - rect.height / 2) / s + this.center.y,
    };
  };

  SceneViewer.prototype.cellAt = function (point) {
    if (!(point.x >= 0 && point.y >= 0 && point.x < this.width && point.y < this.height)) return null;
    const step = this.data.step;
    return Math.floor(point.y / step) * this.data.columns + Math.floor(point.x / step);
  };

  // The image rectangle of a cell: x, y, w, h in pixels.
  SceneViewer.prototype.cellRect = function (cell) {
    const step = this.data.step;
    const x = (cell % this.data.columns) * step;
    const y = Math.floor(cell / this.data.columns) * step;
    return { x: x, y: y, w: Math.min(step, this.width - x), h: Math.min(step, this.height - y) };
  };

  SceneViewer.prototype.attachPointer = function (view) {
    const self = this;
    const canvas = view.canvas;
    let drag = null;
    canvas.addEventListener('pointerdown', function (e) {
      drag = { x: e.clientX, y: e.clientY, cx: self.center.x, cy: self.center.y, moved: false };
    });
    canvas.addEventListener('pointermove', function (e) {
      if (drag && e.buttons) {
        const s = self.scale(view);
        const dx = e.clientX - drag.x;
        const dy = e.clientY - drag.y;
        if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
        if (drag.moved) {
          self.center = { x: drag.cx - dx / s, y: drag.cy - dy / s };
          self.drawAll();
          return;
        }
      }
      self.hover = self.cellAt(self.toImage(view, e.clientX, e.clientY));
      if (self.pinned === null) self.updateReadout();
      self.drawAll();
    });
    canvas.addEventListener('pointerup', function (e) {
      const wasDrag = drag && drag.moved;
      drag = null;
      if (wasDrag) return;
      const cell = self.cellAt(self.toImage(view, e.clientX, e.clientY));
      self.pin(cell === self.pinned ? null : cell);
    });
    canvas.addEventListener('pointerleave', function () {
      drag = null;
      self.hover = null;
      self.drawAll();
    });
    canvas.addEventListener(
      'wheel',
      function (e) {
        e.preventDefault();
        const before = self.toImage(view, e.clientX, e.clientY);
        self.setZoom(self.zoom * Math.pow(2, -Math.sign(e.deltaY) * 0.25), false);
        const after = self.toImage(view, e.clientX, e.clientY);
        self.center = { x: self.center.x + before.x - after.x, y: self.center.y + before.y - after.y };
        self.drawAll();
      },
      { passive: false }
    );
    canvas.addEventListener('keydown', function (e) {
      if (self.handleKey(e.key)) e.preventDefault();
    });
  };

  SceneViewer.prototype.handleKey = function (key) {
    const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
    if (moves[key]) {
      const base = this.pinned !== null ? this.pinned : this.cellAt(this.center) || 0;
      const columns = this.data.columns;
      const col = Math.min(columns - 1, Math.max(0, (base % columns) + moves[key][0]));
      const row = Math.min(this.data.rows - 1, Math.max(0, Math.floor(base / columns) + moves[key][1]));
      this.pin(row * columns + col);
      return true;
    }
    if (key === '+' || key === '=') return this.setZoom(this.zoom * 2), true;
    if (key === '-') return this.setZoom(this.zoom / 2), true;
    if (key === '0') return this.fit(), true;
    if (key === 'f' || key === 'F') return this.toggleFlip(), true;
    if (key === 'Escape') return this.pin(null), true;
    return false;
  };

  SceneViewer.prototype.setZoom = function (zoom, redraw) {
    // From the whole image to about 128 screen pixels per image pixel.
    const maxZoom = Math.max(1, (128 * Math.max(this.width, this.height)) / 256);
    this.zoom = Math.min(maxZoom, Math.max(0.25, zoom));
    const label = document.getElementById('zoom-level');
    const view = this.visibleViews()[0];
    if (label && view) {
      const s = this.scale(view);
      label.textContent = Math.abs(this.zoom - 1) < 1e-9 ? 'fit' : formatNumber(s) + ' px/px';
    }
    if (redraw !== false) this.drawAll();
  };

  SceneViewer.prototype.fit = function () {
    this.center = { x: this.width / 2, y: this.height / 2 };
    this.setZoom(1);
  };

  // Pins a cell (null releases): the readout then shows it until another is pinned.
  SceneViewer.prototype.pin = function (cell) {
    this.pinned = cell;
    if (cell !== null) {
      const r = this.cellRect(cell);
      const view = this.visibleViews()[0];
      if (view) {
        // Keep the pinned pixel in sight.
        const s = this.scale(view);
        const halfW = view.canvas.clientWidth / (2 * s);
        const halfH = view.canvas.clientHeight / (2 * s);
        const px = r.x + r.w / 2;
        const py = r.y + r.h / 2;
        if (Math.abs(px - this.center.x) > halfW * 0.9) this.center.x = px;
        if (Math.abs(py - this.center.y) > halfH * 0.9) this.center.y = py;
      }
    }
    this.updateReadout();
    this.drawAll();
  };

  SceneViewer.prototype.goToWorst = function () {
    const z = this.layers.z;
    let worst = 0;
    for (let c = 1; c < z.values.length; ++c) {
      const a = Math.abs(z.values[c]);
      if (Number.isNaN(a) || a > Math.abs(z.values[worst])) worst = c;
      if (Number.isNaN(a)) break;
    }
    const r = this.cellRect(worst);
    this.center = { x: r.x + r.w / 2, y: r.y + r.h / 2 };
    const view = this.visibleViews()[0];
    const fitScale = view ? this.scale(view) / this.zoom : 1;
    this.setZoom(Math.max(this.zoom, 24 / (fitScale * this.data.step)), false);
    this.pin(worst);
  };

  SceneViewer.prototype.toggleFlip = function () {
    this.flipShowsNew = !this.flipShowsNew;
    const button = document.getElementById('flip');
    if (button) button.setAttribute('aria-pressed', String(this.flipShowsNew));
    const state = document.getElementById('flip-state');
    if (state) state.textContent = this.flipShowsNew ? 'New render' : 'Reference';
    this.drawAll();
  };

  SceneViewer.prototype.setMode = function (mode) {
    this.mode = mode;
    const side = document.getElementById('side-by-side');
    const compare = document.getElementById('compare');
    if (side) side.hidden = mode !== 'side';
    if (compare) {
      compare.hidden = mode === 'side';
      compare.dataset.mode = mode;
    }
    document.querySelectorAll('input[name="mode"]').forEach(function (radio) {
      radio.checked = radio.value === mode;
    });
    this.setZoom(this.zoom);
  };

  SceneViewer.prototype.setSplit = function (percent) {
    this.split = Math.min(100, Math.max(0, percent)) / 100;
    const input = document.getElementById('split');
    if (input && Number(input.value) !== percent) input.value = String(percent);
    const output = document.getElementById('split-value');
    if (output) output.textContent = Math.round(this.split * 100) + ' %';
    if (this.compareView) this.compareView.canvas.dataset.split = String(this.split);
    this.drawAll();
  };

  SceneViewer.prototype.setupControls = function () {
    const self = this;
    const on = function (id, event, handler) {
      const element = document.getElementById(id);
      if (element) element.addEventListener(event, handler);
    };
    on('zoom-in', 'click', function () {
      self.setZoom(self.zoom * 2);
    });
    on('zoom-out', 'click', function () {
      self.setZoom(self.zoom / 2);
    });
    on('zoom-fit', 'click', function () {
      self.fit();
    });
    on('worst-pixel', 'click', function () {
      self.goToWorst();
    });
    on('flip', 'click', function () {
      self.toggleFlip();
    });
    on('split', 'input', function (e) {
      self.setSplit(Number(e.target.value));
    });
    on('mark-failing', 'change', function (e) {
      self.markFailing = e.target.checked;
      self.drawAll();
    });
    document.querySelectorAll('input[name="mode"]').forEach(function (radio) {
      radio.addEventListener('change', function () {
        if (radio.checked) self.setMode(radio.value);
      });
    });
    document.addEventListener('keydown', function (e) {
      const target = e.target;
      if (target && (target.tagName === 'INPUT' || target.tagName === 'CANVAS' || target.isContentEditable)) return;
      if ((e.key === 'f' || e.key === 'F') && self.mode === 'flip') {
        self.toggleFlip();
        e.preventDefault();
      }
    });
  };

  // "#x=12&y=20&zoom=8&mode=slider" pins a pixel and sets the view (links and screenshots).
  SceneViewer.prototype.readHash = function () {
    const params = {};
    location.hash
      .replace(/^#/, '')
      .split('&')
      .forEach(function (part) {
        const kv = part.split('=');
        if (kv.length === 2) params[decodeURIComponent(kv[0])] = decodeURIComponent(kv[1]);
      });
    if (params.mode === 'slider' || params.mode === 'flip' || params.mode === 'side') this.setMode(params.mode);
    if (params.zoom && Number(params.zoom) > 0) this.zoom = Number(params.zoom);
    if (params.split !== undefined && !Number.isNaN(Number(params.split))) this.setSplit(Number(params.split));
    const x = Number(params.x);
    const y = Number(params.y);
    if (params.x !== undefined && params.y !== undefined) {
      const cell = this.cellAt({ x: x + 0.5, y: y + 0.5 });
      if (cell !== null) {
        if (this.zoom > 1) this.center = { x: x + 0.5, y: y + 0.5 };
        this.pinned = cell;
      }
    }
    this.setZoom(this.zoom, false);
  };

  SceneViewer.prototype.visibleViews = function () {
    return this.views.filter(function (view) {
      return view.canvas.offsetParent !== null && view.canvas.clientWidth > 0;
    });
  };

  SceneViewer.prototype.drawAll = function () {
    const self = this;
    this.visibleViews().forEach(function (view) {
      self.draw(view);
    });
  };

  SceneViewer.prototype.drawImage = function (ctx, key) {
    const img = this.images[key];
    if (img && img.complete && img.naturalWidth > 0) ctx.drawImage(img, 0, 0, this.width, this.height);
  };

  SceneViewer.prototype.draw = function (view) {
    const canvas = view.canvas;
    const ratio = window.devicePixelRatio || 1;
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    if (canvas.width !== Math.round(w * ratio) || canvas.height !== Math.round(h * ratio)) {
      canvas.width = Math.round(w * ratio);
      canvas.height = Math.round(h * ratio);
    }
    const ctx = canvas.getContext('2d');
    const s = this.scale(view);
    const ox = w / 2 - this.center.x * s;
    const oy = h / 2 - this.center.y * s;
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, w, h);
    ctx.imageSmoothingEnabled = false;
    ctx.save();
    ctx.translate(ox, oy);
    ctx.scale(s, s);
    if (view.key !== 'compare') {
      this.drawImage(ctx, view.key);
    } else if (this.mode === 'flip') {
      this.drawImage(ctx, this.flipShowsNew ? 'new' : 'reference');
    } else {
      this.drawImage(ctx, 'reference');
      ctx.restore();
      ctx.save();
      ctx.beginPath();
      ctx.rect(w * this.split, 0, w * (1 - this.split), h);
      ctx.clip();
      ctx.translate(ox, oy);
      ctx.scale(s, s);
      this.drawImage(ctx, 'new');
    }
    ctx.restore();
    if (view.key === 'compare' && this.mode === 'slider' && this.split > 0 && this.split < 1)
      this.drawSplitLine(ctx, w * this.split, h);
    if (this.markFailing && (view.key === 'z' || view.key === 'compare')) this.drawFailing(ctx, s, ox, oy);
    const selected = this.pinned !== null ? this.pinned : this.hover;
    if (selected !== null) this.drawSelection(ctx, selected, s, ox, oy, this.pinned !== null);
    canvas.dataset.scale = String(s);
  };

  SceneViewer.prototype.drawSplitLine = function (ctx, x, h) {
    ctx.fillStyle = '#000';
    ctx.fillRect(x - 2, 0, 4, h);
    ctx.fillStyle = '#fff';
    ctx.fillRect(x - 1, 0, 2, h);
  };

  // A rectangle of two outlines, black outside and white inside: visible on any colour.
  function outline(ctx, x, y, w, h, minimum) {
    if (w < minimum) {
      x -= (minimum - w) / 2;
      w = minimum;
    }
    if (h < minimum) {
      y -= (minimum - h) / 2;
      h = minimum;
    }
    ctx.lineWidth = 3;
    ctx.strokeStyle = '#000';
    ctx.strokeRect(x - 1.5, y - 1.5, w + 3, h + 3);
    ctx.lineWidth = 1;
    ctx.strokeStyle = '#fff';
    ctx.strokeRect(x + 0.5, y + 0.5, w - 1, h - 1);
  }

  SceneViewer.prototype.drawFailing = function (ctx, s, ox, oy) {
    for (let i = 0; i < this.failingCells.length; ++i) {
      const r = this.cellRect(this.failingCells[i]);
      outline(ctx, ox + r.x * s, oy + r.y * s, r.w * s, r.h * s, 5);
    }
  };

  SceneViewer.prototype.drawSelection = function (ctx, cell, s, ox, oy, pinned) {
    const r = this.cellRect(cell);
    const x = ox + r.x * s;
    const y = oy + r.y * s;
    ctx.setLineDash(pinned ? [] : [4, 3]);
    ctx.lineWidth = 2;
    ctx.strokeStyle = '#ffd400';
    ctx.strokeRect(x - 3, y - 3, r.w * s + 6, r.h * s + 6);
    ctx.lineWidth = 1;
    ctx.strokeStyle = '#000';
    ctx.strokeRect(x - 4.5, y - 4.5, r.w * s + 9, r.h * s + 9);
    ctx.setLineDash([]);
  };

  // ------------------------------------------------------------------ readout

  function setText(id, text) {
    const element = document.getElementById(id);
    if (element) element.textContent = text;
  }

  SceneViewer.prototype.updateReadout = function () {
    const cell = this.pinned !== null ? this.pinned : this.hover;
    if (cell === null || cell === undefined) return;
    const r = this.cellRect(cell);
    const step = this.data.step;
    const where =
      step === 1
        ? 'x = ' + r.x + ', y = ' + r.y
        : 'block of ' + step + '\u00d7' + step + ' pixels at x = ' + r.x + '\u2013' + (r.x + r.w - 1) +
          ', y = ' + r.y + '\u2013' + (r.y + r.h - 1);
    const position = document.getElementById('ro-position');
    if (position) {
      position.textContent = (this.pinned !== null ? 'Pinned pixel: ' : 'Pixel: ') + where;
      position.dataset.x = String(r.x);
      position.dataset.y = String(r.y);
    }
    const self = this;
    ['reference', 'new'].forEach(function (side) {
      const rgb = cellValues(self.layers[side + '.rgb'], cell);
      setText('ro-' + side + '-rgb', rgb ? formatList(rgb) : '\u2013');
      setText('ro-' + side + '-xyz', rgb ? formatList(multiply(self.data.rgbToXyz, rgb)) : '\u2013');
      const stokes = cellValues(self.layers[side + '.stokes'], cell);
      if (stokes) {
        const s0 = stokes[0];
        const dolp = s0 > 0 ? Math.sqrt(stokes[1] * stokes[1] + stokes[2] * stokes[2]) / s0 : 0;
        const aolp = (0.5 * Math.atan2(stokes[2], stokes[1]) * 180) / Math.PI;
        setText('ro-' + side + '-stokes', formatList(stokes));
        setText('ro-' + side + '-dolp', formatNumber(dolp));
        setText('ro-' + side + '-aolp', formatNumber(aolp));
      } else {
        ['stokes', 'dolp', 'aolp'].forEach(function (row) {
          setText('ro-' + side + '-' + row, 'not in this image');
        });
      }
    });
    const z = cellValues(this.layers.z, cell)[0];
    setText('ro-z', formatNumber(z));
    setText('ro-p', formatPValue(cellValues(this.layers.nlp, cell)[0]));
    const failing = cellValues(this.layers.failing, cell)[0];
    const failingText = step === 1 ? (failing > 0 ? 'Yes' : 'No') : failing + ' of ' + r.w * r.h + ' pixels';
    setText('ro-failing', failingText);
    const failingElement = document.getElementById('ro-failing');
    if (failingElement) failingElement.classList.toggle('fails', failing > 0);
    setText('ro-de00', cellValues(this.layers.de00, cell)[0].toFixed(2));
    this.drawSpectrum(cell);
  };

  // ------------------------------------------------------------------ spectrum

  // Elements in the namespace of the page's inline <svg id="spectrum"> (the HTML parser's SVG namespace).
  function svgElement(name, attributes, text) {
    const element = document.createElementNS(document.getElementById('spectrum').namespaceURI, name);
    for (const key in attributes) element.setAttribute(key, attributes[key]);
    if (text !== undefined) element.textContent = text;
    return element;
  }

  SceneViewer.prototype.drawSpectrum = function (cell) {
    const section = document.getElementById('spectrum-section');
    const svg = document.getElementById('spectrum');
    const sides = ['reference', 'new'].filter(function (side) {
      return this.spectral[side];
    }, this);
    if (!section || !svg || sides.length === 0) return;
    section.hidden = false;
    const curves = {};
    let lo = Infinity;
    let hi = -Infinity;
    let top = 0;
    let bottom = 0;
    for (const side of sides) {
      const layer = this.spectral[side];
      const values = cellValues(layer, cell);
      curves[side] = layer.wavelengths.map(function (nm, i) {
        return [nm, values[i]];
      });
      lo = Math.min(lo, layer.wavelengths[0]);
      hi = Math.max(hi, layer.wavelengths[layer.wavelengths.length - 1]);
      values.forEach(function (v) {
        if (Number.isFinite(v)) {
          top = Math.max(top, v);
          bottom = Math.min(bottom, v);
        }
      });
    }
    if (top === bottom) top = bottom + 1;
    if (hi === lo) hi = lo + 1;
    const box = { left: 62, right: 490, top: 12, bottom: 204 };
    const sx = function (nm) {
      return box.left + ((nm - lo) / (hi - lo)) * (box.right - box.left);
    };
    const sy = function (v) {
      return box.bottom - ((v - bottom) / (top - bottom)) * (box.bottom - box.top);
    };
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    const tickStep = hi - lo > 300 ? 100 : 50;
    for (let nm = Math.ceil(lo / tickStep) * tickStep; nm <= hi; nm += tickStep) {
      svg.appendChild(svgElement('line', { class: 'grid', x1: sx(nm), x2: sx(nm), y1: box.top, y2: box.bottom }));
      svg.appendChild(svgElement('text', { x: sx(nm), y: box.bottom + 16, 'text-anchor': 'middle' }, nm + ' nm'));
    }
    for (let i = 0; i <= 4; ++i) {
      const v = bottom + ((top - bottom) * i) / 4;
      svg.appendChild(svgElement('line', { class: 'grid', x1: box.left, x2: box.right, y1: sy(v), y2: sy(v) }));
      svg.appendChild(svgElement('text', { x: box.left - 6, y: sy(v) + 4, 'text-anchor': 'end' }, formatNumber(v)));
    }
    svg.appendChild(svgElement('line', { class: 'axis', x1: box.left, x2: box.left, y1: box.top, y2: box.bottom }));
    svg.appendChild(svgElement('line', { class: 'axis', x1: box.left, x2: box.right, y1: box.bottom, y2: box.bottom }));
    for (const side of sides) {
      const points = curves[side].filter(function (p) {
        return Number.isFinite(p[1]);
      });
      svg.appendChild(
        svgElement('polyline', {
          class: side,
          points: points
            .map(function (p) {
              return sx(p[0]).toFixed(1) + ',' + sy(p[1]).toFixed(1);
            })
            .join(' '),
        })
      );
      points.forEach(function (p) {
        const x = sx(p[0]);
        const y = sy(p[1]);
        svg.appendChild(
          side === 'new'
            ? svgElement('circle', { class: 'point-new', cx: x, cy: y, r: 3 })
            : svgElement('rect', { class: 'point-reference', x: x - 3, y: y - 3, width: 6, height: 6 })
        );
      });
    }
    this.spectrumTable(curves, sides);
  };

  SceneViewer.prototype.spectrumTable = function (curves, sides) {
    const table = document.getElementById('spectrum-table');
    if (!table) return;
    const rows = {};
    for (const side of sides)
      curves[side].forEach(function (p) {
        rows[p[0]] = rows[p[0]] || {};
        rows[p[0]][side] = p[1];
      });
    let html = '<thead><tr><th scope="col">Wavelength (nm)</th><th scope="col">Reference</th><th scope="col">New render</th></tr></thead><tbody>';
    Object.keys(rows)
      .map(Number)
      .sort(function (a, b) {
        return a - b;
      })
      .forEach(function (nm) {
        const cell = function (side) {
          return rows[nm][side] === undefined ? '\u2013' : formatNumber(rows[nm][side]);
        };
        html += '<tr><td>' + formatNumber(nm) + '</td><td>' + cell('reference') + '</td><td>' + cell('new') + '</td></tr>';
      });
    table.innerHTML = html + '</tbody>';
  };

  // ------------------------------------------------------------------ start

  function start() {
    setupIndex();
    if (window.ochreSceneData && document.body.classList.contains('scene-page')) {
      window.ochreViewer = new SceneViewer(window.ochreSceneData);
    }
    document.body.dataset.ready = 'true';
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
