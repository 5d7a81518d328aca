/* ast.h: the syntax tree of an effect file, as parser.y builds it, then decorated in place by
 * check.c (types, resolved names and calls, explicit conversions). Everything lives in the
 * compilation's arena. Lists are arrays with a count (the parser collects into growable
 * vectors and copies them at the end of each rule).
 *
 * Invariants after a successful check (what ir.c may rely on):
 * - every hfx_expr has `type` set (void for calls of void functions);
 * - EX_IDENT has `sym` (a hfx_decl: global, local, parameter) or names a state constant only
 *   inside state values;
 * - EX_CALL has `fn` (a user function) or `intrinsic` (>= 0, an id in check/intrinsics.def) set, and its
 *   arguments already converted to the parameter types;
 * - EX_MEMBER is rewritten to EX_SWIZZLE (vector/scalar .xyzw/.rgba, matrix ._m00/._11) or
 *   EX_FIELD (struct member, `field` = index);
 * - every implicit conversion is an EX_CAST with `implicit` set; binary operands have equal
 *   types (except the shift count and &&/||, which are bool), conditions are bool scalars;
 * - EX_INIT_LIST is flattened to the declared type's components and converted;
 * - constructors (EX_CONSTRUCT) list arguments whose component counts add up exactly.
 */
#ifndef HFX_AST_H
#define HFX_AST_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "base/diag.h"
#include "pp/token.h"
#include "base/types.h"

typedef struct hfx_decl hfx_decl;
typedef struct hfx_stmt hfx_stmt;
typedef struct hfx_func hfx_func;

typedef enum {
    EX_INT, EX_FLOAT, EX_BOOL, EX_STRING,
    EX_IDENT,        /* name */
    EX_UNARY,        /* op: OP_NEG, OP_POS, OP_NOT, OP_BITNOT, OP_PREINC, OP_PREDEC, OP_POSTINC, OP_POSTDEC */
    EX_BINARY,       /* op: OP_ADD .. OP_OR */
    EX_ASSIGN,       /* op: OP_NONE for '=', else the arithmetic op of '+=' etc. */
    EX_TERNARY,      /* a ? b : c (componentwise in HLSL) */
    EX_COMMA,        /* args[0], args[1] */
    EX_CALL,         /* name(args) */
    EX_METHOD,       /* args[0].name(args[1..]): tex.Sample(s, uv) (SM4 syntax; reported) */
    EX_CONSTRUCT,    /* cast_type(args): float4(...), float(x) */
    EX_CAST,         /* (cast_type)args[0]; also implicit conversions after checking */
    EX_MEMBER,       /* args[0].name */
    EX_INDEX,        /* args[0][args[1]] */
    EX_INIT_LIST,    /* { args } */
    EX_COMPILE,      /* compile profile name(args) */
    EX_SAMPLER_STATE,/* sampler_state { states } */
    EX_STATE_REF,    /* <name> in a state value: a parameter reference */
    EX_ASM,          /* asm { ... }: kept for its position, reported as unsupported */
    EX_NULL,         /* NULL in a shader state */
    /* produced by check.c */
    EX_SWIZZLE,      /* args[0].swizzle: comps[] index the source's components (row-major for matrices) */
    EX_FIELD         /* args[0].field */
} hfx_expr_kind;

typedef enum {
    OP_NONE,
    OP_NEG, OP_POS, OP_NOT, OP_BITNOT, OP_PREINC, OP_PREDEC, OP_POSTINC, OP_POSTDEC,
    OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_MOD, OP_SHL, OP_SHR, OP_BITAND, OP_BITOR, OP_BITXOR,
    OP_LT, OP_GT, OP_LE, OP_GE, OP_EQ, OP_NE, OP_AND, OP_OR
} hfx_op;

typedef struct hfx_state_assign hfx_state_assign;

struct hfx_expr {
    hfx_expr_kind kind;
    hfx_op op;
    hfx_loc loc;               /* the operator, or the first token of a primary / call name */
    const hfx_type *type;      /* set by check.c */
    hfx_expr **args; uint32_t arg_count;
    const char *name;          /* IDENT, CALL, METHOD, MEMBER, COMPILE (entry), STATE_REF */
    const char *profile;       /* COMPILE: "vs_3_0" */
    const hfx_type *cast_type; /* CONSTRUCT, CAST */
    int64_t ival;              /* INT, BOOL */
    bool is_unsigned;          /* INT: a u suffix, or past int's range (4294967295, 0xffffffff) */
    double fval;               /* FLOAT */
    const char *sval;          /* STRING (joined, escapes resolved), ASM (raw text) */
    bool parenthesized;        /* written inside ( ): `Texture = (t)` */
    bool implicit;             /* CAST inserted by check.c */
    hfx_state_assign *states; uint32_t state_count; /* SAMPLER_STATE */
    /* check.c */
    hfx_decl *sym;             /* IDENT */
    hfx_func *fn;              /* CALL of a user function */
    int intrinsic;             /* CALL of an intrinsic: id from check/intrinsics.def, -1 otherwise */
    uint8_t comps[16];         /* SWIZZLE */
    uint8_t comp_count;
    uint32_t field;            /* FIELD */
};

typedef struct hfx_annotation_ast {
    const hfx_type *type;      /* string, scalar, vector... */
    const char *name;
    hfx_expr *value;           /* a literal, a constructor, a brace list, or joined strings */
    hfx_loc loc;
} hfx_annotation_ast;

