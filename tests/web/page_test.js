// page_test.js: the web page (web/) in headless Chromium (Debian's, WebGL 2 on SwiftShader),
// driven by playwright-core. Loads the page from disk (file://, as a user would open it), then:
//   - each seed case of web_expect: the effect picked from the list, its technique, the plane,
//     the camera, the parameters; the centre pixel against the seed equations' colour, a corner
//     against the clear colour (within 2/255, as tests/seeds/ probe);
//     (multilights_repaired.fx: both passes, the second added by the application);
//   - spot_specular.fx's ks slider moved in the panel: the pixel follows the equation;
//   - multilights_repaired.fx's struct-array lights switched in the panel;
//   - the orbit camera dragged with the mouse and back, the wheel zoom;
//   - an error typed into the editor: the located message and the editor's mark;
//   - multilights.fx: X3013 at (204,20); a warning (X3206) listed, marked, clickable;
//   - a PNG picked for a texture, several files opened with an #include among them, files
//     dropped (with the include, and without it: X1507), an OBJ mesh, the GLSL tab, the .hfxo download;
//   - a folder opened: an include found from its root (scripts/corpus.sh's include folders);
//   - the mesh following the effect as hfxview's (the screen rectangle for a ViewportSize pass);
//   - an fx_2_0 binary dropped (hfxc /T fx_2_0 /Fo of a source here): drawn, ShaderIndex switching;
//   - hfxview's default 2D, cube and volume textures; time parameters on a fixed clock;
//   - screenshots of three seeds, and the page's timings (first picture, compile).
// Exit 77 (skip) only when Chromium cannot start or the seed corpus is absent.
//   node page_test.js --site DIR --expect WEB_EXPECT --shots DIR [--hfxc HFXC]
"use strict";
const {execFileSync} = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

const arg = (name) => process.argv[process.argv.indexOf("--" + name) + 1];
const site = arg("site"), shots = arg("shots");
const TOLERANCE = 2; // in 1/255 steps, as tests/seeds/
let failures = 0;

function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

function near(got, want, tol = TOLERANCE) {
  return got.every((g, i) => Math.abs(g - want[i] * 255) <= tol);
}
const show = (bytes) => "(" + bytes.join(", ") + ")";
const showWant = (c) => "(" + c.map((x) => (x * 255).toFixed(1)).join(", ") + ")";

function loadPlaywright() {
  try {
    return require(path.join(__dirname, "../../web/node_modules/playwright-core"));
  } catch (e) {
    console.log("FAIL playwright-core is not installed: scripts/web.sh runs npm ci in web/");
    process.exit(1);
  }
}

async function launch(chromium) {
  try {
    return await chromium.launch({executablePath: "/usr/bin/chromium",
      args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
        "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"]});
  } catch (e) {
    console.log("SKIP: Chromium cannot start here (" + String(e.message).split("\n")[0] + ")");
    process.exit(77);
  }
}

// The case's scene through the page's own paths (effect list, technique picker, mesh picker,
// camera, panel setter), then one frame.
async function setUp(page, c, eye) {
  return page.evaluate(async ({c, eye}) => {
    const p = window.hfxPage;
    const r = p.selectEffect("seed", c.file);
    if (!r || !r.ok) return {error: p.diagnosticsText().join("\n") || "no result"};
    const tech = document.getElementById("technique");
    const i = [...tech.options].findIndex((o) => o.text === c.technique);
    tech.value = String(i);
    tech.dispatchEvent(new Event("change"));
    const add = document.getElementById("blend-add"); // the application's additive blending of passes 2..
    if (add.checked !== !!c.addPasses) {
      add.checked = !!c.addPasses;
      add.dispatchEvent(new Event("change"));
    }
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    for (const [name, values] of c.params) {
      const err = p.setParam(name, values === "CAMERA" ? eye : values);
      if (err) return {error: `${name}: ${err}`};
    }
    if (c.texture) p.setTextureRgba(c.texture[0], 2, 2, Array(4).fill(c.texture.slice(1)).flat());
    p.renderNow();
    return {centre: p.pixel(256, 256), corner: p.pixel(4, 4)};
  }, {c, eye});
}

async function seedCases(page, x) {
  for (const c of x.cases) {
    const got = await setUp(page, c, x.camera.eye);
    if (got.error) {
      check(false, `${c.file}: ${got.error}`);
      continue;
    }
    check(near(got.centre, c.expect), `${c.file} ${c.technique}: centre ${show(got.centre)} expected ${showWant(c.expect)}`);
    check(near(got.corner, x.clear), `${c.file}: corner ${show(got.corner)} is the clear colour ${showWant(x.clear)}`);
  }
}

// The ks slider of the panel, moved as a user drags it (an input event on the range).
async function slider(page, x) {
  const c = x.cases.find((k) => k.file === x.slider.file);
  const before = await setUp(page, c, x.camera.eye);
  const after = await page.evaluate(({name, value}) => {
    const range = document.querySelector(`#params input[type=range][data-param="${name}"]`);
    if (!range) return null;
    range.value = String(value);
    range.dispatchEvent(new Event("input"));
    window.hfxPage.renderNow();
    return window.hfxPage.pixel(256, 256);
  }, {name: x.slider.param, value: x.slider.value});
  check(after !== null, `${x.slider.file}: the panel has a slider for ${x.slider.param}`);
  if (!after) return;
  check(near(after, x.slider.expect), `slider ${x.slider.param} = ${x.slider.value}: ${show(after)} expected ${showWant(x.slider.expect)} (was ${show(before.centre)})`);
}

