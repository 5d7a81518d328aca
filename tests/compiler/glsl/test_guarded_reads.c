/* test_guarded_reads.c: the guard on a uniform array read at a dynamic index (zero past either
 * end, as D3D9). Only the upper end when the index is a for counter that starts at a
 * non-negative constant and only goes up; no guard when such a counter's constant bound keeps
 * it inside the array (lower/ranges.c). Where GLSL has uint (330, ES 300) the array is declared
 * one element longer, never uploaded and so zero, and the read clamps into it: arr[min(uint(i),
 * 4u)] sends both ends there (a negative int is a large uint), arr[min(i, 4)] the upper end; GLSL
 * 110 keeps a helper with one compare per end. */
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

static const char BOTH_ENDS_110[] = "float hfx_read_arr(int i)\n{\n    if (i < 0 || i >= 4) return 0.0;\n    return arr[i];\n}\n";
static const char UPPER_END[] =
    "float hfx_readbelow_arr(int i)\n{\n    if (i >= 4) return 0.0;\n    return arr[i];\n}\n";

/* GLSL 330 / ES 300: the padded declaration, no helper, and the clamped read. */
static void check_padded(const char *loop, hfx_target target, const char *read) {
    char *fs = pixel_glsl(loop, target);
    CHECK(fs != NULL);
    CHECK_CONTAINS(fs, "\nuniform float arr[5];\n");
    CHECK(fs && !strstr(fs, "hfx_read"));
    CHECK_CONTAINS(fs, read);
    free(fs);
}

/* An index nothing is known of, where GLSL has uint: one unsigned clamp for both ends. */
static void one_unsigned_clamp(void) {
    check_padded("s += arr[n];", HFX_TARGET_GLSL330, "s += arr[min(uint(n), 4u)];");
    check_padded("s += arr[n];", HFX_TARGET_GLSLES300, "s += arr[min(uint(n), 4u)];");
}

/* A counter from 0 (or 1) up, below a bound it cannot step past: only the upper end. */
static void counter_drops_the_lower_half(void) {
    check_padded("for (int i = 0; i < n; i++) s += arr[i];", HFX_TARGET_GLSL330, "s += arr[min(i, 4)];");
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
    check_padded("for (int i = 0; i < 5; i++) s += arr[i];", HFX_TARGET_GLSLES300, "arr[min(i, 4)]");
    check_guard("for (int i = 0; i < 5; i++) s += arr[i];", HFX_TARGET_GLSL110, UPPER_END, "hfx_readbelow_arr(i)");
    check_padded("for (int i = -1; i < 4; i++) s += arr[i];", HFX_TARGET_GLSL330, "arr[min(uint(i), 4u)]");
    check_guard("for (int i = -1; i < 4; i++) s += arr[i];", HFX_TARGET_GLSL110, BOTH_ENDS_110, "hfx_read_arr(i)");
    check_guard("for (int i = 0; i < 4; i++) { s += arr[i]; i -= n; }", HFX_TARGET_GLSL110, BOTH_ENDS_110,
                "hfx_read_arr(i)");
    check_guard("for (int i = 0; i < 3; i++) s += arr[i + 1];", HFX_TARGET_GLSL110, BOTH_ENDS_110,
                "hfx_read_arr(i + 1)");
    check_guard("for (int i = 0; i <= n; i++) s += arr[i];", HFX_TARGET_GLSL110, BOTH_ENDS_110, "hfx_read_arr(i)");
    check_padded("int i; for (i = 0; i < 4; i++) s += arr[i]; s += arr[i];", HFX_TARGET_GLSL330,
                 "s += arr[min(uint(i), 4u)];");
}

int main(void) {
    RUN(one_unsigned_clamp);
    RUN(counter_drops_the_lower_half);
    RUN(constant_bound_drops_the_guard);
    RUN(out_of_range_keeps_the_guard);
    return test_summary();
}
