/* test_self_check.c: every shader the compiler emits goes through glslang before the compile
 * succeeds. A code generator with a bug (HFXC_TEST_BREAK_GLSL appends a stray token to each
 * shader) must give internal errors at the HLSL entry points, one per target and stage, and
 * no effect; with HFXC_NO_SELF_CHECK the same broken text gets through, which is what the
 * check is there to prevent. */
#include <stdlib.h>
#include <string.h>

#include "hfx/hfxc.h"
#include "test.h"

static const char src[] =
    "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 ps() : COLOR { return 1; }\n"
    "technique T { pass P {\n"
    "    VertexShader = compile vs_3_0 vs();\n"
    "    PixelShader = compile ps_3_0 ps(); } }\n";

static hfxc_result *compile(unsigned flags) {
    hfxc_options o;
    memset(&o, 0, sizeof o);
    o.flags = flags;
    return hfxc_compile_memory(src, sizeof src - 1, "t.fx", &o);
}

static void broken_codegen_is_an_internal_error(void) {
    hfxc_result *r = compile(HFXC_TEST_BREAK_GLSL);
    CHECK_INT(hfxc_result_ok(r), 0);
    CHECK(hfxc_result_effect(r) == NULL);
    CHECK_INT(hfxc_diag_count(r), 4); /* vertex and pixel, GLSL 330 and GLSL ES 300 (the default targets) */
    const hfxc_diag *d = hfxc_diag_at(r, 0);
    CHECK_INT(d->severity, HFXC_ERROR);
    CHECK_INT(d->code, 9000);
    CHECK_INT(d->line, 4); /* at the entry point: `vs` of `compile vs_3_0 vs()` */
    CHECK_INT(d->col, 35);
    const char *want = "internal: the GLSL 330 vertex shader hfx made for 'T.P' does not compile: ERROR: ";
    CHECK(strncmp(d->message, want, strlen(want)) == 0);
    CHECK(strstr(d->message, "syntax error") != NULL); /* glslang's words for the stray token */
    CHECK(strstr(hfxc_diag_at(r, 1)->message, "the GLSL ES 300 vertex shader") != NULL);
    const hfxc_diag *ps = hfxc_diag_at(r, 2);
    CHECK_INT(ps->line, 5); /* `ps` of `compile ps_3_0 ps()` */
    CHECK_INT(ps->col, 34);
    CHECK(strstr(ps->message, "the GLSL 330 pixel shader") != NULL);
    char *text = hfxc_diagnostics_text(r);
    CHECK(strncmp(text, "t.fx(4,35): error X9000: internal: ", 35) == 0);
    free(text);
    hfxc_result_free(r);
}

static void without_the_check_the_bug_gets_through(void) {
    hfxc_result *r = compile(HFXC_TEST_BREAK_GLSL | HFXC_NO_SELF_CHECK);
    CHECK_INT(hfxc_result_ok(r), 1);
    hfxc_result_free(r);
    r = compile(0); /* and the real code generator passes the check */
    CHECK_INT(hfxc_result_ok(r), 1);
    CHECK_INT(hfxc_diag_count(r), 0);
    hfxc_result_free(r);
}

int main(void) {
    RUN(broken_codegen_is_an_internal_error);
    RUN(without_the_check_the_bug_gets_through);
    return test_summary();
}
