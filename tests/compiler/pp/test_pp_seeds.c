/* The seed corpus through the lexer and the preprocessor. An independent reference: the
 * source with comments and white space squeezed out (kept inside strings) must equal the
 * tokens' spellings laid end to end; no seed may produce a diagnostic or a stray byte. */
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "test.h"
#include "pp/token.h"

static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx",
    "fxcomposer_empty.fx", "multilights.fx", "multilights_repaired.fx", "phong.fx", "point.fx",
    "point_specular.fx", "pointlights.fx", "spot.fx", "spot_specular.fx", "tutorial0.fx"};
enum { SEED_COUNT = sizeof seeds / sizeof seeds[0] };

/* A character-level pass, written apart from the lexer: drops comments, white space and
 * backslash-newlines, keeps string literals whole. */
static char *squeeze(const char *s) {
    char *out = malloc(strlen(s) + 1), *o = out;
    while (*s) {
        if (s[0] == '/' && s[1] == '/') {
            while (*s && *s != '\n') s++;
        } else if (s[0] == '/' && s[1] == '*') {
            const char *e = strstr(s + 2, "*/");
            s = e ? e + 2 : s + strlen(s);
        } else if (*s == '"') {
            *o++ = *s++;
            while (*s && *s != '"') {
                if (*s == '\\' && s[1]) *o++ = *s++;
                *o++ = *s++;
            }
            if (*s) *o++ = *s++;
        } else if (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n' || *s == '\f' || *s == '\v') {
            s++;
        } else {
            *o++ = *s++;
        }
    }
    *o = 0;
    return out;
}

static char *concat(const hfx_token *t) {
    size_t n = 1;
    for (const hfx_token *u = t; u; u = u->next) n += u->len;
    char *out = malloc(n), *o = out;
    for (; t; t = t->next) {
        memcpy(o, t->text, t->len);
        o += t->len;
    }
    *o = 0;
    return out;
}

static void every_seed_lexes_to_its_squeezed_text(void) {
    for (int i = 0; i < SEED_COUNT; i++) {
        char *path = test_seed_path(seeds[i]);
        size_t size;
        char *text = test_read_file(path, &size);
        CHECK(text != NULL);
        if (!text) { free(path); continue; }
        hfx_arena a;
        hfx_arena_init(&a);
        hfx_diags d;
        hfx_diags_init(&d, &a, 0);
        uint32_t f = hfx_diags_add_file(&d, seeds[i], path, text, (uint32_t)size);
        hfx_token *toks = hfx_tokenize(&a, &d, f);
        int others = 0, lines_ok = 1;
        uint32_t prev_line = 1;
        for (hfx_token *t = toks; t; t = t->next) {
            others += t->kind == TK_OTHER;
            if (t->loc.line < prev_line) lines_ok = 0;
            prev_line = t->loc.line;
        }
        char *want = squeeze(text), *got = concat(toks);
        if (strcmp(want, got) != 0) fprintf(stderr, "%s: token spellings differ from the squeezed source\n", seeds[i]);
        CHECK(strcmp(want, got) == 0);
        CHECK_INT(others, 0);
        CHECK(lines_ok);
        CHECK_INT(d.count, 0);
        free(want);
        free(got);
        hfx_arena_free(&a);
        free(text);
        free(path);
    }
}

/* Only pointlights.fx has a directive; every other seed comes out of the preprocessor as the
 * lexer cut it, token for token and place for place. */
static void preprocessing_changes_only_pointlights(void) {
    for (int i = 0; i < SEED_COUNT; i++) {
        char *path = test_seed_path(seeds[i]);
        hfx_arena a;
        hfx_arena_init(&a);
        hfx_diags d;
        hfx_diags_init(&d, &a, 0);
        hfx_token *pp = hfx_preprocess(&a, &d, path, NULL, 0, NULL);
        CHECK_INT(d.count, 0);
        CHECK_INT(d.errors, 0);
        hfx_token *raw = hfx_tokenize(&a, &d, 0);
        if (strcmp(seeds[i], "pointlights.fx") == 0) {
            for (int k = 0; k < 4; k++) raw = raw->next; /* "# define MaxLights 50" */
        }
        int same = 1;
        for (; raw && pp; raw = raw->next, pp = pp->next) {
            if (strcmp(raw->text, "MaxLights") == 0) {
                CHECK_STR(pp->text, "50");
                continue;
            }
            if (strcmp(raw->text, pp->text) != 0 || raw->loc.line != pp->loc.line || raw->loc.col != pp->loc.col)
                same = 0;
        }
        CHECK(raw == NULL && pp == NULL);
        if (!same) fprintf(stderr, "%s: preprocessed tokens differ\n", seeds[i]);
        CHECK(same);
        hfx_arena_free(&a);
        free(path);
    }
}

