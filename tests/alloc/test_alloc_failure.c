/* Allocation failure: allocation number N fails, for every N, while the compiler compiles two
 * seed effects (once with only allocation N failing, once with N and every later one failing),
 * while the runtime loads them (.hfxo bytes: the reader, then GL objects), applies every pass
 * and destroys them, and while it reloads one from a file. Every run must end in a clean error
 * (X9001 "out of memory"; NULL or an error code with "out of memory" in hfx_device_last_error)
 * or in exactly the result of a run without failure; LSan (the ASan build) checks nothing
 * leaks, and the caller's objects (the device, a second effect, the effect being reloaded) keep
 * their values and keep applying.
 *
 * The hook: this program is linked with -Wl,--wrap=malloc,... (tests/extra.cmake), so every
 * malloc, calloc, realloc and strdup the hfx libraries make goes through the __wrap_ functions
 * below; the libraries themselves carry no hook and no global state. glslang (C++, whose
 * operator new lives in libstdc++) and Mesa allocate outside the hook: out of scope here. */
#include <GL/glcorearb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "gl_context.h"
#include "hfx/hfx.h"
#include "hfx/hfxc.h"
#include "test.h"

/* ---- the hook (this test program's state, not the libraries') ---- */

void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t n);
char *__real_strdup(const char *s);

static long counted, fail_at; /* fail_at 0: nothing fails */
static int persistent;        /* 1: allocation fail_at and every later one fail (memory stays short) */

static int fail_now(void) { return fail_at && (++counted == fail_at || (persistent && counted > fail_at)); }
void *__wrap_malloc(size_t n) { return fail_now() ? NULL : __real_malloc(n); }
void *__wrap_calloc(size_t n, size_t size) { return fail_now() ? NULL : __real_calloc(n, size); }
void *__wrap_realloc(void *p, size_t n) { return fail_now() ? NULL : __real_realloc(p, n); }
char *__wrap_strdup(const char *s) { return fail_now() ? NULL : __real_strdup(s); }

static void arm(long n) { counted = 0, fail_at = n; }
static int disarm(void) { /* 1 when the armed allocation was reached (it failed) */
    int reached = counted >= fail_at;
    fail_at = 0;
    return reached;
}

static const char *const seeds[] = {"phong.fx", "spot.fx"};

typedef struct bytes { void *data; size_t size; } bytes;

static bytes hfxo_of(const hfxc_result *r) {
    bytes b = {NULL, 0};
    if (hfxc_result_effect(r)) CHECK_INT(hfx_fx_write_hfxo(hfxc_result_effect(r), &b.data, &b.size), 0);
    return b;
}

static int same_bytes(bytes a, bytes b) { return a.size == b.size && memcmp(a.data, b.data, a.size) == 0; }

/* ---- compiling ---- */

/* Refused, and says why: with memory short for good, even the message may not fit. */
static int says_out_of_memory(const hfxc_result *r) {
    char *text = hfxc_diagnostics_text(r);
    int said = text && strstr(text, "error X9001: out of memory");
    int ok = (said || persistent) && !hfxc_result_ok(r) && !hfxc_result_effect(r);
    if (!ok) fprintf(stderr, "a failed compile says:\n%s\n", text ? text : "(nothing)");
    free(text);
    return ok;
}

/* One compile with allocation n failing; returns 0 once n is past the last allocation. */
static int compile_failing(const char *src, size_t size, long n, bytes reference, int *refused) {
    arm(n);
    hfxc_result *r = hfxc_compile_memory(src, size, "seed.fx", NULL);
    int reached = disarm();
    if (reached && r && !hfxc_result_ok(r)) {
        CHECK(says_out_of_memory(r));
        ++*refused;
    } else if (r) { /* the failure was absorbed (a retry, an optional cache): the same output */
        bytes b = hfxo_of(r);
        if (!same_bytes(b, reference)) fprintf(stderr, "allocation %ld: a different effect\n", n);
        CHECK(same_bytes(b, reference));
        free(b.data);
    }
    hfxc_result_free(r);
    return reached;
}

static void compile_seeds_failing(void) {
    for (size_t s = 0; s < sizeof seeds / sizeof *seeds; s++) {
        size_t size;
        char *path = test_seed_path(seeds[s]), *src = test_read_file(path, &size);
        hfxc_result *r = hfxc_compile_memory(src, size, "seed.fx", NULL);
        bytes reference = hfxo_of(r);
        hfxc_result_free(r);
        long n = 1;
        int refused = 0;
        while (compile_failing(src, size, n, reference, &refused)) n++;
        printf("  %s: compiled with allocation 1..%ld failing%s (%d refused)\n", seeds[s], n - 1,
               persistent ? ", and all after it" : "", refused);
        CHECK(n > 20 && refused > 0);
        free(reference.data);
        free(src);
        free(path);
    }
}

static void compile_every_allocation_failing(void) { compile_seeds_failing(); }

static void compile_with_memory_short_from_every_allocation(void) {
    persistent = 1;
    compile_seeds_failing();
    persistent = 0;
}

/* ---- loading, applying, reloading ---- */

static hfx_device *dev;

static bytes compiled_seed(const char *name) {
    char *path = test_seed_path(name);
    hfxc_result *r = hfxc_compile_file(path, NULL);
    bytes b = hfxo_of(r);
    hfxc_result_free(r);
    free(path);
    return b;
}

