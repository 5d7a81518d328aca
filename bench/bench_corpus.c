/* bench_corpus.c: the real-world corpus compiled in one process on one core, as issue 12 asks:
 * every root effect of a list (tests/corpus/sources.tsv's roots, fetched by scripts/corpus.sh),
 * GLSL 330 + ES 300, the .hfxo encoded in memory, best of `rounds` per effect. Prints ms per
 * effect without and with the self-check (glslang), their ratio, and the slowest effects.
 * An effect may include from any folder above it in its repository, as the corpus runner
 * allows. Run by hand: bench_corpus CORPUS_DIR LIST [rounds]; LIST holds paths relative to
 * CORPUS_DIR, one a line (e.g. scripts/corpus.sh roots CORPUS_DIR). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "effect.h"
#include "hfx/hfxc.h"

enum { MAX_EFFECTS = 4096, MAX_DIRS = 32, SLOWEST = 10 };

typedef struct effect {
    char *path;
    char *dirs[MAX_DIRS]; /* the folders above it, up to its repository's */
    size_t dir_count;
    double best[2];       /* seconds: [0] without the self-check, [1] with */
} effect;

/* The folders from the effect's own up to CORPUS/<repository>. */
static void ancestors(effect *e, size_t root_len) {
    char *dir = strdup(e->path);
    if (!dir) return;
    for (char *slash = strrchr(dir, '/'); slash && (size_t)(slash - dir) > root_len; slash = strrchr(dir, '/')) {
        *slash = 0;
        if (e->dir_count < MAX_DIRS) e->dirs[e->dir_count++] = strdup(dir);
        if (!strchr(dir + root_len + 1, '/')) break; /* reached the repository's folder */
    }
    free(dir);
}

/* Seconds for one compile and encode; negative when it failed. */
static double compile_once(const effect *e, unsigned flags) {
    hfxc_options o;
    memset(&o, 0, sizeof o);
    o.flags = flags | HFXC_PACK_UNIFORMS | HFXC_NO_WARNINGS;
    o.include_dirs = (const char *const *)e->dirs;
    o.include_dir_count = e->dir_count;
    double t0 = now();
    hfxc_result *r = hfxc_compile_file(e->path, &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    void *data = NULL;
    size_t size = 0;
    int ok = fx && hfx_fx_write_hfxo(fx, &data, &size) == 0;
    free(data);
    hfxc_result_free(r);
    double t = now() - t0;
    return ok ? t : -1;
}

static size_t read_list(const char *corpus, const char *list, effect *fx) {
    FILE *f = fopen(list, "r");
    if (!f) return 0;
    char line[4096];
    size_t n = 0;
    while (n < MAX_EFFECTS && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = 0;
        if (!line[0]) continue;
        size_t len = strlen(corpus) + strlen(line) + 2;
        fx[n].path = malloc(len);
        if (!fx[n].path) break;
        snprintf(fx[n].path, len, "%s/%s", corpus, line);
        ancestors(&fx[n], strlen(corpus));
        n++;
    }
    fclose(f);
    return n;
}

static int slower(const void *a, const void *b) {
    double x = ((const effect *)a)->best[0], y = ((const effect *)b)->best[0];
    return x < y ? 1 : x > y ? -1 : 0;
}

static void report(effect *fx, size_t n, size_t failed, int rounds, size_t root_len) {
    double total[2] = {0, 0};
    for (size_t i = 0; i < n; i++) total[0] += fx[i].best[0], total[1] += fx[i].best[1];
    size_t ok = n - failed;
    printf("%zu effects compiled (%zu failed), GLSL 330 + ES 300 + .hfxo, best of %d each, one core\n", ok, failed, rounds);
    printf("  without self-check: %8.3f ms/effect (%.3f s in all)\n", total[0] * 1e3 / (double)ok, total[0]);
    printf("  with self-check:    %8.3f ms/effect (%.3f s in all)\n", total[1] * 1e3 / (double)ok, total[1]);
    printf("  ratio with / without: %.2fx\n", total[1] / total[0]);
    qsort(fx, n, sizeof *fx, slower);
    printf("slowest without self-check:\n");
    for (size_t i = 0; i < n && i < SLOWEST; i++)
        printf("  %8.3f ms  %s\n", fx[i].best[0] * 1e3, fx[i].path + root_len + 1);
}

int main(int argc, char **argv) {
    if (argc < 3) { fprintf(stderr, "usage: bench_corpus CORPUS_DIR LIST [rounds]\n"); return 2; }
    int rounds = argc > 3 ? atoi(argv[3]) : 5;
    if (rounds < 1) rounds = 1;
    static effect fx[MAX_EFFECTS];
    size_t n = read_list(argv[1], argv[2], fx), failed = 0;
    if (!n) { fprintf(stderr, "no effects in %s\n", argv[2]); return 1; }
    for (size_t i = 0; i < n; i++) {
        for (int check = 0; check < 2; check++) {
            fx[i].best[check] = 1e9;
            for (int k = 0; k < rounds; k++) {
                double t = compile_once(&fx[i], check ? 0 : HFXC_NO_SELF_CHECK);
                if (t < 0) { fx[i].best[0] = fx[i].best[1] = 0; failed++; check = 2; break; }
                if (t < fx[i].best[check]) fx[i].best[check] = t;
            }
        }
    }
    report(fx, n, failed, rounds, strlen(argv[1]));
    for (size_t i = 0; i < n; i++) {
        free(fx[i].path);
        for (size_t d = 0; d < fx[i].dir_count; d++) free(fx[i].dirs[d]);
    }
    return 0;
}