/* `Name[index] = value;` in a pass or a sampler_state block. */
struct hfx_state_assign {
    const char *name;          /* as written (any case) */
    hfx_expr *index;           /* NULL when not indexed */
    hfx_expr *value;           /* expr, EX_STATE_REF (<p>), EX_COMPILE, EX_NULL, EX_ASM... */
    hfx_loc loc;               /* the state name */
};

typedef struct hfx_attribute {
    const char *name;          /* unroll, loop, branch, flatten, fastopt, ... */
    hfx_expr **args; uint32_t arg_count;
    hfx_loc loc;
} hfx_attribute;

typedef enum {
    ST_BLOCK, ST_DECL, ST_EXPR, ST_IF, ST_FOR, ST_WHILE, ST_DO, ST_SWITCH, ST_CASE, ST_DEFAULT,
    ST_BREAK, ST_CONTINUE, ST_DISCARD, ST_RETURN, ST_EMPTY, ST_ASM
} hfx_stmt_kind;

struct hfx_stmt {
    hfx_stmt_kind kind;
    hfx_loc loc;
    hfx_attribute *attrs; uint32_t attr_count;
    hfx_stmt **body; uint32_t body_count;   /* BLOCK and SWITCH (its cases and statements) */
    hfx_decl **decls; uint32_t decl_count;  /* DECL: one per declarator */
    hfx_expr *expr;            /* EXPR, RETURN (may be NULL), IF/WHILE/DO/SWITCH condition, FOR condition (may be NULL), CASE value */
    hfx_stmt *init;            /* FOR: a DECL or EXPR statement, or NULL */
    hfx_expr *step;            /* FOR: may be NULL */
    hfx_stmt *then_stmt;       /* IF, and the loop body of FOR/WHILE/DO */
    hfx_stmt *else_stmt;       /* IF: may be NULL */
};

typedef enum { DECL_VAR, DECL_FUNC, DECL_STRUCT, DECL_TYPEDEF, DECL_TECHNIQUE, DECL_PARAM } hfx_decl_kind;

typedef struct hfx_pass_ast {
    const char *name;          /* NULL when anonymous */
    hfx_annotation_ast *annotations; uint32_t annotation_count;
    hfx_state_assign *states; uint32_t state_count;
    hfx_loc loc;
} hfx_pass_ast;

typedef struct hfx_technique_ast {
    const char *name;          /* NULL when anonymous */
    const char *keyword;       /* "technique", "Technique", "technique10"... as written */
    hfx_annotation_ast *annotations; uint32_t annotation_count;
    hfx_pass_ast *passes; uint32_t pass_count;
} hfx_technique_ast;

struct hfx_func {
    const hfx_type *ret;
    const char *name;
    hfx_decl **params; uint32_t param_count;  /* DECL_PARAM */
    const char *ret_semantic;  /* NULL when none */
    hfx_stmt *body;            /* NULL for a forward declaration */
    hfx_attribute *attrs; uint32_t attr_count;
    hfx_func *definition;      /* check.c: the definition a prototype resolves to */
    hfx_loc loc;               /* the name */
    bool returns_per_pass;     /* check.c: may end without a return unless the values of its uniform
                                  parameters fold a branch away; ir/lower/limits.c decides per pass */
};

/* A variable (global, local), a function parameter, a function, a struct, a typedef or a
 * technique. One per declarator: `float c1, c2, c3;` makes three. */
struct hfx_decl {
    hfx_decl_kind kind;
    hfx_loc loc;               /* the name */
    const char *name;
    const hfx_type *type;      /* VAR, PARAM, TYPEDEF (the aliased type), STRUCT (the struct type) */
    uint32_t mods;             /* MOD_* (storage class, in/out/uniform, row_major...) */
    const char *semantic;      /* NULL when none */
    const char *reg;           /* `register(c0)`: "c0"; `register(ps, c1)`: "ps,c1"; several joined by ';'
                                * ("vs,c13;ps,c14"): hfx_register_for picks a shader's; NULL when none */
    hfx_annotation_ast *annotations; uint32_t annotation_count;
    hfx_expr *init;            /* initializer or parameter default; NULL when none */
    hfx_func *func;            /* FUNC */
    hfx_technique_ast *technique; /* TECHNIQUE */
    bool is_global;
    /* check.c */
    uint32_t index;            /* globals: declaration order; params: position */
    bool assigned;             /* a global some shader writes to (needs a private copy) */
};

typedef struct hfx_ast {
    hfx_decl **decls; uint32_t decl_count;  /* top level, in source order */
} hfx_ast;

/* The parse entry point (parser.y): tokens from hfx_preprocess, errors to diags, recovers at
 * ';' and '}' so every syntax error is reported. Never NULL (an empty tree on total failure). */
hfx_ast *hfx_parse(hfx_arena *arena, hfx_diags *diags, hfx_types *types, struct hfx_token *tokens);

/* A readable dump of the tree (ast.c), for hfxc --ast and tests. malloc'ed. */
char *hfx_ast_dump(const hfx_ast *ast);
/* The reservation among a declaration's `reg` that applies to a shader of `profile` ("vs_2_0",
 * "ps_3_0"): `register(ps, c1)` in a pixel shader, else the unqualified `register(c1)`; copied
 * into buf ("c1"); NULL when none applies (or it does not fit). */
const char *hfx_register_for(const char *reg, const char *profile, char *buf, size_t cap);
/* The evaluator's operator for op; false for the ones it has none of (++, --, OP_NONE). */
bool hfx_op_ev(hfx_op op, hfx_ev_op *out);

#endif