/* Every pass of every technique; HFX_OK or HFX_ERR_MEMORY each. */
static void apply_all(hfx_effect *fx, int must_succeed) {
    for (size_t t = 0; t < hfx_effect_technique_count(fx); t++) {
        hfx_technique *tech = hfx_effect_technique_at(fx, t);
        for (size_t p = 0; p < hfx_technique_pass_count(tech); p++) {
            int rc = hfx_pass_apply(hfx_technique_pass(tech, p));
            if (must_succeed) CHECK_INT(rc, HFX_OK);
            else CHECK(rc == HFX_OK || rc == HFX_ERR_MEMORY);
        }
    }
}

/* The first parameter (a matrix, vector or scalar of floats in both seeds), every element v. */
static void set_first(hfx_effect *fx, float v) {
    hfx_param *p = hfx_effect_param_at(fx, 0);
    float m[16] = {v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v};
    CHECK_INT(hfx_param_set_floats(p, m, hfx_param_rows(p) * hfx_param_columns(p)), HFX_OK);
}

/* The caller's effect: its first parameter still holds `value` everywhere, and it applies. */
static void witness_unchanged(hfx_effect *fx, float value) {
    hfx_param *p = hfx_effect_param_at(fx, 0);
    float m[16] = {0};
    size_t n = hfx_param_rows(p) * hfx_param_columns(p);
    CHECK_INT(hfx_param_get_floats(p, m, n), HFX_OK);
    for (size_t i = 0; i < n; i++) CHECK_NEAR(m[i], value, 0);
    apply_all(fx, 1);
}

static int load_failing(bytes b, long n, hfx_effect *witness, int *refused) {
    char *errors = NULL;
    arm(n);
    hfx_effect *fx = hfx_effect_load_memory(dev, b.data, b.size, "seed.hfxo", NULL, &errors);
    if (fx) apply_all(fx, 0);
    hfx_effect_destroy(fx);
    int reached = disarm();
    if (!fx) {
        CHECK(reached);
        CHECK_CONTAINS(hfx_device_last_error(dev), "out of memory");
        ++*refused;
    }
    hfx_free(errors);
    witness_unchanged(witness, 0.25f);
    return reached;
}

static hfx_effect *witness_effect(bytes b) {
    hfx_effect *w = hfx_effect_load_memory(dev, b.data, b.size, "witness.hfxo", NULL, NULL);
    CHECK(w != NULL);
    set_first(w, 0.25f);
    return w;
}

static void load_and_apply_every_allocation_failing(void) {
    for (size_t s = 0; s < sizeof seeds / sizeof *seeds; s++) {
        bytes b = compiled_seed(seeds[s]);
        hfx_effect *witness = witness_effect(b);
        long n = 1;
        int refused = 0;
        while (load_failing(b, n, witness, &refused)) n++;
        printf("  %s: loaded and applied with allocation 1..%ld failing (%d refused)\n", seeds[s], n - 1, refused);
        CHECK(n > 10 && refused > 0);
        hfx_effect_destroy(witness);
        free(b.data);
    }
}

static int reload_failing(hfx_effect *fx, const char *path, long n, int *refused) {
    char *errors = NULL;
    set_first(fx, 0.5f);
    size_t techniques = hfx_effect_technique_count(fx);
    arm(n);
    int rc = hfx_effect_reload(fx, path, NULL, &errors);
    int reached = disarm();
    if (rc != HFX_OK) {
        CHECK(reached);
        CHECK(rc == HFX_ERR_MEMORY || rc == HFX_ERR_LOAD);
        CHECK_CONTAINS(hfx_device_last_error(dev), "out of memory");
        ++*refused;
    }
    witness_unchanged(fx, 0.5f); /* kept by a failed reload, carried over by a good one */
    CHECK_INT(hfx_effect_technique_count(fx), techniques);
    hfx_free(errors);
    return reached;
}

static void reload_every_allocation_failing(void) {
    bytes b = compiled_seed(seeds[0]);
    char *dir = test_temp_dir(), path[512];
    snprintf(path, sizeof path, "%s/seed.hfxo", dir);
    FILE *f = fopen(path, "wb");
    CHECK(f && fwrite(b.data, 1, b.size, f) == b.size);
    if (f) fclose(f);
    hfx_effect *fx = hfx_effect_load(dev, path, NULL, NULL);
    CHECK(fx != NULL);
    long n = 1;
    int refused = 0;
    while (fx && reload_failing(fx, path, n, &refused)) n++;
    printf("  %s: reloaded with allocation 1..%ld failing (%d refused)\n", seeds[0], n - 1, refused);
    CHECK(refused > 0);
    hfx_effect_destroy(fx);
    remove(path);
    remove(dir);
    free(dir);
    free(b.data);
}

int main(void) {
    test_require_seeds();
    RUN(compile_every_allocation_failing);
    RUN(compile_with_memory_short_from_every_allocation);
    test_gl *gl = test_gl_create(32, 32);
    if (!gl) test_skip("no OSMesa context");
    dev = hfx_device_create_gl(test_gl_loader);
    RUN(load_and_apply_every_allocation_failing);
    RUN(reload_every_allocation_failing);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
