/* scene.c: hfx_effect_bind_scene, FX Composer's and DirectX SAS's standard semantics filled from
 * the application's world, view and projection, as D3DX samples and FX Composer bind them. The
 * matrices follow docs/conventions.md: row-major with row vectors, so WorldView = World * View
 * and the camera sits in the last row of ViewInverse. Which parameters to fill is decided once
 * per effect (a reload starts over); each derived matrix is computed at most once per call, and
 * a parameter is only set when its value differs, so an unchanged scene marks nothing changed
 * and the next Apply uploads nothing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "internal.h"

enum { B_WORLD, B_VIEW, B_PROJ, B_WORLDVIEW, B_VIEWPROJ, B_WVP, B_COUNT };
enum { F_PLAIN, F_INVERSE, F_TRANSPOSE, F_INVERSE_TRANSPOSE, F_COUNT };
enum { /* semantic ids past the matrices (B_COUNT * F_COUNT of them) */
    S_CAMERA = B_COUNT * F_COUNT, S_TIME, S_ELAPSED, S_VIEWPORT, S_NONE
};

static const struct { const char *name; int base; } bases[] = {
    {"WorldViewProjection", B_WVP}, {"WorldViewProj", B_WVP}, {"WorldView", B_WORLDVIEW},
    {"ViewProjection", B_VIEWPROJ}, {"ViewProj", B_VIEWPROJ}, {"World", B_WORLD}, {"View", B_VIEW},
    {"Projection", B_PROJ},
};
static const char *const forms[F_COUNT] = {"", "Inverse", "Transpose", "InverseTranspose"};

static const struct { const char *name; int id; } others[] = {
    {"CameraPosition", S_CAMERA}, {"ViewPosition", S_CAMERA}, {"EyePosition", S_CAMERA},
    {"Time", S_TIME}, {"ElapsedTime", S_ELAPSED}, {"ViewportPixelSize", S_VIEWPORT},
    {"ViewportSize", S_VIEWPORT},
};

/* The semantic's id (case-insensitive, as D3DX matches semantics), or S_NONE. */
static int semantic_id(const char *s) {
    for (size_t b = 0; b < sizeof bases / sizeof *bases; b++) {
        size_t n = strlen(bases[b].name);
        if (strncasecmp(s, bases[b].name, n) != 0) continue;
        for (int f = 0; f < F_COUNT; f++)
            if (strcasecmp(s + n, forms[f]) == 0) return bases[b].base * F_COUNT + f;
    }
    for (size_t i = 0; i < sizeof others / sizeof *others; i++)
        if (strcasecmp(s, others[i].name) == 0) return others[i].id;
    return S_NONE;
}

/* Whether parameter p can take what semantic id gives: a float matrix of up to 4x4 for the
 * matrices (a smaller one takes the upper-left block), a float scalar or vector otherwise. */
static int shape_fits(const hfx_param *p, int id) {
    if (hfx_param_get_type(p) != HFX_TYPE_FLOAT || hfx_param_elements(p)) return 0;
    hfx_param_class k = hfx_param_get_class(p);
    if (id < S_CAMERA) return k == HFX_CLASS_MATRIX && hfx_param_rows(p) <= 4 && hfx_param_columns(p) <= 4;
    return k == HFX_CLASS_SCALAR || k == HFX_CLASS_VECTOR;
}

/* FX Composer's `Object = "SpotLight0"` and DXSAS's `SasBindAddress` say whose matrix or
 * position a parameter is: `float4x4 ShadowXf : View < string Object = "SpotLight0"; >` is the
 * light's view, not the camera's, and is the application's to set. Only an Object naming a
 * camera (or none) leaves the parameter to the scene. */
static int names_another_object(hfx_param *p) {
    if (hfx_param_annotation(p, "SasBindAddress")) return 1;
    hfx_annotation *a = hfx_param_annotation(p, "Object");
    const char *object = a ? hfx_annotation_string(a) : NULL;
    return object && *object && strncasecmp(object, "Camera", 6) != 0;
}

/* The effect's top-level parameters with a standard semantic, as (index << 8 | id). */
static int make_plan(hfx_effect *fx) {
    size_t n = hfx_effect_param_count(fx);
    fx->sas_plan = calloc(n ? n : 1, sizeof *fx->sas_plan);
    if (!fx->sas_plan) return HFX_ERR_MEMORY;
    for (size_t i = 0; i < n; i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        int id = semantic_id(hfx_param_semantic(p));
        if (id != S_NONE && shape_fits(p, id) && !names_another_object(p)) fx->sas_plan[fx->sas_count++] = (uint32_t)i << 8 | (uint32_t)id;
    }
    fx->sas_ready = 1;
    return HFX_OK;
}

/* out = a * b (row vectors: a first, then b). out may not alias a or b. */
static void mul(float out[16], const float a[16], const float b[16]) {
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            out[r * 4 + c] = a[r * 4] * b[c] + a[r * 4 + 1] * b[4 + c] + a[r * 4 + 2] * b[8 + c] + a[r * 4 + 3] * b[12 + c];
}

static void transpose(float out[16], const float m[16]) {
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) out[c * 4 + r] = m[r * 4 + c];
}

