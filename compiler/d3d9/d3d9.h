/* d3d9.h: Direct3D 9 shader bytecode (vs_1_1..vs_3_0, ps_1_1..ps_3_0) read into plain structs,
 * validated, printed as fxc's assembly listing, and turned into hfx's IR. One opcode table
 * (d3d9_ops.def) drives all of it. Everything lives in the caller's arena.
 *
 * Positions: bytecode has no lines, so a diagnostic's location is line 0 and column = the byte
 * offset, in the file, of the token at fault (`base` + offset in the blob):
 *     BasicEffect.fxb(0,1284): error X5002: ...
 * (hfx_diags prints line 0 without a caret.) The numbers are hfx's own X5xxx, fxc having none
 * for reading bytecode: X5000 truncated / malformed stream, X5001 bad version, X5002 opcode not
 * allowed in the model, X5003 bad operand / register, X5004 unbalanced flow control,
 * X5005 bad constant table, X5006 not supported by the translator. */
#ifndef HFX_D3D9_H
#define HFX_D3D9_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "base/arena.h"
#include "base/diag.h"
#include "base/sbuf.h"

enum {
    X_D3D9_TRUNCATED = 5000,   /* a length runs past the buffer, no END token */
    X_D3D9_VERSION = 5001,     /* not a vs/ps version token, or a model hfx does not read */
    X_D3D9_OPCODE = 5002,      /* unknown opcode, or one the model does not allow */
    X_D3D9_OPERAND = 5003,     /* operand count, register type or number, modifier */
    X_D3D9_FLOW = 5004,        /* if / loop / rep nesting does not balance */
    X_D3D9_CTAB = 5005,        /* the constant table points outside its comment */
    X_D3D9_UNSUPPORTED = 5006  /* valid bytecode the translator to IR does not handle */
};

/* Models as one byte: D3D9_SM(2, 1) is 2_x (vs_2_a, ps_2_a, ps_2_b all carry minor 1). */
#define D3D9_SM(major, minor) (((major) << 4) | (minor))

enum { /* d3d9_op_info.flags */
    D3D9_OPF_TEX = 1u << 0,     /* a texture instruction (counted as such in the slot summary) */
    D3D9_OPF_FLOW = 1u << 1,    /* flow control */
    D3D9_OPF_OPEN = 1u << 2,    /* opens a block (if, loop, rep) */
    D3D9_OPF_CLOSE = 1u << 3,   /* closes one (endif, endloop, endrep) */
    D3D9_OPF_DECL = 1u << 4,    /* declaration: no instruction slot (dcl, def*, label, phase) */
    D3D9_OPF_DEF4 = 1u << 5,    /* four literal words follow the destination (def, defi) */
    D3D9_OPF_DEF1 = 1u << 6,    /* one literal word follows (defb) */
    D3D9_OPF_COMPARE = 1u << 7, /* controls hold a comparison (if_gt, break_ne, setp_lt) */
    D3D9_OPF_SCALAR = 1u << 8,  /* sources take a replicate swizzle (rcp, rsq, exp, log, pow...) */
    D3D9_OPF_MATRIX = 1u << 9   /* m4x4 family: the second source is the first of N registers */
};

typedef enum d3d9_opcode {
#define D3D9_OP(id, name, token, dst, src, slots, vs0, vs1, ps0, ps1, flags) D3D9_##id = token,
#include "d3d9/d3d9_ops.def"
    D3D9_COMMENT = 0xfffe,
    D3D9_END = 0xffff
} d3d9_opcode;

typedef struct d3d9_op_info {
    const char *name;
    uint16_t token;
    uint8_t dst, src;               /* operand counts (SM2+ forms; see hfx_d3d9_operand_counts) */
    uint8_t slots;                  /* instruction slots fxc counts */
    uint8_t vs_first, vs_last;      /* D3D9_SM; 0: never in a vertex shader */
    uint8_t ps_first, ps_last;      /* D3D9_SM; 0: never in a pixel shader */
    uint32_t flags;                 /* D3D9_OPF_* */
} d3d9_op_info;

/* The table row of an opcode token; NULL for an unknown opcode. */
const d3d9_op_info *hfx_d3d9_op_find(uint32_t opcode);

