/* parse_ctx.h: the state parser.y shares with its helpers: the token cursor and the
 * type-name scopes of the lexer hack (hfx_parse_lex.c), growable vectors and the node
 * constructors the grammar actions call (parse_expr.c, parse_decl.c). Everything lives in the
 * arena. The pb_* functions each build one node kind from what a grammar rule matched; the
 * loc they take is the node's (operator, first token, or name: see ast.h). */
#ifndef HFX_PARSE_CTX_H
#define HFX_PARSE_CTX_H

#include <stdbool.h>
#include <stdint.h>

#include "parse/ast.h"

enum {
    PARSE_MAX_NESTING = 256,  /* ( [ { levels before "nesting too deep" */
    PARSE_MAX_EXPR_DEPTH = 4096, /* expression tree depth (long operator chains) */
    PARSE_MAX_STMT_DEPTH = 1024  /* statement nesting (else-if chains, unbraced loops) */
};

/* A growable vector of pointers, allocated in the arena (growth leaves the old copy behind). */
typedef struct parse_vec {
    void **items;
    uint32_t count, cap;
} parse_vec;

/* A name the lexer returns as TYPE_NAME: a struct or a typedef, visible from its brace depth on. */
typedef struct parse_typename {
    const char *name;
    const hfx_type *type;     /* a typedef's type is filled when the parser reduces it */
    uint32_t depth;           /* brace depth it was declared at */
    hfx_struct *st;           /* structs: the object the definition fills */
    uint32_t mods;            /* typedefs: `typedef row_major float4x4 M;` carries row_major */
} parse_typename;

/* The semantic value of every token. */
typedef struct parse_tok {
    const char *text;         /* spelling */
    const hfx_type *type;     /* TYPE_NAME: the type (NULL for a typedef until resolved) */
    parse_typename *entry;    /* TYPE_NAME of a struct or typedef */
    uint32_t mods;            /* MODIFIER: MOD_* bits */
    hfx_op op;                /* ASSIGN_OP */
} parse_tok;

/* `mods type` at the start of a declaration. */
typedef struct parse_specs {
    uint32_t mods;
    const hfx_type *type;
    hfx_loc loc;
    hfx_struct *defines;      /* `struct S {...}` written here: the declaration also declares S */
} parse_specs;

/* An expression as the parser allocates it: the depth bounds later recursive passes. */
typedef struct parse_expr_node {
    hfx_expr e;               /* first, so an hfx_expr* from the parser is a parse_expr_node* */
    uint32_t depth;
} parse_expr_node;

typedef struct parse_stmt_node {
    hfx_stmt s;
    uint32_t depth;
} parse_stmt_node;

/* One declarator before its specifiers are known to it: name, dims, semantic, annotations... */
typedef struct parse_declarator {
    const char *name;
    hfx_loc loc;
    parse_vec dims;           /* hfx_expr* per [n]; NULL entry for [] */
    const char *semantic;
    const char *reg;
    parse_vec annotations;    /* hfx_annotation_ast* */
    hfx_expr *init;
} parse_declarator;

