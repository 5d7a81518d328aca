/* test_passes.c: the one pass list (compiler/ir/lower/passes.c). docs/architecture.md's table
 * is the same list, row for row; hfxc_pass_name gives it in order; hfxc_options.dump_ir dumps
 * each stage after the pass named (or after every pass, in the table's order, the preshade rows
 * only when they run); and golden dumps of small effects, each line checked by hand. */
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "hfx/hfxc.h"
#include "ir/ir.h"
#include "test.h"

/* The docs' table as passes.c's rows print it. */
static char *table_text(void) {
    sbuf b = {0};
    hfx_sb_put(&b, "| # | pass | runs | why |\n|---|---|---|---|\n");
    for (uint32_t i = 0; i < hfx_ir_pass_count(); i++)
        hfx_sb_printf(&b, "| %u | `%s` | %s | %s |\n", (unsigned)i + 1, hfx_ir_pass_name(i), hfx_ir_pass_runs(i), hfx_ir_pass_why(i));
    return hfx_sb_take(&b);
}

/* docs/architecture.md's lines from the table's head to the end marker. */
static char *docs_table(void) {
    char *doc = test_read_file(HFX_SOURCE_DIR "/docs/architecture.md", NULL);
    char *from = doc ? strstr(doc, "| # | pass | runs | why |\n") : NULL;
    char *to = from ? strstr(from, "<!-- passes: end -->") : NULL;
    char *out = to ? strndup(from, (size_t)(to - from)) : NULL;
    free(doc);
    return out;
}

static void docs_list_the_table(void) {
    char *want = table_text(), *got = docs_table();
    CHECK(got != NULL);
    if (got && strcmp(got, want) != 0) fprintf(stderr, "docs/architecture.md's pass list should read:\n%s", want);
    CHECK_STR(got ? got : "", want);
    free(want);
    free(got);
}

/* The names are unique, the public list is the table, and the rows this test knows of keep
 * their relative order: preshade after its reorderings, after the stage's own passes. */
static void names_in_order(void) {
    size_t n = 0;
    const char *why;
    while (hfxc_pass_name(n, &why)) {
        CHECK_STR(hfxc_pass_name(n, NULL), hfx_ir_pass_name((uint32_t)n));
        CHECK(why && why[0]);
        for (size_t k = 0; k < n; k++) CHECK(strcmp(hfxc_pass_name(k, NULL), hfxc_pass_name(n, NULL)) != 0);
        n++;
    }
    CHECK_INT(n, hfx_ir_pass_count());
    CHECK(n >= 22);
    static const char *const order[] = {"specialise", "fold", "calls", "globals", "uses", "check", "sums",
                                        "forward", "factors", "preshade", "uses-again", "varyings"};
    size_t at = 0;
    for (size_t i = 0; i < n && at < sizeof order / sizeof *order; i++)
        if (!strcmp(hfxc_pass_name(i, NULL), order[at])) at++;
    CHECK_INT(at, sizeof order / sizeof *order);
    CHECK(hfxc_pass_name(n, &why) == NULL && why == NULL);
}

/* The dump of src after `pass`, compiled with flags (GLSL 330 only); NULL when it fails. */
static char *dump_after(const char *src, const char *pass, unsigned flags) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    o.flags = flags | HFXC_NO_WARNINGS;
    o.dump_ir = pass;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", &o);
    char *text = hfxc_result_ok(r) ? hfxc_result_ir_dump(r) : NULL;
    if (!text) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s", d);
        free(d);
    }
    hfxc_result_free(r);
    return text;
}

/* How many times `needle` starts a line of text. */
static unsigned lines_starting(const char *text, const char *needle) {
    unsigned n = 0;
    for (const char *p = text; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : NULL)
        n += strncmp(p, needle, strlen(needle)) == 0;
    return n;
}

static const char two_stages[] =
    "float4x4 World, ViewProj;\n"
    "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, mul(World, ViewProj)); }\n"
    "float4 PS() : COLOR0 { return 1; }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

/* After every pass: each stage once per row that runs, in the table's order; the preshade rows
 * only with packed parameters and preshaders on; uses-again only where preshade made one (the
 * vertex stage); varyings once per stage of the program. */
static void every_pass_in_order(void) {
    char *all = dump_after(two_stages, "all", HFXC_PACK_UNIFORMS);
    CHECK(all != NULL);
    for (uint32_t i = 0; all && i < hfx_ir_pass_count(); i++) {
        char head[64];
        snprintf(head, sizeof head, "// after %s: ", hfx_ir_pass_name(i));
        unsigned want = !strcmp(hfx_ir_pass_name(i), "uses-again") ? 1 : 2;
        if (lines_starting(all, head) != want) fprintf(stderr, "  %s\n", head);
        CHECK_INT(lines_starting(all, head), want);
    }
    const char *check = all ? strstr(all, "// after check: ") : NULL, *sums = all ? strstr(all, "// after sums: ") : NULL;
    CHECK(check && sums && check < sums); /* a stage's rows in order: check, then the preshade rows */
    free(all);
    char *off = dump_after(two_stages, "all", HFXC_PACK_UNIFORMS | HFXC_NO_PRESHADERS);
    CHECK(off != NULL);
    CHECK_INT(lines_starting(off, "// after fold: "), 2);
    CHECK_INT(lines_starting(off, "// after sums: "), 0);
    CHECK_INT(lines_starting(off, "// after preshade: "), 0);
    CHECK_INT(lines_starting(off, "// after uses-again: "), 0);
    free(off);
    char *none = dump_after(two_stages, NULL, HFXC_PACK_UNIFORMS);
    CHECK_STR(none, "");
    free(none);
}