typedef enum d3d9_stage { D3D9_VS, D3D9_PS } d3d9_stage;

/* Register types, as the token encodes them (D3DSHADER_PARAM_REGISTER_TYPE). */
typedef enum d3d9_regtype {
    D3D9_REG_TEMP = 0, D3D9_REG_INPUT = 1, D3D9_REG_CONST = 2,
    D3D9_REG_ADDR = 3,        /* a0 in a vertex shader; t (texture) in a pixel shader */
    D3D9_REG_RASTOUT = 4,     /* oPos, oFog, oPts */
    D3D9_REG_ATTROUT = 5,     /* oD0, oD1 */
    D3D9_REG_OUTPUT = 6,      /* oT below vs_3_0, o in vs_3_0 */
    D3D9_REG_CONSTINT = 7, D3D9_REG_COLOROUT = 8, D3D9_REG_DEPTHOUT = 9, D3D9_REG_SAMPLER = 10,
    D3D9_REG_CONST2 = 11, D3D9_REG_CONST3 = 12, D3D9_REG_CONST4 = 13,
    D3D9_REG_CONSTBOOL = 14, D3D9_REG_LOOP = 15, D3D9_REG_TEMPFLOAT16 = 16,
    D3D9_REG_MISC = 17,       /* vPos (0), vFace (1) */
    D3D9_REG_LABEL = 18, D3D9_REG_PREDICATE = 19
} d3d9_regtype;

enum { /* d3d9_dst.mods */
    D3D9_DMOD_SAT = 1, D3D9_DMOD_PP = 2, D3D9_DMOD_CENTROID = 4
};

typedef enum d3d9_srcmod { /* D3DSHADER_PARAM_SRCMOD_TYPE */
    D3D9_SMOD_NONE, D3D9_SMOD_NEG, D3D9_SMOD_BIAS, D3D9_SMOD_BIASNEG, D3D9_SMOD_SIGN,
    D3D9_SMOD_SIGNNEG, D3D9_SMOD_COMP, D3D9_SMOD_X2, D3D9_SMOD_X2NEG, D3D9_SMOD_DZ,
    D3D9_SMOD_DW, D3D9_SMOD_ABS, D3D9_SMOD_ABSNEG, D3D9_SMOD_NOT
} d3d9_srcmod;

typedef struct d3d9_src {
    uint8_t type;             /* d3d9_regtype */
    uint8_t mod;              /* d3d9_srcmod */
    uint8_t swizzle;          /* 2 bits per component, x in bits 0-1: 0xe4 = .xyzw */
    bool relative;            /* indexed: c[a0.x + n], v[aL + n], ... */
    uint16_t num;             /* register number (0..2047; CONST2..4 folded into CONST + 2048k) */
    uint8_t rel_type;         /* relative: the index register's type (ADDR or LOOP) */
    uint8_t rel_comp;         /* relative: its component 0..3 */
    uint16_t rel_num;         /* relative: its number */
} d3d9_src;

typedef struct d3d9_dst {
    uint8_t type;             /* d3d9_regtype */
    uint8_t mask;             /* write mask, x = bit 0 */
    uint8_t mods;             /* D3D9_DMOD_* */
    int8_t shift;             /* ps_1_x result shift: 1 = _x2, 2 = _x4, 3 = _x8, -1 = _d2 ... */
    bool relative;            /* vs_3_0 o[aL + n] */
    uint16_t num;
    uint8_t rel_type, rel_comp;
    uint16_t rel_num;
} d3d9_dst;

typedef struct d3d9_inst {
    uint16_t op;              /* d3d9_opcode */
    uint8_t control;          /* instruction-specific bits 16-23: comparison, texld's project / bias */
    bool coissue;             /* ps_1_x '+' pairing */
    bool predicated;          /* (p0.x) prefix: `pred` holds the predicate register */
    bool has_dst;
    uint8_t src_count;
    uint32_t offset;          /* byte offset of the instruction token in the blob */
    d3d9_src pred;
    d3d9_dst dst;
    d3d9_src src[4];
    union { float f[4]; int32_t i[4]; uint32_t u[4]; } value; /* def: floats; defi: ints; defb: u[0] */
    uint8_t usage, usage_index; /* dcl of v / o / t registers (D3DDECLUSAGE: 0 position, 5 texcoord, 10 color...) */
    uint8_t sampler_type;     /* dcl of s: 1 1D (hfx's reading), 2 2D, 3 cube, 4 volume */
} d3d9_inst;