// An undeclared name typed at the end of the file: where fxc puts X3004, and the editor's mark.
async function typedError(page) {
  await page.evaluate(() => window.hfxPage.selectEffect("seed", "spot_specular.fx"));
  const lines = await page.evaluate(() => document.querySelectorAll(".cm-content .cm-line").length);
  await page.click(".cm-content");
  await page.keyboard.press("Control+End");
  await page.keyboard.type("\nfloat4 broken = undefined_thing;");
  const want = /^spot_specular\.fx\((\d+),17\): error X3004: undeclared identifier 'undefined_thing'$/;
  await page.waitForFunction(() => window.hfxPage.diagnosticsText().some((t) => t.includes("undefined_thing")), null, {timeout: 10000})
    .catch(() => {});
  const texts = await page.evaluate(() => window.hfxPage.diagnosticsText());
  const hit = texts.find((t) => want.test(t));
  check(!!hit, `typed error listed as file(line,col): error X3004: ... (${texts.find((t) => t.includes("undefined")) || texts.join(" | ")})`);
  const docLines = await page.evaluate(() => window.hfxPage.lineCount());
  if (hit) check(Number(want.exec(hit)[1]) === docLines, `the error is on the last line, ${docLines} (the file had ${lines} visible lines)`);
  const mark = await page.evaluate(() => [...document.querySelectorAll(".cm-lintRange-error")].map((e) => e.textContent));
  check(mark.includes("undefined_thing"), `the editor marks 'undefined_thing' (${JSON.stringify(mark)})`);
  await page.click("#diagnostics li.error");
  const cursor = await page.evaluate(() => window.hfxPage.cursor());
  check(cursor.line === docLines && cursor.col === 17, `clicking the message puts the cursor at ${cursor.line}:${cursor.col}`);
}

// multilights_repaired.fx's lights are arrays of structs: the panel folds their members under
// each array's name; switching two lights there (an int field each, as the effect declares
// Encender) changes the centre pixel as the equations say.
async function structPanel(page, x) {
  const c = x.cases.find((k) => k.file === x.panel.file);
  await setUp(page, c, x.camera.eye);
  await page.evaluate(() => window.hfxPage.refreshPanel());
  const groups = await page.evaluate(() => [...document.querySelectorAll("#params details")].map((d) => d.dataset.group));
  check(["direccionales", "puntuales", "spots"].every((g) => groups.includes(g)), `panel groups for the struct arrays (${groups})`);
  for (const [name] of x.panel.set) await page.click(`#params details[data-group="${name.split("[")[0]}"] > summary`);
  const r = await page.evaluate(({set}) => {
    const shown = [];
    for (const [name, value] of set) {
      const box = document.querySelector(`#params [data-param="${name}"]`);
      const field = box && (box.matches("input") ? box : box.querySelector("input"));
      if (!field) return {missing: name};
      shown.push(`${name}=${field.value}${field.checkVisibility() ? "" : " (hidden)"}`);
      field.value = value;
      field.dispatchEvent(new Event("change"));
    }
    window.hfxPage.renderNow();
    return {shown, centre: window.hfxPage.pixel(256, 256)};
  }, {set: x.panel.set});
  check(!r.missing, `the panel has a field for ${r.missing || x.panel.set.map((p) => p[0]).join(", ")} (${r.shown})`);
  if (r.missing) return;
  check(r.shown.join() === "puntuales[0].Encender=1,spots[1].Encender=0", `the fields showed the values set (${r.shown})`);
  check(near(r.centre, x.panel.expect), `panel: ${x.panel.set.map((p) => p.join("=")).join(", ")}: centre ${show(r.centre)} expected ${showWant(x.panel.expect)}`);
}

async function multilights(page) {
  const r = await page.evaluate(() => {
    const res = window.hfxPage.selectEffect("seed", "multilights.fx");
    return {ok: res && res.ok, texts: window.hfxPage.diagnosticsText()};
  });
  check(r.ok === false, "multilights.fx does not compile");
  check(r.texts.some((t) => /^multilights\.fx\(204,20\): error X3013: /.test(t)), `multilights.fx: X3013 at (204,20) (${r.texts.find((t) => t.includes("X3013"))})`);
  // The editor draws only the lines in view: the message's click scrolls line 204 there.
  await page.click("#diagnostics li.error");
  const view = await page.evaluate(() => ({cursor: window.hfxPage.cursor(),
    marks: [...document.querySelectorAll(".cm-lintRange-error")].map((e) => e.textContent)}));
  check(view.cursor.line === 204 && view.cursor.col === 20, `clicking X3013 puts the cursor at ${view.cursor.line}:${view.cursor.col}`);
  check(view.marks.length > 0, `multilights.fx: marked in the editor at line 204 (${JSON.stringify(view.marks)})`);
}

// Several files opened at once (the file picker; a drop gives the page the same list): the
// root's #include resolves among them. The include supplies the colour a flat pixel shader
// writes, so the centre pixel shows whether it was read.
const INCLUDING = `#include "colour.fxh"
float4x4 WorldViewProj : WorldViewProjection;
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 PS() : COLOR { return TINT; }
technique Flat { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
`;
const TINT = [0.25, 0.5, 0.75, 1];

