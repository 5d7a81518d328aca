// web_corpus.js: techniques of real effects drawn by the web page (web/, built by scripts/web.sh)
// in headless Chromium, as `scripts/corpus.sh compare` draws them with hfxview on GL and Vulkan:
// hfxview's scene and defaults (the page shares its scene code), 128x128, the camera at
// hfxview's eye (0, 1, 3), time parameters at hfxview's headless 1 s. Each effect's repository
// goes into the page's file system with the paths it has there, and the page searches the
// include folders scripts/corpus.sh gives hfxview (every folder above the effect's, up to the
// repository's root: a game's working folder). One PNG per technique, and a line per technique:
//   ok|FAIL<tab>effect#technique[<tab>first error]   (tabs: paths may hold spaces)
//   node scripts/web_corpus.js --site SITE --corpus DIR --list FILE --out DIR
// FILE holds "effect#technique" lines (effect relative to DIR); PNGs go to
// OUT/<effect with / as _>.<technique>.web.png. Exit 77 when Chromium cannot start.
"use strict";
const {execFileSync} = require("child_process");
const fs = require("fs");
const path = require("path");

const arg = (name) => process.argv[process.argv.indexOf("--" + name) + 1];
const site = path.resolve(arg("site")), corpus = path.resolve(arg("corpus")), out = path.resolve(arg("out"));
const SOURCE = /\.(fx|fxh|h|hlsl|hlsli|inc|cginc|fxc|vsh|psh)$/i;

function loadPlaywright() {
  try {
    return require(path.join(__dirname, "../web/node_modules/playwright-core"));
  } catch (e) {
    console.error("playwright-core is not installed: scripts/web.sh runs npm ci in web/");
    process.exit(2);
  }
}

// Every source file of the effect's repository folder in the corpus, by its path there, as
// base64: the page gets the bytes hfxc reads (a BOM, Latin-1 comments), not a re-encoding.
function repositoryFiles(effect) {
  const repo = effect.split("/")[0], files = {};
  const walk = (dir) => {
    for (const e of fs.readdirSync(dir, {withFileTypes: true})) {
      const p = path.join(dir, e.name);
      if (e.isDirectory()) walk(p);
      else if (SOURCE.test(e.name) && fs.statSync(p).size < (1 << 20))
        files[path.relative(path.join(corpus, repo), p)] = fs.readFileSync(p).toString("base64");
    }
  };
  walk(path.join(corpus, repo));
  const main = path.relative(repo, effect), include = [];
  for (let d = path.dirname(main); d !== "."; d = path.dirname(d)) include.push(path.dirname(d) === "." ? "" : path.dirname(d));
  return {main, files, include};
}

// The effect into the page; its first error when it does not compile, else null.
async function open(page, effect) {
  const {main, files, include} = repositoryFiles(effect);
  return page.evaluate(({main, files, include}) => {
    const bytes = (b) => Uint8Array.from(atob(b), (c) => c.charCodeAt(0));
    window.HFX_EFFECTS.corpus = Object.fromEntries(Object.entries(files).map(([n, b]) => [n, bytes(b)]));
    const r = window.hfxPage.selectEffect("corpus", main, include);
    if (r && r.ok) return null;
    const texts = window.hfxPage.diagnosticsText().filter((t) => t.includes("error"));
    return texts[0] || "no result";
  }, {main, files, include});
}

// Technique t drawn (every pass, as hfxview): the framebuffer's RGBA bytes (hfxPage.frame).
async function draw(page, t) {
  return page.evaluate((t) => {
    const tech = document.getElementById("technique");
    tech.value = String(t);
    tech.dispatchEvent(new Event("change"));
    window.hfxPage.setClock(1);
    window.hfxPage.renderNow();
    return window.hfxPage.frame();
  }, t);
}

// The frame as a PNG with its bytes as they are (ImageMagick, which corpus.sh compares with).
function writePng(frame, file) {
  const raw = file + ".rgba";
  fs.writeFileSync(raw, Buffer.from(frame.rgba, "base64"));
  execFileSync("convert", ["-size", `${frame.width}x${frame.height}`, "-depth", "8", "rgba:" + raw, "png32:" + file]);
  fs.unlinkSync(raw);
}

async function main() {
  const {chromium} = loadPlaywright();
  let browser;
  try {
    browser = await chromium.launch({executablePath: "/usr/bin/chromium",
      args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
        "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"]});
  } catch (e) {
    console.error("Chromium cannot start here: " + String(e.message).split("\n")[0]);
    process.exit(77);
  }
  const page = await browser.newPage();
  await page.goto("file://" + path.join(site, "index.html"));
  await page.evaluate(() => window.hfxPage.ready);
  await page.evaluate(() => {
    const c = document.getElementById("view");
    c.width = c.height = 128;
    window.hfxPage.setCamera(0, Math.atan2(1, 3) * 180 / Math.PI, Math.sqrt(10)); // hfxview's eye (0, 1, 3)
    window.hfxPage.renderNow(); // the session's size is then 128 x 128 when effects load (ViewportSize, the screen mesh)
  });
  const lines = fs.readFileSync(arg("list"), "utf8").split("\n").filter((l) => l.includes("#"));
  let current = null, error = null;
  for (const line of lines) {
    const [effect, t] = [line.slice(0, line.lastIndexOf("#")), Number(line.slice(line.lastIndexOf("#") + 1))];
    if (effect !== current) (current = effect), (error = await open(page, effect).catch((e) => String(e.message)));
    if (error) {
      console.log(`FAIL\t${line}\t${error.split("\n")[0]}`);
      continue;
    }
    const frame = await draw(page, t).catch(() => null);
    if (!frame) {
      console.log(`FAIL\t${line}\tthe page failed to draw`);
      continue;
    }
    writePng(frame, path.join(out, `${effect.replace(/\//g, "_")}.${t}.web.png`));
    console.log(`ok\t${line}`);
  }
  await browser.close();
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
