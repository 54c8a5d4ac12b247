/* infmob-usd gallery: cards, filters, statistics charts and a three.js viewer with joint sliders.
 *
 * Data arrive as <script> files calling INFMOB_GALLERY.index / .stats / .object / .texture, so the
 * page works from file:// (no fetch, no ES modules). three.js (vendored) loads on the first open.
 * Conventions of the objects: metres, Z up, fronts face +X, a joint's rest is 0 clipped to its range.
 */
(function () {
  'use strict';
  const PREFIX = window.INFMOB_PREFIX || '';
  const PAGE = 60;
  const G = window.INFMOB_GALLERY = {
    data: null, statsData: null, objects: {}, textures: {}, viewer: null, page: 0, filtered: [],
  };
  G.index = (d) => { G.data = d; };
  G.stats = (d) => { G.statsData = d; };
  G.object = (key, d) => { G.objects[key] = d; };
  G.texture = (hash, uri) => { G.textures[hash] = uri; };

  const $ = (id) => document.getElementById(id);
  const el = (tag, attrs, ...kids) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'class') e.className = v; else if (k === 'text') e.textContent = v; else e.setAttribute(k, v);
    }
    for (const k of kids) if (k != null) e.append(k);
    return e;
  };

  const scripts = {};
  function loadScript(src) {
    if (!scripts[src]) {
      scripts[src] = new Promise((resolve, reject) => {
        const s = document.createElement('script');
        s.src = src;
        s.onload = () => { s.remove(); resolve(); };
        s.onerror = () => { delete scripts[src]; reject(new Error('cannot load ' + src)); };
        document.head.appendChild(s);
      });
    }
    return scripts[src];
  }

  // ------------------------------------------------------------------------------------ cards

  function kindsText(kinds) {
    return Object.entries(kinds).map(([k, n]) => `${k} ${n}`).join(', ');
  }

  function fillFilters() {
    const rows = G.data.objects;
    const cats = {}, kinds = {};
    for (const r of rows) {
      cats[r.category] = (cats[r.category] || 0) + 1;
      for (const k of Object.keys(r.kinds)) kinds[k] = (kinds[k] || 0) + 1;
    }
    const fc = $('f-category'), fk = $('f-kind');
    fc.append(el('option', { value: '', text: `all (${rows.length})` }));
    for (const c of Object.keys(cats).sort()) fc.append(el('option', { value: c, text: `${c} (${cats[c]})` }));
    fk.append(el('option', { value: '', text: 'any' }));
    fk.append(el('option', { value: '-', text: 'no movable joint' }));
    for (const k of Object.keys(kinds).sort()) fk.append(el('option', { value: k, text: `${k} (${kinds[k]})` }));
    for (const f of [fc, fk]) f.addEventListener('change', () => { G.page = 0; applyFilters(); });
    $('f-name').addEventListener('input', () => { G.page = 0; applyFilters(); });
  }

  function applyFilters() {
    const c = $('f-category').value, k = $('f-kind').value, q = $('f-name').value.trim().toLowerCase();
    const rows = G.data.objects;
    G.filtered = [];
    for (let i = 0; i < rows.length; i++) {
      const r = rows[i];
      if (c && r.category !== c) continue;
      if (k === '-' ? r.joints > 0 : (k && !r.kinds[k])) continue;
      if (q && !r.name.toLowerCase().includes(q)) continue;
      G.filtered.push(i);
    }
    renderCards();
  }

  function cardFor(i) {
    const r = G.data.objects[i];
    const thumb = el('div', { class: 'thumb' });
    if (r.thumb) {
      const img = el('img', { src: r.thumb, alt: r.name, loading: 'lazy' });
      if (r.half) img.className = 'half';
      thumb.append(img);
    } else {
      thumb.append(el('div', { class: 'placeholder', text: `${r.category}\n(no thumbnail)` }));
    }
    const kinds = el('div', { class: 'kinds' });
    for (const [k, n] of Object.entries(r.kinds)) kinds.append(el('span', { class: 'kind', text: `${k} ×${n}` }));
    const meta = el('div', { class: 'meta' },
      el('b', { text: r.category }), ` · seed ${r.seed}`, el('br'),
      `${r.joints} movable joint${r.joints === 1 ? '' : 's'} · ${r.links} links · ${r.mass.toFixed(2)} kg`, kinds);
    const card = el('div', { class: 'card', tabindex: '0', 'data-index': String(i), title: r.path }, thumb, meta);
    card.addEventListener('click', () => { location.hash = 'object=' + i; });
    card.addEventListener('keydown', (e) => { if (e.key === 'Enter') location.hash = 'object=' + i; });
    return card;
  }

  function renderCards() {
    const n = G.filtered.length, pages = Math.max(1, Math.ceil(n / PAGE));
    G.page = Math.min(G.page, pages - 1);
    const frag = document.createDocumentFragment();
    for (const i of G.filtered.slice(G.page * PAGE, (G.page + 1) * PAGE)) frag.append(cardFor(i));
    const cards = $('cards');
    cards.replaceChildren(frag);
    $('summary').textContent = `${n} of ${G.data.objects.length} objects`;
    const pager = $('pager');
    pager.replaceChildren();
    if (pages > 1) {
      const prev = el('button', { id: 'page-prev', text: '‹ previous' });
      const next = el('button', { id: 'page-next', text: 'next ›' });
      prev.disabled = G.page === 0;
      next.disabled = G.page >= pages - 1;
      prev.onclick = () => { G.page--; renderCards(); scrollTo(0, 0); };
      next.onclick = () => { G.page++; renderCards(); scrollTo(0, 0); };
      pager.append(prev, el('span', { id: 'page-label', text: `page ${G.page + 1} of ${pages}` }), next);
    }
    document.body.dataset.cards = 'ready';
  }

  // ------------------------------------------------------------------------------------ scenes

  function sceneCard(r) {
    const pics = el('div', { class: 'scene-pics' });
    for (const [url, label] of [[r.rest, 'at rest'], [r.open, 'every joint open']]) {
      pics.append(url ? el('figure', {}, el('img', { src: url, alt: `${r.name} ${label}`, loading: 'lazy' }),
                           el('figcaption', { text: label }))
                      : el('div', { class: 'placeholder', text: `${r.kind}\n(no picture: infmob preview ${r.path})` }));
    }
    const room = r.room.map((v) => v.toFixed(2)).join(' × ');
    const meta = el('div', { class: 'meta' }, el('b', { text: r.name }),
      ` · ${r.kind}${r.layout ? ' (' + r.layout.replace(/_/g, ' ') + ')' : ''} · seed ${r.seed}`, el('br'),
      `${r.objects} objects (${r.fixed} fixed) · room ${room} m · ${r.path}`);
    return el('div', { class: 'scene-card' }, pics, meta);
  }

  function renderScenes() {
    const box = $('scene-cards');
    if (box.dataset.done) return;
    box.replaceChildren(...G.data.scenes.map(sceneCard));
    box.dataset.done = '1';
  }

  // ------------------------------------------------------------------------------------ statistics (SVG)

  const SVGNS = 'http://www.w3.org/2000/svg';
  function svg(tag, attrs, text) {
    const e = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (text != null) e.textContent = text;
    return e;
  }
  const PALETTE = ['#2a6fdb', '#e8743b', '#19a979', '#ed4a7b', '#945ecf', '#13a4b4', '#525df4', '#bf399e', '#6c8893', '#ee6868'];

  function barChart(labels, values, opts) {
    // horizontal bars: one row per label; opts.refs = [{label, value, color}] draws vertical lines
    const o = Object.assign({ width: 640, row: 18, left: 150, fmt: (v) => v.toFixed(2), refs: [] }, opts);
    const max = Math.max(1e-9, ...values, ...o.refs.map((r) => r.value));
    const h = labels.length * o.row + 30;
    const s = svg('svg', { width: o.width, height: h, viewBox: `0 0 ${o.width} ${h}`, role: 'img' });
    const w = o.width - o.left - 60;
    labels.forEach((lab, i) => {
      const y = i * o.row + 4, bw = (values[i] / max) * w;
      s.append(svg('text', { x: o.left - 6, y: y + o.row * 0.65, 'text-anchor': 'end', 'font-size': 11 }, lab));
      const rect = svg('rect', { x: o.left, y: y + 2, width: Math.max(0, bw), height: o.row - 5, fill: o.color || PALETTE[0] });
      rect.append(svg('title', {}, `${lab}: ${o.fmt(values[i])}`));
      s.append(rect);
      s.append(svg('text', { x: o.left + bw + 4, y: y + o.row * 0.65, 'font-size': 10, fill: '#444' }, o.fmt(values[i])));
    });
    o.refs.forEach((r, k) => {
      const x = o.left + (r.value / max) * w;
      s.append(svg('line', { x1: x, x2: x, y1: 0, y2: h - 22, stroke: r.color, 'stroke-dasharray': '4 3' }));
      s.append(svg('text', { x: Math.min(x, o.width - 4), y: h - 12 + (k % 2) * 10, 'font-size': 10, fill: r.color,
        'text-anchor': x > o.width - 120 ? 'end' : 'middle' }, `${r.label} ${o.fmt(r.value)}`));
    });
    return s;
  }

  function histogram(counts, color) {
    // counts: {jointCount: objects}; vertical bars over 0..max joint count
    const keys = Object.keys(counts).map(Number);
    const maxK = Math.max(...keys), maxV = Math.max(...Object.values(counts));
    const W = 200, H = 110, L = 24, B = 18, bw = (W - L - 4) / (maxK + 1);
    const s = svg('svg', { width: W, height: H, viewBox: `0 0 ${W} ${H}`, role: 'img' });
    s.append(svg('line', { x1: L, x2: W - 2, y1: H - B, y2: H - B, stroke: '#999' }));
    s.append(svg('text', { x: L - 3, y: 10, 'text-anchor': 'end', 'font-size': 9 }, String(maxV)));
    for (let k = 0; k <= maxK; k++) {
      const v = counts[k] || 0, bh = (v / maxV) * (H - B - 8);
      const r = svg('rect', { x: L + k * bw + 0.5, y: H - B - bh, width: Math.max(1, bw - 1), height: bh, fill: color });
      r.append(svg('title', {}, `${k} joints: ${v} objects`));
      s.append(r);
      if (maxK < 12 || k % Math.ceil(maxK / 8) === 0) {
        s.append(svg('text', { x: L + (k + 0.5) * bw, y: H - 5, 'text-anchor': 'middle', 'font-size': 9 }, String(k)));
      }
    }
    return s;
  }

  function kindsChart(cats, kindNames) {
    // one stacked bar per category: share of each joint kind
    const W = 720, row = 18, L = 150, legendRows = Math.ceil(kindNames.join('____').length * 6 / (W - L)) + 1;
    const H = cats.length * row + 14 + legendRows * 16;
    const s = svg('svg', { width: W, height: H, viewBox: `0 0 ${W} ${H}`, role: 'img' });
    const colour = (k) => PALETTE[kindNames.indexOf(k) % PALETTE.length];
    const st = G.statsData.categories;
    cats.forEach((c, i) => {
      const kinds = st[c].joint_kinds, tot = Object.values(kinds).reduce((a, b) => a + b, 0);
      const y = i * row + 2;
      s.append(svg('text', { x: L - 6, y: y + row * 0.65, 'text-anchor': 'end', 'font-size': 11 }, c));
      let x = L;
      for (const k of kindNames) {
        if (!kinds[k]) continue;
        const w = (kinds[k] / tot) * (W - L - 10);
        const r = svg('rect', { x, y: y + 2, width: w, height: row - 5, fill: colour(k) });
        r.append(svg('title', {}, `${c}: ${k} ${kinds[k]}`));
        s.append(r);
        x += w;
      }
    });
    let lx = L, ly = cats.length * row + 10;
    for (const k of kindNames) {
      const w = 24 + k.length * 6;
      if (lx + w > W) { lx = L; ly += 16; }
      s.append(svg('rect', { x: lx, y: ly, width: 10, height: 10, fill: colour(k) }));
      s.append(svg('text', { x: lx + 13, y: ly + 9, 'font-size': 10 }, k));
      lx += w;
    }
    return s;
  }

  function renderStats() {
    const view = $('stats-view');
    if (view.dataset.done) return;
    view.dataset.done = '1';
    const st = G.statsData;
    if (!st) { view.textContent = 'no statistics in this gallery'; return; }
    const cats = Object.keys(st.categories);
    const ov = st.overall;
    const head = el('div', { class: 'chart' }, el('h3', { text: 'Dataset' }),
      el('div', { text: `${ov.objects} objects in ${cats.length} categories · movable joints per object: mean ${ov.mean_joints.toFixed(2)}, variance ${ov.var_joints.toFixed(2)} · mean tree depth ${ov.mean_depth.toFixed(2)} · mean tree edit distance ${ov.mean_ted.toFixed(2)} (${ov.ted_pairs} pairs)` }),
      el('div', { class: 'note', text: 'Figures of `infmob stats` (validate/stats.py): a compound joint counts once; TED is Zhang-Shasha over non-dummy links labelled <joint kind>:<semantic label>, at most ' + st.max_pairs + ' sampled pairs per group.' }));
    const hist = el('div', { class: 'chart', id: 'chart-histograms' }, el('h3', { text: 'Movable joints per object, per category' }));
    const sm = el('div', { class: 'small-multiples' });
    cats.forEach((c, i) => sm.append(el('figure', {}, histogram(st.histogram[c], PALETTE[i % PALETTE.length]),
      el('figcaption', { text: `${c} (${st.categories[c].objects}): mean ${st.categories[c].mean_joints.toFixed(2)}` }))));
    hist.append(sm);
    const kindNames = Object.keys(ov.joint_kinds);
    const kinds = el('div', { class: 'chart', id: 'chart-kinds' }, el('h3', { text: 'Joint kinds' }),
      barChart(kindNames, kindNames.map((k) => ov.joint_kinds[k]), { fmt: (v) => String(Math.round(v)) }),
      el('h3', { text: 'Joint kinds per category (share)' }), kindsChart(cats, kindNames));
    const refs = Object.entries(st.reference || {});
    const ref = (field) => refs.map(([name, r], k) => ({ label: name, value: r[field], color: k ? '#19a979' : '#e8743b' }));
    const ted = el('div', { class: 'chart', id: 'chart-ted' }, el('h3', { text: 'Mean tree edit distance' }),
      barChart(cats.concat(['overall']), cats.map((c) => st.categories[c].mean_ted).concat([ov.mean_ted]), { refs: ref('mean_ted') }),
      el('h3', { text: 'Mean movable joints' }),
      barChart(cats.concat(['overall']), cats.map((c) => st.categories[c].mean_joints).concat([ov.mean_joints]), { refs: ref('mean_joints'), color: PALETTE[2] }),
      el('div', { class: 'note', text: 'Dashed lines: figures reported by the Infinite Mobility paper, for reference (their trees count parts differently).' }));
    const table = el('table', { class: 'stats' });
    table.append(el('tr', {}, ...['category', 'objects', 'mean joints', 'var joints', 'depth', 'mean TED', 'kinds'].map((t) => el('th', { text: t }))));
    for (const [name, s] of Object.entries(st.categories).concat([['overall', ov]])) {
      table.append(el('tr', {}, el('td', { text: name }), el('td', { text: String(s.objects) }),
        el('td', { text: s.mean_joints.toFixed(2) }), el('td', { text: s.var_joints.toFixed(2) }),
        el('td', { text: s.mean_depth.toFixed(2) }), el('td', { text: s.mean_ted.toFixed(2) }),
        el('td', { text: kindsText(s.joint_kinds), style: 'text-align:left' })));
    }
    view.append(head, hist, kinds, ted, el('div', { class: 'chart' }, el('h3', { text: 'Table' }), table));
  }

  // ------------------------------------------------------------------------------------ OBJ parsing

  function parseOBJ(text) {
    // positions, uvs, normals of triangulated faces, one draw group per `usemtl`
    const v = [], vt = [], vn = [], pos = [], uv = [], nor = [], groups = [];
    let cur = null, hasUV = true, hasN = true;
    const lines = text.split('\n');
    for (let li = 0; li < lines.length; li++) {
      const line = lines[li];
      const c0 = line.charCodeAt(0);
      if (c0 === 118) { // v
        const p = line.trim().split(/\s+/);
        if (p[0] === 'v') v.push(+p[1], +p[2], +p[3]);
        else if (p[0] === 'vt') vt.push(+p[1], +p[2]);
        else if (p[0] === 'vn') vn.push(+p[1], +p[2], +p[3]);
      } else if (c0 === 102) { // f
        const p = line.trim().split(/\s+/).slice(1);
        if (!cur) { cur = { material: '', start: pos.length / 3 }; groups.push(cur); }
        const idx = p.map((t) => t.split('/'));
        for (let k = 1; k + 1 < idx.length; k++) {
          for (const t of [idx[0], idx[k], idx[k + 1]]) {
            let a = parseInt(t[0], 10); a = a < 0 ? v.length / 3 + a : a - 1;
            pos.push(v[3 * a], v[3 * a + 1], v[3 * a + 2]);
            if (t[1]) { let b = parseInt(t[1], 10); b = b < 0 ? vt.length / 2 + b : b - 1; uv.push(vt[2 * b], vt[2 * b + 1]); } else { hasUV = false; uv.push(0, 0); }
            if (t[2]) { let n = parseInt(t[2], 10); n = n < 0 ? vn.length / 3 + n : n - 1; nor.push(vn[3 * n], vn[3 * n + 1], vn[3 * n + 2]); } else { hasN = false; nor.push(0, 0, 0); }
          }
        }
      } else if (line.startsWith('usemtl')) {
        cur = { material: line.slice(6).trim(), start: pos.length / 3 };
        groups.push(cur);
      }
    }
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pos), 3));
    if (hasUV && uv.length) geo.setAttribute('uv', new THREE.BufferAttribute(new Float32Array(uv), 2));
    if (hasN && nor.length) geo.setAttribute('normal', new THREE.BufferAttribute(new Float32Array(nor), 3));
    else geo.computeVertexNormals();
    const used = groups.filter((g, i) => (i + 1 < groups.length ? groups[i + 1].start : pos.length / 3) > g.start);
    used.forEach((g, i) => {
      const end = i + 1 < used.length ? used[i + 1].start : pos.length / 3;
      geo.addGroup(g.start, end - g.start, i);
    });
    return { geometry: geo, materials: used.map((g) => g.material) };
  }

  // ------------------------------------------------------------------------------------ the viewer

  const bitmaps = {};  // texture hash -> Promise<ImageBitmap>, decoded once per page
  function bitmap(hash) {
    if (!bitmaps[hash]) {
      const uri = G.textures[hash], bin = atob(uri.slice(uri.indexOf(',') + 1));
      const bytes = new Uint8Array(bin.length);
      for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
      bitmaps[hash] = createImageBitmap(new Blob([bytes], { type: 'image/png' }),
        { imageOrientation: 'flipY', premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
    }
    return bitmaps[hash];
  }

  function restOf(j) { return Math.min(Math.max(0, j.lower), j.upper); }
  function fullTurn(j) { return j.type === 'continuous' || j.upper - j.lower >= 2 * Math.PI - 1e-3; }
  function openOf(j) {
    // fully open: the limit farther from rest; a joint that turns all round: a quarter turn
    if (fullTurn(j)) return restOf(j) + Math.PI / 2;
    const r = restOf(j);
    return Math.abs(j.upper - r) >= Math.abs(j.lower - r) ? j.upper : j.lower;
  }

  class Viewer {
    constructor(host) {
      this.host = host;
      this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
      this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
      this.renderer.outputColorSpace = THREE.SRGBColorSpace;
      this.renderer.toneMapping = THREE.ACESFilmicToneMapping;
      this.renderer.shadowMap.enabled = true;
      this.renderer.shadowMap.type = THREE.PCFShadowMap;
      host.append(this.renderer.domElement);
      this.scene = new THREE.Scene();
      this.scene.background = new THREE.Color(0xf2f1ee);
      const pmrem = new THREE.PMREMGenerator(this.renderer);
      this.scene.environment = pmrem.fromScene(new THREE.RoomEnvironment(), 0.04).texture;
      this.scene.environmentRotation = new THREE.Euler(Math.PI / 2, 0, 0);  // the room's up (Y) -> our Z
      this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
      this.camera.up.set(0, 0, 1);
      this.controls = new THREE.OrbitControls(this.camera, this.renderer.domElement);
      this.controls.addEventListener('change', () => this.request());
      const sun = this.sun = new THREE.DirectionalLight(0xffffff, 1.6);
      sun.castShadow = true;
      sun.shadow.mapSize.set(1024, 1024);
      this.scene.add(sun, sun.target, new THREE.HemisphereLight(0xffffff, 0x8a8478, 0.5));
      this.ground = new THREE.Mesh(new THREE.PlaneGeometry(1, 1), new THREE.ShadowMaterial({ opacity: 0.18 }));
      this.ground.receiveShadow = true;
      this.scene.add(this.ground);
      this.root = null;
      this.pending = false;
      this.anim = null;
      new ResizeObserver(() => this.resize()).observe(host);
    }

    resize() {
      const w = this.host.clientWidth, h = this.host.clientHeight;
      if (!w || !h) return;
      this.renderer.setSize(w, h, false);
      this.camera.aspect = w / h;
      this.camera.updateProjectionMatrix();
      this.request();
    }

    request() {
      if (this.pending) return;
      this.pending = true;
      requestAnimationFrame(() => { this.pending = false; this.step(); this.renderer.render(this.scene, this.camera); });
    }

    clear() {
      if (!this.root) return;
      this.scene.remove(this.root);
      this.root.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
      });
      for (const m of Object.values(this.matCache || {})) m.dispose();
      for (const t of Object.values(this.texCache || {})) t.dispose();
      this.root = null;
    }

    material(data, libs, name, loads) {
      let spec = null, lib0 = '';
      for (const lib of libs) if (data.materials[lib] && data.materials[lib][name]) { spec = data.materials[lib][name]; lib0 = lib; }
      const mkey = lib0 + '|' + name;
      if (this.matCache[mkey]) return this.matCache[mkey];
      const m = this.matCache[mkey] = this.makeMaterial(spec, loads);
      return m;
    }

    makeMaterial(spec, loads) {
      const m = new THREE.MeshStandardMaterial({ color: 0xb0b0b0, roughness: 0.6, metalness: 0 });
      if (!spec) return m;
      const tex = (hash, srgb) => {
        if (!hash || !G.textures[hash]) return null;
        const key = hash + (srgb ? ':srgb' : '');
        if (this.texCache[key]) return this.texCache[key];
        const t = this.texCache[key] = new THREE.Texture();
        t.wrapS = t.wrapT = THREE.RepeatWrapping;
        t.colorSpace = srgb ? THREE.SRGBColorSpace : THREE.NoColorSpace;
        t.flipY = false;  // the bitmap is decoded flipped (OBJ v runs up)
        t.anisotropy = 4;
        loads.push(bitmap(hash).then((b) => { t.image = b; t.needsUpdate = true; }, () => {}));
        return t;
      };
      if (spec.Kd) m.color.setRGB(spec.Kd[0], spec.Kd[1], spec.Kd[2], THREE.SRGBColorSpace);
      if (spec.Pr) m.roughness = spec.Pr[0];
      if (spec.Pm) m.metalness = spec.Pm[0];
      const map = tex(spec.map_Kd, true);
      if (map) { m.map = map; m.color.set(0xffffff); }
      const rough = tex(spec.map_Pr, false);
      if (rough) { m.roughnessMap = rough; m.roughness = 1; }
      const norm = tex(spec.norm || spec.map_Bump || spec.bump, false);
      if (norm) m.normalMap = norm;
      const d = spec.d ? spec.d[0] : 1;
      if (d < 0.999) { m.transparent = true; m.opacity = d; m.depthWrite = false; }
      m.side = THREE.DoubleSide;
      return m;
    }

    async show(data) {
      this.clear();
      this.texCache = {};
      this.matCache = {};
      const loads = [];
      const geos = data.meshes.map((m) => {
        const p = parseOBJ(m.obj);
        const mats = p.materials.map((name) => this.material(data, m.mtl, name, loads));
        return { geometry: p.geometry, materials: mats.length ? mats : [this.material(data, [], '', loads)] };
      });
      const links = {};
      for (const link of data.links) {
        const g = new THREE.Group();
        g.name = link.name;
        for (const v of link.visuals) {
          const src = geos[v.mesh];
          const mesh = new THREE.Mesh(src.geometry, src.materials.length === 1 ? src.materials[0] : src.materials);
          mesh.position.fromArray(v.xyz);
          mesh.quaternion.setFromEuler(new THREE.Euler(v.rpy[0], v.rpy[1], v.rpy[2], 'ZYX'));
          mesh.scale.fromArray(v.scale);
          mesh.castShadow = true;
          g.add(mesh);
        }
        links[link.name] = g;
      }
      const children = new Set(data.joints.map((j) => j.child));
      this.joints = [];
      for (const j of data.joints) {
        const frame = new THREE.Group(), motion = new THREE.Group();
        frame.position.fromArray(j.xyz);
        frame.quaternion.setFromEuler(new THREE.Euler(j.rpy[0], j.rpy[1], j.rpy[2], 'ZYX'));
        frame.add(motion);
        motion.add(links[j.child]);
        links[j.parent].add(frame);
        if (['revolute', 'continuous', 'prismatic'].includes(j.type)) {
          this.joints.push(Object.assign({}, j, { motion, axisV: new THREE.Vector3().fromArray(j.axis).normalize(), q: restOf(j) }));
        }
      }
      this.byName = Object.fromEntries(this.joints.map((j) => [j.name, j]));
      // requires_open: joint -> the joints that must be fully open first: those of the group it names, then
      // those of the group that group's joints name, and so on (tines on a rack behind a door); a joint's
      // stage is the length of that chain of groups (the door opens, then the rack, then the tines)
      const groupJoints = {}, gateOf = {};
      for (const j of this.joints) (groupJoints[j.group] = groupJoints[j.group] || []).push(j.name);
      for (const j of this.joints) if (j.requires_open && !(j.group in gateOf)) gateOf[j.group] = j.requires_open;
      for (const j of this.joints) {
        const chain = [];
        for (let g = j.requires_open; g && !chain.includes(g); g = gateOf[g]) chain.push(g);
        j.gate = chain.flatMap((g) => groupJoints[g] || []);
        j.stage = chain.length;
      }
      this.gates = new Set(this.joints.flatMap((j) => j.gate));
      this.links = links;
      this.root = new THREE.Group();
      for (const link of data.links) if (!children.has(link.name)) this.root.add(links[link.name]);
      this.scene.add(this.root);
      for (const j of this.joints) this.apply(j);
      await Promise.all(loads);
      this.frame();
      this.request();
    }

    apply(j) {
      if (j.type === 'prismatic') j.motion.position.copy(j.axisV).multiplyScalar(j.q);
      else j.motion.quaternion.setFromAxisAngle(j.axisV, j.q);
    }

    isOpen(j) {
      return j.gate.every((n) => { const g = this.byName[n]; return Math.abs(g.q - openOf(g)) <= 1e-3 * Math.max(1e-6, g.upper - g.lower); });
    }

    set(name, q) {
      const j = this.byName[name];
      j.q = Math.min(Math.max(q, j.lower), j.upper);
      this.apply(j);
      // the other modes of its fitting (excludes: a tilt-and-turn sash tilts or turns) go back to rest
      if (j.q !== restOf(j)) for (const n of j.excludes || []) { const k = this.byName[n]; if (k) { k.q = restOf(k); this.apply(k); } }
      // a joint behind a closed door goes back to rest, as it would in the object
      for (const k of this.joints) if (k.gate.length && !this.isOpen(k) && k.q !== restOf(k)) { k.q = restOf(k); this.apply(k); }
      this.request();
      if (this.onchange) this.onchange();
    }

    frame() {
      // camera from the front-left-above (fronts face +X), ground plane under the object at rest
      this.root.updateMatrixWorld(true);
      const box = new THREE.Box3().setFromObject(this.root);
      const c = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
      const r = Math.max(size.length() / 2, 0.05);
      const d = r / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.15;
      const dir = new THREE.Vector3(1.0, 0.75, 0.55).normalize();
      this.camera.position.copy(c).addScaledVector(dir, d);
      this.camera.near = d / 100; this.camera.far = d * 10;
      this.camera.updateProjectionMatrix();
      this.controls.target.copy(c);
      this.controls.update();
      this.ground.position.set(c.x, c.y, box.min.z - 1e-4);
      this.ground.scale.set(r * 8, r * 8, 1);
      this.sun.position.set(c.x + r * 2, c.y + r * 1.5, c.z + r * 4);
      this.sun.target.position.copy(c);
      const cam = this.sun.shadow.camera;
      cam.left = cam.bottom = -r * 2; cam.right = cam.top = r * 2; cam.near = r * 0.5; cam.far = r * 10;
      cam.updateProjectionMatrix();
    }

    animateTo(phases, ms) {
      // phases: [{name: q}, ...] run one after another, each over `ms`
      if (!(ms > 0)) {  // at once
        for (const ph of phases) for (const [n, q] of Object.entries(ph)) { const j = this.byName[n]; j.q = q; this.apply(j); }
        this.anim = null;
        this.request();
        if (this.onchange) this.onchange();
        return Promise.resolve();
      }
      return new Promise((resolve) => {
        this.anim = { phases: phases.filter((p) => Object.keys(p).length), i: 0, t0: null, from: null, ms, resolve };
        if (!this.anim.phases.length) { this.anim = null; resolve(); return; }
        this.request();
      });
    }

    step() {
      const a = this.anim;
      if (!a) return;
      const now = performance.now();
      const ph = a.phases[a.i];
      if (a.t0 === null) { a.t0 = now; a.from = Object.fromEntries(Object.keys(ph).map((n) => [n, this.byName[n].q])); }
      const t = Math.min(1, (now - a.t0) / a.ms), e = t * t * (3 - 2 * t);
      for (const [n, q] of Object.entries(ph)) { const j = this.byName[n]; j.q = a.from[n] + (q - a.from[n]) * e; this.apply(j); }
      if (t >= 1) { a.i++; a.t0 = null; }
      if (a.i >= a.phases.length) { this.anim = null; if (this.onchange) this.onchange(); a.resolve(); return; }
      if (this.onchange) this.onchange();
      this.pending = true;
      requestAnimationFrame(() => { this.pending = false; this.step(); this.renderer.render(this.scene, this.camera); });
    }

    stages() {
      // one phase per stage: the joints nothing requires open last, a door before the rack it gates
      const top = Math.max(0, ...this.joints.map((j) => j.stage));
      return Array.from({ length: top + 2 }, () => ({}));
    }

    openAll(ms) {
      // doors first (the joints others require open, the outermost first), then everything else
      // of the modes that exclude each other, the first opens (a tilt-and-turn sash turns)
      const phases = this.stages(), shut = new Set();
      for (const j of this.joints) {
        phases[this.gates.has(j.name) ? j.stage : phases.length - 1][j.name] = shut.has(j.name) ? restOf(j) : openOf(j);
        if (!shut.has(j.name)) for (const n of j.excludes || []) shut.add(n);
      }
      return this.animateTo(phases, ms);
    }

    reset(ms) {
      const phases = this.stages();
      for (const j of this.joints) phases[this.gates.has(j.name) ? j.stage : phases.length - 1][j.name] = restOf(j);
      return this.animateTo(phases.reverse(), ms);
    }

    screenBox(linkName) {
      // the link's (and its subtree's) bounding box projected to canvas pixels: [x0, y0, x1, y1]
      const g = this.links[linkName];
      this.root.updateMatrixWorld(true);
      const box = new THREE.Box3().setFromObject(g);
      const w = this.renderer.domElement.width, h = this.renderer.domElement.height;
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      for (let i = 0; i < 8; i++) {
        const p = new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z).project(this.camera);
        const x = (p.x + 1) / 2 * w, y = (1 - p.y) / 2 * h;
        x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
      }
      return [Math.max(0, x0), Math.max(0, y0), Math.min(w, x1), Math.min(h, y1)];
    }
  }

  function fmtValue(j, q) {
    return j.type === 'prismatic' ? `${(q * 1000).toFixed(0)} mm` : `${(q * 180 / Math.PI).toFixed(0)}°`;
  }

  function buildSliders(v) {
    const box = $('sliders');
    box.replaceChildren();
    const groups = {};
    for (const j of v.joints) (groups[j.group] = groups[j.group] || []).push(j);
    const rows = [];
    for (const [group, js] of Object.entries(groups)) {
      const g = el('div', { class: 'slider-group' }, el('div', { class: 'group-name', text: `${group} · ${js[0].kind}` + (js[0].role ? ` (${js[0].role})` : '') }));
      js.forEach((j, k) => {
        const input = el('input', { type: 'range', min: String(j.lower), max: String(j.upper), step: String((j.upper - j.lower) / 1000), 'data-joint': j.name });
        input.value = String(j.q);
        const value = el('span', { class: 'value' });
        const name = js.length > 1 ? `${j.type} (chain ${k + 1}/${js.length})` : j.type;
        const gate = j.requires_open ? el('div', { class: 'gate', text: `moves with ${j.requires_open} open` }) : null;
        const row = el('div', { class: 'slider' }, el('label', {}, el('span', { text: name }), value), input, gate);
        input.addEventListener('input', () => v.set(j.name, parseFloat(input.value)));
        rows.push({ j, input, value, row });
        g.append(row);
      });
      box.append(g);
    }
    if (!rows.length) box.append(el('p', { class: 'hint', text: 'This object has no movable joint.' }));
    v.onchange = () => {
      for (const r of rows) {
        r.input.value = String(r.j.q);
        r.value.textContent = fmtValue(r.j, r.j.q);
        const open = v.isOpen(r.j);
        r.input.disabled = !open || !!v.anim;
        r.row.classList.toggle('gated', !open);
      }
    };
    v.onchange();
  }

  async function openObject(i) {
    const r = G.data.objects[i];
    const box = $('viewer');
    box.hidden = false;
    box.dataset.state = 'loading';
    $('viewer-title').textContent = r.name;
    $('viewer-info').textContent = `${r.category} · seed ${r.seed} · ${r.joints} movable joints · ${r.links} links · ${r.mass.toFixed(2)} kg · ${r.path}`;
    $('sliders').replaceChildren();
    $('viewer-status').textContent = 'loading…';
    const t = [performance.now()];
    try {
      if (!window.THREE) await loadScript(PREFIX + 'assets/three.gallery.min.js');
      t.push(performance.now());
      if (!G.objects[r.key]) await loadScript(`${G.data.data}/obj/${r.key}.js`);
      const data = G.objects[r.key];
      await Promise.all(data.textures.filter((h) => !G.textures[h]).map((h) => loadScript(`${G.data.data}/tex/${h}.js`)));
      t.push(performance.now());
      await Promise.all(data.textures.map((h) => bitmap(h).catch(() => null)));  // decode before WebGL work
      t.push(performance.now());
      if (!G.viewer) G.viewer = new Viewer($('viewer-canvas'));
      G.viewer.resize();
      t.push(performance.now());
      await G.viewer.show(data);
      t.push(performance.now());
      buildSliders(G.viewer);
      G.viewer.renderer.render(G.viewer.scene, G.viewer.camera);  // compile and draw before 'ready'
      t.push(performance.now());
      G.timing = { three: t[1] - t[0], data: t[2] - t[1], decode: t[3] - t[2], viewer: t[4] - t[3], build: t[5] - t[4], draw: t[6] - t[5] };
      $('viewer-status').textContent = '';
      box.dataset.state = 'ready';
      box.dataset.key = r.key;
    } catch (e) {
      $('viewer-status').textContent = 'could not open this object: ' + e.message;
      box.dataset.state = 'error';
      console.warn(e);
    }
  }

  function closeViewer() {
    $('viewer').hidden = true;
    if (G.viewer) G.viewer.clear();
  }

  function route() {
    const h = location.hash.replace(/^#/, '');
    const stats = h === 'stats', scenes = h === 'scenes' && G.data.scenes.length > 0;
    $('objects-view').hidden = stats || scenes;
    $('filters').style.visibility = stats || scenes ? 'hidden' : '';
    $('stats-view').hidden = !stats;
    $('scenes-view').hidden = !scenes;
    $('tab-objects').classList.toggle('active', !stats && !scenes);
    $('tab-stats').classList.toggle('active', stats);
    $('tab-scenes').classList.toggle('active', scenes);
    if (stats) renderStats();
    if (scenes) renderScenes();
    const m = /^object=(\d+)$/.exec(h);
    if (m && G.data.objects[+m[1]]) openObject(+m[1]); else closeViewer();
  }

  G.start = function () {
    if (!G.data) { document.body.textContent = 'gallery data (data/index.js) is missing: run `infmob gallery DIR` again'; return; }
    G.data.scenes = G.data.scenes || [];
    $('tab-scenes').hidden = G.data.scenes.length === 0;
    $('tab-scenes').textContent = `Scenes (${G.data.scenes.length})`;
    fillFilters();
    applyFilters();
    $('viewer-close').onclick = () => { history.pushState('', '', location.pathname + location.search); route(); };
    document.addEventListener('keydown', (e) => { if (e.key === 'Escape' && !$('viewer').hidden) $('viewer-close').click(); });
    $('btn-open').onclick = () => G.viewer && G.viewer.openAll(700);
    $('btn-reset').onclick = () => G.viewer && G.viewer.reset(500);
    window.addEventListener('hashchange', route);
    route();
  };
})();