async function openedFiles(page) {
  await page.setInputFiles("#open-files", [
    {name: "flat.fx", mimeType: "text/plain", buffer: Buffer.from(INCLUDING)},
    {name: "colour.fxh", mimeType: "text/plain", buffer: Buffer.from("#define TINT float4(0.25, 0.5, 0.75, 1.0)\n")}]);
  await page.waitForFunction(() => document.getElementById("file-list").options.length === 2, null, {timeout: 10000}).catch(() => {});
  const r = await page.evaluate(async () => {
    const p = window.hfxPage;
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    p.renderNow();
    return {ok: p.lastResult && p.lastResult.ok, files: [...document.getElementById("file-list").options].map((o) => o.value),
      centre: p.pixel(256, 256)};
  });
  check(r.ok && r.files.join() === "flat.fx,colour.fxh", `opened flat.fx and colour.fxh, the include resolved (${r.files})`);
  check(near(r.centre, TINT), `flat.fx: centre ${show(r.centre)} is colour.fxh's TINT ${showWant(TINT)}`);
}

// Files dropped on the editor (a real drop event: a DataTransfer holding File objects, as the
// browser makes when files are dragged from the desktop). The effect and its include: the
// page opens both and draws; the effect alone: fxc's X1507 at the #include, which starts
// line 1 at column 1, and the editor marks it.
const TINT2 = [0.75, 0.25, 0.5, 1];

async function droppedFiles(page) {
  // The page reads the files asynchronously: lastResult is cleared first to see the new compile.
  const drop = (files) => page.evaluate(async (files) => {
    window.hfxPage.lastResult = null;
    const dt = new DataTransfer();
    for (const [name, text] of files) dt.items.add(new File([text], name, {type: "text/plain"}));
    const target = document.querySelector(".cm-content");
    for (const type of ["dragenter", "dragover", "drop"])
      target.dispatchEvent(new DragEvent(type, {dataTransfer: dt, bubbles: true, cancelable: true}));
  }, files);
  const files = () => page.evaluate(() => [...document.getElementById("file-list").options].map((o) => o.value).join());
  await drop([["flat.fx", INCLUDING], ["colour.fxh", "#define TINT float4(0.75, 0.25, 0.5, 1.0)\n"]]);
  await page.waitForFunction(() => window.hfxPage.lastResult, null, {timeout: 10000}).catch(() => {});
  const r = await page.evaluate(async () => {
    const p = window.hfxPage;
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    p.renderNow();
    return {ok: p.lastResult && p.lastResult.ok, text: p.editorText(), centre: p.pixel(256, 256)};
  });
  check(r.ok && (await files()) === "flat.fx,colour.fxh", `dropped flat.fx and colour.fxh: compiled (${await files()})`);
  check(r.text === INCLUDING, "the editor shows flat.fx as dropped (nothing pasted into the old file)");
  check(near(r.centre, TINT2), `dropped flat.fx: centre ${show(r.centre)} is the dropped colour.fxh's TINT ${showWant(TINT2)}`);

  await drop([["flat.fx", INCLUDING]]);
  await page.waitForFunction(() => window.hfxPage.lastResult, null, {timeout: 10000}).catch(() => {});
  const texts = await page.evaluate(() => window.hfxPage.diagnosticsText());
  const want = "flat.fx(1,1): error X1507: failed to open source file: 'colour.fxh'";
  check(texts.includes(want) && (await files()) === "flat.fx", `dropped flat.fx alone: ${JSON.stringify(texts)} (want ${want})`);
  const marks = await page.evaluate(() => [...document.querySelectorAll(".cm-lintRange-error")].map((e) => e.textContent));
  check(marks.includes("#"), `the editor marks the #include (${JSON.stringify(marks)})`);
}

// Include folders (scripts/corpus.sh's rule for a game's working folder): an effect in
// game/DATA/Shader includes "DATA\\Shader\\tint.inc", which resolves only from game/, the
// opened folder's root. The folder picked with "Open folder…" (its files keep their paths):
// compiled, the centre is the include's TINT; through the page API with no include folders:
// fxc's X1507 at the #include; with ["game"]: compiled again.
const WORKING_FOLDER = INCLUDING.replace('#include "colour.fxh"', '#include "DATA\\Shader\\tint.inc"');
const TINT3 = [0.5, 0.75, 0.25, 1];