/* After preshade, the vertex stage: mul(World, ViewProj) is the preshader hfx_pre0 (named by
 * its HLSL), the return reads it; World and ViewProj are still listed, since uses has not run
 * again yet (hfx_pre0 is not listed for the same reason). After uses-again: hfx_pre0 is the
 * one global, the parameters are gone. The header names the compile's place, which is where it
 * names its entry: line 4, column 54 for VS, 89 for PS. The pixel stage has no preshader: no
 * dump of it after uses-again. */
static void golden_preshade(void) {
    char *pre = dump_after(two_stages, "preshade", HFXC_PACK_UNIFORMS);
    CHECK_STR(pre,
        "// after preshade: t.fx(4,54)\n"
        "shader vertex VS\n"
        "global uniform float4x4 World\n"
        "global uniform float4x4 ViewProj\n"
        "preshader float4x4 hfx_pre0 = mul(World, ViewProj)\n"
        "function VS : float4\n"
        "  param float4 p\n"
        "  block\n"
        "    return (mul (param p) (private hfx_pre0))\n"
        "// after preshade: t.fx(4,89)\n"
        "shader pixel PS\n"
        "function PS : float4\n"
        "  block\n"
        "    return (const float4 1 1 1 1)\n");
    free(pre);
    char *again = dump_after(two_stages, "uses-again", HFXC_PACK_UNIFORMS);
    CHECK_STR(again,
        "// after uses-again: t.fx(4,54)\n"
        "shader vertex VS\n"
        "global private float4x4 hfx_pre0\n"
        "preshader float4x4 hfx_pre0 = mul(World, ViewProj)\n"
        "function VS : float4\n"
        "  param float4 p\n"
        "  block\n"
        "    return (mul (param p) (private hfx_pre0))\n");
    free(again);
}

/* After specialise, then after fold, then after dce (PS at line 9, column 53). specialise: PS(true)
 * binds `bright`, which leaves the signature, and its read is the argument, a bool constant;
 * the checker's conversions are there (`1 + 1` to float, `two` and `Half` splat to float4, the
 * int 3 to float4). Globals are hfx_ir_build's list (uses has not run): Tint and the static Half,
 * listed by its GLSL name. fold: 1 + 1 is 2; `two` and `Half` are constants where they are read,
 * and their splats fold to float4 constants; (Tint * 2) * 0.5 is not reassociated; the if on a
 * constant and the declarations stay. dce: the if on true is its branch alone; the unread
 * `two` stays (dce removes unreachable code, not unused locals). */
static void golden_fold(void) {
    static const char src[] =
        "float4 Tint;\n"
        "static const float Half = 0.5;\n"
        "float4 PS(uniform bool bright) : COLOR0 {\n"
        "    const float two = 1 + 1;\n"
        "    float4 c = Tint * two * Half;\n"
        "    if (bright) c *= 3;\n"
        "    return c;\n"
        "}\n"
        "technique T { pass P { PixelShader = compile ps_3_0 PS(true); } }\n";
    char *spec = dump_after(src, "specialise", 0), *fold = dump_after(src, "fold", 0), *dce = dump_after(src, "dce", 0);
    const char *head =
        "shader pixel PS\n"
        "global uniform float4 Tint\n"
        "global private float hfx_static_Half\n"
        "function PS : float4\n"
        "  block\n";
    char want[2048];
    snprintf(want, sizeof want, "// after specialise: t.fx(9,53)\n%s%s", head,
        "    decl float two (convert float (+ (const int 1) (const int 1)))\n"
        "    decl float4 c (* (* (uniform Tint) (convert float4 (local two))) (convert float4 (private Half)))\n"
        "    if (const bool 1)\n"
        "      expr (assign * (local c) (convert float4 (const int 3)))\n"
        "    return (local c)\n");
    CHECK_STR(spec, want);
    snprintf(want, sizeof want, "// after fold: t.fx(9,53)\n%s%s", head,
        "    decl float two (const float 2)\n"
        "    decl float4 c (* (* (uniform Tint) (const float4 2 2 2 2)) (const float4 0.5 0.5 0.5 0.5))\n"
        "    if (const bool 1)\n"
        "      expr (assign * (local c) (const float4 3 3 3 3))\n"
        "    return (local c)\n");
    CHECK_STR(fold, want);
    snprintf(want, sizeof want, "// after dce: t.fx(9,53)\n%s%s", head,
        "    decl float two (const float 2)\n"
        "    decl float4 c (* (* (uniform Tint) (const float4 2 2 2 2)) (const float4 0.5 0.5 0.5 0.5))\n"
        "    expr (assign * (local c) (const float4 3 3 3 3))\n"
        "    return (local c)\n");
    CHECK_STR(dce, want);
    free(spec);
    free(fold);
    free(dce);
}

int main(void) {
    RUN(docs_list_the_table);
    RUN(names_in_order);
    RUN(every_pass_in_order);
    RUN(golden_preshade);
    RUN(golden_fold);
    return test_summary();
}
