/* check_ctx.h: the checker's state, shared by its files: check.c (scopes, declarations,
 * techniques), check_expr.c (expressions, conversions), check_call.c (calls, overloads,
 * constructors, initializers), check_stmt.c (statements, function bodies). */
#ifndef HFX_CHECK_CTX_H
#define HFX_CHECK_CTX_H

#include <stdbool.h>
#include <stdint.h>

#include "parse/ast.h"
#include "check/conv.h"

/* fxc's numbers the checker uses beyond those in diag.h. */
enum {
    X_CTOR_ARGS = 3014,          /* incorrect number of arguments to numeric-type constructor */
    X_NO_IF_SCALAR = 3019,       /* conditional expressions must evaluate to a scalar */
    X_TYPE_MISMATCH_OP = 3020,   /* type mismatch */
    X_SCALAR_EXPECTED = 3022,    /* scalar, vector, or matrix expected */
    X_ARRAY_DIM = 3058,          /* array dimensions must be literal scalar expressions */
    X_VOID_RETURN = 3079,        /* void functions cannot return a value */
    X_MISSING_RETURN = 3080,     /* function must return a value */
    X_INT_REQUIRED = 3082,       /* int or unsigned int type required */
    X_NOT_INDEXABLE = 3121,      /* array, matrix, vector, or indexable object type expected */
    X_INDEX_RANGE = 3504,        /* array index out of bounds */
    X_BAD_JUMP = 3518,           /* break/continue outside a loop */
    X_CASE_FALLTHROUGH = 3533,   /* non-empty case statements must have break or return */
    X_RECURSION = 3500,          /* recursive calls */
    X_UNDEFINED = 3501,          /* entrypoint not found / declared but not defined */
    X_LOOP_VAR_CONFLICT = 3078,  /* warning: a for-init variable hides an earlier one */
    X_SIGNED_UNSIGNED = 3203     /* warning: signed/unsigned mismatch, unsigned assumed */
};

/* A call from a function body (or a compile, from == NULL) to a user function. */
typedef struct check_edge {
    hfx_func *from, *to;
    hfx_loc loc;
    bool compile;
} check_edge;

typedef struct check_entry {
    const char *name;
    hfx_decl *decl;
    uint32_t depth;
    int32_t next;                /* the previous entry in the same bucket, -1 at the end */
} check_entry;

enum { CHECK_BUCKETS = 4096 };

typedef struct check_ctx {
    hfx_arena *arena;
    hfx_diags *diags;
    hfx_types *types;
    const hfx_type *err;         /* the type of an erroneous expression: no further reports */
    check_entry *entries; uint32_t entry_count, entry_cap; /* in the arena */
    int32_t buckets[CHECK_BUCKETS];
    uint32_t depth;              /* 0: globals */
    hfx_decl *func;              /* the function whose body is checked, NULL at top level */
    uint32_t loops, switches;    /* enclosing loops / switches, for break and continue */
    bool in_state;               /* a state value: unknown names are state constants */
    bool oom;
    uint32_t global_count;
    check_edge *edges; uint32_t edge_count, edge_cap;  /* in the arena */
} check_ctx;

/* check_attrs.c: a statement's attributes (X3524, X3084; X3554 warnings) */
void hfx_ck_attributes(check_ctx *c, const hfx_stmt *s);

/* check.c: the call graph */
void hfx_ck_record_call(check_ctx *c, hfx_func *to, hfx_loc loc, bool compile);

/* check.c: scopes */
void hfx_ck_scope_push(check_ctx *c);
void hfx_ck_scope_pop(check_ctx *c);
void hfx_ck_scope_add(check_ctx *c, hfx_decl *d);                 /* reports X3003 in the same scope */
hfx_decl *hfx_ck_lookup(check_ctx *c, const char *name);          /* innermost; NULL when absent */
bool hfx_ck_declared_here(check_ctx *c, const char *name);        /* in the innermost scope */
/* Makes d visible in the current scope without the redefinition check: a for-init variable
 * stays visible after its loop, as in fxc (codegen hoists it). */
void hfx_ck_scope_leak(check_ctx *c, hfx_decl *d);
/* Every function overload named `name`, in declaration order; returns the count (up to max). */
uint32_t hfx_ck_lookup_funcs(check_ctx *c, const char *name, hfx_decl **out, uint32_t max);
/* A declaration's type with array sizes folded (`float a[N]`); reports X3058. */
const hfx_type *hfx_ck_resolve_type(check_ctx *c, const hfx_type *ty, hfx_loc loc);
bool hfx_ck_fold_int(check_ctx *c, hfx_expr *e, int64_t *out);    /* constant integer expressions */
void hfx_ck_annotations(check_ctx *c, hfx_annotation_ast *a, uint32_t n);

/* check_expr.c */
bool hfx_ck_is_err(const check_ctx *c, const hfx_type *t);
const char *hfx_ck_type_name(check_ctx *c, const hfx_type *t);
hfx_loc hfx_ck_start(const hfx_expr *e);                          /* leftmost token of an expression */
const hfx_type *hfx_ck_expr(check_ctx *c, hfx_expr *e);           /* sets and returns e->type */
/* e converted to `to` (an implicit EX_CAST, or e itself). Reports X3017 when impossible (then
 * returns e typed as the error type), X3206 at the expression's start when it truncates and
 * `warn` is set. */
hfx_expr *hfx_ck_convert(check_ctx *c, hfx_expr *e, const hfx_type *to, bool warn);
/* The same for an argument of `call` (EX_CALL / EX_COMPILE): X3206 names the function and
 * points at the call, as fxc does. */
hfx_expr *hfx_ck_convert_arg(check_ctx *c, hfx_expr *e, const hfx_type *to, bool warn, const hfx_expr *call);
hfx_expr *hfx_ck_implicit_cast(check_ctx *c, hfx_expr *e, const hfx_type *to);
void hfx_ck_cond(check_ctx *c, hfx_expr **pe, const char *what);  /* a bool scalar condition */
bool hfx_ck_lvalue(check_ctx *c, hfx_expr *e);                    /* reports X3025; marks globals assigned */

/* check_call.c */
const hfx_type *hfx_ck_call(check_ctx *c, hfx_expr *e);
const hfx_type *hfx_ck_construct(check_ctx *c, hfx_expr *e);
const hfx_type *hfx_ck_compile(check_ctx *c, hfx_expr *e);
void hfx_ck_init(check_ctx *c, hfx_decl *d);                      /* a variable's initializer */
void hfx_ck_state_value(check_ctx *c, hfx_state_assign *s);

/* check_stmt.c */
void hfx_ck_function(check_ctx *c, hfx_decl *d);

#endif
