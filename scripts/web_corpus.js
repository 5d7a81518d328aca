// web_corpus.js: techniques of real effects drawn by the web page (web/, built by scripts/web.sh)
// in headless Chromium, as `scripts/corpus.sh compare` draws them with hfxview on GL and Vulkan:
// hfxview's scene and defaults (the page shares its scene code), 128x128, the camera at
// hfxview's eye (0, 1, 3), time parameters at hfxview's headless 1 s. Each effect's folder goes
// into the page's file system with the paths it has in its repository, so relative #includes
// resolve (the page has no -I folders). One PNG per technique, and a line per technique:
//   ok|FAIL effect#technique [first error]
//   node scripts/web_corpus.js --site SITE --corpus DIR --list FILE --out DIR
// FILE holds "effect#technique" lines (effect relative to DIR); PNGs go to
// OUT/<effect with / as _>.<technique>.web.png. Exit 77 when Chromium cannot start.
"use strict";
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
  return {main: path.relative(repo, effect), files};
}

// The effect into the page; its first error when it does not compile, else null.
async function open(page, effect) {
  const {main, files} = repositoryFiles(effect);
  return page.evaluate(({main, files}) => {
    const bytes = (b) => Uint8Array.from(atob(b), (c) => c.charCodeAt(0));
    window.HFX_EFFECTS.corpus = Object.fromEntries(Object.entries(files).map(([n, b]) => [n, bytes(b)]));
    const r = window.hfxPage.selectEffect("corpus", main);
    if (r && r.ok) return null;
    const texts = window.hfxPage.diagnosticsText().filter((t) => t.includes("error"));
    return texts[0] || "no result";
  }, {main, files});
}

// Technique t drawn (every pass, as hfxview), the canvas as a PNG data URL.
async function draw(page, t) {
  return page.evaluate((t) => {
    const tech = document.getElementById("technique");
    tech.value = String(t);
    tech.dispatchEvent(new Event("change"));
    window.hfxPage.setClock(1);
    window.hfxPage.renderNow();
    return document.getElementById("view").toDataURL("image/png");
  }, t);
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
  });
  const lines = fs.readFileSync(arg("list"), "utf8").split("\n").filter((l) => l.includes("#"));
  let current = null, error = null;
  for (const line of lines) {
    const [effect, t] = [line.slice(0, line.lastIndexOf("#")), Number(line.slice(line.lastIndexOf("#") + 1))];
    if (effect !== current) (current = effect), (error = await open(page, effect).catch((e) => String(e.message)));
    if (error) {
      console.log(`FAIL ${line} ${error.split("\n")[0]}`);
      continue;
    }
    const url = await draw(page, t).catch(() => null);
    if (!url) {
      console.log(`FAIL ${line} the page failed to draw`);
      continue;
    }
    fs.writeFileSync(path.join(out, `${effect.replace(/\//g, "_")}.${t}.web.png`), Buffer.from(url.split(",")[1], "base64"));
    console.log(`ok   ${line}`);
  }
  await browser.close();
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
