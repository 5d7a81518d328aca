/* test_intrinsics.c: the one intrinsic table (check/intrinsics.def) holds together: names are
 * unique and found by name, argument counts fit the rules, every texture row names a dimension
 * and a form, every row the GLSL printer lowers as a plain call names its GLSL function, and
 * the few rows with a hand-checked meaning say what HLSL says. */
#include <string.h>

#include "check/intrinsics.h"
#include "test.h"

typedef struct row {
    const char *id, *name, *glsl, *how;
    int min, max, sig, dim, form, ev;
} row;

static const row rows[] = {
#define HFX_INTRINSIC(id, name, mn, mx, sig, dim, form, glsl, how, ev) {#id, name, glsl, #how, mn, mx, sig, dim, form, ev},
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
        if (!tex && r->sig != SIG_REINTERPRET) CHECK_INT(r->form, 0);
        if (strcmp(r->how, "call") == 0 || strcmp(r->how, "legacy") == 0) CHECK(r->glsl != NULL);
        /* a row that folds names an evaluator function of the same name and argument count */
        if (r->ev != HFX_EV_FN_NONE) {
            CHECK_STR(hfx_ev_fn_name((hfx_ev_fn)r->ev), r->id);
            CHECK_INT(hfx_ev_fn_args((hfx_ev_fn)r->ev), r->max);
        }
    }
}

/* tex2Dlod: 2D, the level in .w of a float4 (HLSL reference: tex2Dlod(s, t), t.w = mip level). */
/* Every function the evaluator has is reached from exactly one row. */
static void every_evaluator_function_has_its_row(void) {
    int seen[HFX_EV_FN_COUNT] = {0};
    for (size_t i = 0; i < ROW_COUNT; i++)
        if (rows[i].ev != HFX_EV_FN_NONE) seen[rows[i].ev]++;
    for (int f = 0; f < HFX_EV_FN_COUNT; f++) CHECK_INT(seen[f], 1);
}

static void tex2dlod_row(void) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(HFX_INTR_TEX2DLOD);
    CHECK_STR(info->name, "tex2Dlod");
    CHECK_INT(info->dim, DIM_2D);
    CHECK_INT(info->form, TEXF_LOD);
    CHECK_INT(info->min_args, 2);
    CHECK_INT(info->max_args, 2);
    /* texCUBEproj divides by .w; tex1D takes up to 4 arguments (the gradient form) */
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_TEXCUBEPROJ)->form, TEXF_PROJ);
    CHECK_INT(hfx_intrinsic_info_of(HFX_INTR_TEX1D)->max_args, 4);
}

int main(void) {
    RUN(names_are_unique_and_found);
    RUN(counts_and_texture_columns);
    RUN(every_evaluator_function_has_its_row);
    RUN(tex2dlod_row);
    return test_summary();
}