/* Swaps rows r and s of both halves of the Gauss-Jordan pair. */
static void swap_rows(double a[4][8], int r, int s) {
    for (int c = 0; c < 8; c++) {
        double t = a[r][c];
        a[r][c] = a[s][c];
        a[s][c] = t;
    }
}

/* Gauss-Jordan with partial pivoting, in double. A singular matrix gives zeros (D3DXMatrixInverse
 * fails and leaves its output alone; zeros make the mistake visible rather than stale). */
static void invert(float out[16], const float m[16]) {
    double a[4][8];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 8; c++) a[r][c] = c < 4 ? m[r * 4 + c] : (c - 4 == r);
    for (int c = 0; c < 4; c++) {
        int pivot = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[pivot][c])) pivot = r;
        if (a[pivot][c] == 0.0) return (void)memset(out, 0, 16 * sizeof *out);
        swap_rows(a, c, pivot);
        double inv = 1.0 / a[c][c];
        for (int k = 0; k < 8; k++) a[c][k] *= inv;
        for (int r = 0; r < 4; r++) {
            double f = a[r][c];
            if (r != c && f != 0.0)
                for (int k = 0; k < 8; k++) a[r][k] -= f * a[c][k];
        }
    }
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) out[r * 4 + c] = (float)a[r][c + 4];
}

/* Matrices computed in one call, each at most once. */
typedef struct sas_cache {
    const hfx_scene *s;
    float m[B_COUNT * F_COUNT][16];
    uint32_t have; /* bit per id */
} sas_cache;

static const float *matrix(sas_cache *c, int id);

/* World, View, Projection as given; the products in the row-vector order. */
static void plain_matrix(sas_cache *c, int base, float out[16]) {
    const hfx_scene *s = c->s;
    switch (base) {
    case B_WORLD: memcpy(out, s->world, sizeof s->world); break;
    case B_VIEW: memcpy(out, s->view, sizeof s->view); break;
    case B_PROJ: memcpy(out, s->projection, sizeof s->projection); break;
    case B_WORLDVIEW: mul(out, s->world, s->view); break;
    case B_VIEWPROJ: mul(out, s->view, s->projection); break;
    default: mul(out, matrix(c, B_WORLDVIEW * F_COUNT), s->projection); break;
    }
}

static const float *matrix(sas_cache *c, int id) {
    if (c->have & (1u << id)) return c->m[id];
    int base = id / F_COUNT, form = id % F_COUNT;
    float *out = c->m[id];
    if (form == F_PLAIN) plain_matrix(c, base, out);
    else if (form == F_INVERSE) invert(out, matrix(c, base * F_COUNT));
    else if (form == F_TRANSPOSE) transpose(out, matrix(c, base * F_COUNT));
    else transpose(out, matrix(c, base * F_COUNT + F_INVERSE));
    c->have |= 1u << id;
    return out;
}

/* The value of semantic id for p: n floats in v (a matrix's upper-left rows x columns block). */
static size_t value_of(sas_cache *c, int id, const hfx_param *p, float v[16]) {
    size_t rows = hfx_param_rows(p), cols = hfx_param_columns(p), n = rows * cols;
    if (id < S_CAMERA) {
        const float *m = matrix(c, id);
        for (size_t r = 0; r < rows; r++)
            for (size_t k = 0; k < cols; k++) v[r * cols + k] = m[r * 4 + k];
        return n;
    }
    const float *vi = matrix(c, B_VIEW * F_COUNT + F_INVERSE);
    float all[4] = {0, 0, 0, 0};
    if (id == S_CAMERA) all[0] = vi[12], all[1] = vi[13], all[2] = vi[14], all[3] = 1; /* ViewInverse's last row */
    else if (id == S_TIME) all[0] = c->s->time;
    else if (id == S_ELAPSED) all[0] = c->s->elapsed_time;
    else all[0] = c->s->viewport_width, all[1] = c->s->viewport_height;
    memcpy(v, all, (n < 4 ? n : 4) * sizeof *v);
    return n < 4 ? n : 4;
}

/* Sets p when its value differs, so an unchanged scene leaves nothing for Apply to send. */
static int set_if_changed(hfx_param *p, const float *v, size_t n) {
    float now[16];
    if (hfx_param_get_floats(p, now, n) == HFX_OK && memcmp(now, v, n * sizeof *v) == 0) return HFX_OK;
    return hfx_param_set_floats(p, v, n);
}

int hfx_scene_semantic_known(const char *semantic) {
    return semantic && semantic_id(semantic) != S_NONE;
}

int hfx_effect_bind_scene(hfx_effect *fx, const hfx_scene *scene) {
    if (!fx || !scene) return HFX_ERR_NULL;
    if (!fx->sas_ready && make_plan(fx) != HFX_OK) return hfx_rt_fail(fx->dev, HFX_ERR_MEMORY, "out of memory");
    sas_cache c;
    c.s = scene;
    c.have = 0;
    for (uint32_t i = 0; i < fx->sas_count; i++) {
        hfx_param *p = hfx_effect_param_at(fx, fx->sas_plan[i] >> 8);
        float v[16];
        size_t n = value_of(&c, (int)(fx->sas_plan[i] & 0xff), p, v);
        int rc = set_if_changed(p, v, n);
        if (rc != HFX_OK) return rc;
    }
    return (int)fx->sas_count;
}
