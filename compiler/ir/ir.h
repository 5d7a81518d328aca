/* ir.h: the intermediate form of one shader stage of one pass. It is a typed tree (structured
 * control flow, like GLSL and SPIR-V's structured form), copied out of the checked AST by ir.c
 * so each pass can specialise its entry point without touching the shared tree. Names are
 * resolved to ir_var / ir_func, intrinsics to ir_intrin, implicit conversions are IE_CONVERT.
 * Everything lives in the compilation's arena.
 *
 * The passes over it, and their order, are one table: lower/passes.c.
 * glsl.c prints the result; a preshader or SPIR-V back end would read the same tree. */
#ifndef HFX_IR_H
#define HFX_IR_H

#include <stdbool.h>
#include <stdint.h>

#include "check/intrinsics.h"
#include "parse/ast.h"
#include "effect.h"

typedef struct ir_expr ir_expr;
typedef struct ir_stmt ir_stmt;
typedef struct ir_func ir_func;
typedef struct ir_var ir_var;
typedef struct ir_ctx ir_ctx;

typedef enum { IR_VERTEX, IR_PIXEL } ir_stage;

typedef enum {
    IRV_LOCAL,    /* function local */
    IRV_PARAM,    /* function parameter (mods: MOD_IN / MOD_OUT) */
    IRV_UNIFORM,  /* non-static global: a GLSL uniform named fx->params[param].glsl_name */
    IRV_PRIVATE,  /* static global, or the private copy of a uniform a shader writes */
    IRV_SAMPLER   /* sampler parameter */
} ir_var_kind;

/* A variable: what it is, and the results of passes that later phases read (each says who
 * writes and who reads it). A pass's own scratch about variables lives in the pass (an
 * ir_var_map), not here. */
struct ir_var {
    ir_var_kind kind;
    const char *name;        /* HLSL spelling */
    const char *glsl;        /* GLSL spelling (hfx_glsl_name, made unique per function) */
    const hfx_type *type;
    uint32_t mods;
    uint32_t param;          /* UNIFORM / SAMPLER: top-level fx param index; else HFX_NONE */
    const hfx_decl *decl;    /* where it came from (NULL for temporaries) */
    ir_expr *init;           /* PRIVATE statics: initialiser run at main's start */
    /* The copy-on-write of a written uniform: globals.c writes both; preshade, varyings, fold,
     * the GLSL printer and codegen read them. */
    ir_var *copy_of;         /* PRIVATE copy of this uniform */
    ir_var *priv;            /* UNIFORM written somewhere: its private copy */
    hfx_dim dim;             /* SAMPLER: dimension as sampled; uses.c writes it, the GLSL printer reads it */
    bool hoisted;            /* for-init variable used after its loop (HLSL scoping): ir.c writes it; forward,
                              * licm and the GLSL printer (which declares it before the loop) read it */
    /* A preshader (preshade.c writes it, or d3d9_ir.c for fxc's): the uniform-only expression
     * this private global holds, its eval_code program and readable HLSL. codegen copies the
     * code into the effect; the GLSL printer reads the value from hfx_c registers. */
    const ir_expr *pre;
    const uint32_t *pre_code; uint32_t pre_words;
    const char *pre_text;
};

/* A pass's facts about variables, keyed by the variable (var_map.c); the builder (ir.c) keys its
 * declarations and functions the same way. Zero-initialise; lives in the arena, so nothing to free. */
typedef struct ir_var_map { const void **keys; void **vals; uint32_t count, cap; } ir_var_map;
bool hfx_ir_var_map_put(ir_ctx *c, ir_var_map *m, const void *key, void *val); /* false: out of memory */
void *hfx_ir_var_map_get(const ir_var_map *m, const void *key);                /* NULL when absent */

typedef enum {
    IE_CONST,     /* cval[] holds type's components (row-major), by base: b/i/f */
    IE_VAR,
    IE_UNARY,     /* op: OP_NEG, OP_NOT, OP_BITNOT, OP_PRE/POST INC/DEC */
    IE_BINARY,    /* op, a[0], a[1]; for OP_MUL both sides have equal type (componentwise) */
    IE_SELECT,    /* a[0] ? a[1] : a[2], componentwise when a[0] is a bool vector */
    IE_ASSIGN,    /* a[0] op= a[1] (op OP_NONE for '=') */
    IE_COMMA,
    IE_CALL,      /* fn(args) */
    IE_INTRIN,    /* intrin(args) */
    IE_CONSTRUCT, /* type(args): components in order */
    IE_CONVERT,   /* type(a[0]) with HLSL's conversion rules (truncation, splat, base change) */
    IE_SWIZZLE,   /* a[0].comps (row-major component indexes for matrices) */
    IE_INDEX,     /* a[0][a[1]] (matrix: a row) */
    IE_FIELD      /* a[0].field */
} ir_expr_kind;

