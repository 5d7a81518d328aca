/* The seed corpus through the checker: the 13 good files check without error and satisfy
 * ast.h's invariants; multilights.fx fails with exactly its one X3013 (through the real
 * pipeline, hfxc_compile_file). */
#include <stdlib.h>
#include <string.h>

#include "check_util.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "test.h"

static const char *const good[] = {
    "tutorial0.fx", "phong.fx", "pointlights.fx", "ambient.fx", "ambient_textured.fx", "directional.fx",
    "point.fx", "spot.fx", "directional_specular.fx", "point_specular.fx", "spot_specular.fx",
    "multilights_repaired.fx", "fxcomposer_empty.fx"};

static ckt_result *run_seed(const char *name) {
    char *path = test_seed_path(name);
    char *src = test_read_file(path, NULL);
    free(path);
    if (!src) return NULL;
    ckt_result *r = ckt_run(src);
    free(src);
    return r;
}

static void good_seeds_check(void) {
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
        ckt_result *r = run_seed(good[i]);
        CHECK(r != NULL);
        if (!r) continue;
        if (!r->ok || r->diags.errors) {
            char *t = ckt_text(r);
            fprintf(stderr, "%s:\n%s", good[i], t);
            free(t);
        }
        CHECK(r->ok);
        CHECK_INT(r->diags.errors, 0);
        char why[256];
        int bad = ckt_invariants(r, why, sizeof why);
        if (bad) fprintf(stderr, "%s: %d invariant violations, first: %s\n", good[i], bad, why);
        CHECK_INT(bad, 0);
        ckt_free(r);
    }
}

static void phong_truncations(void) {
    /* line 46: output.N = mul(float4(input.Normal, 0), World); line 48: camPosition - worldPosition */
    ckt_result *r = run_seed("phong.fx");
    char *t = ckt_text(r);
    CHECK_STR(t, "t.fx(46,16): warning X3206: implicit truncation of vector type\n"
                 "t.fx(48,16): warning X3206: implicit truncation of vector type\n");
    free(t);
    ckt_free(r);
}

static void assigned_globals(void) {
    /* ambient_textured.fx: `colorMaterialAmbiental *= texturaColor;` in the pixel shader */
    ckt_result *r = run_seed("ambient_textured.fx");
    CHECK(ckt_find(r, "colorMaterialAmbiental")->assigned);
    CHECK(!ckt_find(r, "world")->assigned);
    ckt_free(r);
    /* directional.fx: `direccionLuz = normalize(direccionLuz);` */
    r = run_seed("directional.fx");
    CHECK(ckt_find(r, "direccionLuz")->assigned);
    ckt_free(r);
}

static void multilights_fails_once(void) {
    char *path = test_seed_path("multilights.fx");
    hfxc_result *res = hfxc_compile_file(path, NULL);
    free(path);
    unsigned errors = 0;
    const hfxc_diag *err = NULL;
    for (size_t i = 0; i < hfxc_diag_count(res); i++) {
        const hfxc_diag *g = hfxc_diag_at(res, i);
        if (g->severity == HFXC_ERROR) errors++, err = g;
    }
    CHECK_INT(errors, 1);
    CHECK(!hfxc_result_ok(res));
    if (err) {
        size_t n = strlen(err->file);
        CHECK(n >= 14 && strcmp(err->file + n - 14, "multilights.fx") == 0);
        CHECK_INT(err->line, 204);
        CHECK_INT(err->col, 20);
        CHECK_INT(err->code, 3013);
        CHECK_STR(err->message, "'Phong': no matching 4 parameter function");
    }
    char *text = hfxc_diagnostics_text(res);
    CHECK_CONTAINS(text, "multilights.fx(204,20): error X3013: 'Phong': no matching 4 parameter function\n");
    free(text);
    hfxc_result_free(res);
}

/* The checker's errors come out of the library's entry point as they are. */
static void pipeline_reports_checker_errors(void) {
    const char *src = "float4 f(float3 n) : COLOR\n{\n    return float4(normalize(m), 1) + g(n);\n}\n";
    hfxc_result *res = hfxc_compile_memory(src, strlen(src), "snippet.fx", NULL);
    CHECK(!hfxc_result_ok(res));
    CHECK(hfxc_result_effect(res) == NULL);
    char *text = hfxc_diagnostics_text(res);
    CHECK_STR(text, "snippet.fx(3,29): error X3004: undeclared identifier 'm'\n"
                    "snippet.fx(3,38): error X3004: undeclared identifier 'g'\n");
    free(text);
    hfxc_result_free(res);
}

int main(void) {
    test_require_seeds();
    RUN(good_seeds_check);
    RUN(phong_truncations);
    RUN(assigned_globals);
    RUN(multilights_fails_once);
    RUN(pipeline_reports_checker_errors);
    return test_summary();
}
