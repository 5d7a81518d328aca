// app.js: the page. The effect's files live in a Map (name -> text, or bytes for an effect fxc
// compiled) mirrored into the module's in-memory file system under /src, where the compiler
// resolves #include among them and reads fx_2_0 binaries as hfxc does;
// every edit recompiles after a pause; a failed compile lists its errors and keeps the last
// good picture. window.hfxPage is what the tests (tests/web/) drive.
"use strict";

const $ = (id) => document.getElementById(id);
const SRC = "/src/";
const state = {files: new Map(), main: null, current: null, effect: null, timer: 0, dirty: false, diags: [],
  drag: null, camera: {yaw: 30, pitch: 25, distance: 3}};
let M = null;
let editor = null;
let suppressEdit = false;
let resolveReady;
const page = (window.hfxPage = {ready: new Promise((r) => (resolveReady = r)), firstPictureMs: null, compileMs: []});

function call(name, ret, types, args) { return M.ccall(name, ret, types, args); }

function writeFiles() {
  const FS = M.FS;
  const clear = (dir) => {
    for (const e of FS.readdir(dir)) {
      if (e === "." || e === "..") continue;
      const p = dir + "/" + e;
      if (FS.isDir(FS.stat(p).mode)) { clear(p); FS.rmdir(p); } else FS.unlink(p);
    }
  };
  clear(SRC.slice(0, -1));
  for (const [name, text] of state.files) {
    const parts = name.split("/");
    for (let i = 1; i < parts.length; i++) {
      const dir = SRC + parts.slice(0, i).join("/");
      if (!FS.analyzePath(dir).exists) FS.mkdir(dir);
    }
    FS.writeFile(SRC + name, text);
  }
}

function diagText(d) {
  const file = d.file && d.file.startsWith(SRC) ? d.file.slice(SRC.length) : d.file;
  const code = d.code ? ` X${d.code}` : "";
  return `${file}(${d.line},${d.col}): ${d.severity}${code}: ${d.message}`;
}

function showDiagnostics() {
  const list = $("diagnostics");
  list.textContent = "";
  for (const d of state.diags) {
    const li = document.createElement("li");
    li.className = d.severity;
    li.textContent = diagText(d);
    li.addEventListener("click", () => jumpTo(d));
    list.append(li);
  }
  markEditor();
}

function fileOf(d) { return d.file && d.file.startsWith(SRC) ? d.file.slice(SRC.length) : d.file; }

function markEditor() { editor.mark(state.diags.filter((d) => fileOf(d) === state.current && d.line > 0)); }

function jumpTo(d) {
  const f = fileOf(d);
  if (state.files.has(f) && f !== state.current) showFile(f);
  editor.goto(d.line, d.col);
}

// Include folders for the root: every folder above its own up to the root of what was opened
// (a dropped folder's top, a built-in group, the corpus runner's repository), as
// scripts/corpus.sh passes hfxc and hfxview -I for a game's working folder
// (`#include "DATA\Shader\Blur.inc"` from DATA/Shader/x.fx). Searched after the file's own folder.
function includeFolders(main) {
  const parts = main.split("/").slice(0, -1), dirs = [];
  while (parts.length) {
    parts.pop();
    dirs.push(SRC + parts.join("/"));
  }
  return dirs.map((d) => d.replace(/\/$/, ""));
}

function compile() {
  if (!state.main) return null;
  writeFiles();
  const t0 = performance.now();
  const include = (state.include || includeFolders(state.main)).join("\n");
  const r = JSON.parse(call("hfxw_compile", "string", ["string", "string"], [SRC + state.main, include]) || "null");
  const ms = performance.now() - t0;
  page.compileMs.push(ms);
  if (r) page.compilerMs = r.compile_ms; // the compiler alone (the rest: .hfxo, load, WebGL link)
  if (r && page.firstCompilerMs === undefined) page.firstCompilerMs = r.compile_ms; // cold: the module's first run
  state.diags = r ? r.diagnostics : [];
  if (r && r.load_error) state.diags.push({severity: "error", file: SRC + state.main, line: 0, col: 0, code: 0, message: r.load_error});
  showDiagnostics();
  const errors = state.diags.filter((d) => d.severity === "error").length;
  $("status").textContent = r && r.ok ? `compiled in ${ms.toFixed(1)} ms` : `${errors} error(s); showing the last good effect`;
  if (r && r.ok) effectChanged();
  page.lastResult = r;
  return r;
}

function scheduleCompile() {
  clearTimeout(state.timer);
  state.timer = setTimeout(compile, 300);
}

function fillSelect(sel, items) {
  sel.textContent = "";
  items.forEach((text, i) => sel.append(new Option(text || `(${i})`, i)));
}

