/* hfx_web.c: the functions the page calls (web/app.js, through ccall). Each answers with JSON
 * or a number; the effect's files live in emscripten's in-memory file system, so #include
 * resolves among the files the page wrote there exactly as on disk. */
#include <emscripten.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bind.h"
#include "hfx/hfxc.h"
#include "json.h"
#include "session.h"
#include "webgl.h"

static hfxw_session session; /* the page's one session (session.h) */

hfxw_session *hfxw_get(void) { return &session; }

const char *hfxw_answer(char *json) {
    free(session.answer);
    session.answer = json;
    return json ? json : "null";
}

/* The WebGL 2 context on the page's canvas, and hfx's device over it. 0, or -1. */
EMSCRIPTEN_KEEPALIVE int hfxw_init(const char *canvas) {
    EmscriptenWebGLContextAttributes a;
    emscripten_webgl_init_context_attributes(&a);
    a.majorVersion = 2, a.minorVersion = 0;
    a.antialias = 0;             /* one sample per pixel: the tests read exact colours */
    a.preserveDrawingBuffer = 1; /* readPixels and screenshots after the frame */
    a.stencil = 1;
    session.context = emscripten_webgl_create_context(canvas, &a);
    if (session.context <= 0 || emscripten_webgl_make_context_current(session.context) != EMSCRIPTEN_RESULT_SUCCESS)
        return -1;
    session.clock_s = -1;
    session.dev = hfx_device_create_gl(hfxw_gl_proc);
    if (!session.dev) return -1;
    return hfxw_draw_init(&session);
}

static void diagnostics_json(hfxw_json *j, const hfxc_result *r) {
    static const char *const severity[] = {"error", "warning", "note"};
    hfxw_json_raw(j, "[");
    for (size_t i = 0; i < hfxc_diag_count(r); i++) {
        const hfxc_diag *d = hfxc_diag_at(r, i);
        hfxw_json_raw(j, i ? ",{" : "{");
        hfxw_json_key(j, "severity"), hfxw_json_str(j, severity[d->severity]);
        hfxw_json_raw(j, ","), hfxw_json_key(j, "file"), hfxw_json_str(j, d->file);
        hfxw_json_raw(j, ","), hfxw_json_key(j, "line"), hfxw_json_num(j, d->line);
        hfxw_json_raw(j, ","), hfxw_json_key(j, "col"), hfxw_json_num(j, d->col);
        hfxw_json_raw(j, ","), hfxw_json_key(j, "code"), hfxw_json_num(j, d->code);
        hfxw_json_raw(j, ","), hfxw_json_key(j, "message"), hfxw_json_str(j, d->message);
        hfxw_json_raw(j, "}");
    }
    hfxw_json_raw(j, "]");
}

static void release_effect(hfxw_session *s) {
    if (s->fx) hfx_effect_destroy(s->fx);
    if (s->texture_count) s->gl.DeleteTextures((GLsizei)s->texture_count, s->textures);
    hfx_fx_effect_free(s->code);
    free(s->hfxo);
    free((void *)s->bound);
    s->fx = NULL, s->code = NULL, s->hfxo = NULL, s->hfxo_size = 0, s->texture_count = 0;
    s->bound = NULL, s->bound_count = 0;
}

/* The compiled effect into the runtime, through its .hfxo (what an application would ship):
 * NULL with *why set when the runtime or WebGL refuses it. */
static hfx_effect *load_compiled(hfxw_session *s, const hfx_fx_effect *code, void **hfxo, size_t *size, char **why) {
    if (hfx_fx_write_hfxo(code, hfxo, size) != 0) return NULL;
    hfx_load_options o;
    memset(&o, 0, sizeof o);
    o.target = HFX_TARGET_GLSLES300;
    hfx_effect *fx = hfx_effect_load_memory(s->dev, *hfxo, *size, code->source_name, &o, why);
    if (!fx && !*why) *why = strdup(hfx_device_last_error(s->dev));
    return fx;
}

/* The compile's options: GLSL ES 300, packed uniforms, and the include folders (hfxc's -I)
 * split from `includes`, one folder a line, into dirs (at most max; the rest are dropped). */
