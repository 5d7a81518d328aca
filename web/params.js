// params.js: the parameter panel, built from the effect's annotations the way FX Composer
// builds its property grid (docs/annotations.md): UIName labels, UIWidget "Color" a colour
// picker, "Slider" a range with UIMin / UIMax / UIStep, bools a checkbox, ints and floats
// number fields, textures an image picker (the checker until one is chosen); the members of
// struct parameters (arrays of light structs...) fold under the parameter's name. Matrices, and
// parameters with a scene semantic, are bound from the camera every frame and only listed. Each
// name's tooltip says how hfxview's binding (bind.h) filled it; a line at the top lists the
// parameters it could not bind.
"use strict";

const HfxParams = (() => {
  // Names hfxview's bind.c fills from the camera (besides any SAS semantic).
  const CAMERA_NAME = /^(mat)?(world|view|proj|projection|worldview|viewproj|worldviewproj|worldviewprojection|wvp)(inverse|transpose|it|i|t)*(xf)?$|^(cam|camera|eye|view)(pos|position)(ition)?$|^(posicioncamara|camaraposicion)$/i;
  const SCENE_SEMANTIC = /^(world|view|projection|worldview|viewprojection|worldviewprojection|worldviewproj|viewproj)(inverse|transpose|inversetranspose)?$|^(cameraposition|viewposition|eyeposition|time|elapsedtime|viewportpixelsize|viewportsize)$/i;

  const ann = (p, key) => {
    for (const k of Object.keys(p.annotations)) if (k.toLowerCase() === key.toLowerCase()) return p.annotations[k];
    return undefined;
  };
  const fmt = (v) => String(Math.round(v * 1e6) / 1e6);

  function isAutomatic(p) {
    return p.class === "matrix" || SCENE_SEMANTIC.test(p.semantic || "") || CAMERA_NAME.test(p.name);
  }

  function toHex(v) {
    const c = (x) => Math.round(Math.min(Math.max(x, 0), 1) * 255).toString(16).padStart(2, "0");
    return "#" + c(v[0]) + c(v[1]) + c(v[2]);
  }

  function colourInput(p, set) {
    const input = document.createElement("input");
    input.type = "color";
    input.value = toHex(p.value);
    input.dataset.param = p.name;
    input.addEventListener("input", () => {
      const hex = input.value;
      const v = p.value.slice();
      for (let i = 0; i < 3; i++) v[i] = parseInt(hex.substr(1 + 2 * i, 2), 16) / 255;
      p.value = v;
      set(p.name, v.map(fmt).join(","));
    });
    return input;
  }

  function slider(p, set) {
    const box = document.createElement("span");
    const range = document.createElement("input");
    range.type = "range";
    range.min = ann(p, "UIMin") ?? 0;
    range.max = ann(p, "UIMax") ?? 1;
    range.step = ann(p, "UIStep") ?? "any";
    range.value = p.value[0];
    range.dataset.param = p.name;
    const shown = document.createElement("output");
    shown.textContent = fmt(p.value[0]);
    range.addEventListener("input", () => {
      shown.textContent = fmt(Number(range.value));
      set(p.name, range.value);
    });
    box.append(range, " ", shown);
    return box;
  }

  function numberFields(p, set) {
    const box = document.createElement("span");
    box.dataset.param = p.name;
    const fields = p.value.map((v) => {
      const f = document.createElement("input");
      f.type = "number";
      f.step = p.type === "int" ? 1 : ann(p, "UIStep") ?? "any";
      f.value = fmt(v);
      f.addEventListener("change", () => set(p.name, fields.map((x) => x.value || "0").join(",")));
      box.append(f);
      return f;
    });
    return box;
  }

  function checkbox(p, set) {
    const c = document.createElement("input");
    c.type = "checkbox";
    c.checked = p.value[0] !== 0;
    c.dataset.param = p.name;
    c.addEventListener("change", () => set(p.name, c.checked ? "true" : "false"));
    return c;
  }

  function texturePicker(p, setTexture) {
    const f = document.createElement("input");
    f.type = "file";
    f.accept = "image/png,image/jpeg";
    f.addEventListener("change", () => f.files[0] && setTexture(p.name, f.files[0]));
    return f;
  }

  function control(p, h) {
    const widget = String(ann(p, "UIWidget") ?? "").toLowerCase();
    if (p.texture && p.type.startsWith("texture")) return texturePicker(p, h.setTexture);
    if (p.class === "struct" || p.elements > 0 || !p.value.length) return null;
    if (p.type === "bool") return checkbox(p, h.set);
    if (widget === "color" && p.value.length >= 3) return colourInput(p, h.set);
    if (widget === "slider" && p.value.length === 1) return slider(p, h.set);
    return numberFields(p, h.set);
  }

  // A struct parameter's leaves ("lights[0].Color"...) go in a folding group of its own.
  function groupOf(panel, groups, name) {
    let g = groups.get(name);
    if (!g) {
      g = document.createElement("details");
      g.dataset.group = name;
      g.append(Object.assign(document.createElement("summary"), {textContent: name}));
      groups.set(name, g);
      panel.append(g);
    }
    return g;
  }

  // effect: hfxw_describe's JSON; h: {set(name, values), setTexture(name, file)}.
  function build(panel, effect, h) {
    panel.textContent = "";
    const groups = new Map();
    // What the binding could not recognise, so that a black picture explains itself.
    if (effect.unbound) panel.append(Object.assign(document.createElement("p"), {className: "unbound",
      textContent: "Not bound, left at the effect's values: " + effect.unbound}));
    for (const p of effect.params) {
      if (String(ann(p, "UIWidget") ?? "").toLowerCase() === "none" || p.type === "string") continue;
      if (p.type.startsWith("sampler")) continue;
      const label = document.createElement("label");
      const name = document.createElement("span");
      name.textContent = ann(p, "UIName") ?? p.name;
      name.title = p.name + (p.semantic ? " : " + p.semantic : "") + (p.bound ? " (" + p.bound + ")" : "");
      const c = isAutomatic(p) ? Object.assign(document.createElement("span"), {className: "auto", textContent: "from the camera"})
        : control(p, h);
      if (!c) continue;
      label.append(name, c);
      if (p.group && p.group !== p.name) {
        name.textContent = p.name.slice(p.group.length); // "[0].Color" under "lights"
        groupOf(panel, groups, p.group).append(label);
      } else panel.append(label);
    }
  }

  return {build};
})();
