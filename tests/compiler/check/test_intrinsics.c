/* test_intrinsics.c: the one intrinsic table (check/intrinsics.def) holds together: names are
 * unique and found by name, argument counts fit the rules, each column means one thing (texture
 * columns only on texture rows, the IR rewrite only where its rule fits, a GLSL function exactly
 * where the GLSL emitter calls one), every evaluator function is reached from its one row and
 * folds there, and the few rows with a hand-checked meaning say what HLSL says. */
#include <stdio.h>
#include <string.h>

#include "check/intrinsics.h"
#include "test.h"

typedef struct row {
    const char *id, *name, *glsl, *how;
    int min, max, sig, dim, form, lower, ev;
} row;

static const row rows[] = {
#define HFX_INTRINSIC(id, name, mn, mx, sig, dim, texf, lower, ev, glsl_emit, glsl_fn) \
    {#id, name, glsl_fn, #glsl_emit, mn, mx, sig, dim, texf, lower, ev},
#include "check/intrinsics.def"
#undef HFX_INTRINSIC
};
#define ROW_COUNT (sizeof rows / sizeof rows[0])

static void names_are_unique_and_found(void) {
    CHECK_INT(ROW_COUNT, HFX_INTR_COUNT);
    for (size_t i = 0; i < ROW_COUNT; i++) {
        CHECK_INT(hfx_intrinsic_find(rows[i].name), (int)i);
        CHECK_STR(hfx_intrinsic_name((int)i), rows[i].name);
    }
    CHECK_INT(hfx_intrinsic_find("tex2dlod"), -1); /* HLSL names are case-sensitive */
    CHECK(hfx_intrinsic_name(HFX_INTR_COUNT) == NULL);
}

static void counts_and_texture_columns(void) {
    for (size_t i = 0; i < ROW_COUNT; i++) {
        const row *r = &rows[i];
        CHECK(r->min >= 1 && r->min <= r->max && r->max <= 4);
        int tex = r->sig == SIG_TEX;
        CHECK_INT(tex, strcmp(r->how, "tex") == 0);
        if (tex) CHECK(r->dim == DIM_1D || r->dim == DIM_2D || r->dim == DIM_3D || r->dim == DIM_CUBE);
        if (!tex) CHECK_INT(r->dim, DIM_GENERIC);
        if (!tex) CHECK_INT(r->form, 0);
        /* a row that folds names an evaluator function of the same name and argument count */
        if (r->ev != HFX_EV_FN_NONE) {
            CHECK_STR(hfx_ev_fn_name((hfx_ev_fn)r->ev), r->id);
            CHECK_INT(hfx_ev_fn_args((hfx_ev_fn)r->ev), r->max);
        }
    }
}

/* The GLSL function column is set exactly on the rows whose emitter prints a call of it on the
 * arguments as they are; round (floor(x + 0.5)) and ldexp (x * exp2(e)) name none. */
static void glsl_function_column(void) {
    static const char *const calls[] = {"call", "legacy", "numeric", "matrix", "all_any", "trunc", "modf"};
    for (size_t i = 0; i < ROW_COUNT; i++) {
        int named = 0;
        for (size_t k = 0; k < sizeof calls / sizeof calls[0]; k++) named |= strcmp(rows[i].how, calls[k]) == 0;
        if (named != (rows[i].glsl != NULL)) printf("  %s: emitter %s, GLSL function %s\n", rows[i].id, rows[i].how, rows[i].glsl ? rows[i].glsl : "none");
        CHECK_INT(named, rows[i].glsl != NULL);
    }
    CHECK(hfx_intrinsic_info_of(HFX_INTR_ROUND) && rows[HFX_INTR_ROUND].glsl == NULL);
    CHECK(rows[HFX_INTR_LDEXP].glsl == NULL);
    CHECK_STR(rows[HFX_INTR_FRAC].glsl, "fract");
    CHECK_STR(rows[HFX_INTR_LERP].glsl, "mix");
}

/* LOWER_ROWS splits a call into one per matrix row with the same arguments' rows: only the
 * componentwise rules (every argument of the result's type) allow it; LOWER_MUL is mul's. */
static void ir_rewrite_column(void) {
    for (size_t i = 0; i < ROW_COUNT; i++) {
        const row *r = &rows[i];
        CHECK(r->lower == LOWER_NONE || r->lower == LOWER_ROWS || r->lower == LOWER_MUL);
        if (r->lower == LOWER_ROWS) CHECK(r->sig == SIG_SAME || r->sig == SIG_SAME_FLOAT);
        CHECK_INT(r->lower == LOWER_MUL, r->sig == SIG_MUL);
    }
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_SATURATE)->lower, LOWER_ROWS);
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_DOT)->lower, LOWER_NONE);
}

/* Every function the evaluator has is reached from exactly one row. */
static void every_evaluator_function_has_its_row(void) {
    int seen[HFX_EV_FN_COUNT] = {0};
    for (size_t i = 0; i < ROW_COUNT; i++)
        if (rows[i].ev != HFX_EV_FN_NONE) seen[rows[i].ev]++;
    for (int f = 0; f < HFX_EV_FN_COUNT; f++) CHECK_INT(seen[f], 1);
}

/* Every row that names an evaluator function folds there: its argument count of float3
 * constants (cross's float3, dot's and length's vectors) gives a value. */
static void every_folding_row_folds(void) {
    int folded = 0;
    for (size_t i = 0; i < ROW_COUNT; i++) {
        if (rows[i].ev == HFX_EV_FN_NONE) continue;
        hfx_ev_value args[3], out;
        for (int k = 0; k < 3; k++) args[k] = (hfx_ev_value){HFX_EV_FLOAT, 3, {0.25 + k * 0.125, 0.5, 0.75}};
        int ok = hfx_ev_call((hfx_ev_fn)rows[i].ev, args, (unsigned)rows[i].max, &out);
        if (!ok) printf("  %s does not fold\n", rows[i].id);
        CHECK(ok);
        folded += ok;
    }
    CHECK_INT(folded, HFX_EV_FN_COUNT); /* and there are as many as the evaluator has functions */
    /* a row the evaluator leaves to the GPU: ddx depends on the neighbouring pixels */
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_DDX)->fold, HFX_EV_FN_NONE);
}

/* tex2Dlod: 2D, the level in .w of a float4 (HLSL reference: tex2Dlod(s, t), t.w = mip level). */
static void tex2dlod_row(void) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(HFX_INTR_TEX2DLOD);
    CHECK_STR(info->name, "tex2Dlod");
    CHECK_INT(info->dim, DIM_2D);
    CHECK_INT(info->tex_form, TEXF_LOD);
    CHECK_INT(info->min_args, 2);
    CHECK_INT(info->max_args, 2);
    /* texCUBEproj divides by .w; tex1D takes up to 4 arguments (the gradient form) */
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_TEXCUBEPROJ)->tex_form, TEXF_PROJ);
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_TEX1D)->max_args, 4);
}

int main(void) {
    RUN(names_are_unique_and_found);
    RUN(counts_and_texture_columns);
    RUN(glsl_function_column);
    RUN(ir_rewrite_column);
    RUN(every_evaluator_function_has_its_row);
    RUN(every_folding_row_folds);
    RUN(tex2dlod_row);
    return test_summary();
}