async function includeFolders(page) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "hfx-page-"));
  fs.mkdirSync(path.join(dir, "game/DATA/Shader"), {recursive: true});
  fs.writeFileSync(path.join(dir, "game/DATA/Shader/flat.fx"), WORKING_FOLDER);
  fs.writeFileSync(path.join(dir, "game/DATA/Shader/tint.inc"), "#define TINT float4(0.5, 0.75, 0.25, 1.0)\n");
  await page.evaluate(() => (window.hfxPage.lastResult = null));
  await page.setInputFiles("#open-folder", path.join(dir, "game"));
  await page.waitForFunction(() => window.hfxPage.lastResult, null, {timeout: 10000}).catch(() => {});
  const r = await page.evaluate(async () => {
    const p = window.hfxPage;
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    p.renderNow();
    return {ok: p.lastResult && p.lastResult.ok, files: [...document.getElementById("file-list").options].map((o) => o.value),
      centre: p.pixel(256, 256), texts: p.diagnosticsText()};
  });
  fs.rmSync(dir, {recursive: true});
  check(r.ok && r.files.join() === "game/DATA/Shader/flat.fx,game/DATA/Shader/tint.inc",
    `opened folder game: DATA\\Shader\\tint.inc found from the folder's root (${r.files}; ${r.texts.join(" | ")})`);
  check(near(r.centre, TINT3), `game/DATA/Shader/flat.fx: centre ${show(r.centre)} is tint.inc's TINT ${showWant(TINT3)}`);
  const api = await page.evaluate(({fx, inc}) => {
    const p = window.hfxPage;
    window.HFX_EFFECTS.folders = {"game/DATA/Shader/flat.fx": fx, "game/DATA/Shader/tint.inc": inc};
    const none = p.selectEffect("folders", "game/DATA/Shader/flat.fx", []);
    const noneTexts = p.diagnosticsText();
    const root = p.selectEffect("folders", "game/DATA/Shader/flat.fx", ["game"]);
    delete window.HFX_EFFECTS.folders;
    return {none: none.ok, noneTexts, root: root.ok};
  }, {fx: WORKING_FOLDER, inc: "#define TINT float4(0.5, 0.75, 0.25, 1.0)\n"});
  const want = "game/DATA/Shader/flat.fx(1,1): error X1507: failed to open source file: 'DATA\\Shader\\tint.inc'";
  check(!api.none && api.noneTexts.includes(want), `no include folders: ${JSON.stringify(api.noneTexts)} (want ${want})`);
  check(api.root, "include folders [\"game\"]: compiled");
}

// The mesh follows the effect as hfxview's does (--mesh unset; hv_effect_wants_pixels): a
// post-processing effect that maps pixel positions through ViewportSize itself (DigitalRise's
// ScreenToProjection) gets the picture's rectangle in pixels, uv 0..1 from the top left; its
// pixel shader writes uv, so pixel (128, 384) of 512 x 512 reads (0.25, 0.75) (within 2/255
// whether the centre is at 128 or 128.5), pixel (4, 4) near the top left 4.25 / 512. On the sphere the same
// effect would cover a dot at the top left. The next effect, with a camera, gets the sphere back.
const SCREEN_PASS = `float2 ViewportSize;
void VS(float4 p : POSITION, float2 uv : TEXCOORD0, out float4 o : POSITION, out float2 t : TEXCOORD0) {
  o = float4(p.x / ViewportSize.x * 2 - 1, 1 - p.y / ViewportSize.y * 2, 0, 1);
  t = uv;
}
float4 PS(float2 t : TEXCOORD0) : COLOR { return float4(t, 0, 1); }
technique Copy { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
`;

async function screenMesh(page) {
  const r = await page.evaluate(async ({screen, flat}) => {
    const p = window.hfxPage;
    await p.setMesh("auto");
    window.HFX_EFFECTS.mesh = {"screen.fx": screen, "flat.fx": flat, "colour.fxh": "#define TINT float4(0.25, 0.5, 0.75, 1.0)\n"};
    const a = p.selectEffect("mesh", "screen.fx");
    p.renderNow();
    const post = {ok: a.ok, probe: p.pixel(128, 384), corner: p.pixel(4, 4)};
    const b = p.selectEffect("mesh", "flat.fx");
    p.setCamera(0, 60, 3);
    p.renderNow();
    delete window.HFX_EFFECTS.mesh;
    return {post, flat: {ok: b.ok, centre: p.pixel(256, 256), corner: p.pixel(0, 0)}};
  }, {screen: SCREEN_PASS, flat: INCLUDING});
  check(r.post.ok && near(r.post.probe, [0.25, 0.75, 0, 1]), `auto mesh, ViewportSize pass: pixel (128, 384) ${show(r.post.probe)} expected ${showWant([0.25, 0.75, 0, 1])}`);
  const corner = [4.25 / 512, 4.25 / 512, 0, 1];
  check(near(r.post.corner, corner), `auto mesh, ViewportSize pass: pixel (4, 4) ${show(r.post.corner)} expected ${showWant(corner)}`);
  check(r.flat.ok && near(r.flat.centre, TINT), `auto mesh, then an effect with a camera: the sphere's centre ${show(r.flat.centre)} is TINT ${showWant(TINT)}`);
  check(!near(r.flat.corner, TINT), `auto mesh, then an effect with a camera: the corner ${show(r.flat.corner)} is not covered`);
}

