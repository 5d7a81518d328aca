/* build_int.h: what the effect builder's files (build.c, build_values.c, build_states.c)
 * share. Not a contract: nothing outside compiler/build*.c includes it. */
#ifndef HFX_BUILD_INT_H
#define HFX_BUILD_INT_H

#include <stdbool.h>

#include "effect/build.h"
#include "effect/codegen.h"
#include "ir/ir.h"
#include "states.h"

/* fxc numbers the builder reports with (diag.h has the common ones). */
enum {
    X_UNKNOWN_STATE = 3000,   /* fxc reports unknown state names as syntax-level errors */
    X_NOT_LITERAL = 3011,     /* initial value must be a literal expression */
    X_NO_ENTRY = 3501         /* entrypoint not found */
};

/* One program made so far, with the shader pair that made it (for deduplication). */
typedef struct hfx_program_key {
    const hfx_expr *vs, *ps;
    bool flat_colors;              /* the pass's ShadeMode is FLAT */
} hfx_program_key;

typedef struct hfx_builder {
    hfx_arena *arena;
    hfx_diags *diags;
    hfx_types *types;
    hfx_ast *ast;
    hfx_fx_effect *fx;
    unsigned targets;
    uint32_t param_cap, value_cap, annotation_cap, state_cap, sampler_cap, program_cap, pass_cap, technique_cap;
    uint32_t expr_cap;             /* of fx->exprs */
    uint32_t variant_cap;          /* of fx->variants */
    const hfx_type **param_types;  /* parallel to fx->params: the HLSL type each param has (arena) */
    hfx_decl **param_decls;        /* parallel to fx->params: the global (top level only) (arena) */
    uint32_t param_type_cap, param_decl_cap;
    hfx_program_key *keys;         /* parallel to fx->programs, in the arena */
    uint32_t key_cap;
    hfx_codegen *cg;
    hfx_fx_program pending;        /* the program the codegen is filling, before it joins fx */
    hfx_arena_cleanup *cleanup;    /* frees fx and pending if a failure escapes */
    bool failed_alloc;
} hfx_builder;

/* A flat list of constant components, as an initializer lists them. */
typedef struct hfx_cvec {
    double *v;
    uint32_t n, cap;
    bool integral;                 /* every component came from an int or bool */
} hfx_cvec;

/* Makes room for one more element of `elem` bytes in *arr (zeroed); false when out of memory. */
bool hfx_build_grow(hfx_builder *b, void **arr, size_t elem, uint32_t count, uint32_t *cap);
#define HFX_BUILD_GROW(b, arr, count, cap) hfx_build_grow((b), (void **)&(arr), sizeof *(arr), (count), &(cap))
char *hfx_build_strdup(hfx_builder *b, const char *s);   /* malloc'ed copy; NULL stays NULL */

/* Evaluates a constant expression to its components (literals, constructors, brace lists, casts,
 * arithmetic, static const globals). `names`, when set, also resolves identifiers as that
 * state's named values (`Red | Green`). Returns false when not constant (nothing reported). */
bool hfx_build_eval(hfx_builder *b, const hfx_expr *e, hfx_cvec *out, const hfx_state_info *names);
void hfx_cvec_free(hfx_cvec *c);
/* Writes `c` as the words of `ty` (int32 for bool/int, float bits otherwise) from words[0]. */
/* A state value that reads parameters compiled to a program in fx->exprs (build_code.c):
 * its first word and length; false (nothing added, nothing reported) when it cannot be. */
bool hfx_build_code(hfx_builder *b, const hfx_expr *e, const hfx_state_info *names, uint32_t *first, uint32_t *words);
/* The index of a shader array of `count` entries read at Apply, clamped into 0 .. count - 1. */
bool hfx_build_selector(hfx_builder *b, const hfx_expr *index, uint32_t count, uint32_t *first, uint32_t *words);
void hfx_build_store(const hfx_type *ty, const hfx_cvec *c, uint32_t *words);
uint32_t hfx_build_type_words(const hfx_type *ty);        /* numeric words, objects count 0 */
const hfx_type *hfx_build_innermost(const hfx_type *ty, uint32_t *elements); /* array element, sizes multiplied */

/* The top-level parameter a name or an identifier refers to, or HFX_NONE. */
uint32_t hfx_build_param_of(hfx_builder *b, const hfx_expr *e);
hfx_decl *hfx_build_global(hfx_builder *b, const char *name);

/* build_states.c */
bool hfx_build_samplers(hfx_builder *b);                  /* one hfx_fx_sampler per sampler param */
bool hfx_build_techniques(hfx_builder *b);                /* techniques, passes, states, programs */
void hfx_build_technique(hfx_builder *b, const hfx_technique_ast *ta); /* one technique and its passes */
uint32_t hfx_build_annotations(hfx_builder *b, const hfx_annotation_ast *list, uint32_t count,
                               uint32_t *first);          /* returns the count added */

#endif
