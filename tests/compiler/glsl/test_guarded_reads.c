/* test_guarded_reads.c: the guard on a uniform array read at a dynamic index (zero past either
 * end, as D3D9). Only the upper end when the index is a for counter that starts at a
 * non-negative constant and only goes up; no guard when such a counter's constant bound keeps
 * it inside the array (lower/ranges.c); else one unsigned compare where GLSL has uint, two in
 * GLSL 110. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "test.h"

#define VS "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n"

/* The pixel shader of `float arr[4]; int n; float4 ps() : COLOR { float s = 0; LOOP return s; }`
 * for one target (malloc'ed; NULL, reported, when it fails to compile or link). */
static char *pixel_glsl(const char *loop, hfx_target target) {
    char src[1024];
    snprintf(src, sizeof src, "%sfloat arr[4]; int n;\nfloat4 ps() : COLOR { float s = 0; %s return s; }\n%s", VS, loop,
             TECH);
    hfxc_options o = {0};
    o.targets = 1u << target;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "guards.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    char *fs = NULL, *log = NULL;
    if (fx && fx->program_count == 1 && test_glsl_link(fx->programs[0].code[0][target].data,
                                                       fx->programs[0].code[1][target].data, &log))
        fs = strdup(fx->programs[0].code[1][target].data);
    else
        fprintf(stderr, "failed (target %d):\n%s\n%s\n", (int)target, src, log ? log : "");
    free(log);
    hfxc_result_free(r);
    return fs;
}

static void check_guard(const char *loop, hfx_target target, const char *helper, const char *read) {
    char *fs = pixel_glsl(loop, target);
    CHECK(fs != NULL);
    if (helper) CHECK_CONTAINS(fs, helper);
    else CHECK(fs && !strstr(fs, "hfx_read"));
    CHECK_CONTAINS(fs, read);
    free(fs);
}

static const char UNSIGNED_HELPER[] = "float hfx_read_arr(int i)\n{\n    if (uint(i) >= 4u) return 0.0;\n    return arr[i];\n}\n";
static const char BOTH_ENDS_110[] = "float hfx_read_arr(int i)\n{\n    if (i < 0 || i >= 4) return 0.0;\n    return arr[i];\n}\n";
static const char UPPER_END[] =
    "float hfx_readbelow_arr(int i)\n{\n    if (i >= 4) return 0.0;\n    return arr[i];\n}\n";

/* An index nothing is known of, where GLSL has uint: one unsigned compare for both ends. */
static void one_unsigned_compare(void) {
    check_guard("s += arr[n];", HFX_TARGET_GLSL330, UNSIGNED_HELPER, "s += hfx_read_arr(n);");
    check_guard("s += arr[n];", HFX_TARGET_GLSLES300, UNSIGNED_HELPER, "s += hfx_read_arr(n);");
}

/* A counter from 0 (or 1) up, below a bound it cannot step past: only the upper end. */
static void counter_drops_the_lower_half(void) {
    check_guard("for (int i = 0; i < n; i++) s += arr[i];", HFX_TARGET_GLSL330, UPPER_END, "s += hfx_readbelow_arr(i);");
    check_guard("s += arr[n];", HFX_TARGET_GLSL110, BOTH_ENDS_110, "s += hfx_read_arr(n);");
    check_guard("for (int i = 0; i < n; i++) s += arr[i];", HFX_TARGET_GLSL110, UPPER_END,
                "s += hfx_readbelow_arr(i);");
    check_guard("for (int i = 1; i < 6; ++i) s += arr[i];", HFX_TARGET_GLSL110, UPPER_END,
                "s += hfx_readbelow_arr(i);");
}

/* A constant bound inside the array: the read is plain. i runs 0..3, 0..3 and 1, 3. */
static void constant_bound_drops_the_guard(void) {
    check_guard("for (int i = 0; i < 4; i++) s += arr[i];", HFX_TARGET_GLSL330, NULL, "s += arr[i];");
    check_guard("for (int i = 0; i <= 3; i++) s += arr[i];", HFX_TARGET_GLSL110, NULL, "s += arr[i];");
    check_guard("for (int i = 1; 4 > i && n > 0; i += 2) s += arr[i];", HFX_TARGET_GLSL330, NULL, "s += arr[i];");
}

/* What can still leave the array keeps the whole guard: a bound past its end, a negative start,
 * a counter the body writes, an index computed from the counter, `<=` a bound that is not
 * constant (i could step past INT_MAX), and the counter after the loop. */
static void out_of_range_keeps_the_guard(void) {
    check_guard("for (int i = 0; i < 5; i++) s += arr[i];", HFX_TARGET_GLSLES300, UPPER_END, "hfx_readbelow_arr(i)");
    check_guard("for (int i = 0; i < 5; i++) s += arr[i];", HFX_TARGET_GLSL110, UPPER_END, "hfx_readbelow_arr(i)");
    check_guard("for (int i = -1; i < 4; i++) s += arr[i];", HFX_TARGET_GLSL330, UNSIGNED_HELPER, "hfx_read_arr(i)");
    check_guard("for (int i = -1; i < 4; i++) s += arr[i];", HFX_TARGET_GLSL110, BOTH_ENDS_110, "hfx_read_arr(i)");
    check_guard("for (int i = 0; i < 4; i++) { s += arr[i]; i -= n; }", HFX_TARGET_GLSL110, BOTH_ENDS_110,
                "hfx_read_arr(i)");
    check_guard("for (int i = 0; i < 3; i++) s += arr[i + 1];", HFX_TARGET_GLSL110, BOTH_ENDS_110,
                "hfx_read_arr(i + 1)");
    check_guard("for (int i = 0; i <= n; i++) s += arr[i];", HFX_TARGET_GLSL110, BOTH_ENDS_110, "hfx_read_arr(i)");
    check_guard("int i; for (i = 0; i < 4; i++) s += arr[i]; s += arr[i];", HFX_TARGET_GLSL330, UNSIGNED_HELPER,
                "s += hfx_read_arr(i);");
}

int main(void) {
    RUN(one_unsigned_compare);
    RUN(counter_drops_the_lower_half);
    RUN(constant_bound_drops_the_guard);
    RUN(out_of_range_keeps_the_guard);
    return test_summary();
}