/* What lower/ranges.c proved of an IE_INDEX's index into an array (the printer's guard). */
typedef enum {
    IR_RANGE_ANY,      /* unknown: reads past either end return zero (D3D9) */
    IR_RANGE_NONNEG,   /* never negative: only the upper end needs the check */
    IR_RANGE_IN_BOUNDS /* always within the array: no check */
} ir_index_range;

/* The checker's intrinsic ids (check/intrinsics.def): one table for check, IR and GLSL. */
typedef hfx_intrinsic_id ir_intrin;

typedef union { double f; int64_t i; } ir_value;

struct ir_expr {
    ir_expr_kind kind;
    hfx_op op;
    const hfx_type *type;
    hfx_loc loc;
    ir_expr **a; uint32_t n;
    ir_var *var;
    ir_func *fn;
    ir_intrin intrin;
    uint8_t comps[16], comp_count;
    uint8_t range;           /* INDEX: an ir_index_range */
    uint32_t field;
    double cval[16];         /* CONST: every base stored as a double (ints and bools exact) */
};

typedef enum {
    IS_BLOCK, IS_DECL, IS_EXPR, IS_IF, IS_FOR, IS_WHILE, IS_DO, IS_SWITCH, IS_CASE, IS_DEFAULT,
    IS_BREAK, IS_CONTINUE, IS_DISCARD, IS_RETURN
} ir_stmt_kind;

struct ir_stmt {
    ir_stmt_kind kind;
    hfx_loc loc;
    ir_stmt **body; uint32_t count; /* BLOCK, SWITCH */
    ir_var *var;             /* DECL (initialiser in expr) */
    ir_expr *expr;           /* EXPR, RETURN, IF/WHILE/DO/SWITCH/FOR condition, CASE value, DECL init */
    ir_stmt *init;           /* FOR */
    ir_expr *step;           /* FOR */
    ir_stmt *then_s, *else_s;/* IF; loop body in then_s */
    const char *hint;        /* [unroll], [loop], [branch]...: printed as a comment */
    uint32_t max_iterations; /* FOR: [unroll(n)] runs the body at most n times, as fxc does; 0: no limit */
};

struct ir_func {
    const char *name, *glsl;
    const hfx_type *ret;
    const char *ret_semantic;
    ir_var **params; uint32_t param_count;
    ir_stmt *body;
    const hfx_func *src;
    bool is_entry;
};

/* One stage of one pass, specialised. */
typedef struct ir_shader {
    ir_stage stage;
    ir_func *entry;
    ir_func **funcs; uint32_t func_count, func_cap;  /* callees before callers; entry last */
    ir_var **globals; uint32_t global_count, global_cap; /* uniforms, samplers, privates used */
    ir_var **pres; uint32_t pre_count, pre_cap;          /* preshaders (lower/preshade.c) */
    const hfx_expr *compile;     /* the EX_COMPILE it came from */
    ir_var_map args;             /* the entry's uniform parameters' compile arguments: hfx_ir_build
                                  * writes them, specialise puts them in and drops the parameters */
    bool uses_discard;
} ir_shader;

typedef struct ir_ctx {
    hfx_arena *arena;
    hfx_diags *diags;
    hfx_types *types;
    hfx_ast *ast;
    hfx_fx_effect *fx;
} ir_ctx;