#define HFXW_MAX_INCLUDE_DIRS 32
static hfxc_options page_options(char *includes, const char **dirs, size_t max) {
    hfxc_options o;
    memset(&o, 0, sizeof o);
    o.targets = 1u << HFX_TARGET_GLSLES300;
    o.flags = HFXC_PACK_UNIFORMS; /* as hfx_effect_load compiles */
    for (char *line = includes, *next; line && *line && o.include_dir_count < max; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = 0;
        if (*line) dirs[o.include_dir_count++] = line;
    }
    o.include_dirs = dirs;
    return o;
}

/* Compiles path (in the in-memory file system) for GLSL ES 300, searching `includes` (folders,
 * one a line, as hfxc's -I) after the including file's folder; when it compiles and loads, it
 * becomes the session's effect, otherwise the previous one stays. Answers
 * {"ok", "diagnostics": [...], "text", "load_error", "compile_ms"}. */
EMSCRIPTEN_KEEPALIVE const char *hfxw_compile(const char *path, const char *includes) {
    hfxw_session *s = &session;
    const char *dirs[HFXW_MAX_INCLUDE_DIRS];
    char *folders = strdup(includes ? includes : "");
    hfxc_options o = page_options(folders, dirs, HFXW_MAX_INCLUDE_DIRS);
    double start = emscripten_get_now();
    hfxc_result *r = hfxc_compile_file(path, &o);
    double compiled = emscripten_get_now() - start; /* the compiler alone, to compare with hfxc */
    if (!r) {
        free(folders);
        return hfxw_answer(NULL);
    }
    hfxw_json j = {0};
    char *text = hfxc_diagnostics_text(r), *why = NULL;
    int ok = hfxc_result_ok(r);
    if (ok) {
        hfx_fx_effect *code = hfxc_result_take_effect(r);
        void *hfxo = NULL;
        size_t size = 0;
        hfx_effect *fx = code ? load_compiled(s, code, &hfxo, &size, &why) : NULL;
        if (fx) {
            release_effect(s);
            s->fx = fx, s->code = code, s->hfxo = hfxo, s->hfxo_size = size;
            s->technique = 0, s->pass = -1;
            hfxw_bind_default_textures(s);
            hfxw_bind_scene(s, s->width, s->height); /* the panel then shows what the frame uses */
            hfxw_mesh_fit(s, s->width, s->height);
        } else {
            hfx_fx_effect_free(code);
            free(hfxo);
            ok = 0;
        }
    }
    hfxw_json_raw(&j, "{"), hfxw_json_key(&j, "ok"), hfxw_json_raw(&j, ok ? "true" : "false");
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "diagnostics"), diagnostics_json(&j, r);
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "text"), hfxw_json_str(&j, text ? text : "");
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "load_error"), hfxw_json_str(&j, why);
    hfxw_json_raw(&j, ","), hfxw_json_key(&j, "compile_ms"), hfxw_json_num(&j, compiled);
    hfxw_json_raw(&j, "}");
    free(text);
    free(why);
    hfxc_result_free(r);
    free(folders);
    return hfxw_answer(hfxw_json_take(&j));
}

/* The compiler alone on path with the include folders, as hfxw_compile runs it: `rounds`
 * compiles after as many warm-up ones, the mean in ms (bench/bench_web_compile.c is the same
 * loop natively);
 * -1 when it does not compile. One clock reading per loop, so the browser's coarse timer
 * (0.1 ms) does not limit the figure. */
EMSCRIPTEN_KEEPALIVE double hfxw_compile_bench(const char *path, const char *includes, int rounds) {
    const char *dirs[HFXW_MAX_INCLUDE_DIRS];
    char *folders = strdup(includes ? includes : "");
    hfxc_options o = page_options(folders, dirs, HFXW_MAX_INCLUDE_DIRS);
    double start = 0, ms = -1;
    for (int i = 0; i < 2 * rounds; i++) {
        if (i == rounds) start = emscripten_get_now();
        hfxc_result *r = hfxc_compile_file(path, &o);
        int ok = r && hfxc_result_ok(r);
        hfxc_result_free(r);
        if (!ok) rounds = 0; /* ends the loop: -1 */
    }
    if (rounds > 0) ms = (emscripten_get_now() - start) / rounds;
    free(folders);
    return ms;
}

