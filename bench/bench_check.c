/* bench_check: what type checking costs on top of parsing. Runs the 13 good seed files
 * (repeated) and a generated effect of many functions, globals, overloads and loops through
 * preprocess + parse, and through preprocess + parse + check, and prints lines per second and
 * the ratio check-included / parse-only. Ratios are what to compare between machines. Run by
 * hand:  bench_check [repeats]   (default 200) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "parse/ast.h"
#include "check/check.h"
#include "files.h"
#include "pp/token.h"
#include "base/types.h"
#include "bench.h"

/* One pass over every source; returns diagnostics seen (kept so nothing is optimised away). */
static size_t run(const source *srcs, int count, int check) {
    size_t sink = 0;
    for (int i = 0; i < count; i++) {
        hfx_arena a;
        hfx_arena_init(&a);
        hfx_diags d;
        hfx_diags_init(&d, &a, HFXC_NO_WARNINGS);
        hfx_types *types = hfx_types_new(&a);
        hfx_token *t = hfx_preprocess(&a, &d, srcs[i].name, srcs[i].text, srcs[i].size, NULL);
        hfx_ast *ast = hfx_parse(&a, &d, types, t);
        if (check && !d.errors) hfx_check(&a, &d, types, ast);
        sink += d.count + ast->decl_count;
        hfx_arena_free(&a);
    }
    return sink;
}

static double measure(const source *srcs, int count, int repeats, int check, size_t *sink) {
    size_t lines = 0;
    for (int i = 0; i < count; i++) lines += srcs[i].lines;
    double t0 = now();
    for (int r = 0; r < repeats; r++) *sink += run(srcs, count, check);
    double dt = now() - t0;
    return dt > 0 ? (double)lines * repeats / dt : 0;
}

static void report(const char *what, const source *srcs, int count, int repeats) {
    size_t sink = 0;
    double parse = measure(srcs, count, repeats, 0, &sink);
    double check = measure(srcs, count, repeats, 1, &sink);
    printf("%s (%d repeats)\n", what, repeats);
    printf("  preprocess + parse         : %12.0f lines/s\n", parse);
    printf("  preprocess + parse + check : %12.0f lines/s   (parse+check time) / (parse time) = %5.2f\n", check,
           check > 0 ? parse / check : 0);
    if (sink == 42) printf(" \n");
}

/* n functions, each with locals, a loop, overloaded calls, intrinsics and swizzles. */
static char *generated_effect(uint32_t n, uint32_t *size) {
    size_t cap = (size_t)n * 700 + 1024, len = 0;
    char *text = malloc(cap);
    len += (size_t)snprintf(text, cap,
                            "float4x4 World; float4x4 ViewProj; float3 Light; float4 Colors[8]; int Count;\n"
                            "float shade(float x) { return saturate(x); }\n"
                            "float3 shade(float3 x) { return saturate(x); }\n");
    for (uint32_t i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, cap - len,
                                "static const float k%u = %u.5;\n"
                                "float4 f%u(float3 p, float3 n, float2 uv)\n"
                                "{\n"
                                "    float4 w = mul(float4(p, 1), World);\n"
                                "    float3 l = normalize(Light - w.xyz);\n"
                                "    float d = shade(dot(normalize(n), l)) * k%u;\n"
                                "    float4 c = 0;\n"
                                "    for (int j = 0; j < Count; j++) c += Colors[j] * d;\n"
                                "    c.rgb = lerp(c.rgb, shade(l), uv.x);\n"
                                "    return mul(w, ViewProj) * 0.5 + c;\n"
                                "}\n",
                                i, i, i, i);
    *size = (uint32_t)len;
    return text;
}

int main(int argc, char **argv) {
    int repeats = argc > 1 ? atoi(argv[1]) : 200;
    if (repeats <= 0) repeats = 200;
    static const char *const seeds[] = {
        "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
        "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
        "spot_specular.fx", "tutorial0.fx"};
    enum { N = sizeof seeds / sizeof seeds[0] };
    source srcs[N];
    int count = 0;
    for (int i = 0; i < N; i++) {
        char *path = test_seed_path(seeds[i]);
        size_t size = 0;
        char *text = path ? test_read_file(path, &size) : NULL;
        if (text) srcs[count++] = (source){seeds[i], text, (uint32_t)size, count_lines(text, (uint32_t)size)};
        free(path);
    }
    if (count) report("seed corpus", srcs, count, repeats);
    else printf("seed corpus absent: skipped\n");
    source big;
    big.name = "generated.fx";
    big.text = generated_effect(5000, &big.size);
    big.lines = count_lines(big.text, big.size);
    report("generated effect (5000 functions)", &big, 1, repeats / 50 > 0 ? repeats / 50 : 1);
    free(big.text);
    for (int i = 0; i < count; i++) free(srcs[i].text);
    return 0;
}
