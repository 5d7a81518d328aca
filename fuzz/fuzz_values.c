/* Hostile values through the runtime's public API (fuzz_values.h). Return codes are not
 * checked: a setter of the wrong type is refused with an error, which is fine; what the
 * harness asks is that nothing crashes and nothing is undefined (ASan + UBSan with
 * float-cast-overflow, fatal). */
#include "fuzz_values.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "effect.h"

enum { MAX_DEPTH = 3, MAX_CHILDREN = 8, MAX_WORDS = 256 };

static const float hostile_floats[] = {NAN, INFINITY, -INFINITY, FLT_MAX, -FLT_MAX, FLT_TRUE_MIN, -FLT_TRUE_MIN,
                                       FLT_MIN, 1e30f, -1e30f, 2147483648.0f, -2147483904.0f, 4294967296.0f,
                                       -0.0f, 0.5f, -1.0f};
static const int hostile_ints[] = {INT_MIN, INT_MAX, -1, 0, 1, INT_MIN + 1, 255, 256};
enum { NF = sizeof hostile_floats / sizeof *hostile_floats, NI = sizeof hostile_ints / sizeof *hostile_ints };

uint32_t fuzz_seed(const uint8_t *data, size_t size) {
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < size; i++) h = (h ^ data[i]) * 16777619u;
    return h;
}

static float pick_float(uint32_t seed, uint32_t k) { return hostile_floats[(seed + k * 7u) % NF]; }
static int pick_int(uint32_t seed, uint32_t k) { return hostile_ints[(seed / NF + k * 3u) % NI]; }

/* ---- annotations ---- */

static void read_annotation(const hfx_annotation *a) {
    float f[16];
    int i = 0;
    (void)hfx_annotation_name(a);
    (void)hfx_annotation_type(a);
    (void)hfx_annotation_string(a);
    (void)hfx_annotation_float(a, f);
    (void)hfx_annotation_int(a, &i);
    for (size_t n = 0; n <= 16; n++) (void)hfx_annotation_floats(a, f, n);
}

static void read_param_annotations(hfx_param *p) {
    size_t n = hfx_param_annotation_count(p);
    for (size_t i = 0; i <= n; i++) read_annotation(hfx_param_annotation_at(p, i)); /* n: past the end */
}

/* The annotation names of [first, first + count) of the file's list, each asked for by name. */
static void read_named(const hfx_fx_effect *e, uint32_t first, uint32_t count, hfx_technique *t, hfx_pass *p) {
    for (uint32_t i = 0; i < count && first + i < e->annotation_count; i++) {
        const char *name = e->annotations[first + i].name;
        read_annotation(t ? hfx_technique_annotation(t, name) : hfx_pass_annotation(p, name));
    }
    read_annotation(t ? hfx_technique_annotation(t, "NoSuchAnnotation") : hfx_pass_annotation(p, "NoSuchAnnotation"));
}

void fuzz_read_annotations(hfx_effect *fx, const uint8_t *hfxo, size_t size) {
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) read_param_annotations(hfx_effect_param_at(fx, i));
    char err[256];
    hfx_fx_effect *e = hfx_fx_read_hfxo(hfxo, size, err, sizeof err);
    if (!e) return;
    for (size_t t = 0; t < hfx_effect_technique_count(fx) && t < e->technique_count; t++) {
        const hfx_fx_technique *ft = &e->techniques[t];
        hfx_technique *tech = hfx_effect_technique_at(fx, t);
        read_named(e, ft->first_annotation, ft->annotation_count, tech, NULL);
        for (uint32_t k = 0; k < ft->pass_count && ft->first_pass + k < e->pass_count; k++) {
            const hfx_fx_pass *fp = &e->passes[ft->first_pass + k];
            read_named(e, fp->first_annotation, fp->annotation_count, NULL, hfx_technique_pass(tech, k));
        }
    }
    hfx_fx_effect_free(e);
}

/* ---- parameters ---- */

