// dualhex atlas page: builds the three.js view of the page's scene (embedded JSON, see
// atlas/include/dualhex/atlas/scene.hpp) and the tables beside it.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("atlas-data").textContent);
  if (!data) return;  // the index has no scene

  const BACKGROUND = 0xf7f7f2;  // the browser test compares canvas pixels with this colour
  const ROLE_COLOURS = { chain: 0x4e79a7, bend: 0xf28e2b, lid: 0x59a14f, corner: 0xe15759,
                         rest: 0xb07aa1, hex: 0xbab0ac, fine: 0xdcdcdc };
  const SIZE_COLOURS = { 3: 0xe15759, 4: 0xd0d0d0, 5: 0x4e79a7, 6: 0xf28e2b, 7: 0x76b7b2 };
  const HEX_EDGES = [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,7],[7,4],[0,4],[1,5],[2,6],[3,7]];
  const scene = data.scene;

  function element(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = String(text);
    return e;
  }

  // ---- geometry helpers (lattice coordinates, centred and scaled to about [-1, 1]) ----
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const v of scene.vertices)
    for (let a = 0; a < 3; ++a) { lo[a] = Math.min(lo[a], v[a]); hi[a] = Math.max(hi[a], v[a]); }
  const centre = lo.map((l, a) => (l + hi[a]) / 2);
  const scale = 2 / Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const world = (p) => p.map((x, a) => (x - centre[a]) * scale);

  function halfFaceLoop(h) {
    const loop = scene.faces[h[0]];
    return h[1] === 0 ? loop : [loop[0]].concat(loop.slice(1).reverse());
  }
  const cellCentres = scene.cells.map((c) => {
    const seen = new Set();
    for (const h of c.faces) for (const v of scene.faces[h[0]]) seen.add(v);
    const s = [0, 0, 0];
    for (const v of seen) for (let a = 0; a < 3; ++a) s[a] += scene.vertices[v][a];
    return world(s.map((x) => x / seen.size));
  });
  function elementColour(name) {  // a stable hue per element name
    let h = 0;
    for (const ch of name) h = (h * 31 + ch.charCodeAt(0)) % 360;
    return new THREE.Color().setHSL(h / 360, 0.55, 0.55).getHex();
  }
  function cellColour(cell, faceSize, mode) {
    if (mode === "size") return SIZE_COLOURS[faceSize] !== undefined ? SIZE_COLOURS[faceSize] : 0x222222;
    if (mode === "element") return cell.role === "fine" ? ROLE_COLOURS.fine : elementColour(cell.element);
    return ROLE_COLOURS[cell.role] !== undefined ? ROLE_COLOURS[cell.role] : 0x888888;
  }

  // ---- the view ----
  // Configurations open with the plain and fine hexes hidden: the elements are the point.
  const configuration = data.kind === "transition" || data.kind === "weak";
  const state = { explode: 0.35, mode: "role", cells: true, plain: !configuration, dual: false, clip: false, clipAxis: "x", clipAt: 0.0 };
  // The URL fragment may preset the controls, e.g. page.html#mode=size&dual=1&clip=1&clipAt=0.2
  for (const [k, v] of new URLSearchParams(location.hash.slice(1))) {
    if (!(k in state)) continue;
    state[k] = typeof state[k] === "boolean" ? v === "1" : typeof state[k] === "number" ? parseFloat(v) : v;
  }
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setSize(720, 540);
  renderer.setClearColor(BACKGROUND);
  renderer.localClippingEnabled = true;
  const camera = new THREE.PerspectiveCamera(35, 720 / 540, 0.1, 100);
  camera.position.set(0, 0, 6.5);
  const world3 = new THREE.Scene();
  world3.add(new THREE.AmbientLight(0xffffff, 0.55));
  const light = new THREE.DirectionalLight(0xffffff, 0.6);
  light.position.set(1, 2, 3);
  camera.add(light);
  world3.add(camera);
  const model = new THREE.Group();
  model.quaternion.setFromEuler(new THREE.Euler(-0.55, 0.75, 0));
  world3.add(model);
  // The materials clip by clipPlane (world space); it follows clipInModel (the model's frame).
  const clipPlane = new THREE.Plane(), clipInModel = new THREE.Plane();

  function buildCells() {
    const pos = [], col = [], edges = [];
    const colour = new THREE.Color();
    scene.cells.forEach((cell, c) => {
      if (!state.plain && (cell.role === "fine" || cell.role === "hex")) return;
      const shift = cellCentres[c].map((x) => x * state.explode);
      const at = (v) => world(scene.vertices[v]).map((x, a) => x + shift[a]);
      for (const h of cell.faces) {
        const loop = halfFaceLoop(h).map(at);
        colour.setHex(cellColour(cell, loop.length, state.mode));
        for (let i = 1; i + 1 < loop.length; ++i)  // fan: faces need not be planar
          for (const p of [loop[0], loop[i], loop[i + 1]]) { pos.push(...p); col.push(colour.r, colour.g, colour.b); }
        loop.forEach((p, i) => edges.push(...p, ...loop[(i + 1) % loop.length]));
      }
    });
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(pos, 3));
    g.setAttribute("color", new THREE.Float32BufferAttribute(col, 3));
    g.computeVertexNormals();
    const planes = state.clip ? [clipPlane] : [];
    const mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors,
      side: THREE.DoubleSide, clippingPlanes: planes, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
    const eg = new THREE.BufferGeometry();
    eg.setAttribute("position", new THREE.Float32BufferAttribute(edges, 3));
    return [mesh, new THREE.LineSegments(eg, new THREE.LineBasicMaterial({ color: 0x333333, clippingPlanes: planes }))];
  }
  function buildDual() {
    const pts = scene.dual.points.map((p) => world([p[0] / p[3], p[1] / p[3], p[2] / p[3]]));
    const seg = [];
    for (const hex of scene.dual.hexes) for (const [a, b] of HEX_EDGES) seg.push(...pts[hex[a]], ...pts[hex[b]]);
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(seg, 3));
    return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0xc0142c,
      clippingPlanes: state.clip ? [clipPlane] : [] }));
  }
  function rebuild() {
    while (model.children.length) {
      const o = model.children.pop();
      o.geometry.dispose();
      o.material.dispose();
    }
    if (state.cells) for (const o of buildCells()) model.add(o);
    if (state.dual) model.add(buildDual());
    // keeps the side below clipAt along the axis of the model
    clipInModel.normal.set(state.clipAxis === "x" ? -1 : 0, state.clipAxis === "y" ? -1 : 0, state.clipAxis === "z" ? -1 : 0);
    clipInModel.constant = state.clipAt;
    render();
  }
  let zoom = 1;
  function render() {
    camera.position.z = 5.8 * (1 + state.explode) * zoom;  // the exploded model stays in view
    model.updateMatrixWorld();
    clipPlane.copy(clipInModel).applyMatrix4(model.matrixWorld);
    renderer.render(world3, camera);
  }

  // ---- mouse: drag rotates, wheel zooms ----
  let drag = null;
  const canvas = renderer.domElement;
  canvas.addEventListener("mousedown", (e) => { drag = [e.clientX, e.clientY]; });
  window.addEventListener("mouseup", () => { drag = null; });
  window.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const q = new THREE.Quaternion().setFromEuler(new THREE.Euler((e.clientY - drag[1]) * 0.01, (e.clientX - drag[0]) * 0.01, 0));
    model.quaternion.premultiply(q);
    drag = [e.clientX, e.clientY];
    render();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    zoom = Math.min(5, Math.max(0.3, zoom * (e.deltaY > 0 ? 1.1 : 0.9)));
    render();
  });

  // ---- controls ----
  function control(label, input, onChange) {
    const l = element("label", {}, label + " ");
    l.appendChild(input);
    input.addEventListener("input", () => { onChange(input); rebuild(); });
    return l;
  }
  function checkbox(key) {
    const c = element("input", { type: "checkbox", "data-control": key });
    c.checked = state[key];
    return control(key === "plain" ? "plain hexes" : key === "dual" ? "dual hexes" : key, c, (i) => { state[key] = i.checked; });
  }
  function slider(key, min, max) {
    const s = element("input", { type: "range", min: min, max: max, step: "0.01", value: state[key], "data-control": key });
    return control(key === "clipAt" ? "at" : key, s, (i) => { state[key] = parseFloat(i.value); });
  }
  const modes = element("select", { "data-control": "mode" });
  for (const m of ["role", "size", "element"]) modes.appendChild(element("option", { value: m }, m === "size" ? "face size" : m));
  modes.value = state.mode;
  const axes = element("select", { "data-control": "clipAxis" });
  for (const a of ["x", "y", "z"]) axes.appendChild(element("option", { value: a }, a));
  axes.value = state.clipAxis;
  const controls = element("div", { class: "controls" });
  controls.append(slider("explode", 0, 1.5), control("colour by", modes, (i) => { state.mode = i.value; }),
                  checkbox("cells"), checkbox("plain"), checkbox("dual"), checkbox("clip"),
                  control("along", axes, (i) => { state.clipAxis = i.value; }), slider("clipAt", -1.2, 1.2));
  const legend = element("div", { class: "legend" });
  function fillLegend() {
    legend.innerHTML = "";
    const entries = state.mode === "size" ? Object.keys(SIZE_COLOURS).map((k) => [k + "-gon", SIZE_COLOURS[k]])
      : state.mode === "role" ? Object.keys(ROLE_COLOURS).map((k) => [k, ROLE_COLOURS[k]])
      : [...new Set(scene.cells.map((c) => c.element))].map((n) => [n, n === "fine" ? ROLE_COLOURS.fine : elementColour(n)]);
    for (const [name, c] of entries) {
      const s = element("span", {}, name);
      s.style.background = "#" + c.toString(16).padStart(6, "0");
      legend.appendChild(s);
    }
  }
  modes.addEventListener("input", fillLegend);

  // ---- tables and links ----
  function tableElement(t) {
    const table = element("table", { "data-table": t.id });
    table.appendChild(element("caption", {}, t.title));
    const head = element("tr");
    for (const c of t.columns) head.appendChild(element("th", {}, c));
    table.appendChild(head);
    for (const row of t.rows) {
      const tr = element("tr", { "data-key": String(row[0]) });
      for (const v of row) tr.appendChild(element("td", {}, v === null ? "-" : v));
      table.appendChild(tr);
    }
    return table;
  }
  const viewer = element("div", { class: "viewer" });
  viewer.append(canvas, controls, legend);
  const side = element("div", { class: "side" });
  side.appendChild(element("p", { class: "summary" }, data.summary));
  for (const t of data.tables) side.appendChild(tableElement(t));
  const links = element("div", { class: "links" });
  for (const l of data.links) links.appendChild(element("a", { href: l.href }, l.text));
  side.appendChild(links);
  document.getElementById("page").append(viewer, side);
  fillLegend();
  rebuild();
  const r = canvas.getBoundingClientRect();  // for the browser test's screenshot crop
  document.body.setAttribute("data-canvas", [r.left, r.top, r.width, r.height].map(Math.round).join(","));
})();