// The panel from the effect's current values.
function buildPanel() {
  state.effect = JSON.parse(call("hfxw_describe", "string", [], []) || "null");
  if (state.effect) HfxParams.build($("params"), state.effect, {set: setParam, setTexture});
}

// A new compile: the pickers refilled; an edit of the same effect keeps the technique picked.
function effectChanged() {
  const picked = state.shownMain === state.main ? $("technique").selectedOptions[0]?.text : undefined;
  state.shownMain = state.main;
  buildPanel();
  if (!state.effect) return;
  const names = state.effect.techniques.map((t) => t.name);
  fillSelect($("technique"), names);
  if (names.includes(picked)) $("technique").value = String(names.indexOf(picked));
  fillPasses();
  requestRender();
}

function fillPasses() {
  const t = state.effect.techniques[Number($("technique").value)] || {passes: []};
  fillSelect($("pass"), ["all passes", ...t.passes]);
  call("hfxw_set_technique", null, ["number", "number"], [Number($("technique").value) || 0, -1]);
  showGlsl();
}

function showGlsl() {
  $("glsl-text").textContent = call("hfxw_glsl", "string", ["number"], [Number($("glsl-stage").value)]);
}

function setParam(name, values) {
  const err = call("hfxw_set_param", "string", ["string", "string"], [name, String(values)]);
  if (err) $("status").textContent = err;
  requestRender();
  return err;
}

async function imageRgba(blob) {
  const bmp = await createImageBitmap(blob);
  const c = new OffscreenCanvas(bmp.width, bmp.height);
  const g = c.getContext("2d");
  g.drawImage(bmp, 0, 0);
  return g.getImageData(0, 0, bmp.width, bmp.height);
}

async function setTexture(name, file) {
  const img = await imageRgba(file);
  const p = M._malloc(img.data.length);
  M.HEAPU8.set(img.data, p);
  call("hfxw_set_texture", "number", ["string", "number", "number", "number"], [name, p, img.width, img.height]);
  M._free(p);
  requestRender();
}

function requestRender() {
  if (state.dirty) return;
  state.dirty = true;
  requestAnimationFrame(render);
}

function render() {
  state.dirty = false;
  const c = state.camera;
  call("hfxw_set_camera", null, ["number", "number", "number"], [c.yaw, c.pitch, c.distance]);
  const canvas = $("view");
  call("hfxw_render", null, ["number", "number"], [canvas.width, canvas.height]);
  if (state.effect && page.firstPictureMs === null) {
    page.firstPictureMs = performance.now();
    resolveReady();
  }
}

function showFile(name) {
  state.current = name;
  $("file-list").value = name;
  suppressEdit = true;
  const content = state.files.get(name);
  editor.setText(content instanceof Uint8Array ? binaryNote(name, content) : content || "");
  editor.view.dispatch({selection: {anchor: 0}, scrollIntoView: true});
  suppressEdit = false;
  markEditor();
}

// include: the folders (relative to the files' root) to search, instead of includeFolders(main).
function setFiles(files, main, include) {
  state.files = files;
  state.main = main;
  state.include = include ? include.map((d) => (SRC + d).replace(/\/$/, "")) : null;
  $("file-list").textContent = "";
  for (const name of files.keys()) $("file-list").append(new Option(name, name));
  showFile(main);
  return compile();
}

// A folder of the built-in list (effects.js): its every file, with `name` the root.
function selectEffect(group, name, include) {
  const folder = window.HFX_EFFECTS[group];
  $("effect-list").value = group + "/" + name;
  return setFiles(new Map(Object.entries(folder)), name, include);
}

// Whether bytes start as an effect fxc compiled: fx_2_0's version token, XNA's effect header or
// an .xnb (runtime/compile_none.c knows the same three); such a file stays bytes.
function isBinaryEffect(b) {
  const starts = (m) => m.every((x, i) => b[i] === x);
  return starts([0x01, 0x09, 0xff, 0xfe]) || starts([0xcf, 0x0b, 0xf0, 0xbc]) || starts([0x58, 0x4e, 0x42]);
}

// What the editor shows for a binary: it has no source to edit (edits to it are ignored).
function binaryNote(name, bytes) {
  return `// ${name}: an effect compiled by fxc (fx_2_0, ${bytes.length} bytes), loaded as it is;\n` +
    "// its shaders' Direct3D 9 bytecode is translated to GLSL ES.\n";
}

