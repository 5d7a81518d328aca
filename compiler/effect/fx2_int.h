/* fx2_int.h: what the fx_2_0 reader's files (fx2_read.c, fx2_states.c, fxlvm.c, fx2_list.c)
 * and its writer's (fx2_write.c, fxlvm_write.c) share. Not a contract: nothing else includes
 * it. The layout is in docs/fx2.md. */
#ifndef HFX_FX2_INT_H
#define HFX_FX2_INT_H

#include <stdbool.h>

#include "d3d9/d3d9.h"
#include "effect/codegen.h"
#include "effect/fx2.h"
#include "bytes.h"
#include "eval.h"

/* An fx_2_0 container's first word. */
enum { FX2_MAGIC = 0xFEFF0901u };

/* D3DXPARAMETER_CLASS and D3DXPARAMETER_TYPE as the file stores them. */
enum { PC_SCALAR, PC_VECTOR, PC_MATRIX_ROWS, PC_MATRIX_COLUMNS, PC_OBJECT, PC_STRUCT, PC_COUNT };
enum {
    PT_VOID, PT_BOOL, PT_INT, PT_FLOAT, PT_STRING, PT_TEXTURE, PT_TEXTURE1D, PT_TEXTURE2D, PT_TEXTURE3D,
    PT_TEXTURECUBE, PT_SAMPLER, PT_SAMPLER1D, PT_SAMPLER2D, PT_SAMPLER3D, PT_SAMPLERCUBE, PT_PIXELSHADER,
    PT_VERTEXSHADER, PT_COUNT
};

/* The state operations of fx_2_0 (D3DX's table order): the ones the reader treats apart. */
enum { OP_VERTEXSHADER = 146, OP_PIXELSHADER = 147, OP_TEXTURE = 164, OP_SAMPLER = 178, OP_COUNT = 179 };

/* FXLVM, fxc's expression programs (fxlvm.c reads them, fxlvm_write.c writes them): an operand's
 * register table, the opcodes (each instruction token's low 16 bits), the comment blocks' fourccs. */
enum { T_IMM = 1, T_CONST = 2, T_OUT = 4, T_OUT_BOOL = 5, T_OUT_INT = 6, T_TEMP = 7 };
enum {
    FXLVM_MOV = 0x100, FXLVM_NEG = 0x101, FXLVM_RCP = 0x103, FXLVM_FRC = 0x104, FXLVM_EXP = 0x105, FXLVM_LOG = 0x106,
    FXLVM_RSQ = 0x107, FXLVM_SIN = 0x108, FXLVM_COS = 0x109, FXLVM_ASIN = 0x10a, FXLVM_ACOS = 0x10b, FXLVM_ATAN = 0x10c,
    FXLVM_MIN = 0x200, FXLVM_MAX = 0x201, FXLVM_LT = 0x202, FXLVM_GE = 0x203, FXLVM_ADD = 0x204, FXLVM_MUL = 0x205,
    FXLVM_ATAN2 = 0x206, FXLVM_DIV = 0x208, FXLVM_CMP = 0x300, FXLVM_DOT = 0x500, FXLVM_DOTSWIZ = 0x70e
};
enum { FXLVM_CLIT = 0x54494c43u, FXLVM_FXLC = 0x434c5846u };

/* Resource usages (the large objects' fifth word). */
enum { USE_NONE = -1, USE_DATA = 0, USE_PARAM = 1, USE_SELECTOR = 2 };

typedef struct fx2_blob {
    const uint8_t *data;
    uint32_t size;
    uint32_t at;              /* its offset in the file */
} fx2_blob;

/* A selector blob starts with the length of the array's name; 0 when the blob is too short. */
static inline uint32_t hfx_fx2_name_len(const fx2_blob *b) { return b->size >= 4 ? hfx_le32(b->data) : 0; }

/* A type as the file lays it out (a typedef record). */
typedef struct fx2_type {
    uint32_t type, klass;     /* PT_*, PC_* */
    const char *name, *semantic; /* arena; "" when absent */
    uint32_t elements;        /* 0: not an array */
    uint32_t rows, cols;
    uint32_t member_count;
    struct fx2_type *members;
    uint32_t words;           /* numeric words of one element (0 for objects) */
    uint32_t at;
} fx2_type;

/* One state as the file gives it: in a pass or in a sampler's sampler_state. */
typedef struct fx2_raw {
    uint32_t op, index;
    fx2_type type;
    uint32_t value_at;        /* file offset of its value */
    uint32_t object;          /* object id of an object-typed value, else HFX_NONE */
    uint32_t state;           /* its fx->states index; HFX_NONE for a sampler's Texture */
    int usage;                /* USE_*: what a resource said about it */
    fx2_blob blob;            /* that resource's data */
    uint32_t at;              /* file offset of the state record */
} fx2_raw;

/* An entry of the object table: a string, a texture, a shader (with its bytecode). */
typedef struct fx2_object {
    uint32_t type;            /* PT_* of what refers to it */
    bool has_data;
    fx2_blob blob;
} fx2_object;