typedef enum d3d9_regset { D3D9_RS_BOOL, D3D9_RS_INT4, D3D9_RS_FLOAT4, D3D9_RS_SAMPLER } d3d9_regset;

/* One constant of the CTAB comment (D3DXSHADER_CONSTANTINFO + its type info). Struct members
 * are not split: the constant covers its registers whole. */
typedef struct d3d9_constant {
    const char *name;
    uint8_t regset;           /* d3d9_regset */
    uint16_t reg, count;      /* first register and register count */
    uint16_t cls, type;       /* D3DXPARAMETER_CLASS (0 scalar, 1 vector, 2 rows, 3 columns,
                               * 4 object, 5 struct), D3DXPARAMETER_TYPE (0 void, 1 bool, 2 int,
                               * 3 float, 4 string, 5 texture.., 10 sampler, 11 1D, 12 2D, 13 3D, 14 cube) */
    uint16_t rows, cols, elements, members;
    const uint32_t *default_value; /* words as in the table (NULL: none), default_words long */
    uint32_t default_words;
} d3d9_constant;

/* A comment block kept raw (CTAB is also parsed into `constants`; PRES / CLIT / FXLC for the
 * effect reader's preshaders). */
typedef struct d3d9_comment {
    uint32_t fourcc;          /* its first word ('CTAB' = 0x42415443), 0 when empty */
    const uint32_t *words;    /* all its words, the fourcc included, host order */
    uint32_t word_count;
    uint32_t offset;          /* byte offset of the comment token in the blob */
} d3d9_comment;

/* Registers a preshader computes (fx_2_0 keeps a shader's PRES block, an FXLVM program, in a
 * comment: the effect reader validates it, translates it into a common/eval_code program and
 * lists its outputs here before hfx_codegen_d3d9_program). The shader reads c[reg .. reg +
 * count - 1] (or b[reg], i[reg]: fxc's ob# / oi# outputs, for `if b#` and `loop i#`) from them; the program's hfx_fx_preshader entries carry the code to the runtime,
 * which runs it at Apply as for a compiled effect (needs HFXC_PACK_UNIFORMS). */
typedef enum d3d9_pre_file { D3D9_PRE_C, D3D9_PRE_B, D3D9_PRE_I } d3d9_pre_file;
typedef struct d3d9_preshader_out {
    uint32_t reg, count;      /* first register, how many (1..4; 1 for b and i registers) */
    const uint32_t *code;     /* eval_code words computing count * 4 floats, register after register */
    uint32_t words;
    const char *text;         /* what it computes, for the GLSL comment; NULL: "c<reg>" */
    d3d9_pre_file file;       /* the registers it sets: c# (floats), b# (x != 0), i# (each truncated) */
} d3d9_preshader_out;

typedef struct d3d9_shader {
    d3d9_stage stage;
    uint8_t model;            /* D3D9_SM(major, minor) */
    uint32_t version;         /* the raw version token */
    d3d9_inst *insts; uint32_t inst_count;
    d3d9_comment *comments; uint32_t comment_count;
    d3d9_constant *constants; uint32_t constant_count;
    const char *creator;      /* CTAB's creator string ("Microsoft (R) HLSL Shader Compiler ...") */
    const char *target;       /* CTAB's target string ("ps_2_0"); NULL when the CTAB has none */
    const char *file;         /* file name for diagnostics (from the decode input) */
    uint32_t file_index, base; /* hfx_diags file and the blob's byte offset in it */
    const d3d9_preshader_out *pres; uint32_t pre_count; /* set by the effect reader (NULL, 0: none) */
} d3d9_shader;

/* What to decode: `size` bytes at `data` (any alignment; little-endian words), which sit at
 * byte offset `base` of diags file `file` (positions in errors count from the file's start). */