// Textures the application never set get hfxview's defaults of their kind (image.h: 8 x 8
// squares of (235, 235, 235) and (90, 90, 100) on 256 texels, each cube face the same, a 32^3
// volume of 4^3 cubes), so that the page draws an effect as hfxview does; and time parameters
// follow the page's clock, or a fixed one (hfxPage.setClock, what scripts/web_corpus.js uses).
// Point sampling at a square's centre: the cube's +X face at direction (1, -0.125, -0.375)
// is u = (0.375 + 1) / 2 = 0.6875, v = (0.125 + 1) / 2 = 0.5625 (D3D's face orientation:
// u from -z, v from -y), texel (176, 144), square (5, 4): odd, dark; the volume at texel
// (12.5, 4.5, 4.5) is cube (1, 0, 0): odd, dark; the 2D texture at (0.1875, 0.0625) is square
// (1, 0): odd, dark, and at (0.0625, 0.0625) square (0, 0): light. Time at 1 s: frac(1 / 4) =
// 0.25 of red; at 2 s, 0.5.
const DEFAULTS = `float4x4 WorldViewProj : WorldViewProjection;
float Time;
texture2D Flat; sampler2D S2 = sampler_state { Texture = <Flat>; MinFilter = Point; MagFilter = Point; MipFilter = None; };
textureCUBE Sky; samplerCUBE SC = sampler_state { Texture = <Sky>; MinFilter = Point; MagFilter = Point; MipFilter = None; };
texture3D Vol; sampler3D S3 = sampler_state { Texture = <Vol>; MinFilter = Point; MagFilter = Point; MipFilter = None; };
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 Light() : COLOR { return tex2D(S2, float2(0.0625, 0.0625)); }
float4 Dark() : COLOR { return tex2D(S2, float2(0.1875, 0.0625)); }
float4 Cube() : COLOR { return texCUBE(SC, float3(1, -0.125, -0.375)); }
float4 Volume() : COLOR { return tex3D(S3, float3(12.5, 4.5, 4.5) / 32); }
float4 Clock() : COLOR { return float4(frac(Time / 4), 0, 0, 1); }
technique Light { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Light(); } }
technique Dark { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Dark(); } }
technique Cube { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Cube(); } }
technique Volume { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Volume(); } }
technique Clock { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Clock(); } }
`;

async function defaultTextures(page) {
  await page.setInputFiles("#open-files", [{name: "defaults.fx", mimeType: "text/plain", buffer: Buffer.from(DEFAULTS)}]);
  await page.waitForFunction(() => document.getElementById("technique").options.length === 5, null, {timeout: 10000}).catch(() => {});
  const centre = (t, clock) => page.evaluate(async ({t, clock}) => {
    const p = window.hfxPage, tech = document.getElementById("technique");
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    tech.value = String(t);
    tech.dispatchEvent(new Event("change"));
    if (clock !== undefined) p.setClock(clock);
    p.renderNow();
    return p.pixel(256, 256);
  }, {t, clock});
  const light = [235 / 255, 235 / 255, 235 / 255, 1], dark = [90 / 255, 90 / 255, 100 / 255, 1];
  for (const [t, name, want] of [[0, "2D, square (0, 0)", light], [1, "2D, square (1, 0)", dark], [2, "cube", dark], [3, "volume", dark]]) {
    const got = await centre(t);
    check(near(got, want), `default ${name} texture: centre ${show(got)} expected ${showWant(want)}`);
  }
  for (const [clock, want] of [[1, [0.25, 0, 0, 1]], [2, [0.5, 0, 0, 1]]]) {
    const got = await centre(4, clock);
    check(near(got, want), `Time with the clock fixed at ${clock} s: centre ${show(got)} expected ${showWant(want)}`);
  }
  await page.evaluate(() => window.hfxPage.setClock(-1));
}

// An effect compiled to fx_2_0 (hfx's own binary: hfxc /T fx_2_0 /Fo, the container and
// bytecode fxc writes) dropped on the page: it loads through the binary reader (the editor says
// so), draws Tint on the plane, and ShaderIndex picks the array's second pixel shader, which
// halves the colour: (0.125, 0.25, 0.375, 1).
const BINARY_SOURCE = `float4x4 WorldViewProj : WorldViewProjection;
float4 Tint = {0.25, 0.5, 0.75, 1};
int ShaderIndex = 0;
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 Plain() : COLOR { return Tint; }
float4 Halved() : COLOR { return float4(Tint.rgb * 0.5, 1); }
PixelShader Shaders[2] = { compile ps_2_0 Plain(), compile ps_2_0 Halved() };
technique Flat { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = (Shaders[ShaderIndex]); } }
`;

function fx2Bytes() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "hfx-page-"));
  try {
    fs.writeFileSync(path.join(dir, "tint.fx"), BINARY_SOURCE);
    execFileSync(arg("hfxc"), ["/T", "fx_2_0", "/nologo", "/Fo", path.join(dir, "tint.fxo"), path.join(dir, "tint.fx")]);
    return [...fs.readFileSync(path.join(dir, "tint.fxo"))];
  } finally {
    fs.rmSync(dir, {recursive: true, force: true});
  }
}

