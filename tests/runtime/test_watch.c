/* test_watch.c: hfx_effect_dependencies and hfx_effect_reload_if_changed (runtime/watch.c). An
 * effect whose colour comes from an include is drawn, the include is rewritten under it, and the
 * next check reloads: the pixels before and after are worked out by hand from the shaders below,
 * a broken edit keeps the last good picture (and is not retried every frame), a parameter set
 * before keeps its value, and a new include joins the list. GL turns x in 0..1 into round(x * 255). */
#define _DEFAULT_SOURCE /* mkstemp */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "files.h"
#include "gl_context.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;
static char *tmp;

/* rgb = BASE * Scale, BASE from color.fxh; the application sets Scale = 0.5. */
static const char main_fx[] =
    "#include \"color.fxh\"\n"
    "float Scale = 1;\n"
    "float4 VS(float2 p : POSITION0) : POSITION0 { return float4(p, 0, 1); }\n"
    "float4 PS() : COLOR0 { return float4(BASE * Scale, 1); }\n"
    "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* The same plus a second include that adds to the colour. */
static const char main_fx_extra[] =
    "#include \"color.fxh\"\n"
    "#include \"extra.fxh\"\n"
    "float Scale = 1;\n"
    "float4 VS(float2 p : POSITION0) : POSITION0 { return float4(p, 0, 1); }\n"
    "float4 PS() : COLOR0 { return float4(BASE * Scale + EXTRA, 1); }\n"
    "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* (0.4, 0.8, 1.6) * 0.5 = (0.2, 0.4, 0.8) -> (51, 102, 204) */
static const char color_v1[] = "#define BASE float3(0.4, 0.8, 1.6)\n";
static const int v1_rgb[3] = {51, 102, 204};
/* (1.2, 0.4, 0.0) * 0.5 = (0.6, 0.2, 0.0) -> (153, 51, 0) */
static const char color_v2[] = "#define BASE float3(1.2, 0.4, 0.0)\n";
static const int v2_rgb[3] = {153, 51, 0};
/* the macro's closing parenthesis is gone: PS's line (4) no longer parses */
static const char color_broken[] = "#define BASE float3(1.2, 0.4, 0.0\n";
/* (0.4, 1.2, 0.8) * 0.5 = (0.2, 0.6, 0.4) -> (51, 153, 102) */
static const char color_v3[] = "#define BASE float3(0.4, 1.2, 0.8)\n";
static const int v3_rgb[3] = {51, 153, 102};
/* v3 + (0.2, 0, 0.4) = (0.4, 0.6, 0.8) -> (102, 153, 204) */
static const char extra_v1[] = "#define EXTRA float3(0.2, 0, 0.4)\n";
static const int v3_extra_rgb[3] = {102, 153, 204};

static char *path_of(const char *name) {
    size_t n = strlen(tmp) + strlen(name) + 2;
    char *p = malloc(n);
    snprintf(p, n, "%s/%s", tmp, name);
    return p;
}

/* Writes the file, then dates it `age` seconds after a fixed epoch, so that every version has a
 * time of its own whatever the file system's resolution. */
static void write_file(const char *name, const char *text, int age) {
    char *p = path_of(name);
    FILE *f = fopen(p, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    struct timespec ts[2] = {{1700000000 + age, 0}, {1700000000 + age, 0}};
    CHECK_INT(utimensat(AT_FDCWD, p, ts, 0), 0);
    free(p);
}

static void render_and_check(hfx_effect *fx, const int rgb[3]) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint vbo, vao = tgl_triangles(&g, quad, 6, &vbo);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    g.BindVertexArray(vao);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    unsigned char px[4];
    test_gl_read(gl, 4, 4, px);
    for (int i = 0; i < 3; i++) CHECK_NEAR(px[i], rgb[i], 1);
}

static void check_dependencies(const hfx_effect *fx, const char *const *names, size_t n) {
    size_t count = 99;
    const char *const *deps = hfx_effect_dependencies(fx, &count);
    CHECK_INT(count, n);
    for (size_t i = 0; i < n && i < count; i++) {
        char *want = path_of(names[i]);
        CHECK_STR(deps[i], want);
        free(want);
    }
}

static void reloads_when_an_include_changes(void) {
    write_file("main.fx", main_fx, 0);
    write_file("color.fxh", color_v1, 0);
    char *path = path_of("main.fx"), *errors = NULL;
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, &errors);
    CHECK(fx != NULL);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    if (!fx) return free(path);
    check_dependencies(fx, (const char *[]){"main.fx", "color.fxh"}, 2);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Scale"), 0.5f), HFX_OK);
    render_and_check(fx, v1_rgb);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 0); /* nothing changed */

    write_file("color.fxh", color_v2, 1);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, &errors), 1);
    CHECK_STR(errors ? errors : "", ""); /* no warnings either */
    hfx_free(errors);
    render_and_check(fx, v2_rgb); /* new code, Scale still 0.5 */
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 0);

    write_file("color.fxh", color_broken, 2);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, &errors), HFX_ERR_LOAD);
    char want[1024];
    snprintf(want, sizeof want, "%s(4,", path); /* located where BASE is used, in main.fx */
    CHECK_CONTAINS(errors, want);
    CHECK_CONTAINS(errors, ": error X");
    hfx_free(errors);
    render_and_check(fx, v2_rgb); /* the last good picture */
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 0); /* not retried until the next edit */

    write_file("color.fxh", color_v3, 3);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 1);
    render_and_check(fx, v3_rgb);

    /* the root gains an include: it joins the watched files */
    write_file("extra.fxh", extra_v1, 0);
    write_file("main.fx", main_fx_extra, 4);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 1);
    check_dependencies(fx, (const char *[]){"main.fx", "color.fxh", "extra.fxh"}, 3);
    render_and_check(fx, v3_extra_rgb);
    /* same bytes, a new time: a save without edits reloads too (mtime counts, not content) */
    write_file("extra.fxh", extra_v1, 5);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 1);
    render_and_check(fx, v3_extra_rgb);

    /* a clone watches the same files as last seen, and reloads on its own */
    hfx_effect *clone = hfx_effect_clone(fx);
    CHECK(clone != NULL);
    check_dependencies(clone, (const char *[]){"main.fx", "color.fxh", "extra.fxh"}, 3);
    CHECK_INT(hfx_effect_reload_if_changed(clone, NULL, NULL), 0);
    write_file("color.fxh", color_v1, 6);
    CHECK_INT(hfx_effect_reload_if_changed(clone, NULL, NULL), 1);
    render_and_check(clone, (const int[3]){102, 102, 255}); /* (0.2, 0.4, 0.8) + (0.2, 0, 0.4) = (0.4, 0.4, 1.2) */
    render_and_check(fx, v3_extra_rgb);                     /* fx has not looked yet */
    hfx_effect_destroy(clone);
    hfx_effect_destroy(fx);
    free(path);
}

