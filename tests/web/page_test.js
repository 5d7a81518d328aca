// page_test.js: the web page (web/) in headless Chromium (Debian's, WebGL 2 on SwiftShader),
// driven by playwright-core. Loads the page from disk (file://, as a user would open it), then:
//   - each seed case of web_expect: the effect picked from the list, its technique, the plane,
//     the camera, the parameters; the centre pixel against the seed equations' colour, a corner
//     against the clear colour (within 2/255, as tests/seeds/ probe);
//   - spot_specular.fx's ks slider moved in the panel: the pixel follows the equation;
//   - an error typed into the editor: the located message and the editor's mark;
//   - multilights.fx: X3013 at (204,20);
//   - screenshots of three seeds, and the page's timings (first picture, compile).
// Exit 77 (skip) only when Chromium cannot start or the seed corpus is absent.
//   node page_test.js --site DIR --expect WEB_EXPECT --shots DIR
"use strict";
const {execFileSync} = require("child_process");
const fs = require("fs");
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

async function screenshots(page) {
  fs.mkdirSync(shots, {recursive: true});
  const views = [["spot_specular.fx", "sphere", 20, 25], ["directional_specular.fx", "teapot", 30, 25], ["ambient_textured.fx", "torus", 0, 40]];
  for (const [file, mesh, yaw, pitch] of views) {
    await page.evaluate(async ({file, mesh, yaw, pitch}) => {
      window.hfxPage.selectEffect("seed", file);
      await window.hfxPage.setMesh(mesh);
      document.getElementById("mesh").value = mesh;
      window.hfxPage.setCamera(yaw, pitch, 3);
      window.hfxPage.renderNow();
    }, {file, mesh, yaw, pitch});
    const out = path.join(shots, file.replace(/\.fx$/, "") + ".png");
    await page.screenshot({path: out});
    console.log(`screenshot ${out}`);
  }
}

async function timings(page) {
  const t = await page.evaluate(() => {
    const ms = [];
    for (let i = 0; i < 5; i++) {
      window.hfxPage.selectEffect("seed", "spot_specular.fx");
      ms.push(window.hfxPage.compileMs[window.hfxPage.compileMs.length - 1]);
    }
    return {first: window.hfxPage.firstPictureMs, compile: ms.sort((a, b) => a - b)[2]};
  });
  console.log(`web-measure: page load to first picture ${t.first.toFixed(0)} ms; spot_specular.fx compile+load in page ${t.compile.toFixed(1)} ms (median of 5)`);
}

async function main() {
  const {chromium} = loadPlaywright();
  if (!fs.existsSync(path.join(site, "index.html"))) {
    console.log(`FAIL no page at ${site}: scripts/web.sh builds it (the build's web_site target)`);
    process.exit(1);
  }
  const x = JSON.parse(execFileSync(arg("expect"), {encoding: "utf8"}));
  const browser = await launch(chromium);
  const page = await browser.newPage({viewport: {width: 1300, height: 820}});
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
  await multilights(page);
  await typedError(page);
  await screenshots(page);
  await browser.close();
  console.log(failures ? `${failures} check(s) failed` : "all checks passed");
  process.exit(failures ? 1 : 0);
}

main().catch((e) => {
  console.log("FAIL " + (e.stack || e));
  process.exit(1);
});