EMSCRIPTEN_KEEPALIVE void hfxw_render(int width, int height) {
    emscripten_webgl_make_context_current(session.context);
    session.width = width, session.height = height;
    hfxw_draw_frame(&session, width, height);
}

EMSCRIPTEN_KEEPALIVE void hfxw_set_camera(float yaw, float pitch, float distance) {
    session.yaw = yaw, session.pitch = pitch, session.distance = distance;
}

/* Time parameters read `seconds` from now on (hfxview's headless 1 s, for comparing pictures);
 * a negative value lets the page's clock run again. */
EMSCRIPTEN_KEEPALIVE void hfxw_set_clock(double seconds) { session.clock_s = seconds; }

EMSCRIPTEN_KEEPALIVE void hfxw_set_technique(int technique, int pass) {
    session.technique = technique, session.pass = pass;
}

/* 1: the application adds passes 2.. to the first (ONE, ONE, no depth writes), 0: passes as written. */
EMSCRIPTEN_KEEPALIVE void hfxw_set_blend_add(int on) { session.blend_add = on != 0; }

/* "auto" (hfxview's choice per effect), a built-in mesh name or an .obj path in the file
 * system: "" when set, else the message. */
EMSCRIPTEN_KEEPALIVE const char *hfxw_set_mesh(const char *spec) {
    char *err = session.message;
    err[0] = 0;
    if (hfxw_mesh_set(&session, spec, err, sizeof session.message) != 0 && !err[0])
        snprintf(err, sizeof session.message, "cannot load %s", spec);
    return err;
}

/* NAME ("a", "a[2]", "a[1].Member") = comma-separated VALUES or true / false: "" when set. */
EMSCRIPTEN_KEEPALIVE const char *hfxw_set_param(const char *name, const char *values) {
    char *err = session.message;
    err[0] = 0;
    if (!session.fx) return "no effect";
    hv_set_param(session.fx, name, values, err, sizeof session.message);
    return err;
}

/* An RGBA8 image (top row first: D3D's v = 0) for a texture parameter. 0, or -1. */
EMSCRIPTEN_KEEPALIVE int hfxw_set_texture(const char *name, const unsigned char *rgba, int width, int height) {
    hfxw_session *s = &session;
    hfx_param *p = s->fx ? hv_find_param(s->fx, name) : NULL;
    if (!p || s->texture_count == sizeof s->textures / sizeof s->textures[0]) return -1;
    unsigned tex = hfxw_texture_rgba(s, rgba, width, height);
    s->textures[s->texture_count++] = tex;
    return hfx_param_set_texture(p, tex) == HFX_OK ? 0 : -1;
}

/* The GLSL ES of the selected pass's program: stage 0 vertex, 1 fragment ("" when none). */
EMSCRIPTEN_KEEPALIVE const char *hfxw_glsl(int stage) {
    const hfx_fx_effect *c = session.code;
    if (!c || stage < 0 || stage >= HFX_STAGE_COUNT || (uint32_t)session.technique >= c->technique_count) return "";
    const hfx_fx_technique *t = &c->techniques[session.technique];
    uint32_t pass = session.pass < 0 ? 0 : (uint32_t)session.pass;
    if (pass >= t->pass_count) return "";
    uint32_t prog = c->passes[t->first_pass + pass].program;
    if (prog == HFX_NONE || prog >= c->program_count) return "";
    const char *text = c->programs[prog].code[stage][HFX_TARGET_GLSLES300].data;
    return text ? text : "";
}

EMSCRIPTEN_KEEPALIVE const void *hfxw_hfxo(void) { return session.hfxo; }
EMSCRIPTEN_KEEPALIVE int hfxw_hfxo_size(void) { return (int)session.hfxo_size; }
EMSCRIPTEN_KEEPALIVE const char *hfxw_version(void) { return hfxc_version(); }