/* Builds the IR of `compile entry(args)` for one stage; NULL (with a located error) on failure. */
ir_shader *hfx_ir_build(ir_ctx *c, const hfx_expr *compile, ir_stage stage);
/* hfx_ir_lower's options: what the caller's compile asks beyond the passes every stage runs. */
enum {
    IR_LOWER_PACKED = 1u << 0,   /* parameters share hfx_c's registers (registers are counted) */
    IR_LOWER_PRESHADE = 1u << 1, /* packed, preshaders on, from HLSL: the preshade rows run */
    IR_LOWER_DERIVE = 1u << 2    /* a program's derived varyings (lower/varyings.c) */
};
/* Runs a stage's rows of the pass table in order (lower/passes.c); 0, or -1 with errors. */
int hfx_ir_lower(ir_ctx *c, ir_shader *sh, unsigned opts);
/* A program's two lowered stages (either may be NULL), for the program's rows. */
typedef struct ir_program {
    ir_shader *vs, *ps;      /* may become copies (varyings): stages are shared between programs */
    unsigned opts;           /* IR_LOWER_* */
    const char **derived; uint32_t derived_count; /* the vertex outputs the pixel stage derives */
} ir_program;
void hfx_ir_lower_program(ir_ctx *c, ir_program *p);
/* The pass table's rows, for hfxc --dump-ir and the docs' test: name and one line of why. */
uint32_t hfx_ir_pass_count(void);
const char *hfx_ir_pass_name(uint32_t i); /* NULL past the end */
const char *hfx_ir_pass_why(uint32_t i);
const char *hfx_ir_pass_runs(uint32_t i); /* when it runs: "every stage", "HLSL stages, parameters packed, preshaders on"... */
/* A value outside shader code (a state value, a selector's index) as IR, by hfx_ir_build's rules:
 * names are a state's named values (names, may be NULL), constants' initialisers, or the
 * parameters param_of finds (NULL: none). NULL, nothing reported, when it is no such value. */
typedef struct ir_value_src {
    const struct hfx_state_info *names;
    uint32_t (*param_of)(void *data, const hfx_expr *e);
    void *data;
} ir_value_src;
ir_expr *hfx_ir_build_value(ir_ctx *c, const hfx_expr *e, const ir_value_src *src);
/* Folds *slot as fxc folds a value: hfx_ir_pass_fold's operators and conversions, and intrinsics. */
void hfx_ir_fold_value(ir_ctx *c, ir_expr **slot);

/* Passes (one file each in lower/). */
void hfx_ir_pass_specialise(ir_ctx *c, ir_shader *sh);
void hfx_ir_pass_intrinsics(ir_ctx *c, ir_shader *sh);
void hfx_ir_pass_arrays(ir_ctx *c, ir_shader *sh);      /* float a[2][3] is float a[6] */
void hfx_ir_pass_lvalues(ir_ctx *c, ir_shader *sh);     /* m._11_22 = v: one target per component */
void hfx_ir_pass_fold(ir_ctx *c, ir_shader *sh);
void hfx_ir_pass_calls(ir_ctx *c, ir_shader *sh);       /* copies of callees with constant arguments bound */
void hfx_ir_pass_dce(ir_ctx *c, ir_shader *sh);
void hfx_ir_pass_once(ir_ctx *c, ir_shader *sh);       /* operands a lowering reads twice computed once; pow's products */
void hfx_ir_pass_flatten(ir_ctx *c, ir_shader *sh);    /* if (c) x = a; else x = b; as x = c ? a : b (small, pure) */
void hfx_ir_pass_distances(ir_ctx *c, ir_shader *sh);  /* distance(P, L) beside L - P: length(L - P), sharing it */
void hfx_ir_pass_globals(ir_ctx *c, ir_shader *sh);
void hfx_ir_pass_licm(ir_ctx *c, ir_shader *sh);       /* loop-invariant work to locals before the loop */
void hfx_ir_pass_ranges(ir_ctx *c, ir_shader *sh);     /* array reads a loop counter keeps in range */
void hfx_ir_pass_registers(ir_ctx *c, ir_shader *sh); /* register(cN) reservations of what the stage reads: X4500, X4509 */
int hfx_ir_pass_check(ir_ctx *c, ir_shader *sh);   /* target limits: reports what GLSL cannot express */
int hfx_ir_check_model(ir_ctx *c, ir_shader *sh);
int hfx_ir_loop_trips(const ir_stmt *s, const ir_var **counter, double *start, double *step); /* model.c */
void hfx_ir_pass_samplers(ir_ctx *c, ir_shader *sh);
/* Element k of the sampler array parameter d, as its own sampler (one per element; ir.c). */
ir_var *hfx_ir_sampler_element(ir_ctx *c, ir_shader *sh, const hfx_decl *d, uint32_t k);  /* model.c, run by check: semantics (X4502) and [unroll] loops (X3511) the profile refuses */
void hfx_ir_pass_uses(ir_ctx *c, ir_shader *sh);
void hfx_ir_pass_preshade(ir_ctx *c, ir_shader *sh);    /* uniform-only work to preshaders (when packing) */
void hfx_ir_pass_forward(ir_ctx *c, ir_shader *sh);     /* single-use locals forward, mul chains regrouped (readies preshade) */
void hfx_ir_pass_sums(ir_ctx *c, ir_shader *sh);        /* a loop's sum of parameter-only terms, added once before it (readies preshade) */
void hfx_ir_pass_factors(ir_ctx *c, ir_shader *sh);     /* vector products: parameters, then scalars, then vectors (readies preshade) */
/* Registers a stage may take for parameters and preshaders together (preshade.c): two stages
 * then always fit a program's 256. */