async function droppedBinary(page) {
  if (!process.argv.includes("--hfxc")) {
    console.log("skip an fx_2_0 binary dropped: no --hfxc to write one");
    return;
  }
  const bytes = fx2Bytes();
  check(bytes[0] === 0x01 && bytes[1] === 0x09 && bytes[2] === 0xff && bytes[3] === 0xfe, "hfxc wrote tint.fxo as fx_2_0");
  await page.evaluate(async (bytes) => {
    window.hfxPage.lastResult = null;
    const dt = new DataTransfer();
    dt.items.add(new File([new Uint8Array(bytes)], "tint.fxo", {type: "application/octet-stream"}));
    const target = document.querySelector(".cm-content");
    for (const type of ["dragenter", "dragover", "drop"])
      target.dispatchEvent(new DragEvent(type, {dataTransfer: dt, bubbles: true, cancelable: true}));
  }, bytes);
  await page.waitForFunction(() => window.hfxPage.lastResult, null, {timeout: 10000}).catch(() => {});
  const r = await page.evaluate(async () => {
    const p = window.hfxPage;
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    p.renderNow();
    const plain = p.pixel(256, 256);
    const err = p.setParam("ShaderIndex", "1");
    p.renderNow();
    return {ok: p.lastResult && p.lastResult.ok, diags: p.diagnosticsText(), text: p.editorText(), plain, err,
      halved: p.pixel(256, 256)};
  });
  check(r.ok, `dropped tint.fxo: loaded (${JSON.stringify(r.diags)})`);
  check(r.text.startsWith("// tint.fxo: an effect compiled by fxc (fx_2_0, " + bytes.length + " bytes)"),
    `the editor says tint.fxo is a binary: ${JSON.stringify(r.text.split("\n")[0])}`);
  const tint = [0.25, 0.5, 0.75, 1], halved = [0.125, 0.25, 0.375, 1];
  check(near(r.plain, tint), `tint.fxo, ShaderIndex 0: centre ${show(r.plain)} is Tint ${showWant(tint)}`);
  check(!r.err && near(r.halved, halved), `tint.fxo, ShaderIndex 1: centre ${show(r.halved)} is Tint / 2 ${showWant(halved)}`);
}

// The orbit camera driven by the mouse on the canvas: a drag of (60, -40) pixels turns the
// camera to yaw -30, pitch 40 (app.js: half a degree a pixel); phong.fx's light comes from the
// side, so the centre pixel's highlight takes the colour the equation gives for that eye, not
// the mirror view's; dragging back restores the first picture. Then the wheel: one notch in
// (distance 3 / 1.1) and two out (3 * 1.1) move the plane's right edge, x = 1 on the screen's
// middle row at 256 + 256 / (distance tan 22.5 degrees): 462.0 at 3, 482.6 closer, 443.3 further.
async function orbitCamera(page, x) {
  const o = x.orbit;
  const start = await setUp(page, o, x.camera.eye);
  check(near(start.centre, o.start), `orbit: phong.fx from yaw 0, pitch 60: ${show(start.centre)} expected ${showWant(o.start)}`);
  const box = await page.locator("#view").boundingBox();
  const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
  const drag = async (from, to) => {
    await page.mouse.move(from[0], from[1]);
    await page.mouse.down();
    await page.mouse.move(to[0], to[1], {steps: 5});
    await page.mouse.up();
  };
  const probe = () => page.evaluate(() => { window.hfxPage.renderNow(); return {cam: window.hfxPage.camera(), centre: window.hfxPage.pixel(256, 256)}; });
  const end = [cx + o.drag[0], cy + o.drag[1]];
  await drag([cx, cy], end);
  const a = await probe();
  check(a.cam.yaw === -30 && a.cam.pitch === 40, `dragged (${o.drag}): yaw ${a.cam.yaw}, pitch ${a.cam.pitch}`);
  check(near(a.centre, o.end), `orbit: after the drag ${show(a.centre)} expected ${showWant(o.end)} (start ${show(start.centre)})`);
  check(!near(a.centre, o.mirror), `orbit: not the mirror view's ${showWant(o.mirror)}`);
  await drag(end, [cx, cy]);
  const b = await probe();
  check(b.centre.every((v, i) => Math.abs(v - start.centre[i]) <= TOLERANCE), `orbit: dragged back ${show(b.centre)} is the first picture ${show(start.centre)}`);
}

async function wheelZoom(page, x) {
  await page.evaluate(async () => {
    await window.hfxPage.setMesh("plane");
    window.hfxPage.setCamera(0, 60, 3);
  });
  const box = await page.locator("#view").boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  const edge = (d) => 256 + 256 / (d * Math.tan(Math.PI / 8));
  const probe = () => page.evaluate(() => {
    window.hfxPage.renderNow();
    return {d: window.hfxPage.camera().distance, in: window.hfxPage.pixel(472, 256), out: window.hfxPage.pixel(452, 256)};
  });
  const at3 = await probe();
  check(near(at3.in, x.clear) && near(at3.out, TINT), `zoom: at distance 3 the edge is at ${edge(3).toFixed(1)}: 452 plane, 472 clear`);
  await page.mouse.wheel(0, -100);
  await page.waitForFunction(() => window.hfxPage.camera().distance < 3, null, {timeout: 5000}).catch(() => {});
  const closer = await probe();
  check(Math.abs(closer.d - 3 / 1.1) < 1e-9 && near(closer.in, TINT),
    `zoom: one notch in, distance ${closer.d.toFixed(3)}, edge ${edge(closer.d).toFixed(1)}: 472 is the plane ${show(closer.in)}`);
  await page.mouse.wheel(0, 100);
  await page.mouse.wheel(0, 100);
  await page.waitForFunction(() => window.hfxPage.camera().distance > 3.2, null, {timeout: 5000}).catch(() => {});
  const further = await probe();
  check(Math.abs(further.d - 3.3) < 1e-9 && near(further.out, x.clear),
    `zoom: two notches out, distance ${further.d.toFixed(3)}, edge ${edge(further.d).toFixed(1)}: 452 is the clear colour ${show(further.out)}`);
}