static void pointlights_max_lights_is_50_at_the_use_site(void) {
    char *path = test_seed_path("pointlights.fx");
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    hfx_token *t = hfx_preprocess(&a, &d, path, NULL, 0, NULL);
    /* float3 LightPosition[MaxLights]; float4 LightColor[MaxLights]; float LightRadius[MaxLights]; */
    static const struct { const char *decl; int line, col; } uses[] = {
        {"LightPosition", 9, 22}, {"LightColor", 10, 19}, {"LightRadius", 11, 19}};
    int found = 0;
    for (; t; t = t->next) {
        for (int i = 0; i < 3; i++) {
            if (strcmp(t->text, uses[i].decl) != 0 || t->loc.line != (uint32_t)uses[i].line) continue;
            hfx_token *n = t->next->next;
            CHECK_STR(t->next->text, "[");
            CHECK_STR(n->text, "50");
            CHECK_INT(n->kind, TK_INT);
            CHECK_INT(n->loc.line, uses[i].line);
            CHECK_INT(n->loc.col, uses[i].col);
            CHECK_INT(n->spelling.line, 1);
            CHECK_INT(n->spelling.col, 19);
            CHECK_STR(n->next->text, "]");
            found++;
        }
    }
    CHECK_INT(found, 3);
    CHECK_INT(d.count, 0);
    hfx_arena_free(&a);
    free(path);
}

static void multilights_phong_call_is_at_204_20(void) {
    char *path = test_seed_path("multilights.fx");
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    int found = 0;
    for (hfx_token *t = hfx_preprocess(&a, &d, path, NULL, 0, NULL); t; t = t->next)
        if (t->loc.line == 204 && strcmp(t->text, "Phong") == 0) {
            CHECK_INT(t->loc.col, 20);
            CHECK_STR(t->next->text, "(");
            found++;
        }
    CHECK_INT(found, 1);
    hfx_arena_free(&a);
    free(path);
}

/* fxc /P output: preprocessing the text hfx_tokens_to_text made gives the same tokens on the
 * same lines again. */
static void preprocessed_text_round_trips(void) {
    for (int i = 0; i < SEED_COUNT; i++) {
        char *path = test_seed_path(seeds[i]);
        hfx_arena a;
        hfx_arena_init(&a);
        hfx_diags d;
        hfx_diags_init(&d, &a, 0);
        hfx_token *first = hfx_preprocess(&a, &d, path, NULL, 0, NULL);
        char *text = hfx_tokens_to_text(&d, first);
        hfx_token *again = hfx_preprocess(&a, &d, "again.fx", text, (uint32_t)strlen(text), NULL);
        int same = 1;
        for (; first && again; first = first->next, again = again->next)
            if (strcmp(first->text, again->text) != 0 || first->kind != again->kind || first->loc.line != again->loc.line)
                same = 0;
        CHECK(first == NULL && again == NULL);
        if (!same) fprintf(stderr, "%s: the /P text does not give the same tokens\n", seeds[i]);
        CHECK(same);
        CHECK_INT(d.count, 0);
        free(text);
        hfx_arena_free(&a);
        free(path);
    }
}

int main(void) {
    test_require_seeds();
    RUN(every_seed_lexes_to_its_squeezed_text);
    RUN(preprocessing_changes_only_pointlights);
    RUN(pointlights_max_lights_is_50_at_the_use_site);
    RUN(multilights_phong_call_is_at_204_20);
    RUN(preprocessed_text_round_trips);
    return test_summary();
}