typedef struct fx2_reader {
    hfx_arena *arena;
    hfx_diags *diags;
    uint32_t file;            /* diags file index */
    const uint8_t *data;      /* the fx_2_0 container: offsets inside it count from data + 8 */
    uint32_t size;
    uint32_t skip;            /* bytes before the container in the file (xnb, XNA's header) */
    unsigned targets, flags;
    bool failed;              /* a fatal error: stop */
    bool oom;
    hfx_fx_effect *fx;
    uint32_t param_cap, anno_cap, state_cap, sampler_cap, pass_cap, tech_cap, expr_cap, variant_cap, program_cap;
    fx2_type *param_types;    /* per top-level parameter (arena) */
    uint32_t *param_value_at; /* per fx->params: file offset of its value (arena) */
    uint32_t *param_object;   /* per fx->params: object id (strings, textures, shaders), HFX_NONE */
    uint32_t *param_raw_first, *param_raw_count; /* per fx->params: a sampler's raw states */
    fx2_raw *raws; uint32_t raw_count, raw_cap;
    uint32_t *pass_raw_first; /* per pass */
    uint32_t *pass_tech;      /* per pass: its technique */
    fx2_object *objects; uint32_t object_count;
    uint32_t shader_count;    /* the header's third word */
    hfx_codegen *cg;          /* made with the first program */
    struct fx2_program_key *keys; uint32_t key_cap; /* per program: the bytecode pair that made it */
} fx2_reader;

/* fx2_read.c */
void hfx_fx2_error(fx2_reader *r, uint32_t at, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
void hfx_fx2_fatal(fx2_reader *r, uint32_t at, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
bool hfx_fx2_u32(fx2_reader *r, uint32_t off, uint32_t *v, const char *what); /* fatal past the end */
uint32_t hfx_fx2_file_at(const fx2_reader *r, uint32_t off); /* container offset -> file offset */
bool hfx_fx2_grow(fx2_reader *r, void **arr, size_t elem, uint32_t count, uint32_t *cap);
#define FX2_GROW(r, arr, count, cap) hfx_fx2_grow((r), (void **)&(arr), sizeof *(arr), (count), &(cap))
char *hfx_fx2_strdup(fx2_reader *r, const char *s);       /* malloc'ed; NULL stays NULL */
/* Sets r up and reads the binary (hfx_fx2_read's arguments); r->fx is the effect (the
 * caller's) when it returns true, and the reader's tables stay for a listing. */
bool hfx_fx2_open(fx2_reader *r, hfx_arena *arena, hfx_diags *diags, const char *name, const char *path,
                  const void *data, size_t size, unsigned targets, unsigned flags);
/* Decodes everything but programs into r->fx; false after a fatal error. */
bool hfx_fx2_decode(fx2_reader *r, const char *name);
bool hfx_fx2_xnb(fx2_reader *r, uint32_t *start);        /* where an .xnb's effect starts */
uint32_t hfx_fx2_param_by_name(const fx2_reader *r, const char *name); /* "a", "a[2]", "s.m"; HFX_NONE */
const char *hfx_fx2_type_name(uint32_t pt);               /* "float", "texture2D"... */

/* fx2_states.c */
uint32_t hfx_fx2_state_id(uint32_t op);                   /* hfx_state_id of a file operation, 0 unknown */
const char *hfx_fx2_op_name(uint32_t op);                 /* as the listing spells it; NULL unknown */
/* Fills state st from raw (its constant value) when the raw is read; resources come later. */
void hfx_fx2_state_value(fx2_reader *r, const fx2_raw *raw, hfx_fx_state *st);
/* Reads the resource table at off (after the strings), binding each to its raw state. */
bool hfx_fx2_resources(fx2_reader *r, uint32_t off, uint32_t count);
/* After the resources: PARAM references, expressions, samplers' textures, and (unless
 * HFX_FX2_DECODE_ONLY) the passes' programs and variants. */
bool hfx_fx2_finish(fx2_reader *r);

/* fxlvm.c: an FXLVM program (fxc's expressions: a `FX` version token, then CLIT, FXLC and CTAB
 * comments) computing n components, as an eval_code program of base `base` appended to
 * r->fx->exprs; *first, *words say where. False (and a located error) when it cannot be. */
bool hfx_fxlvm_translate(fx2_reader *r, const fx2_blob *blob, uint32_t n, hfx_ev_base base, uint32_t *first,
                         uint32_t *words);
/* A shader's PRES block (its FXLVM program): the c registers it computes, in runs of up to 4
 * registers, each with its eval_code (arena); false (and a located error) when it cannot be. */
bool hfx_fxlvm_preshader(fx2_reader *r, const fx2_blob *blob, d3d9_preshader_out **outs, uint32_t *count);
/* Its instructions as text (`mov oc0.x, c[c32.x].x`), one a line, for the listing (arena). */
char *hfx_fxlvm_text(fx2_reader *r, const fx2_blob *blob);

#endif