// A warning: a float4 initialising a float3 is fxc's X3206, implicit truncation, at the
// initializer (line 3: "float4 PS() : COLOR { float3 c = " is 33 characters, so column 34).
// The effect still compiles and draws the truncated colour; the warning is listed in its own
// style, marked in the editor as a warning, and clicking it moves the cursor there.
const WARNING_FX = `float4x4 WorldViewProj : WorldViewProjection;
float4 VS(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }
float4 PS() : COLOR { float3 c = float4(0.5, 0.25, 1, 0); return float4(c, 1); }
technique Warn { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
`;

async function warning(page, x) {
  await page.setInputFiles("#open-files", [{name: "warn.fx", mimeType: "text/plain", buffer: Buffer.from(WARNING_FX)}]);
  await page.waitForFunction(() => window.hfxPage.diagnosticsText().some((t) => t.startsWith("warn.fx")), null, {timeout: 10000})
    .catch(() => {});
  const r = await page.evaluate(async () => {
    const p = window.hfxPage;
    await p.setMesh("plane");
    p.setCamera(0, 60, 3);
    p.renderNow();
    return {ok: p.lastResult && p.lastResult.ok, items: [...document.querySelectorAll("#diagnostics li")].map((li) => [li.className, li.textContent]),
      marks: [...document.querySelectorAll(".cm-lintRange-warning")].map((e) => e.textContent),
      errorMarks: document.querySelectorAll(".cm-lintRange-error").length, centre: p.pixel(256, 256)};
  });
  const want = "warn.fx(3,34): warning X3206: implicit truncation of vector type";
  check(r.ok && r.items.length === 1 && r.items[0][0] === "warning" && r.items[0][1] === want,
    `warning listed: ${JSON.stringify(r.items)} (want [warning, ${want}])`);
  check(r.marks.join() === "float4" && r.errorMarks === 0, `the editor marks float4 as a warning (${JSON.stringify(r.marks)}, ${r.errorMarks} error marks)`);
  check(near(r.centre, [0.5, 0.25, 1, 1]), `warn.fx draws float3(0.5, 0.25, 1): ${show(r.centre)}`);
  await page.click("#diagnostics li.warning");
  const cursor = await page.evaluate(() => window.hfxPage.cursor());
  check(cursor.line === 3 && cursor.col === 34, `clicking the warning puts the cursor at ${cursor.line}:${cursor.col}`);
}

// An OBJ from the mesh picker's file input: two small quads either side of the origin (each
// drawn from both sides), centred and scaled into the unit sphere by hfxview's reader. The
// centre, which the plane covered, now shows the clear colour; the right quad is at pixel 415.
const OBJ = ["v -1 0 -0.2", "v -0.6 0 -0.2", "v -0.6 0 0.2", "v -1 0 0.2", "v 0.6 0 -0.2", "v 1 0 -0.2", "v 1 0 0.2", "v 0.6 0 0.2",
  "f 1 2 3 4", "f 4 3 2 1", "f 5 6 7 8", "f 8 7 6 5", ""].join("\n");

async function objMesh(page, x) {
  await page.setInputFiles("#obj-file", {name: "two_quads.obj", mimeType: "text/plain", buffer: Buffer.from(OBJ)});
  await page.waitForFunction(() => /two_quads\.obj loaded/.test(document.getElementById("status").textContent), null, {timeout: 10000})
    .catch(() => {});
  const r = await page.evaluate(() => {
    window.hfxPage.renderNow();
    return {status: document.getElementById("status").textContent, centre: window.hfxPage.pixel(256, 256),
      right: window.hfxPage.pixel(415, 256)};
  });
  check(/loaded/.test(r.status), `OBJ file: ${r.status}`);
  check(near(r.centre, x.clear), `OBJ: the gap at the centre shows the clear colour ${show(r.centre)}`);
  check(near(r.right, TINT), `OBJ: the right quad at (415, 256) is TINT ${show(r.right)}`);
}

// The GLSL tab shows the pass's GLSL ES; the download button saves the .hfxo (its magic number).
async function glslAndDownload(page) {
  await page.click('.tabs button[data-tab="glsl"]');
  const glsl = await page.evaluate(() => document.getElementById("glsl-text").textContent);
  check(glsl.startsWith("#version 300 es"), `GLSL tab: ${JSON.stringify(glsl.split("\n")[0])}`);
  await page.click('.tabs button[data-tab="params"]');
  const [download] = await Promise.all([page.waitForEvent("download"), page.click("#download")]);
  const bytes = fs.readFileSync(await download.path());
  const magic = [0x89, 0x48, 0x46, 0x58, 0x4f, 0x0d, 0x0a, 0x1a];
  check(download.suggestedFilename() === "flat.hfxo" && magic.every((b, i) => bytes[i] === b),
    `download: ${download.suggestedFilename()}, ${bytes.length} bytes starting with the .hfxo magic`);
}

