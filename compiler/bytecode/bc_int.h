/* bc_int.h: what the files of compiler/bytecode/ share. bc_emit.c: instructions as records,
 * registers, constants, the CTAB and the token stream; bc_gen.c: the entry's interface,
 * variables and statements (flattened, unrolled); bc_expr.c: expressions; bc_intrin.c: the
 * intrinsics, one table. */
#ifndef HFX_BC_INT_H
#define HFX_BC_INT_H

#include <stdarg.h>
#include <string.h>

#include "bytecode/bytecode.h"
#include "d3d9/d3d9.h"

enum { BC_REG_NONE = 0xff }; /* an input the model has no register for: an error when read */
/* BC_MAX_TEMPS: the generator's virtual temporaries (any number it needs, up to the token's
 * 11-bit register number); the allocator packs them into the model's few (hfx_bc_temp_limit). */
enum { BC_MAX_TEMPS = 2048, BC_MAX_CONSTS = 256, BC_MAX_VARS = 4096 };
/* fxc's codes where it has one (X3511 loops it cannot unroll, X4505 temporaries, X5608 / X5609
 * instruction slots); X5006 what the writer does not handle, X5610 constant registers (hfx's own). */
enum { X_BC_UNSUPPORTED = 5006, X_BC_TEMPS = 4505, X_BC_CONSTS = 5610, X_BC_LOOP = 3511 };

/* One operand of up to four components: register, the register component each value component
 * reads, a source modifier; `own` when it is a temporary the reader frees. */
typedef struct bc_val {
    uint8_t type, n, mod;
    uint16_t num;
    uint8_t sw[4];
    bool own;
    bool rel;                 /* c[a0.x + num] */
    bool rel_aL;              /* with rel: c[aL + num] */
} bc_val;

/* A value of any type: slots of up to four components (matrices one per row, or one per column
 * when `cols`; arrays and structs flattened in order). */
typedef struct bc_obj {
    bc_val *slot;
    uint32_t count;
    bool cols;
} bc_obj;

/* A variable's registers; `owned`: the slots whose temporaries its scope's end frees (an inlined
 * callee's parameter may borrow its argument's registers). */
typedef struct bc_binding { const ir_var *var; bc_obj obj; uint64_t owned; double konst; bool is_const; } bc_binding;

/* A CTAB constant: a parameter (or sampler) the shader reads, its register set and registers. */
typedef struct bc_ctab { const char *name; const hfx_type *type; uint8_t set; uint16_t reg, count; bool cols; } bc_ctab;

typedef struct bc_def { float v[4]; uint8_t used; uint16_t num; } bc_def;

typedef struct bc_gen {
    ir_ctx *c;
    const ir_shader *sh;
    d3d9_stage stage;
    uint8_t model;            /* D3D9_SM */
    const char *profile;
    bool ps2;                 /* ps_2_x: t and v inputs */
    hfx_loc loc;
    d3d9_inst *insts; uint32_t inst_count, inst_cap;
    uint8_t *temps_used;      /* per virtual temporary: held by a value (BC_MAX_TEMPS of them) */
    unsigned temp_space;      /* the numbers hfx_bc_temp cycles through: 32, doubled when all are held */
    unsigned next_temp;       /* where hfx_bc_temp looks first */
    uint8_t cused[BC_MAX_CONSTS];  /* c registers taken by parameters or defs */
    uint32_t max_consts;
    d3d9_inst *dcls; uint32_t dcl_count, dcl_cap; /* dcl instructions, written before the code */
    bool broke;               /* a break ended the loop being unrolled */
    bc_def *defs; uint32_t def_count, def_cap;
    bc_ctab *ctab; uint32_t ctab_count, ctab_cap;
    bc_binding *binds; uint32_t bind_count, bind_cap;
    bc_obj *ret;              /* the current function's return value's registers */
    bc_obj *capture;          /* or: a straight callee's returned value, taken as it is */
    uint32_t capture_mark;    /* the callee's first binding */
    bc_val cond;              /* flattening: the condition the current code runs under (n == 0: always) */
    bc_val done;              /* flattening: 1 where the current function has returned (n == 0: nowhere yet) */
    int last_fresh;           /* instruction that wrote a fresh temporary whole, or -1 */
    uint32_t inputs, outputs, samplers;
    uint32_t depth;           /* inlined calls, against recursion */
    bool failed;
    /* flow control (bc_flow.c) */
    struct bc_region *loop_region; /* the innermost real loop's pinned variables (a break syncs them) */
    uint32_t loop_fn_depth;   /* g->depth of that loop: a return there cannot be flattened */
    const ir_var *aL_var;     /* the counter aL follows: its arrays read as c[aL + n] */
    uint32_t aL_per;          /* registers aL steps per element */
    uint32_t loop_nest, if_nest;
    struct bc_defi { int32_t v[4]; uint16_t num; } *defis; uint32_t defi_count, defi_cap;
    uint16_t next_int;        /* i registers taken */
    bool has_flow;            /* the code has if / loop / rep: liveness follows the flow */
} bc_gen;

