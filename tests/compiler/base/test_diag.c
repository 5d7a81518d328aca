/* Diagnostics: fxc's format, severity counting, werror, the caret line. */
#include <stdlib.h>

#include "base/diag.h"
#include "test.h"

static void formats_like_fxc(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    uint32_t f = hfx_diags_add_file(&d, "multilights.fx", NULL, "a\n    float4 color = Phong(\n", 27);
    hfx_error(&d, (hfx_loc){f, 2, 20}, 3013, "'%s': no matching %d parameter function", "Phong", 4);
    hfx_warning(&d, (hfx_loc){f, 1, 1}, 3206, "implicit truncation of vector type");
    CHECK_INT(d.errors, 1);
    CHECK_INT(d.warnings, 1);
    char *text = hfx_diags_format(&d, 0);
    CHECK_STR(text, "multilights.fx(2,20): error X3013: 'Phong': no matching 4 parameter function\n"
                    "multilights.fx(1,1): warning X3206: implicit truncation of vector type\n");
    free(text);
    text = hfx_diags_format(&d, 1);
    CHECK_CONTAINS(text, "\n      float4 color = Phong(\n                     ^\n");
    free(text);
    hfx_arena_free(&a);
}

static void werror_promotes_and_nowarn_drops(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, HFXC_WERROR);
    uint32_t f = hfx_diags_add_file(&d, "x.fx", NULL, "", 0);
    hfx_warning(&d, (hfx_loc){f, 1, 1}, 3206, "w");
    CHECK_INT(d.errors, 1);
    CHECK_INT(d.items[0].severity, HFXC_ERROR);
    hfx_diags_init(&d, &a, HFXC_NO_WARNINGS);
    f = hfx_diags_add_file(&d, "x.fx", NULL, "", 0);
    hfx_warning(&d, (hfx_loc){f, 1, 1}, 3206, "w");
    CHECK_INT(d.count, 0);
    hfx_arena_free(&a);
}

int main(void) {
    RUN(formats_like_fxc);
    RUN(werror_promotes_and_nowarn_drops);
    return test_summary();
}
