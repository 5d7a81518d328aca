/* Bad input never crashes the front end: the seeds, cut and spliced at pseudo-random places
 * (a fixed-seed generator, so every run is the same), always give a tree, every diagnostic
 * is located in the file, and the unchanged file still parses cleanly afterwards. Meant to
 * run under the sanitizer build as well. */
#include <stdint.h>
#include <stdio.h>

#include "files.h"
#include "parse_util.h"
#include "test.h"

static uint32_t next_random(uint64_t *state) {
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(*state >> 33);
}

static const char *const splices[] = {
    "{", "}", "(", ")", "[", "]", ";", ",", "<", ">", "=", ".", ":", "?", "\"", "/*", "'",
    "struct ", "typedef ", "technique ", "pass ", "asm {", "sampler_state", "compile ", "[unroll] ",
    "#define X (\n", "#if 1\n", "float4x4 ", "return ", "else ", "case 1:", "0x", "1e", "@", "\\\n",
    "register(", "vector<float,", "linear ", "in out ", "NULL", "<t>", "Texture = ", "{{{{", "))))",
    "\n#pragma pack_matrix(row_major)\n", "__hfx_pack_matrix (", "Texture2D<", "pass Pass {", "x.sample",
};

/* One mutation of text: delete, duplicate or insert at a random place. malloc'ed. */
static char *mutate(const char *text, size_t len, uint64_t *rng) {
    size_t at = len ? next_random(rng) % len : 0;
    size_t span = 1 + next_random(rng) % 24;
    if (at + span > len) span = len - at;
    const char *ins = splices[next_random(rng) % (sizeof splices / sizeof *splices)];
    size_t ins_len = strlen(ins);
    char *out = malloc(len + span + ins_len + 1);
    size_t n = 0;
    switch (next_random(rng) % 3) {
    case 0: /* delete */
        memcpy(out, text, at);
        memcpy(out + at, text + at + span, len - at - span);
        n = len - span;
        break;
    case 1: /* duplicate */
        memcpy(out, text, at + span);
        memcpy(out + at + span, text + at, len - at);
        n = len + span;
        break;
    default: /* insert */
        memcpy(out, text, at);
        memcpy(out + at, ins, ins_len);
        memcpy(out + at + ins_len, text + at, len - at);
        n = len + ins_len;
        break;
    }
    out[n] = 0;
    return out;
}

/* Every diagnostic line names the file with a position. */
static int all_located(const char *errors) {
    for (const char *p = errors; *p;) {
        if (strncmp(p, "t.fx(", 5) != 0) return 0;
        const char *nl = strchr(p, '\n');
        if (!nl) return 0;
        p = nl + 1;
    }
    return 1;
}

static void mutated_seeds_never_crash(void) {
    static const char *const seeds[] = {
        "ambient.fx", "ambient_textured.fx", "directional.fx", "fxcomposer_empty.fx",
        "multilights_repaired.fx", "phong.fx", "point.fx", "pointlights.fx", "spot_specular.fx",
        "tutorial0.fx",
    };
    uint64_t rng = 12345;
    int with_errors = 0, total = 0;
    for (size_t s = 0; s < sizeof seeds / sizeof *seeds; s++) {
        char *path = test_seed_path(seeds[s]);
        size_t len = 0;
        char *text = test_read_file(path, &len);
        free(path);
        CHECK(text != NULL);
        if (!text) continue;
        for (int i = 0; i < 150; i++) {
            char *m = mutate(text, len, &rng);
            /* a second mutation on every other round */
            if (i % 2) {
                char *m2 = mutate(m, strlen(m), &rng);
                free(m);
                m = m2;
            }
            tp_result *r = tp_parse(m);
            CHECK(r->ast != NULL);
            CHECK(r->dump != NULL);
            if (!all_located(r->errors)) fprintf(stderr, "unlocated diagnostic:\n%s", r->errors);
            CHECK(all_located(r->errors));
            with_errors += r->diags.errors > 0;
            total++;
            tp_free(r);
            free(m);
        }
        tp_result *r = tp_parse(text);
        CHECK_STR(r->errors, "");
        tp_free(r);
        free(text);
    }
    /* most mutations break the syntax; a handful (comment or string interiors) do not */
    CHECK(with_errors > total / 2);
    printf("     %d of %d mutated files had errors\n", with_errors, total);
}

/* Streams of arbitrary tokens, not near anything valid. */
static void token_soup_never_crashes(void) {
    uint64_t rng = 777;
    for (int i = 0; i < 300; i++) {
        char buf[2048];
        size_t n = 0;
        int count = 1 + (int)(next_random(&rng) % 120);
        for (int k = 0; k < count && n + 40 < sizeof buf; k++) {
            const char *piece = splices[next_random(&rng) % (sizeof splices / sizeof *splices)];
            n += (size_t)snprintf(buf + n, sizeof buf - n, "%s%s", piece, next_random(&rng) % 3 ? " " : "x ");
        }
        buf[n] = 0;
        tp_result *r = tp_parse(buf);
        CHECK(r->ast != NULL && r->dump != NULL);
        CHECK(all_located(r->errors));
        tp_free(r);
    }
}

int main(void) {
    test_require_seeds();
    RUN(mutated_seeds_never_crash);
    RUN(token_soup_never_crashes);
    return test_summary();
}
