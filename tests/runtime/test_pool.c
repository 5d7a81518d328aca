/* test_pool.c: effect pools (runtime/pool.c). Two effects share `shared float4 Tint`: a set
 * through one shows in the other's pixels (each draws a full-screen quad; the colours are worked
 * out by hand from the pixel shaders below, GL rounding x * 255 to the nearest byte), a joining
 * effect takes the pool's value over its own initializer, parameters not declared shared stay
 * apart, a type mismatch fails the load naming both declarations, and clones, reloads and
 * destruction keep the pool consistent. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

#define VS "float4 VS(float2 p : POSITION0) : POSITION0 { return float4(p, 0, 1); }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"

/* a.fx shows Tint as it is; Gain (not shared) scales nothing it draws. */
static const char a_fx[] = "shared float4 Tint = float4(0.2, 0.4, 0.8, 1);\n"
                           "float Gain = 1;\n" VS
                           "float4 PS() : COLOR0 { return Tint; }\n" TECH;
/* b.fx shows 1 - Tint; its own initializer for Tint loses to the pool's value. */
static const char b_fx[] = "float Gain = 2;\n"
                           "shared float4 Tint = float4(0, 0, 0, 1);\n" VS
                           "float4 PS() : COLOR0 { return float4(1 - Tint.rgb, 1); }\n" TECH;
/* c.fx declares Tint shared as a float3: line 2, column 15. */
static const char c_fx[] = "// another shape\n"
                           "shared float3 Tint;\n" VS
                           "float4 PS() : COLOR0 { return float4(Tint, 1); }\n" TECH;
/* d.fx has a Tint that is not shared: outside the pool's value. */
static const char d_fx[] = "float4 Tint = float4(1, 1, 1, 1);\n" VS
                           "float4 PS() : COLOR0 { return Tint; }\n" TECH;

static char *write_fx(const char *name, const char *text) {
    size_t n = strlen(tmp) + strlen(name) + 2;
    char *p = malloc(n);
    snprintf(p, n, "%s/%s", tmp, name);
    FILE *f = fopen(p, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    return p;
}

static hfx_effect *load(const char *name, const char *text, hfx_pool *pool, char **errors) {
    char *path = write_fx(name, text);
    hfx_load_options opt = {0};
    opt.pool = pool;
    hfx_effect *fx = hfx_effect_load(dev, path, &opt, errors);
    free(path);
    return fx;
}

static void render_and_check(hfx_effect *fx, const int rgb[3]) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint vbo, vao = tgl_triangles(&g, quad, 6, &vbo);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)), HFX_OK);
    g.BindVertexArray(vao);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    unsigned char px[4];
    test_gl_read(gl, 4, 4, px);
    for (int i = 0; i < 3; i++) CHECK_NEAR(px[i], rgb[i], 1);
}

static void shared_between_two_effects(void) {
    hfx_pool *pool = hfx_pool_create(dev);
    CHECK(pool != NULL);
    hfx_effect *a = load("a.fx", a_fx, pool, NULL), *b = load("b.fx", b_fx, pool, NULL);
    CHECK(a && b);
    if (!a || !b) return hfx_effect_destroy(a), hfx_effect_destroy(b), hfx_pool_destroy(pool);
    /* b joined holding a's (0.2, 0.4, 0.8): a shows (51, 102, 204), b 1 - that = (0.8, 0.6, 0.2) */
    render_and_check(a, (const int[3]){51, 102, 204});
    render_and_check(b, (const int[3]){204, 153, 51});
    /* set once, through b: (0.6, 0.2, 0.4) -> a (153, 51, 102), b (0.4, 0.8, 0.6) = (102, 204, 153) */
    static const float tint[4] = {0.6f, 0.2f, 0.4f, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(b, "Tint"), tint, 4), HFX_OK);
    float v[4];
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(a, "Tint"), v, 4), HFX_OK);
    CHECK_NEAR(v[0], 0.6, 1e-7);
    CHECK_NEAR(v[2], 0.4, 1e-7);
    render_and_check(a, (const int[3]){153, 51, 102});
    render_and_check(b, (const int[3]){102, 204, 153});
    /* Gain is not shared: each keeps its own */
    CHECK_INT(hfx_param_set_float(hfx_effect_param(a, "Gain"), 5), HFX_OK);
    CHECK_INT(hfx_param_get_float(hfx_effect_param(b, "Gain"), v), HFX_OK);
    CHECK_NEAR(v[0], 2, 0);
    /* a clone is in the pool too */
    hfx_effect *clone = hfx_effect_clone(a);
    CHECK(clone != NULL);
    static const float red[4] = {1, 0, 0, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(clone, "Tint"), red, 4), HFX_OK);
    render_and_check(b, (const int[3]){0, 255, 255});
    hfx_effect_destroy(clone);
    hfx_effect_destroy(a);
    render_and_check(b, (const int[3]){0, 255, 255}); /* b lives on with the value */
    hfx_effect_destroy(b);
    hfx_pool_destroy(pool);
}