static size_t words_of(const hfx_param *p) {
    size_t n = hfx_param_rows(p) * hfx_param_columns(p), e = hfx_param_elements(p);
    n *= e ? e : 1;
    return n < MAX_WORDS ? n : MAX_WORDS;
}

static void read_back(const hfx_param *p) {
    float f[MAX_WORDS];
    int i[MAX_WORDS];
    size_t n = words_of(p);
    (void)hfx_param_get_bool(p, i);
    (void)hfx_param_get_int(p, i);
    (void)hfx_param_get_float(p, f);
    (void)hfx_param_get_floats(p, f, n);
    (void)hfx_param_get_ints(p, i, n);
    (void)hfx_param_get_matrix(p, f);
    unsigned tex = 0;
    (void)hfx_param_get_texture(p, &tex);
    (void)hfx_param_texture_target(p);
}

/* Every setter once (ints first, so that the float ones leave the hostile float in place). */
static void set_all(hfx_param *p, uint32_t seed, uint32_t k) {
    float f[MAX_WORDS];
    int i[MAX_WORDS];
    size_t n = words_of(p);
    for (size_t w = 0; w < MAX_WORDS; w++) f[w] = pick_float(seed, k + (uint32_t)w), i[w] = pick_int(seed, k + (uint32_t)w);
    (void)hfx_param_set_bool(p, pick_int(seed, k));
    (void)hfx_param_set_int(p, pick_int(seed, k + 1));
    (void)hfx_param_set_ints(p, i, n);
    (void)hfx_param_set_ints(p, i, n + 1);
    read_back(p);
    (void)hfx_param_set_matrix_transpose(p, f + 1);
    (void)hfx_param_set_matrix(p, f);
    (void)hfx_param_set_float(p, pick_float(seed, k));
    (void)hfx_param_set_floats(p, f, n);
    (void)hfx_param_set_floats(p, f, n ? n - 1 : 0);
    read_back(p);
}

static void visit(hfx_param *p, uint32_t seed, uint32_t k, int depth) {
    if (!p || depth > MAX_DEPTH) return;
    set_all(p, seed, k);
    size_t e = hfx_param_elements(p), m = hfx_param_member_count(p);
    for (size_t i = 0; i < e && i < MAX_CHILDREN; i++) visit(hfx_param_element(p, i), seed, k + 11u * (uint32_t)i, depth + 1);
    (void)hfx_param_element(p, e); /* past the end */
    for (size_t i = 0; i < m && i < MAX_CHILDREN; i++) visit(hfx_param_member_at(p, i), seed, k + 13u * (uint32_t)i, depth + 1);
    (void)hfx_param_member_at(p, m);
}

static void hostile_matrix(float m[16], uint32_t seed, uint32_t k) {
    switch ((seed >> (k % 24)) & 3u) {
    case 0: for (int i = 0; i < 16; i++) m[i] = pick_float(seed, k + (uint32_t)i); break;
    case 1: memset(m, 0, 16 * sizeof *m); break;                    /* singular: no inverse */
    case 2: for (int i = 0; i < 16; i++) m[i] = i % 5 == 0 ? FLT_MAX : FLT_TRUE_MIN; break;
    default: for (int i = 0; i < 16; i++) m[i] = i % 5 == 0 ? 1.0f : 0.0f; m[k % 16] = pick_float(seed, k); break;
    }
}

void fuzz_hostile_values(hfx_effect *fx, uint32_t seed) {
    size_t n = hfx_effect_param_count(fx);
    for (size_t i = 0; i < n; i++) visit(hfx_effect_param_at(fx, i), seed, (uint32_t)i, 0);
    (void)hfx_effect_param_at(fx, n);
    hfx_scene s;
    hostile_matrix(s.world, seed, 1);
    hostile_matrix(s.view, seed, 2);
    hostile_matrix(s.projection, seed, 3);
    s.time = pick_float(seed, 4);
    s.elapsed_time = pick_float(seed, 5);
    s.viewport_width = pick_float(seed, 6);
    s.viewport_height = pick_float(seed, 7);
    (void)hfx_effect_bind_scene(fx, &s);
}