// Files by their path in what was opened: a folder's files (picked with "Open folder…" or
// dropped) keep their paths under the folder's name, so includes resolve as on disk.
async function openFiles(list) {
  const files = new Map();
  for (const f of list) {
    const bytes = new Uint8Array(await f.arrayBuffer());
    files.set(f.path || f.webkitRelativePath || f.name, isBinaryEffect(bytes) ? bytes : new TextDecoder().decode(bytes));
  }
  const names = [...files.keys()];
  const main = names.find((n) => /\.fx$/i.test(n)) || names.find((n) => files.get(n) instanceof Uint8Array) || names[0];
  if (main) setFiles(files, main);
}

// A drop's files, folders walked (their entries), each as {path, arrayBuffer}.
async function droppedFiles(dt) {
  const entries = [...dt.items].map((i) => i.webkitGetAsEntry && i.webkitGetAsEntry()).filter(Boolean);
  if (!entries.some((e) => e.isDirectory)) return [...dt.files];
  const out = [];
  const walk = async (e) => {
    if (e.isFile) {
      const f = await new Promise((ok, fail) => e.file(ok, fail));
      out.push({path: e.fullPath.replace(/^\//, ""), arrayBuffer: () => f.arrayBuffer()});
    } else if (e.isDirectory) {
      const reader = e.createReader();
      for (let batch; (batch = await new Promise((ok, fail) => reader.readEntries(ok, fail))).length;)
        for (const child of batch) await walk(child);
    }
  };
  for (const e of entries) await walk(e);
  return out.sort((a, b) => (a.path < b.path ? -1 : 1));
}

function fillEffectList() {
  const sel = $("effect-list");
  for (const [group, folder] of Object.entries(window.HFX_EFFECTS || {})) {
    const og = document.createElement("optgroup");
    og.label = group;
    for (const name of Object.keys(folder).filter((n) => /\.fx$/i.test(n)).sort()) og.append(new Option(name, group + "/" + name));
    sel.append(og);
  }
  sel.addEventListener("change", () => {
    const [group, ...rest] = sel.value.split("/");
    selectEffect(group, rest.join("/"));
  });
}

function wireCamera() {
  const canvas = $("view");
  canvas.addEventListener("pointerdown", (e) => { state.drag = {x: e.clientX, y: e.clientY}; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener("pointerup", () => (state.drag = null));
  canvas.addEventListener("pointermove", (e) => {
    if (!state.drag) return;
    state.camera.yaw -= (e.clientX - state.drag.x) * 0.5;
    state.camera.pitch = Math.max(-89, Math.min(89, state.camera.pitch + (e.clientY - state.drag.y) * 0.5));
    state.drag = {x: e.clientX, y: e.clientY};
    requestRender();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    state.camera.distance = Math.max(1.2, Math.min(20, state.camera.distance * (e.deltaY > 0 ? 1.1 : 1 / 1.1)));
    requestRender();
  });
}

async function setMesh(value) {
  if (value === "obj") { $("obj-file").click(); return ""; }
  const err = call("hfxw_set_mesh", "string", ["string"], [value]);
  requestRender();
  return err;
}

function wireControls() {
  $("technique").addEventListener("change", () => { fillPasses(); requestRender(); });
  $("pass").addEventListener("change", () => {
    call("hfxw_set_technique", null, ["number", "number"], [Number($("technique").value), Number($("pass").value) - 1]);
    showGlsl();
    requestRender();
  });
  $("blend-add").addEventListener("change", () => {
    call("hfxw_set_blend_add", null, ["number"], [$("blend-add").checked ? 1 : 0]);
    requestRender();
  });
  $("mesh").addEventListener("change", () => setMesh($("mesh").value));
  $("obj-file").addEventListener("change", async () => {
    const f = $("obj-file").files[0];
    if (!f) return;
    M.FS.writeFile("/mesh.obj", await f.text());
    const err = call("hfxw_set_mesh", "string", ["string"], ["/mesh.obj"]);
    $("status").textContent = err || `${f.name} loaded`;
    requestRender();
  });
  $("file-list").addEventListener("change", () => showFile($("file-list").value));
  $("open-files").addEventListener("change", () => openFiles($("open-files").files));
  $("open-folder").addEventListener("change", () =>
    openFiles([...$("open-folder").files].sort((a, b) => (a.webkitRelativePath < b.webkitRelativePath ? -1 : 1))));
  $("glsl-stage").addEventListener("change", showGlsl);
  for (const b of document.querySelectorAll(".tabs button[data-tab]"))
    b.addEventListener("click", () => {
      for (const x of document.querySelectorAll(".tabs button[data-tab]")) x.classList.toggle("active", x === b);
      for (const t of document.querySelectorAll(".tab")) t.hidden = t.id !== b.dataset.tab;
      showGlsl();
    });
  $("download").addEventListener("click", downloadHfxo);
  document.addEventListener("dragover", (e) => { e.preventDefault(); document.body.classList.add("dropping"); });
  document.addEventListener("dragleave", () => document.body.classList.remove("dropping"));
  document.addEventListener("drop", (e) => {
    e.preventDefault();
    document.body.classList.remove("dropping");
    droppedFiles(e.dataTransfer).then(openFiles);
  });
}

function downloadHfxo() {
  const n = call("hfxw_hfxo_size", "number", [], []);
  if (!n) return;
  const p = call("hfxw_hfxo", "number", [], []);
  const blob = new Blob([M.HEAPU8.slice(p, p + n)], {type: "application/octet-stream"});
  const a = Object.assign(document.createElement("a"), {href: URL.createObjectURL(blob), download: state.main.replace(/\.[^./]*$/, "") + ".hfxo"});
  a.click();
  URL.revokeObjectURL(a.href);
}

// What the tests use: the same paths the controls take.
Object.assign(page, {
  selectEffect, setParam, setMesh,
  setCamera(yaw, pitch, distance) { state.camera = {yaw, pitch, distance}; requestRender(); },
  // Time parameters fixed at `seconds` (< 0: the page's clock again), as hfxview's headless 1 s.
  setClock(seconds) { call("hfxw_set_clock", null, ["number"], [seconds]); requestRender(); },
  edit(text) { editor.setText(text); },
  renderNow() { render(); },
  // The panel rebuilt from the effect's current values (after setParam from outside the panel).
  refreshPanel() { buildPanel(); },
  camera: () => ({...state.camera}),
  // Pixel (x, y) counted from the top left, as RGBA bytes.
  pixel(x, y) {
    const canvas = $("view");
    const gl = canvas.getContext("webgl2");
    const out = new Uint8Array(4);
    gl.readPixels(x, canvas.height - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return Array.from(out);
  },
  // A solid or small texture from RGBA bytes (top row first), as a picked image would be.
  setTextureRgba(name, width, height, bytes) {
    const p = M._malloc(bytes.length);
    M.HEAPU8.set(bytes, p);
    call("hfxw_set_texture", "number", ["string", "number", "number", "number"], [name, p, width, height]);
    M._free(p);
    requestRender();
  },
  // The whole frame as the framebuffer holds it: RGBA bytes, top row first, base64. Not the
  // canvas's toDataURL, which takes the colours as premultiplied by alpha and divides them by
  // it; hfxview's PNG (scripts/corpus.sh compare) has the framebuffer's bytes.
  frame() {
    const canvas = $("view"), gl = canvas.getContext("webgl2"), w = canvas.width, h = canvas.height;
    const rows = new Uint8Array(w * h * 4), out = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, rows);
    for (let y = 0; y < h; y++) out.set(rows.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    let text = "";
    for (let i = 0; i < out.length; i += 0x8000) text += String.fromCharCode.apply(null, out.subarray(i, i + 0x8000));
    return {width: w, height: h, rgba: btoa(text)};
  },
  lineCount: () => editor.view.state.doc.lines,
  editorText: () => editor.getText(),
  // The compiler alone on the current effect, `rounds` times after as many warm-up compiles:
  // the mean in ms (hfx_web.c's hfxw_compile_bench; bench/bench_web_compile natively).
  compileBench: (rounds) => call("hfxw_compile_bench", "number", ["string", "string", "number"],
    [SRC + state.main, (state.include || includeFolders(state.main)).join("\n"), rounds]),
  cursor() {
    const st = editor.view.state, at = st.selection.main.head, line = st.doc.lineAt(at);
    return {line: line.number, col: at - line.from + 1};
  },
  diagnosticsText: () => [...document.querySelectorAll("#diagnostics li")].map((li) => li.textContent),
});

createHfx().then((module) => {
  M = module;
  M.FS.mkdir("/src");
  if (call("hfxw_init", "number", ["string"], ["#view"]) !== 0) {
    $("status").textContent = "WebGL 2 is not available";
    return;
  }
  $("version").textContent = call("hfxw_version", "string", [], []);
  editor = HfxEditor.create($("editor"), (text) => {
    if (suppressEdit || state.files.get(state.current) instanceof Uint8Array) return;
    state.files.set(state.current, text);
    scheduleCompile();
  });
  fillEffectList();
  wireControls();
  wireCamera();
  const groups = window.HFX_EFFECTS || {};
  const first = groups.seed && groups.seed["spot_specular.fx"] ? ["seed", "spot_specular.fx"]
    : [Object.keys(groups)[0], Object.keys(groups[Object.keys(groups)[0]] || {}).find((n) => /\.fx$/i.test(n))];
  if (first[0] && first[1]) selectEffect(first[0], first[1]);
});