typedef struct d3d9_input {
    const void *data;
    uint32_t size;
    uint32_t file;            /* index into diags->files */
    uint32_t base;
} d3d9_input;

/* Decodes and validates a shader: version, every instruction against the opcode table (allowed in
 * the model, operand counts, register types and numbers for the model and stage, lengths inside
 * the buffer, flow-control nesting), comments (CTAB parsed), END present. Returns the shader, or
 * NULL with every error found reported in diags (located as above). Never reads past `size`. */
d3d9_shader *hfx_d3d9_decode(hfx_arena *arena, hfx_diags *diags, const d3d9_input *in);

/* Appends fxc's assembly listing of s to out: the CTAB header (`// Parameters:`,
 * `// Registers:`), the model line, one line per instruction as fxc prints it, and
 * `// approximately N instruction slots used` (with fxc's texture / arithmetic split for ps). */
void hfx_d3d9_disassemble(const d3d9_shader *s, sbuf *out);

/* For `hfxc --disassemble X.vso` (a raw shader blob): decodes the file's bytes and appends the
 * listing; returns 0, or -1 with located errors in diags. */
int hfx_d3d9_disassemble_blob(hfx_arena *arena, hfx_diags *diags, const d3d9_input *in, sbuf *out);

/* Whether `size` bytes start with a vs / ps version token hfx reads (vs_1_1..3_0, ps_1_1..3_0):
 * how `hfxc --disassemble` tells a raw shader blob (.vso, .pso, fxc /T ps_2_0) from an effect. */
bool hfx_d3d9_is_shader(const void *data, size_t size);

/* Read ports (Microsoft's "Registers" table of each model): how many different registers of a
 * type one instruction may read. SM2 / SM3: r 3, every other type 1 (vPos and vFace are one each);
 * ps_1_1..1_3: c 2, v 2, r 2, t 2 (1_1) or 3; ps_1_4: c 2, v 2, r 3, t 1. */
unsigned hfx_d3d9_read_ports(d3d9_stage stage, uint8_t model, unsigned type);

/* Whether source k of `in` takes a read port: SM2's sincos reads its two macro constants
 * (D3DSINCOSCONST1 / 2, fxc's c registers beside the angle) apart from the ports. */
bool hfx_d3d9_port_source(const d3d9_inst *in, uint8_t model, unsigned k);

/* Whether two sources read the same register (type, number, and the index of a relative one). */
bool hfx_d3d9_same_register(const d3d9_src *a, const d3d9_src *b);
/* How many of the instruction's sources are read as one component (D3D9_OPF_SCALAR: all of pow's,
 * sincos's first), which from SM2 on must carry a replicate swizzle; 0 for other instructions. */
unsigned hfx_d3d9_scalar_sources(const d3d9_inst *in);

/* The first register type `in` reads more different registers of than the model's read ports
 * allow, or -1; *count: how many it reads. The reader refuses such an instruction (X5003), as
 * D3D9's runtime does; the bytecode writer copies one of them into a temporary first. */
int hfx_d3d9_port_excess(d3d9_stage stage, uint8_t model, const d3d9_inst *in, unsigned *count);

/* Instruction slots fxc counts for s (its listing's "approximately N"): arithmetic and texture. */
void hfx_d3d9_count_slots(const d3d9_shader *s, uint32_t *arith, uint32_t *tex);

/* The model's name: "vs_2_0", "ps_2_x", "ps_1_4"... (static text). */
const char *hfx_d3d9_model_name(d3d9_stage stage, uint8_t model);

/* The translator to hfx's IR (d3d9_ir.c): one stage, with D3D9's register semantics (c registers
 * read from the effect's packed hfx_c array at the CTAB's register, r as vec4 locals, v / t / o
 * registers as the entry's inputs and outputs by semantic, samplers by the CTAB's names).
 * packed: the program packs parameters into hfx_c (HFXC_PACK_UNIFORMS), which s->pres needs.
 * Returns NULL with located errors (X5006 for what it does not translate). */
struct ir_ctx;
struct ir_shader;
struct ir_shader *hfx_d3d9_to_ir(struct ir_ctx *c, const d3d9_shader *s, bool packed);

#endif