typedef struct parse_ctx {
    hfx_arena *arena;
    hfx_diags *diags;
    hfx_types *types;
    hfx_token *next;          /* the next token yylex returns */
    hfx_token *prev;          /* the last one it returned */
    int prev_code;            /* its Bison token code */
    hfx_token *hist[2];       /* the two returned before prev, newest first */
    int hist_code[2];
    uint32_t depth;           /* current bracket nesting */
    uint32_t brace_depth;     /* current { } nesting, for type-name scopes */
    parse_typename **names; uint32_t name_count, name_cap;
    const char **shadows; uint32_t shadow_count, shadow_cap; /* builtin type spellings declared as names */
    uint32_t state_blocks[4]; /* brace depths of the open pass / sampler_state blocks (nested) */
    uint32_t state_block_count;
    bool state_block_next;    /* the next '{' opens one */
    bool technique_next;      /* the next '{' opens a technique body (not a state block) */
    int typedef_depth;        /* brace depth of an open `typedef`, -1 when none */
    uint32_t typedef_parens;  /* ( [ < inside that typedef */
    bool fatal;               /* nesting too deep: stop reporting */
    hfx_loc last_error;       /* to drop a second error at the same token */
    uint32_t error_count;
    parse_vec globals;
    hfx_struct *pending_struct; /* the struct body just parsed, for the next parse_specs */
    uint32_t pack_mods;         /* MOD_ROW_MAJOR / MOD_COLUMN_MAJOR from #pragma pack_matrix, or 0 */
    const hfx_type *last_type;  /* the type hfx_pb_typename just made, and its typedef's modifiers, */
    uint32_t last_type_mods;    /* which the decl_specs built from it inherit */
    parse_expr_node *oom_expr;  /* handed out when the arena fails, so actions never see NULL */
    parse_stmt_node *oom_stmt;
    parse_specs *oom_specs;
} parse_ctx;

/* hfx_parse_lex.c */
union HFX_YYSTYPE;
/* Starts a parse over `tokens`; false when out of memory. */
bool hfx_parse_ctx_init(parse_ctx *ctx, hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_token *tokens);
hfx_ast *hfx_parse_ctx_finish(parse_ctx *ctx);                     /* the tree of the globals collected */
int hfx_parse_lex(union HFX_YYSTYPE *lval, hfx_loc *lloc, parse_ctx *ctx); /* next Bison token */
void hfx_parse_report_syntax(parse_ctx *ctx, bool at_eof, hfx_loc loc); /* X3000 at the lookahead */
void hfx_parse_report_failure(parse_ctx *ctx, hfx_loc loc, const char *msg); /* Bison gave up (stack) */
void hfx_parse_fatal(parse_ctx *ctx, hfx_loc loc, const char *msg); /* reports once, then ends the token stream */
parse_typename *hfx_parse_find_typename(parse_ctx *ctx, const char *name);

/* parse_expr.c: vectors (by value; push returns the grown vector) */
parse_vec hfx_parse_vec_new(void);
parse_vec hfx_parse_vec_one(parse_ctx *ctx, void *item);
parse_vec hfx_parse_vec_push(parse_ctx *ctx, parse_vec v, void *item);
parse_vec hfx_parse_vec_concat(parse_ctx *ctx, parse_vec a, parse_vec b); /* a's items, then b's */