enum { IR_STAGE_REGS = 128 };
uint32_t hfx_ir_stage_regs(const ir_ctx *c, const ir_shader *sh); /* registers its parameters and preshaders take (packed) */
/* Derived varyings (lower/varyings.c), for a program's pair of lowered stages: the vertex outputs
 * the pixel stage computes from another output and parameters instead. When there are some,
 * *vs and *ps become copies that do so (the stages given stay as they were: programs share them)
 * and *derived lists their semantics (arena). pack: parameters are packed (registers are
 * counted). Returns how many. */
uint32_t hfx_ir_pass_varyings(ir_ctx *c, ir_shader **vs, ir_shader **ps, bool pack, const char ***derived);

/* Preshaders' pieces (pre_code.c). */
bool hfx_ir_pre_node(const ir_ctx *c, const ir_expr *e);   /* a preshader computes e from arguments it computes */
bool hfx_ir_pre_only(const ir_ctx *c, const ir_expr *e);  /* e reads parameters and constants alone (every node hfx_ir_pre_node) */
bool hfx_ir_pre_work(const ir_expr *e);                    /* e computes (not only moves components) */
uint32_t *hfx_ir_pre_code(ir_ctx *c, const ir_expr *e, uint32_t *words); /* validated eval_code (arena), or NULL */
/* The same for a state value (integer / and % too); clamp > 0: then a table 0 .. clamp - 1 that
 * clamps it into an array of clamp entries (a selector: `PixelShader = (Shaders[i]);`). */
uint32_t *hfx_ir_value_code(ir_ctx *c, const ir_expr *e, uint32_t clamp, uint32_t *words);
const char *hfx_ir_pre_text(ir_ctx *c, const ir_expr *e); /* e as HLSL, for the GLSL's comment (arena) */

/* Constructors shared by the passes (ir.c). */
ir_expr *hfx_ir_new_expr(ir_ctx *c, ir_expr_kind k, const hfx_type *ty, hfx_loc loc, uint32_t n);
ir_expr *hfx_ir_new_binary(ir_ctx *c, hfx_op op, const hfx_type *ty, ir_expr *a, ir_expr *b); /* a op b, at a's place */
ir_expr *hfx_ir_new_convert(ir_ctx *c, const hfx_type *ty, ir_expr *x);                    /* (ty)x: a splat, a cast */
ir_stmt *hfx_ir_new_stmt(ir_ctx *c, ir_stmt_kind k, hfx_loc loc);                          /* an empty statement of kind k */
ir_expr *hfx_ir_const_scalar(ir_ctx *c, const hfx_type *ty, double v, hfx_loc loc);
ir_expr *hfx_ir_clone_expr(ir_ctx *c, const ir_expr *e);
bool hfx_ir_is_const(const ir_expr *e);
bool hfx_ir_has_side_effects(const ir_expr *e);
bool hfx_ir_same_expr(const ir_expr *a, const ir_expr *b); /* the same tree: kinds, types, variables, constants */
ir_var *hfx_ir_lvalue_root(const ir_expr *e); /* the variable an l-value writes, or NULL */
/* The variables a statement may change (walk.c): what it assigns (through swizzles, fields,
 * indexes, out arguments) and declares; calls: it calls a user function (a private global may
 * change); unknown: some target's variable cannot be told, or memory ran out. */
typedef struct ir_var_set { const ir_var **vars; uint32_t count, cap; bool calls, unknown; } ir_var_set;
void hfx_ir_note_writes(ir_ctx *c, ir_stmt *s, ir_var_set *w);
void hfx_ir_var_set_add(ir_ctx *c, ir_var_set *s, const ir_var *v); /* NULL: unknown */
bool hfx_ir_var_set_has(const ir_var_set *s, const ir_var *v);
/* Statement `at` out of block b. */
void hfx_ir_remove_stmt(ir_stmt *b, uint32_t at);
/* Every read in s of a variable of `values` (an ir_expr each) becomes a copy of its value. */
void hfx_ir_put_values(ir_ctx *c, ir_stmt *s, const ir_var_map *values);
/* The n statements s into block b before its statement `at` (false: out of memory). */
bool hfx_ir_insert_stmts(ir_ctx *c, ir_stmt *b, uint32_t at, ir_stmt *const *s, uint32_t n);
/* Reads and writes of one variable in a statement (walk.c): a compound assignment's target
 * counts as both; with decls, a declaration of v counts as a write; slot: the last read. */