/* A deleted include is a change (the reload fails and the old effect stays); its return is one too. */
static void a_missing_file_is_a_change(void) {
    write_file("main.fx", main_fx, 10);
    write_file("color.fxh", color_v1, 10);
    char *path = path_of("main.fx"), *inc = path_of("color.fxh"), *errors = NULL;
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return free(path), free(inc);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Scale"), 0.5f), HFX_OK);
    CHECK_INT(remove(inc), 0);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, &errors), HFX_ERR_LOAD);
    CHECK_CONTAINS(errors, "error X1507: failed to open source file: 'color.fxh'");
    hfx_free(errors);
    render_and_check(fx, v1_rgb);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 0);
    write_file("color.fxh", color_v2, 11);
    CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 1);
    render_and_check(fx, v2_rgb);
    hfx_effect_destroy(fx);
    free(path), free(inc);
}

/* A .hfxo depends on itself alone; from memory, only the includes count. */
static void hfxo_and_memory(void) {
    write_file("main.fx", main_fx, 20);
    write_file("color.fxh", color_v1, 20);
    char *src = path_of("main.fx"), *hfxo = path_of("main.hfxo");
    hfx_effect *compiled = hfx_effect_load(dev, src, NULL, NULL);
    void *data = NULL;
    size_t size = 0;
    CHECK(compiled && hfx_fx_write_hfxo(compiled->sh->fx, &data, &size) == 0);
    FILE *f = fopen(hfxo, "wb");
    CHECK(f && fwrite(data, 1, size, f) == size);
    if (f) fclose(f);
    hfx_effect *fx = hfx_effect_load(dev, hfxo, NULL, NULL);
    CHECK(fx != NULL);
    if (fx) {
        check_dependencies(fx, (const char *[]){"main.hfxo"}, 1);
        struct timespec ts[2] = {{1700000100, 0}, {1700000100, 0}};
        CHECK_INT(utimensat(AT_FDCWD, hfxo, ts, 0), 0);
        CHECK_INT(hfx_effect_reload_if_changed(fx, NULL, NULL), 1);
        check_dependencies(fx, (const char *[]){"main.hfxo"}, 1);
    }
    hfx_effect *mem = hfx_effect_load_memory(dev, main_fx, strlen(main_fx), src, NULL, NULL);
    CHECK(mem != NULL);
    if (mem) check_dependencies(mem, (const char *[]){"color.fxh"}, 1);
    CHECK(hfx_effect_dependencies(NULL, NULL) == NULL);
    CHECK_INT(hfx_effect_reload_if_changed(NULL, NULL, NULL), HFX_ERR_NULL);
    hfx_effect_destroy(mem), hfx_effect_destroy(fx), hfx_effect_destroy(compiled);
    free(data), free(src), free(hfxo);
}

/* What a check costs when nothing changed: printed for docs/runtime.md, and bounded loosely so
 * that a check which compiled every time (milliseconds) would fail. */
static void a_check_is_cheap(void) {
    write_file("main.fx", main_fx_extra, 30);
    write_file("color.fxh", color_v1, 30);
    write_file("extra.fxh", extra_v1, 30);
    char *path = path_of("main.fx");
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, NULL);
    CHECK(fx != NULL);
    if (!fx) return free(path);
    enum { N = 20000 };
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    int changed = 0;
    for (int i = 0; i < N; i++) changed += hfx_effect_reload_if_changed(fx, NULL, NULL);
    clock_gettime(CLOCK_MONOTONIC, &b);
    double us = ((double)(b.tv_sec - a.tv_sec) * 1e9 + (double)(b.tv_nsec - a.tv_nsec)) / N / 1000.0;
    printf("hfx_effect_reload_if_changed, 3 files, nothing changed: %.2f us per call\n", us);
    CHECK_INT(changed, 0);
    CHECK(us < 200.0);
    hfx_effect_destroy(fx);
    free(path);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    hfx_device_set_viewport(dev, 0, 0, W, H);
    tmp = test_temp_dir();
    RUN(reloads_when_an_include_changes);
    RUN(a_missing_file_is_a_change);
    RUN(hfxo_and_memory);
    RUN(a_check_is_cheap);
    test_remove_dir(tmp);
    free(tmp);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