/* parse_expr.c: expressions */
hfx_expr *hfx_pb_expr(parse_ctx *ctx, hfx_expr_kind kind, hfx_loc loc);
hfx_expr *hfx_pb_int(parse_ctx *ctx, const char *text, hfx_loc loc);
hfx_expr *hfx_pb_float(parse_ctx *ctx, const char *text, hfx_loc loc);
hfx_expr *hfx_pb_bool(parse_ctx *ctx, bool v, hfx_loc loc);
hfx_expr *hfx_pb_string(parse_ctx *ctx, const char *text, hfx_loc loc);
hfx_expr *hfx_pb_string_join(parse_ctx *ctx, hfx_expr *s, const char *text);
hfx_expr *hfx_pb_ident(parse_ctx *ctx, const char *name, hfx_loc loc);
hfx_expr *hfx_pb_unary(parse_ctx *ctx, hfx_op op, hfx_expr *a, hfx_loc loc);
hfx_expr *hfx_pb_binary(parse_ctx *ctx, hfx_op op, hfx_expr *a, hfx_expr *b, hfx_loc loc);
hfx_expr *hfx_pb_assign(parse_ctx *ctx, hfx_op op, hfx_expr *a, hfx_expr *b, hfx_loc loc);
hfx_expr *hfx_pb_ternary(parse_ctx *ctx, hfx_expr *c, hfx_expr *a, hfx_expr *b, hfx_loc loc);
hfx_expr *hfx_pb_comma(parse_ctx *ctx, hfx_expr *a, hfx_expr *b, hfx_loc loc);
hfx_expr *hfx_pb_call(parse_ctx *ctx, const char *name, parse_vec args, hfx_loc loc);
hfx_expr *hfx_pb_method(parse_ctx *ctx, hfx_expr *obj, const char *name, parse_vec args, hfx_loc loc);
hfx_expr *hfx_pb_construct(parse_ctx *ctx, const hfx_type *type, parse_vec args, hfx_loc loc);
hfx_expr *hfx_pb_cast(parse_ctx *ctx, const hfx_type *type, hfx_expr *a, hfx_loc loc);
hfx_expr *hfx_pb_member(parse_ctx *ctx, hfx_expr *a, const char *name, hfx_loc loc);
hfx_expr *hfx_pb_index(parse_ctx *ctx, hfx_expr *a, hfx_expr *i, hfx_loc loc);
hfx_expr *hfx_pb_init_list(parse_ctx *ctx, parse_vec items, hfx_loc loc);
hfx_expr *hfx_pb_compile(parse_ctx *ctx, const char *profile, const char *entry, parse_vec args, hfx_loc loc);
hfx_expr *hfx_pb_sampler_state(parse_ctx *ctx, parse_vec states, hfx_loc loc);
hfx_expr *hfx_pb_state_ref(parse_ctx *ctx, const char *name, hfx_loc loc);
hfx_expr *hfx_pb_asm(parse_ctx *ctx, const char *text, hfx_loc loc);
hfx_expr *hfx_pb_paren(hfx_expr *e);

/* parse_expr.c: type specifiers (array sizes folded when constant) */
const hfx_type *hfx_pb_generic_vector(parse_ctx *ctx, const hfx_type *scalar, const char *n, hfx_loc loc);
const hfx_type *hfx_pb_generic_matrix(parse_ctx *ctx, const hfx_type *scalar, const char *r, const char *c, hfx_loc loc);
const hfx_type *hfx_pb_array_type(parse_ctx *ctx, const hfx_type *elem, parse_vec dims);
const hfx_type *hfx_pb_template(parse_ctx *ctx, const hfx_type *object, const hfx_type *elem, hfx_loc loc);
const hfx_type *hfx_pb_typename(parse_ctx *ctx, const parse_tok *t, hfx_loc loc);
const hfx_type *hfx_pb_unsigned(parse_ctx *ctx, const hfx_type *ty, hfx_loc loc); /* unsigned int */
const hfx_type *hfx_pb_struct(parse_ctx *ctx, const char *name, parse_vec fields, hfx_loc loc);
const hfx_type *hfx_pb_struct_derived(parse_ctx *ctx, const char *name, const hfx_type *base, parse_vec fields,
                                  hfx_loc loc);
const hfx_type *hfx_pb_struct_ref(parse_ctx *ctx, const char *name, hfx_loc loc);
parse_vec hfx_pb_fields(parse_ctx *ctx, parse_vec fields, parse_specs *specs, parse_vec declarators);
parse_specs *hfx_pb_specs(parse_ctx *ctx, uint32_t mods, const hfx_type *type, hfx_loc loc);
/* mods then one more modifier: row_major or column_major twice is X3048 */
uint32_t hfx_pb_more_mods(parse_ctx *ctx, uint32_t mods, uint32_t more, hfx_loc loc);