/* --- bc_emit.c --- */
void hfx_bc_fail(bc_gen *g, hfx_loc loc, unsigned code, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
unsigned hfx_bc_temp_limit(const bc_gen *g);                  /* the model's r registers */
int hfx_bc_temp(bc_gen *g);                                    /* a free r register, or -1 (error reported) */
void hfx_bc_release(bc_gen *g, bc_val v);                      /* frees v's temporary when it owns one */
void hfx_bc_release_obj(bc_gen *g, bc_obj o);
bc_val hfx_bc_reg(uint8_t type, uint16_t num, unsigned n);     /* .xyzw-like identity read of n components */
bc_val hfx_bc_scalar_of(bc_val v, unsigned i);                 /* component i replicated */
bc_val hfx_bc_neg(bc_val v);
d3d9_inst *hfx_bc_emit(bc_gen *g, uint16_t op, const bc_val *dst, unsigned mask, const bc_val *src, unsigned n);
bc_val hfx_bc_op(bc_gen *g, uint16_t op, unsigned n, const bc_val *src, unsigned count); /* fresh temp = op(src) */
bc_val hfx_bc_op1(bc_gen *g, uint16_t op, unsigned n, bc_val a);
bc_val hfx_bc_op2(bc_gen *g, uint16_t op, unsigned n, bc_val a, bc_val b);
bc_val hfx_bc_op3(bc_gen *g, uint16_t op, unsigned n, bc_val a, bc_val b, bc_val c);
bc_val hfx_bc_const(bc_gen *g, const float *v, unsigned n);    /* a def register's components */
bc_val hfx_bc_constf(bc_gen *g, float v);
bool hfx_bc_literal_fits(const bc_gen *g, const float *v, unsigned n); /* hfx_bc_const(v, n) cannot run out of registers */
bool hfx_bc_can_sat(const bc_gen *g);                         /* the _sat modifier: pixel shaders and vs_3_0 */
bool hfx_bc_is_zero(const bc_gen *g, const bc_val *v);        /* a def register's zeros */
/* Writes value v into the components of target t (t.sw: the register component of each). */
void hfx_bc_store(bc_gen *g, bc_val t, bc_val v, bool sat);
bool hfx_bc_reserve_consts(bc_gen *g, uint16_t first, uint16_t count);
const uint32_t *hfx_bc_encode(bc_gen *g, uint32_t *count);

/* --- bc_gen.c --- */
bc_binding *hfx_bc_bind(bc_gen *g, const ir_var *v);           /* the variable's storage (made on first use), or NULL */
uint32_t hfx_bc_slots(const hfx_type *t, bool cols);
unsigned hfx_bc_slot_width(const hfx_type *t, bool cols, uint32_t k); /* components of slot k */
bc_obj hfx_bc_alloc_obj(bc_gen *g, const hfx_type *t);         /* temporaries for a value of type t (rows) */
void hfx_bc_assign(bc_gen *g, bc_obj dst, bc_obj src, const hfx_type *t, bool sat);
void hfx_bc_call(bc_gen *g, const ir_expr *e, bc_obj *out);
void hfx_bc_bind_globals(bc_gen *g);                          /* parameters' c registers, samplers' s, the CTAB */
void hfx_bc_init_privates(bc_gen *g);                         /* static globals, initialised at the start */
bc_obj hfx_bc_obj_inputs(bc_gen *g, const ir_leaf *l, int n, const ir_var *p, const hfx_type *t);  /* p's input registers (dcl'd) */
bc_obj hfx_bc_obj_outputs(bc_gen *g, const ir_leaf *l, int n, const ir_var *p, const hfx_type *t); /* p's (NULL: the return's) outputs */
void hfx_bc_bind_entry(bc_gen *g, const ir_var *p, bc_obj o, bool owned);
bool hfx_bc_straight_return(const ir_stmt *body);             /* the body returns only at its end */
void hfx_bc_gen_body(bc_gen *g, const ir_stmt *body);
bool hfx_bc_writes_param(bc_gen *g, const ir_func *f, const ir_var *p); /* f's body writes its parameter p */

/* --- bc_expr.c --- */
bc_obj hfx_bc_expr(bc_gen *g, const ir_expr *e);
bool hfx_bc_immutable(const bc_gen *g, const bc_val *v);     /* c / v / t registers nothing writes */
/* lhs = src; owned: the slots of src whose temporaries it may take (the rest are copied or viewed). */
void hfx_bc_assign_expr(bc_gen *g, const ir_expr *lhs, bc_obj src, uint64_t owned);
void hfx_bc_init_binding(bc_gen *g, bc_binding *b, bc_obj src); /* a new variable's value: views, adopted temporaries or copies */
bc_val hfx_bc_expr1(bc_gen *g, const ir_expr *e);              /* a scalar or vector */
bc_val hfx_bc_own(bc_gen *g, bc_val v);                        /* v in a temporary of its own */
bc_val hfx_bc_matrix_elem(bc_obj m, unsigned row, unsigned col);
bc_val hfx_bc_matrix_row(bc_gen *g, bc_obj m, const hfx_type *t, unsigned row);
bc_val hfx_bc_not(bc_gen *g, bc_val a);
bc_val hfx_bc_select(bc_gen *g, bc_val c, bc_val a, bc_val b);  /* c (0 / 1) ? a : b */
bool hfx_bc_try_const(bc_gen *g, const ir_expr *e, double *out);
bc_val hfx_bc_per_comp(bc_gen *g, uint16_t op, bc_val a, const bc_val *b); /* op on each component (rcp, rsq, exp, log, pow) */
bc_val hfx_bc_trunc(bc_gen *g, bc_val x);                     /* toward zero: floor or ceil by the sign */
bc_val hfx_bc_gather(bc_gen *g, const bc_val *parts, unsigned n); /* scalars into a fresh temporary */

/* The binding slots an l-value names: a variable, its fields, constant indexes, a swizzle of one
 * slot (comps, n; n == 0: whole slots). */
typedef struct bc_lval { bc_binding *b; uint32_t first, count; uint8_t comps[4], n; } bc_lval;
bool hfx_bc_lval(bc_gen *g, const ir_expr *e, bc_lval *l);    /* false when e is none of those */
void hfx_bc_own_slot(bc_gen *g, bc_binding *b, uint32_t k, bool keep); /* slot k writable (kept when keep) */
bc_val hfx_bc_binary(bc_gen *g, hfx_op op, bc_val a, bc_val b, const hfx_type *t);

/* --- bc_aggregate.c --- */
bc_obj hfx_bc_construct_aggregate(bc_gen *g, const ir_expr *e); /* a struct or array from its members */
bc_obj hfx_bc_reshape(bc_gen *g, const ir_expr *e);           /* a cast between shapes: components in order */
/* o[idx] (o of type t: vector, matrix or array) for an index the compiler cannot fold. */
bc_obj hfx_bc_index_select(bc_gen *g, bc_obj o, const hfx_type *t, const ir_expr *idx);
bool hfx_bc_addressable(const bc_gen *g, bc_obj o);           /* c registers in a row a vertex shader's a0 can index */
bool hfx_bc_has_matrix(const hfx_type *t);                    /* t is or holds a matrix */
/* dst = src for a struct or array holding matrices, when the two layouts differ: member by member. */
void hfx_bc_assign_members(bc_gen *g, bc_obj dst, bc_obj src, const hfx_type *t, bool sat);
bool hfx_bc_assign_dynamic(bc_gen *g, const ir_expr *e, bc_obj *out); /* false: e's target has no computed index */

/* --- bc_flow.c --- */
/* A loop the unroller cannot unroll (its condition is not a constant), written as a loop with
 * loop / rep / break (SM3, vs_2_x), or false when the caller should unroll it. init already ran. */
bool hfx_bc_flow_loop(bc_gen *g, const ir_stmt *s);
bool hfx_bc_flow_if(bc_gen *g, const ir_stmt *s);           /* an if inside a real loop that breaks: if_comp / endif */
void hfx_bc_flow_break(bc_gen *g, const ir_stmt *s);
bool hfx_bc_loop_index(bc_gen *g, bc_obj o, const ir_expr *idx, uint32_t per, bc_obj *out); /* c[aL + n] */

/* --- bc_peep.c --- */
void hfx_bc_sink(bc_gen *g);                                 /* copies folded into the instructions they copy */
void hfx_bc_dead_code(bc_gen *g);                            /* instructions whose results nothing reads */

/* --- bc_alloc.c --- */
/* Per instruction, the components of each temporary read later on some path (NULL: out of
 * memory): live[i * *span + r]; dead (optional, one per instruction): writes nothing reads,
 * which read nothing. */
uint8_t *hfx_bc_liveness(bc_gen *g, bool *dead, uint32_t *span);
uint32_t hfx_bc_temp_span(const bc_gen *g);                  /* 1 + the highest temporary number the code uses */
unsigned hfx_bc_read_comps(const bc_gen *g, const d3d9_inst *in, unsigned k); /* components source k reads */
unsigned hfx_bc_read_positions(const bc_gen *g, const d3d9_inst *in, unsigned k); /* swizzle positions it reads */
bool hfx_bc_droppable(const d3d9_inst *in);                  /* only writes a temporary */
uint32_t hfx_bc_renumber(bc_gen *g);                         /* temporaries packed by component; how many */
void hfx_bc_prune_constants(bc_gen *g);                      /* parameters and defs nothing reads */
/* A swizzle's unread positions as src_of leaves them (dot: repeating the last read one). */
uint8_t hfx_bc_tidy(uint8_t sw, unsigned positions, bool dot);

/* --- bc_cse.c --- */
bool hfx_bc_cse(bc_gen *g);                                   /* values computed twice read once; true: code changed */

/* --- bc_vec.c --- */
void hfx_bc_vectorize(bc_gen *g);                             /* one op per component of a register: one op */

/* --- bc_mad.c --- */
void hfx_bc_fuse_mad(bc_gen *g);                              /* a mul's temporary added once: a mad */
void hfx_bc_nrm_into_adds(bc_gen *g);                         /* a nrm only adds read: dp3 / rsq and mads */

/* --- bc_ports.c --- */
/* Registers an instruction reads over the model's read ports copied into temporaries before it;
 * temps: the renumbered temporaries' count. Returns the count after. */
uint32_t hfx_bc_read_ports(bc_gen *g, uint32_t temps);
void hfx_bc_gather_literals(bc_gen *g);                       /* literals one instruction reads in one def */

/* --- bc_sched.c --- */
/* The temporaries packed (hfx_bc_renumber); when they are more than the model's, the code is
 * first reordered so that each value is computed just before it is read. How many. */
uint32_t hfx_bc_allocate(bc_gen *g);

/* --- bc_fold.c --- */
void hfx_bc_fold(bc_gen *g);                                 /* constants followed component by component */
void hfx_bc_replicate_scalars(bc_gen *g);                    /* scalar instructions read replicate swizzles */
void hfx_bc_merge_mova(bc_gen *g);                           /* bones' indices in one mova a0.xyzw */

/* --- bc_intrin.c --- */
typedef bc_val (*bc_intrin_fn)(bc_gen *g, const ir_expr *e, bc_val *a);
/* A row of the intrinsics' table: the function writing it; ps_first: the pixel model it needs
 * (nonzero: pixel shaders only). */
typedef struct bc_intrin_row { int id; bc_intrin_fn fn; uint8_t ps_first; } bc_intrin_row;
bc_obj hfx_bc_intrinsic(bc_gen *g, const ir_expr *e);
bc_val hfx_bc_cross(bc_gen *g, bc_val a, bc_val b);
bc_val hfx_bc_dot(bc_gen *g, bc_val a, bc_val b);
bc_val hfx_bc_floor(bc_gen *g, bc_val x);
bc_val hfx_bc_fmod(bc_gen *g, bc_val a, bc_val b);            /* fxc's: frc(|a / b|) with a / b's sign, times b */

/* --- bc_intrin_math.c --- */
const bc_intrin_row *hfx_bc_math_row(int intrin);            /* the expansions of values, or NULL */
bool hfx_bc_math_obj(bc_gen *g, const ir_expr *e, bc_obj *out); /* modf, frexp, determinant, bit casts */

#endif
