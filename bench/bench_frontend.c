/* bench_frontend: how fast the front end eats source. Runs the seed corpus (all 14 files,
 * repeated) and a generated 100 000-line effect through tokenize, preprocess, and
 * preprocess + parse, and prints lines per second next to a baseline measured in the same run
 * on the same text: a plain pass that counts lines and bytes. The ratios are what to compare
 * between machines; the absolute figures are not. Run by hand:
 *   bench_frontend [repeats] [seeds|generated]      (default 200, both inputs)
 * Naming one input is for instruction counts, which the other would only muddle:
 *   valgrind --tool=callgrind bench_frontend 5 seeds */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "parse/ast.h"
#include "files.h"
#include "pp/token.h"
#include "base/types.h"
#include "bench.h"

/* The baseline: touch every byte once (count newlines and non-blank bytes). */
static size_t baseline(const source *srcs, int count) {
    size_t sum = 0;
    for (int i = 0; i < count; i++) {
        const unsigned char *p = (const unsigned char *)srcs[i].text;
        for (uint32_t k = 0; k < srcs[i].size; k++) sum += p[k] == '\n' ? 1000 : p[k] > ' ';
    }
    return sum;
}

typedef enum { MODE_TOKENIZE, MODE_PREPROCESS, MODE_PARSE } mode;

static size_t run_front_end(const source *srcs, int count, mode m) {
    size_t tokens = 0;
    for (int i = 0; i < count; i++) {
        hfx_arena a;
        hfx_arena_init(&a);
        hfx_diags d;
        hfx_diags_init(&d, &a, HFXC_NO_WARNINGS);
        hfx_token *t;
        if (m == MODE_TOKENIZE) {
            uint32_t f = hfx_diags_add_file(&d, srcs[i].name, NULL, srcs[i].text, srcs[i].size);
            t = hfx_tokenize(&a, &d, f);
        } else {
            t = hfx_preprocess(&a, &d, srcs[i].name, srcs[i].text, srcs[i].size, NULL);
        }
        if (m == MODE_PARSE) {
            hfx_types *types = hfx_types_new(&a);
            (void)hfx_parse(&a, &d, types, t);
        }
        for (; t; t = t->next) tokens++;
        hfx_arena_free(&a);
    }
    return tokens;
}

/* Runs the work `repeats` times over the sources in 5 rounds and keeps the fastest round (other
 * processes on the machine only ever slow a round down); returns lines per second. */
static double measure(const source *srcs, int count, int repeats, mode m, int is_baseline, size_t *sink) {
    size_t lines = 0;
    for (int i = 0; i < count; i++) lines += srcs[i].lines;
    int per_round = repeats / 5 > 0 ? repeats / 5 : 1;
    double best = 0;
    for (int round = 0; round < 5; round++) {
        double t0 = now();
        for (int r = 0; r < per_round; r++)
            *sink += is_baseline ? baseline(srcs, count) : run_front_end(srcs, count, m);
        double dt = now() - t0;
        double rate = dt > 0 ? (double)lines * per_round / dt : 0;
        if (rate > best) best = rate;
    }
    return best;
}

static void report(const char *what, const source *srcs, int count, int repeats) {
    size_t sink = 0;
    double base = measure(srcs, count, repeats, MODE_TOKENIZE, 1, &sink);
    double lex = measure(srcs, count, repeats, MODE_TOKENIZE, 0, &sink);
    double pp = measure(srcs, count, repeats, MODE_PREPROCESS, 0, &sink);
    double parse = measure(srcs, count, repeats, MODE_PARSE, 0, &sink);
    printf("%s (%d repeats)\n", what, repeats);
    printf("  baseline byte pass : %12.0f lines/s\n", base);
    printf("  tokenize           : %12.0f lines/s   baseline/tokenize   = %6.1f\n", lex, base / lex);
    printf("  preprocess         : %12.0f lines/s   baseline/preprocess = %6.1f\n", pp, base / pp);
    printf("  preprocess + parse : %12.0f lines/s   baseline/pp+parse   = %6.1f\n", parse, base / parse);
    if (sink == 42) printf(" \n"); /* keeps the work from being optimised away */
}

static char *generated_effect(uint32_t lines, uint32_t *size) {
    static const char *const body[] = {
        "#define SCALE(x) ((x) * 2.0f)\n",
        "float4 f%u(float4 p : POSITION) : COLOR { return mul(p, World) * SCALE(%u.5f); } // c\n",
        "/* block comment %u */ float g%u = 1.0e-3f + 0x%x;\n",
        "#if %u %% 2\nfloat h%u;\n#else\nfloat i%u;\n#endif\n"};
    size_t cap = (size_t)lines * 100 + 256, n = 0;
    char *text = malloc(cap);
    n += (size_t)snprintf(text, cap, "float4x4 World;\n%s", body[0]);
    for (uint32_t i = 2; i < lines;) {
        int k = 1 + (int)(i % 3);
        if (k == 3 && i + 5 > lines) k = 1;
        n += (size_t)snprintf(text + n, cap - n, body[k], i, i, i);
        i += k == 3 ? 5 : 1;
    }
    *size = (uint32_t)n;
    return text;
}

static void report_generated(int repeats) {
    source big;
    big.name = "generated.fx";
    big.text = generated_effect(100000, &big.size);
    big.lines = count_lines(big.text, big.size);
    report("generated 100000-line effect", &big, 1, repeats / 20 > 5 ? repeats / 20 : 5);
    free(big.text);
}

int main(int argc, char **argv) {
    int repeats = argc > 1 ? atoi(argv[1]) : 200;
    if (repeats <= 0) repeats = 200;
    const char *only = argc > 2 ? argv[2] : "";
    bool seeds_too = strcmp(only, "generated") != 0, generated_too = strcmp(only, "seeds") != 0;
    static const char *const seeds[] = {
        "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx",
        "fxcomposer_empty.fx", "multilights.fx", "multilights_repaired.fx", "phong.fx", "point.fx",
        "point_specular.fx", "pointlights.fx", "spot.fx", "spot_specular.fx", "tutorial0.fx"};
    enum { N = sizeof seeds / sizeof seeds[0] };
    source srcs[N];
    int count = 0;
    for (int i = 0; i < N && seeds_too; i++) {
        char *path = test_seed_path(seeds[i]);
        size_t size = 0;
        char *text = path ? test_read_file(path, &size) : NULL;
        if (text) {
            srcs[count] = (source){seeds[i], text, (uint32_t)size, count_lines(text, (uint32_t)size)};
            count++;
        }
        free(path);
    }
    if (count) report("seed corpus", srcs, count, repeats);
    else if (seeds_too) printf("seed corpus absent: skipped\n");
    if (generated_too) report_generated(repeats);
    for (int i = 0; i < count; i++) free(srcs[i].text);
    return 0;
}