/* parse_decl.c: declarations, one hfx_decl per declarator */
parse_declarator *hfx_pb_declarator(parse_ctx *ctx, const char *name, hfx_loc loc);
parse_declarator *hfx_pb_decl_dims(parse_ctx *ctx, parse_declarator *d, parse_vec dims);
parse_declarator *hfx_pb_decl_semantic(parse_declarator *d, const char *semantic);
parse_declarator *hfx_pb_decl_register(parse_ctx *ctx, parse_declarator *d, const char *reg);
parse_declarator *hfx_pb_decl_annotations(parse_ctx *ctx, parse_declarator *d, parse_vec annotations);
parse_declarator *hfx_pb_decl_init(parse_declarator *d, hfx_expr *init);
parse_vec hfx_pb_vars(parse_ctx *ctx, parse_specs *specs, parse_vec declarators, bool global);
parse_vec hfx_pb_typedefs(parse_ctx *ctx, parse_specs *specs, parse_vec declarators);
hfx_decl *hfx_pb_struct_decl(parse_ctx *ctx, parse_specs *specs);
hfx_decl *hfx_pb_param(parse_ctx *ctx, parse_specs *specs, parse_declarator *d, hfx_loc loc);
hfx_decl *hfx_pb_function(parse_ctx *ctx, parse_specs *specs, const char *name, hfx_loc loc, parse_vec params,
                      const char *semantic);
hfx_decl *hfx_pb_function_body(parse_ctx *ctx, hfx_decl *fn, parse_vec attrs, hfx_stmt *body);
hfx_annotation_ast *hfx_pb_annotation(parse_ctx *ctx, const hfx_type *type, parse_declarator *d);
hfx_attribute *hfx_pb_attribute(parse_ctx *ctx, const char *name, parse_vec args, hfx_loc loc);
hfx_state_assign *hfx_pb_state(parse_ctx *ctx, const char *name, hfx_expr *index, hfx_expr *value, hfx_loc loc);
/* loc: the name, or the keyword when anonymous */
hfx_pass_ast *hfx_pb_pass(parse_ctx *ctx, const char *name, parse_vec annotations, parse_vec states, hfx_loc loc);
hfx_decl *hfx_pb_technique(parse_ctx *ctx, const char *keyword, const char *name, parse_vec annotations,
                       parse_vec passes, hfx_loc loc);
void hfx_pb_global(parse_ctx *ctx, hfx_decl *d);
void hfx_pb_globals(parse_ctx *ctx, parse_vec decls);
/* `RasterizerState rs { ... };`, `fxgroup g { ... }`: Direct3D 10 effect syntax an fx_2_0 effect
 * drops, with a warning. */
void hfx_pb_d3d10_ignored(parse_ctx *ctx, const char *what, const char *name, hfx_loc loc);

/* parse_decl.c: statements (depth-limited like expressions) */
hfx_stmt *hfx_pb_stmt(parse_ctx *ctx, hfx_stmt_kind kind, hfx_loc loc);
hfx_stmt *hfx_pb_block(parse_ctx *ctx, parse_vec stmts, hfx_loc loc);
hfx_stmt *hfx_pb_decl_stmt(parse_ctx *ctx, parse_vec decls, hfx_loc loc);
hfx_stmt *hfx_pb_expr_stmt(parse_ctx *ctx, hfx_stmt_kind kind, hfx_expr *e, hfx_loc loc);
hfx_stmt *hfx_pb_if(parse_ctx *ctx, hfx_expr *cond, hfx_stmt *then_stmt, hfx_stmt *else_stmt, hfx_loc loc);
hfx_stmt *hfx_pb_loop(parse_ctx *ctx, hfx_stmt_kind kind, hfx_expr *cond, hfx_stmt *body, hfx_loc loc);
hfx_stmt *hfx_pb_for(parse_ctx *ctx, hfx_stmt *init, hfx_expr *cond, hfx_expr *step, hfx_stmt *body, hfx_loc loc);
hfx_stmt *hfx_pb_switch(parse_ctx *ctx, hfx_expr *e, parse_vec body, hfx_loc loc);
hfx_stmt *hfx_pb_attributed(parse_ctx *ctx, hfx_attribute *attr, hfx_stmt *s);
hfx_stmt *hfx_pb_asm_stmt(parse_ctx *ctx, const char *text, hfx_loc loc);

#endif