typedef struct ir_uses { const ir_var *v; bool decls; unsigned reads, writes; ir_expr **slot; } ir_uses;
void hfx_ir_count_uses(ir_uses *u, ir_stmt *s);
bool hfx_ir_has_jumps(const ir_stmt *s); /* a break, continue, return or discard somewhere in s */
/* The intrinsic computes from its arguments alone, wherever it runs: not sampling, derivatives,
 * clip, noise, or one with outputs. */
bool hfx_ir_intrinsic_movable(ir_intrin id);
bool hfx_ir_integer_division(const ir_expr *e); /* an integer / or %: may trap; a guard must stay its guard */
/* e writes its operand i: an assignment's target, ++ / --'s operand, a call's out argument,
 * sincos's / modf's / frexp's outputs. */
bool hfx_ir_writes_operand(const ir_expr *e, uint32_t i);
bool hfx_ir_const_truth(const ir_expr *e); /* the first component as a bool */
/* fxc expands pow(x, y) into multiplications: y a constant splat integer n whose squaring takes
 * few enough of them for a value of `comps` components (once.c). */
bool hfx_ir_pow_products(const ir_expr *y, unsigned comps, int *n);

/* Walks every expression slot in a statement tree (pre-order on statements, post-order on
 * expressions); fn may replace *slot. */
typedef void (*ir_expr_fn)(ir_ctx *c, ir_expr **slot, void *data);
void hfx_ir_walk_stmt_exprs(ir_ctx *c, ir_stmt *s, ir_expr_fn fn, void *data);
void hfx_ir_walk_expr(ir_ctx *c, ir_expr **slot, ir_expr_fn fn, void *data);
/* The same on each statement's own expression slots only (not their subexpressions). */
void hfx_ir_walk_stmt_roots(ir_ctx *c, ir_stmt *s, ir_expr_fn fn, void *data);

/* Intrinsic names (HLSL spelling) and lookup. */

/* A readable dump for golden tests (ir_dump.c). malloc'ed. */
char *hfx_ir_dump_shader(const ir_shader *sh);
char *hfx_ir_dump_func(const ir_func *f);

/* One semantic-carrying value of the entry's interface, with its access path from main's
 * locals (hfx_argN for parameters, hfx_ret for the return value). ir_iface.c */
enum { IR_LEAF_DEPTH = 4 };
typedef struct ir_leaf {
    const char *semantic;    /* canonical: "POSITION0", "TEXCOORD1", "COLOR0", "VPOS0" */
    const hfx_type *type;
    const char *path;        /* "hfx_arg0.Posicion" */
    hfx_loc loc;
    /* A matrix with a semantic takes one register per row (`float3x3 m : TEXCOORD4` is
     * TEXCOORD4..6, path m[0..2]); on the last row's leaf, the matrix's own path. A vertex
     * input's registers hold D3D9's columns (column_major packing): the GLSL transposes it. */
    const char *matrix_path;
    const hfx_type *matrix_type;
    bool flat;               /* nointerpolation: the first vertex's value, as D3D's flat shading */
    uint32_t mods;           /* its interpolation modifiers (MOD_CENTROID, MOD_NOPERSPECTIVE...) */
    /* Its place in IR terms (lower/varyings.c): the entry parameter it is part of (NULL: the
     * return value), then the struct fields to it; `indexed` when an array element or a matrix
     * row is on the way (or the fields are deeper than IR_LEAF_DEPTH). */
    ir_var *root;
    uint32_t fields[IR_LEAF_DEPTH]; uint32_t depth;
    bool indexed;
} ir_leaf;

/* The entry's inputs (outputs false) or outputs; reports X3502 for a value without a
 * semantic. Returns the count (arena array in *out), or -1 on error. */
int hfx_ir_entry_leaves(ir_ctx *c, const ir_func *entry, bool outputs, ir_leaf **out);
/* "TexCoord" -> "TEXCOORD0", "SV_Position" -> "POSITION0", "COLOR1" -> "COLOR1". Arena-owned. */
const char *hfx_ir_canonical_semantic(hfx_arena *a, const char *semantic);

/* A GLSL-legal spelling of an HLSL name: the name itself unless GLSL reserves it (or it starts
 * with gl_ or contains "__"), else "hfx_" + name. Arena-owned. */
const char *hfx_glsl_name(hfx_arena *arena, const char *name);

#endif