static void mismatch_names_both_declarations(void) {
    hfx_pool *pool = hfx_pool_create(dev);
    hfx_effect *a = load("a.fx", a_fx, pool, NULL);
    char *errors = NULL;
    hfx_effect *c = load("c.fx", c_fx, pool, &errors);
    CHECK(a != NULL);
    CHECK(c == NULL);
    char want[2048];
    snprintf(want, sizeof want,
             "%s/c.fx(2,15): error X9003: shared parameter 'Tint' is float3 here but float4 in the pool's %s/a.fx(1,15)",
             tmp, tmp);
    CHECK_CONTAINS(errors, want);
    hfx_free(errors);
    /* the pool is unharmed: a still works, a not-shared Tint in d is its own */
    hfx_effect *d = load("d.fx", d_fx, pool, NULL);
    CHECK(d != NULL);
    static const float green[4] = {0, 1, 0, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(a, "Tint"), green, 4), HFX_OK);
    if (d) render_and_check(d, (const int[3]){255, 255, 255});
    render_and_check(a, (const int[3]){0, 255, 0});
    /* without a pool, c loads: the check is the pool's */
    hfx_effect *alone = load("c.fx", c_fx, NULL, NULL);
    CHECK(alone != NULL);
    hfx_effect_destroy(alone), hfx_effect_destroy(d), hfx_effect_destroy(a);
    hfx_pool_destroy(pool);
}

/* A reloaded effect stays in the pool: the value survives, and sets still reach it. */
static void reload_stays_in_the_pool(void) {
    hfx_pool *pool = hfx_pool_create(dev);
    hfx_effect *a = load("a.fx", a_fx, pool, NULL), *b = load("b.fx", b_fx, pool, NULL);
    CHECK(a && b);
    if (!a || !b) return hfx_effect_destroy(a), hfx_effect_destroy(b), hfx_pool_destroy(pool);
    static const float blue[4] = {0, 0, 1, 1}, grey[4] = {0.2f, 0.2f, 0.2f, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(a, "Tint"), blue, 4), HFX_OK);
    CHECK_INT(hfx_effect_reload(a, NULL, NULL, NULL), HFX_OK); /* NULL options: the pool is kept */
    CHECK(a->pool == pool);
    render_and_check(a, (const int[3]){0, 0, 255});
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(b, "Tint"), grey, 4), HFX_OK);
    render_and_check(a, (const int[3]){51, 51, 51}); /* 0.2 * 255 */
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(a, "Tint"), blue, 4), HFX_OK);
    render_and_check(b, (const int[3]){255, 255, 0}); /* 1 - (0, 0, 1) */
    hfx_effect_destroy(a), hfx_effect_destroy(b);
    hfx_pool_destroy(pool);
}

static void shared_textures_and_nulls(void) {
    static const char t_fx[] = "shared texture Shadow;\nfloat4 PS() : COLOR0 { return 1; }\n" VS TECH;
    hfx_pool *pool = hfx_pool_create(dev);
    hfx_effect *x = load("t1.fx", t_fx, pool, NULL), *y = load("t2.fx", t_fx, pool, NULL);
    CHECK(x && y);
    unsigned int t = 0;
    if (x && y) {
        CHECK_INT(hfx_param_set_texture(hfx_effect_param(x, "Shadow"), 42), HFX_OK);
        CHECK_INT(hfx_param_get_texture(hfx_effect_param(y, "Shadow"), &t), HFX_OK);
        CHECK_INT(t, 42);
    }
    hfx_effect_destroy(x), hfx_effect_destroy(y);
    hfx_pool_destroy(pool);
    CHECK(hfx_pool_create(NULL) == NULL);
    hfx_pool_destroy(NULL);
    CHECK(hfx_pool_device(NULL) == NULL);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    hfx_device_set_viewport(dev, 0, 0, W, H);
    tmp = test_temp_dir();
    RUN(shared_between_two_effects);
    RUN(mismatch_names_both_declarations);
    RUN(reload_stays_in_the_pool);
    RUN(shared_textures_and_nulls);
    test_remove_dir(tmp);
    free(tmp);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
