// effects_list.js: writes effects.js, the page's built-in effect list, at build time (so the
// page reads no files at run time and works from file://). One group per folder: every text
// file in it, keyed by its path inside the folder, so #include resolves among them.
//   node effects_list.js OUT.js GROUP=DIR [GROUP=DIR...]   (a missing DIR is skipped)
"use strict";
const fs = require("fs");
const path = require("path");

function filesOf(dir, prefix = "") {
  const out = {};
  for (const e of fs.readdirSync(dir, {withFileTypes: true}).sort((a, b) => a.name.localeCompare(b.name))) {
    const rel = prefix + e.name;
    if (e.isDirectory()) Object.assign(out, filesOf(path.join(dir, e.name), rel + "/"));
    else if (/\.(fx|fxh|h|hlsl|inc)$/i.test(e.name)) out[rel] = fs.readFileSync(path.join(dir, e.name), "utf8");
  }
  return out;
}

const [out, ...groups] = process.argv.slice(2);
const effects = {};
for (const g of groups) {
  const [name, dir] = g.split("=");
  if (fs.existsSync(dir)) effects[name] = filesOf(dir);
  else console.error(`effects_list: ${dir} is absent; the page lists no ${name} effects`);
}
fs.writeFileSync(out, "window.HFX_EFFECTS = " + JSON.stringify(effects) + ";\n");
