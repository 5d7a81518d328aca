/* Two devices on two OSMesa contexts on two threads at once: each compiles a seed effect (the
 * compiler in-process), applies every pass over a full-screen quad a few times and reads the
 * picture back; both pictures must be byte for byte the ones the same scenes give one after
 * the other on one thread. The libraries keep no global state, so nothing may leak across.
 * test.sh also runs this under ThreadSanitizer (build/tsan). */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "gl_context.h"
#include "rt_support.h"
#include "test.h"

enum { W = 16, H = 16, ROUNDS = 3, SCENES = 2 };

static const char *const effects[SCENES] = {"fxcomposer_empty.fx", "ambient.fx"};
static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

typedef struct scene {
    const char *effect;
    unsigned char pixels[W * H * 4];
    int failed; /* 1 when anything went wrong (the checks of test.h are the main thread's) */
} scene;

static void draw_quad(tgl *g, hfx_pass *pass, int *failed) {
    static const float xyz[18] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0};
    GLuint vao, vbo;
    g->GenVertexArrays(1, &vao);
    g->BindVertexArray(vao);
    g->GenBuffers(1, &vbo);
    g->BindBuffer(GL_ARRAY_BUFFER, vbo);
    g->BufferData(GL_ARRAY_BUFFER, sizeof xyz, xyz, GL_STATIC_DRAW);
    int loc = hfx_pass_attribute_location(pass, "POSITION");
    if (loc < 0) *failed = 1;
    else {
        g->VertexAttribPointer((GLuint)loc, 3, GL_FLOAT, GL_FALSE, 0, NULL);
        g->EnableVertexAttribArray((GLuint)loc);
        g->DrawArrays(GL_TRIANGLES, 0, 6);
    }
    g->DeleteBuffers(1, &vbo);
    g->DeleteVertexArrays(1, &vao);
}

/* Every matrix parameter identity, every pass of the first technique over the quad. */
static void render(tgl *g, hfx_effect *fx, int *failed) {
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        if (hfx_param_get_class(p) == HFX_CLASS_MATRIX) hfx_param_set_matrix(p, identity);
    }
    g->ClearColor(0, 0, 0, 0);
    g->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    hfx_technique *t = hfx_effect_technique_at(fx, 0);
    for (size_t p = 0; p < hfx_technique_pass_count(t); p++) {
        if (hfx_pass_apply(hfx_technique_pass(t, p)) != HFX_OK) *failed = 1;
        draw_quad(g, hfx_technique_pass(t, p), failed);
    }
    if (g->GetError() != GL_NO_ERROR) *failed = 1;
}

static void read_picture(test_gl *gl, unsigned char *out) {
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) test_gl_read(gl, x, y, out + 4 * (y * W + x));
}

/* One device on its own context: ROUNDS renders, each the same picture as the first. */
static void *run_scene(void *arg) {
    scene *s = arg;
    test_gl *gl = test_gl_create(W, H);
    if (!gl) return s->failed = 1, NULL;
    tgl g;
    tgl_load(&g);
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    char *path = test_seed_path(s->effect);
    hfx_effect *fx = dev ? hfx_effect_load(dev, path, NULL, NULL) : NULL;
    unsigned char again[W * H * 4];
    for (int round = 0; fx && round < ROUNDS; round++) {
        render(&g, fx, &s->failed);
        read_picture(gl, round ? again : s->pixels);
        if (round && memcmp(again, s->pixels, sizeof again) != 0) s->failed = 1;
    }
    if (!fx) s->failed = 1;
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    free(path);
    test_gl_destroy(gl);
    return NULL;
}

static void two_devices_on_two_threads(void) {
    static scene alone[SCENES], together[SCENES];
    for (int i = 0; i < SCENES; i++) {
        alone[i].effect = together[i].effect = effects[i];
        run_scene(&alone[i]);
        CHECK_INT(alone[i].failed, 0);
    }
    CHECK(memcmp(alone[0].pixels, alone[1].pixels, sizeof alone[0].pixels) != 0); /* two different pictures */
    pthread_t t[SCENES];
    for (int i = 0; i < SCENES; i++) CHECK_INT(pthread_create(&t[i], NULL, run_scene, &together[i]), 0);
    for (int i = 0; i < SCENES; i++) pthread_join(t[i], NULL);
    for (int i = 0; i < SCENES; i++) {
        CHECK_INT(together[i].failed, 0);
        CHECK(memcmp(together[i].pixels, alone[i].pixels, sizeof alone[i].pixels) == 0);
    }
}

int main(void) {
    test_require_seeds();
    RUN(two_devices_on_two_threads);
    return test_summary();
}