// A PNG picked in the panel's texture field (tutorial0.fx: the texture is the colour).
async function pickedTexture(page) {
  await page.evaluate(() => window.hfxPage.selectEffect("seed", "tutorial0.fx"));
  const png = await page.evaluate(async () => {
    const c = new OffscreenCanvas(2, 2);
    const g = c.getContext("2d");
    g.fillStyle = "rgb(40, 160, 220)";
    g.fillRect(0, 0, 2, 2);
    return Array.from(new Uint8Array(await (await c.convertToBlob({type: "image/png"})).arrayBuffer()));
  });
  await page.setInputFiles('#params input[type=file]', {name: "blue.png", mimeType: "image/png", buffer: Buffer.from(png)});
  await page.waitForTimeout(500); // the image decodes asynchronously
  const r = await page.evaluate(async () => {
    await window.hfxPage.setMesh("plane");
    window.hfxPage.setCamera(0, 60, 3);
    window.hfxPage.renderNow();
    return window.hfxPage.pixel(256, 256);
  });
  check(near(r, [40 / 255, 160 / 255, 220 / 255, 1]), `tutorial0.fx with blue.png picked in the panel: ${show(r)}`);
}

async function screenshots(page) {
  fs.mkdirSync(shots, {recursive: true});
  // Each with a few knobs turned in the panel, as a user would.
  const views = [["spot_specular.fx", "sphere", 20, 25, [["modIluEsp", "true"], ["ks", "1"], ["anguloExterno", "0.6"]]],
    ["directional_specular.fx", "teapot", 30, 25, [["modIluEsp", "true"], ["ks", "1"], ["colorMaterialAmbiental", "0.15,0.15,0.2,1"]]],
    ["ambient_textured.fx", "torus", 0, 40, [["colorMaterialAmbiental", "1,0.85,0.6,1"]]]];
  for (const [file, mesh, yaw, pitch, params] of views) {
    await page.evaluate(async ({file, mesh, yaw, pitch, params}) => {
      const p = window.hfxPage;
      p.selectEffect("seed", file);
      for (const [name, values] of params) p.setParam(name, values);
      p.refreshPanel();
      await p.setMesh(mesh);
      document.getElementById("mesh").value = mesh;
      p.setCamera(yaw, pitch, 3);
      p.renderNow();
    }, {file, mesh, yaw, pitch, params});
    const out = path.join(shots, file.replace(/\.fx$/, "") + ".png");
    await page.screenshot({path: out});
    console.log(`screenshot ${out}`);
  }
}

// The figures of the README's web section: page load to the first picture; the compiler alone
// on spot_specular.fx, cold (the page's first compile, code not yet optimised by the browser)
// and warm (the mean of 200 after 200 warm-up, one clock reading: bench/bench_web_compile is the
// same loop natively); and the median of 5 whole compiles as the page makes them (compiler,
// .hfxo, runtime load, WebGL link, panel).
async function timings(page) {
  const t = await page.evaluate(() => {
    const p = window.hfxPage;
    const ms = [];
    for (let i = 0; i < 5; i++) {
      p.selectEffect("seed", "spot_specular.fx");
      ms.push(p.compileMs[p.compileMs.length - 1]);
    }
    return {first: p.firstPictureMs, cold: p.firstCompilerMs, warm: p.compileBench(200), whole: ms.sort((x, y) => x - y)[2]};
  });
  console.log(`web-measure: page load to first picture ${t.first.toFixed(0)} ms; spot_specular.fx in the page: ` +
    `compiler cold ${t.cold.toFixed(2)} ms, warm ${t.warm.toFixed(3)} ms (mean of 200); ` +
    `compile + .hfxo + load + WebGL link ${t.whole.toFixed(1)} ms (median of 5)`);
}

async function main() {
  const {chromium} = loadPlaywright();
  if (!fs.existsSync(path.join(site, "index.html"))) {
    console.log(`FAIL no page at ${site}: scripts/web.sh builds it (the build's web_site target)`);
    process.exit(1);
  }
  const x = JSON.parse(execFileSync(arg("expect"), {encoding: "utf8"}));
  const browser = await launch(chromium);
  const page = await browser.newPage({viewport: {width: 1300, height: 1000}, acceptDownloads: true});
  page.on("pageerror", (e) => check(false, "page error: " + e.message));
  await page.goto("file://" + path.resolve(site, "index.html"));
  const ready = await Promise.race([page.evaluate(() => window.hfxPage.ready.then(() => true)),
    new Promise((r) => setTimeout(() => r(false), 30000))]);
  check(ready, "the page draws its first picture");
  const hasSeeds = await page.evaluate(() => !!(window.HFX_EFFECTS && window.HFX_EFFECTS.seed));
  if (!ready || !hasSeeds) {
    await browser.close();
    if (!hasSeeds && ready) {
      console.log("SKIP: the seed corpus (../shared/seed-fx) was absent when the page was built");
      process.exit(77);
    }
    process.exit(1);
  }
  await timings(page);
  await seedCases(page, x);
  await slider(page, x);
  await structPanel(page, x);
  await orbitCamera(page, x);
  await multilights(page);
  await typedError(page);
  await warning(page, x);
  await pickedTexture(page);
  await openedFiles(page);
  await wheelZoom(page, x);
  await objMesh(page, x);
  await glslAndDownload(page);
  await droppedFiles(page);
  await includeFolders(page);
  await screenMesh(page);
  await droppedBinary(page);
  await defaultTextures(page);
  await screenshots(page);
  await browser.close();
  console.log(failures ? `${failures} check(s) failed` : "all checks passed");
  process.exit(failures ? 1 : 0);
}

main().catch((e) => {
  console.log("FAIL " + (e.stack || e));
  process.exit(1);
});
