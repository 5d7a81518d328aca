/* parse_util.h: parse a string or a file through the real front end (hfx_preprocess +
 * hfx_parse) and look things up in the tree. Header-only so it adds nothing to the other
 * compiler tests. */
#ifndef HFX_TEST_PARSE_UTIL_H
#define HFX_TEST_PARSE_UTIL_H

#include <stdlib.h>
#include <string.h>

#include "parse/ast.h"
#include "pp/token.h"

typedef struct tp_result {
    hfx_arena arena;
    hfx_diags diags;
    hfx_types *types;
    hfx_ast *ast;
    char *errors;   /* fxc-style text of every diagnostic */
    char *dump;     /* hfx_ast_dump */
} tp_result;

static inline tp_result *tp_run(const char *name, const char *text) {
    tp_result *r = calloc(1, sizeof *r);
    hfx_arena_init(&r->arena);
    hfx_diags_init(&r->diags, &r->arena, 0);
    r->types = hfx_types_new(&r->arena);
    hfx_token *toks = hfx_preprocess(&r->arena, &r->diags, name, text, text ? (uint32_t)strlen(text) : 0, NULL);
    r->ast = hfx_parse(&r->arena, &r->diags, r->types, toks);
    r->errors = hfx_diags_format(&r->diags, 0);
    r->dump = hfx_ast_dump(r->ast);
    return r;
}

/* Parses `text` as the file "t.fx". */
static inline tp_result *tp_parse(const char *text) { return tp_run("t.fx", text); }

static inline void tp_free(tp_result *r) {
    if (!r) return;
    free(r->errors);
    free(r->dump);
    hfx_arena_free(&r->arena);
    free(r);
}

/* The n-th top-level declaration named `name` (n = 0 for the first). */
static inline hfx_decl *tp_find_nth(tp_result *r, const char *name, int n) {
    for (uint32_t i = 0; i < r->ast->decl_count; i++) {
        hfx_decl *d = r->ast->decls[i];
        if (d->name && strcmp(d->name, name) == 0 && n-- == 0) return d;
    }
    return NULL;
}

static inline hfx_decl *tp_find(tp_result *r, const char *name) { return tp_find_nth(r, name, 0); }

/* The state `name` of a pass or sampler_state list, or NULL. */
static inline hfx_state_assign *tp_state(hfx_state_assign *s, uint32_t n, const char *name) {
    for (uint32_t i = 0; i < n; i++)
        if (strcmp(s[i].name, name) == 0) return &s[i];
    return NULL;
}

#endif
