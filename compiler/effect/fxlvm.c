/* fxlvm.c: fxc's expression programs (FXLVM, "preshaders") as common/eval_code programs.
 *
 * An FXLVM program is a token stream like shader bytecode: a version token 0x4658xxxx ("FX"),
 * comment blocks (0xfffe | words << 16, then a fourcc): CLIT (literals: a count, then doubles),
 * FXLC (the code: an instruction count, then instructions), CTAB (which parameters the input
 * registers c# hold, as a shader's constant table), then the end token 0x0000ffff.
 * An instruction is a word `opcode << 20 | components` (bit 31: the first input is a scalar),
 * an input count, then each input and the output as (0 | 1 + index table + index offset),
 * table, offset; tables are 1 literals, 2 inputs (c#), 4 outputs (oc#), 5 and 6 the bool and int
 * registers a preshader sets (ob#, oi#: 4 components each, as oc#), 7 temporaries (r#),
 * offsets count components (c3.y is 13). Opcodes: 0x100 mov, 0x101 neg, 0x103 rcp, 0x104 frc,
 * 0x105 exp, 0x106 log, 0x107 rsq, 0x108 sin, 0x109 cos, 0x10a asin, 0x10b acos, 0x10c atan,
 * 0x200 min, 0x201 max, 0x202 lt, 0x203 ge, 0x204 add, 0x205 mul, 0x206 atan2, 0x208 div,
 * 0x300 cmp (x >= 0 ? y : z), 0x500 dot, 0x70e dotswiz (6 or 8 inputs).
 *
 * The program runs once over each component: every register component becomes an expression
 * tree over parameter words and literals; each output component's tree is written as stack
 * code (shared subtrees are written again: the size is bounded before writing), then the
 * components are concatenated. Relative addressing into a parameter array is ELEMENT, into
 * the literals TABLE. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "effect/fx2_int.h"
#include "eval_code.h"

enum { MAX_REGS = 256, MAX_COMPONENTS = MAX_REGS * 4, MAX_WORDS = 1u << 16, MAX_DEPTH = 512 };

typedef enum { N_CONST, N_PARAM, N_ELEMENT, N_TABLE, N_CALL, N_BINARY, N_SELECT_GE, N_CONVERT, N_NEG } node_kind;

typedef struct node {
    node_kind kind;
    uint32_t op;            /* hfx_ev_fn (N_CALL), hfx_ev_op (N_BINARY) */
    uint32_t kids[3];       /* node indices */
    uint32_t kid_count;
    double value;           /* N_CONST */
    uint32_t offset, count, stride; /* N_PARAM (offset), N_ELEMENT, N_TABLE (first literal, count, 4) */
    hfx_ev_base base;       /* the parameter's */
    uint32_t size;          /* words of its code, saturating at MAX_WORDS */
    uint32_t depth;         /* of its tree: bounds the recursion that writes it */
    uint32_t need;          /* stack slots its code needs, the larger operand written first where
                             * the order is free (Sethi and Ullman's numbering) */
} node;

typedef struct ctab_entry {
    uint32_t param;         /* fx->params index (top level) */
    uint32_t reg, regs;     /* c registers [reg, reg + regs) */
    uint32_t klass;         /* PC_* as the constant table gives it */
    uint32_t rows, cols, elements;
} ctab_entry;

typedef struct vm {
    fx2_reader *r;
    const fx2_blob *blob;
    const uint32_t *w;      /* the blob's words (copied, aligned) */
    uint32_t n;
    const double *lit; uint32_t lit_count;
    ctab_entry *ctab; uint32_t ctab_count;
    node *nodes; uint32_t node_count, node_cap;
    uint32_t *temp, *out;   /* node per component (HFX_NONE unset); out: oc#, then ob#, then oi# */
    uint32_t *code; uint32_t code_count, code_cap;
    bool failed;
} vm;

/* Where output table `table`'s components start in m->out (out_files of them). */
enum { OUT_FILES = 3 };
static uint32_t out_base(uint32_t table) {
    return table == T_OUT_BOOL ? MAX_COMPONENTS : table == T_OUT_INT ? 2 * MAX_COMPONENTS : 0;
}
static bool is_out(uint32_t table) { return table == T_OUT || table == T_OUT_BOOL || table == T_OUT_INT; }

static void fail(vm *m, uint32_t word, const char *fmt, const char *arg) {
    if (m->failed) return;
    char msg[256];
    snprintf(msg, sizeof msg, fmt, arg ? arg : "");
    hfx_error(m->r->diags, (hfx_loc){m->r->file, 0, m->blob->at + 4 * word}, X_FX2_BINARY, "expression: %s", msg);
    m->failed = m->r->failed = true;
}

/* --- the token stream ------------------------------------------------------------------------ */

/* The comment block with this fourcc: its first word after the fourcc, and its size in words. */
static bool find_comment(vm *m, uint32_t fourcc, uint32_t *at, uint32_t *words) {
    for (uint32_t i = 1; i < m->n && (m->w[i] & 0xffff) == 0xfffe;) {
        uint32_t size = m->w[i] >> 16;
        if (!size || size > m->n - i - 1) break;
        if (m->w[i + 1] == fourcc) {
            *at = i + 2;
            *words = size - 1;
            return true;
        }
        i += size + 1;
    }
    return false;
}

static hfx_ev_base param_base(hfx_param_type t) {
    return t == HFX_TYPE_FLOAT ? HFX_EV_FLOAT : t == HFX_TYPE_BOOL ? HFX_EV_BOOL : HFX_EV_INT;
}

/* The constant table (CTAB's layout, as in shaders): which parameter each c# range holds. */
static void read_ctab(vm *m) {
    uint32_t at, words;
    if (!find_comment(m, 0x42415443u /* CTAB */, &at, &words)) return; /* no inputs: constants only */
    const uint8_t *base = (const uint8_t *)(m->w + at);
    uint32_t bytes = words * 4, count, info;
    if (bytes < 28) {
        fail(m, at, "a constant table of %s bytes", words ? "too few" : "no");
        return;
    }
    memcpy(&count, base + 12, 4);
    memcpy(&info, base + 16, 4);
    if (info > bytes || count > (bytes - info) / 20) {
        fail(m, at, "%sthe constant table's entries run past its end", "");
        return;
    }
    m->ctab = HFX_NEW_ARRAY(m->r->arena, ctab_entry, count ? count : 1);
    for (uint32_t i = 0; i < count && !m->failed; i++) {
        uint32_t e[5];
        memcpy(e, base + info + 20 * i, sizeof e);
        uint32_t name = e[0], type = e[3];
        if (name >= bytes || !memchr(base + name, 0, bytes - name) || type > bytes || bytes - type < 16) {
            fail(m, at, "%sa constant's name or type is outside the constant table", "");
            return;
        }
        uint16_t t[8];
        memcpy(t, base + type, sizeof t);
        const char *pname = (const char *)base + name;
        ctab_entry *c = &m->ctab[m->ctab_count];
        c->param = hfx_fx2_param_by_name(m->r, pname);
        if (c->param == HFX_NONE || m->r->fx->params[c->param].parent != HFX_NONE) {
            fail(m, at, "it reads '%s', which is no parameter of the effect", pname);
            return;
        }
        c->reg = e[1] >> 16;
        c->regs = e[2] & 0xffff;
        c->klass = t[0], c->rows = t[2], c->cols = t[3], c->elements = t[4] ? t[4] : 1;
        if ((e[1] & 0xffff) != 2) continue; /* bool and int registers: fxc's expressions read floats */
        m->ctab_count++;
    }
}

/* --- nodes ----------------------------------------------------------------------------------- */

/* Operands whose order a stack program may swap: + * min max, and < >= as > <=. */
static bool swappable(const node *n) {
    if (n->kind == N_BINARY)
        return n->op == HFX_EV_ADD || n->op == HFX_EV_MUL || n->op == HFX_EV_LT || n->op == HFX_EV_GE;
    return n->kind == N_CALL && n->kid_count == 2 && (n->op == HFX_EV_FN_MIN || n->op == HFX_EV_FN_MAX);
}

static uint32_t max2(uint32_t a, uint32_t b) { return a > b ? a : b; }

static uint32_t needs(const vm *m, const node *n) {
    uint32_t k[3] = {0};
    for (uint32_t i = 0; i < n->kid_count; i++) k[i] = m->nodes[n->kids[i]].need;
    switch (n->kind) {
    case N_CONST: case N_PARAM: return 1;
    case N_SELECT_GE: return max2(max2(k[0], k[1] + 1), max2(k[2] + 2, 4));
    default:
        if (n->kid_count < 2) return max2(k[0], 1);
        if (swappable(n)) return k[0] == k[1] ? k[0] + 1 : max2(k[0], k[1]);
        return max2(k[0], k[1] + 1);
    }
}

static uint32_t add_node(vm *m, node n) {
    if (m->failed) return HFX_NONE;
    for (uint32_t k = 0; k < n.kid_count; k++)
        if (n.kids[k] == HFX_NONE) return HFX_NONE;
    if (!HFX_ARENA_GROW(m->r->arena, m->nodes, m->node_count, m->node_cap, 16)) return HFX_NONE;
    uint32_t size = n.kind == N_CONST ? 2 : n.kind == N_PARAM ? 3 : n.kind == N_ELEMENT ? 5 : 1;
    if (n.kind == N_TABLE) size = 2 + n.count + 1;
    n.depth = 1;
    for (uint32_t k = 0; k < n.kid_count; k++) {
        size += m->nodes[n.kids[k]].size;
        if (m->nodes[n.kids[k]].depth + 1 > n.depth) n.depth = m->nodes[n.kids[k]].depth + 1;
    }
    if (n.kind == N_SELECT_GE) size += 3; /* CONST 0, GE */
    n.size = size > MAX_WORDS ? MAX_WORDS : size;
    n.need = needs(m, &n);
    if (n.size >= MAX_WORDS || n.depth > MAX_DEPTH) {
        fail(m, 0, "%sthe computation is too large to run as hfx's expression code", "");
        return HFX_NONE;
    }
    m->nodes[m->node_count] = n;
    return m->node_count++;
}

static uint32_t constant(vm *m, double v) { return add_node(m, (node){.kind = N_CONST, .value = v}); }

static uint32_t op2(vm *m, node_kind k, uint32_t op, uint32_t a, uint32_t b) {
    if (a == HFX_NONE || b == HFX_NONE) return HFX_NONE;
    return add_node(m, (node){.kind = k, .op = op, .kids = {a, b}, .kid_count = 2});
}

static uint32_t call1(vm *m, hfx_ev_fn fn, uint32_t a) {
    if (a == HFX_NONE) return HFX_NONE;
    return add_node(m, (node){.kind = N_CALL, .op = (uint32_t)fn, .kids = {a}, .kid_count = 1});
}

/* Where the parameter word behind component k of register reg is: its entry, and the word. */
static const ctab_entry *input_of(vm *m, uint32_t reg, uint32_t k, uint32_t *word) {
    for (uint32_t i = 0; i < m->ctab_count; i++) {
        const ctab_entry *c = &m->ctab[i];
        if (reg < c->reg || reg >= c->reg + c->regs) continue;
        uint32_t rel = reg - c->reg;
        /* a matrix takes one register per column (column_major) or row; anything else one per element */
        uint32_t per = c->klass == PC_MATRIX_COLUMNS ? c->cols : c->klass == PC_MATRIX_ROWS ? c->rows : 1;
        if (!per) return NULL; /* a table claiming a matrix of 0 columns or rows: nothing to read */
        uint32_t e = rel / per, j = rel % per, size = c->rows * c->cols;
        if (c->klass == PC_MATRIX_COLUMNS) *word = e * size + k * c->cols + j;
        else if (c->klass == PC_MATRIX_ROWS) *word = e * size + j * c->cols + k;
        else *word = e * size + k;
        if ((c->klass == PC_MATRIX_COLUMNS ? k >= c->rows : k >= c->cols) || e >= c->elements) return NULL;
        return c;
    }
    return NULL;
}

/* Component k of input register reg: its parameter word, or 0 where nothing is loaded. */
static uint32_t input(vm *m, uint32_t reg, uint32_t k) {
    uint32_t word;
    const ctab_entry *c = input_of(m, reg, k, &word);
    if (!c) return constant(m, 0.0);
    const hfx_fx_param *p = &m->r->fx->params[c->param];
    if (word >= p->words) return constant(m, 0.0);
    return add_node(m, (node){.kind = N_PARAM, .offset = p->offset + word, .base = param_base(p->type)});
}

/* c[reg + index].k: an element of the parameter array holding reg, by the index's value. */
static uint32_t input_indexed(vm *m, uint32_t reg, uint32_t k, uint32_t index, uint32_t word_at) {
    uint32_t word;
    const ctab_entry *c = input_of(m, reg, k, &word);
    if (!c || c->klass == PC_MATRIX_COLUMNS || c->klass == PC_MATRIX_ROWS) {
        fail(m, word_at, "%sa relative read outside a parameter array", "");
        return HFX_NONE;
    }
    const hfx_fx_param *p = &m->r->fx->params[c->param];
    uint32_t stride = c->rows * c->cols, first = reg - c->reg;
    if (stride * c->elements > p->words) {
        fail(m, word_at, "%sthe constant table is larger than its parameter", "");
        return HFX_NONE;
    }
    return add_node(m, (node){.kind = N_ELEMENT, .kids = {index}, .kid_count = 1, .offset = p->offset + word,
                              .count = c->elements - first, .stride = stride, .base = param_base(p->type)});
}

/* imm[offset + 4 * index]: a table of the literals from offset on, one per register. */
static uint32_t literal_indexed(vm *m, uint32_t offset, uint32_t index, uint32_t word_at) {
    if (offset >= m->lit_count) {
        fail(m, word_at, "%sa relative read past the literals", "");
        return HFX_NONE;
    }
    return add_node(m, (node){.kind = N_TABLE, .kids = {index}, .kid_count = 1, .offset = offset,
                              .count = (m->lit_count - offset + 3) / 4});
}

/* --- instructions ---------------------------------------------------------------------------- */

typedef struct operand {
    uint32_t table, offset;
    bool indexed;
    uint32_t index_table, index_offset;
    uint32_t at;            /* word, for messages */
} operand;

static bool read_operand(vm *m, uint32_t *i, uint32_t end, operand *o) {
    o->at = *i;
    if (*i >= end) return fail(m, *i, "%san operand past the end of the code", ""), false;
    o->indexed = m->w[*i] != 0;
    if (m->w[*i] > 1) return fail(m, *i, "%san unknown addressing mode", ""), false;
    (*i)++;
    if (o->indexed) {
        if (end - *i < 2) return fail(m, *i, "%san operand past the end of the code", ""), false;
        o->index_table = m->w[(*i)++];
        o->index_offset = m->w[(*i)++];
    }
    if (end - *i < 2) return fail(m, *i, "%san operand past the end of the code", ""), false;
    o->table = m->w[(*i)++];
    o->offset = m->w[(*i)++];
    return true;
}

/* The node of one register component (unindexed). */
static uint32_t component(vm *m, uint32_t table, uint32_t offset, uint32_t at) {
    if ((table == T_TEMP || is_out(table)) && offset >= MAX_COMPONENTS)
        return fail(m, at, "%sa register past r255", ""), HFX_NONE;
    switch (table) {
    case T_IMM:
        if (offset >= m->lit_count) return fail(m, at, "%sa literal past the literal table", ""), HFX_NONE;
        return constant(m, m->lit[offset]);
    case T_CONST: return input(m, offset / 4, offset % 4);
    case T_TEMP: case T_OUT: case T_OUT_BOOL: case T_OUT_INT: {
        uint32_t *regs = table == T_TEMP ? m->temp : m->out + out_base(table);
        if (regs[offset] == HFX_NONE) return fail(m, at, "%sa register read before it is written", ""), HFX_NONE;
        return regs[offset];
    }
    default: return fail(m, at, "%san unknown register table", ""), HFX_NONE;
    }
}

/* Input o's component k (the scalar input's only component when scalar). */
static uint32_t fetch(vm *m, const operand *o, uint32_t k) {
    if (!o->indexed) return component(m, o->table, o->offset + k, o->at);
    uint32_t index = component(m, o->index_table, o->index_offset, o->at);
    if (index == HFX_NONE) return HFX_NONE;
    if (o->table == T_CONST) return input_indexed(m, (o->offset + k) / 4, (o->offset + k) % 4, index, o->at);
    if (o->table == T_IMM) return literal_indexed(m, o->offset + k, index, o->at);
    return fail(m, o->at, "%sa relative read of a register that is no input", ""), HFX_NONE;
}

typedef struct opinfo {
    uint32_t code, inputs;
    const char *name;
} opinfo;

static const opinfo ops[] = {
    {FXLVM_MOV, 1, "mov"}, {FXLVM_NEG, 1, "neg"}, {FXLVM_RCP, 1, "rcp"}, {FXLVM_FRC, 1, "frc"}, {FXLVM_EXP, 1, "exp"},
    {FXLVM_LOG, 1, "log"}, {FXLVM_RSQ, 1, "rsq"}, {FXLVM_SIN, 1, "sin"}, {FXLVM_COS, 1, "cos"}, {FXLVM_ASIN, 1, "asin"},
    {FXLVM_ACOS, 1, "acos"}, {FXLVM_ATAN, 1, "atan"}, {FXLVM_MIN, 2, "min"}, {FXLVM_MAX, 2, "max"}, {FXLVM_LT, 2, "lt"},
    {FXLVM_GE, 2, "ge"}, {FXLVM_ADD, 2, "add"}, {FXLVM_MUL, 2, "mul"}, {FXLVM_ATAN2, 2, "atan2"}, {FXLVM_DIV, 2, "div"},
    {FXLVM_CMP, 3, "cmp"}, {FXLVM_DOT, 2, "dot"}, {FXLVM_DOTSWIZ, 6, "dotswiz"}, {FXLVM_DOTSWIZ, 8, "dotswiz"}};

static const opinfo *find_op(uint32_t code, uint32_t inputs) {
    for (size_t i = 0; i < sizeof ops / sizeof *ops; i++)
        if (ops[i].code == code && ops[i].inputs == inputs) return &ops[i];
    return NULL;
}

/* The value of one component of an instruction, from its inputs' nodes. */
static uint32_t compute(vm *m, uint32_t code, const uint32_t *x, uint32_t n) {
    switch (code) {
    case FXLVM_MOV: return x[0];
    case FXLVM_NEG: return x[0] == HFX_NONE ? HFX_NONE : add_node(m, (node){.kind = N_NEG, .kids = {x[0]}, .kid_count = 1});
    case FXLVM_RCP: return op2(m, N_BINARY, HFX_EV_DIV, constant(m, 1.0), x[0]);
    case FXLVM_FRC: return call1(m, HFX_EV_FN_FRAC, x[0]);
    case FXLVM_EXP: return call1(m, HFX_EV_FN_EXP2, x[0]);
    case FXLVM_LOG: return call1(m, HFX_EV_FN_LOG2, call1(m, HFX_EV_FN_ABS, x[0]));
    case FXLVM_RSQ: return call1(m, HFX_EV_FN_RSQRT, call1(m, HFX_EV_FN_ABS, x[0]));
    case FXLVM_SIN: return call1(m, HFX_EV_FN_SIN, x[0]);
    case FXLVM_COS: return call1(m, HFX_EV_FN_COS, x[0]);
    case FXLVM_ASIN: return call1(m, HFX_EV_FN_ASIN, x[0]);
    case FXLVM_ACOS: return call1(m, HFX_EV_FN_ACOS, x[0]);
    case FXLVM_ATAN: return call1(m, HFX_EV_FN_ATAN, x[0]);
    case FXLVM_MIN: return op2(m, N_CALL, HFX_EV_FN_MIN, x[0], x[1]);
    case FXLVM_MAX: return op2(m, N_CALL, HFX_EV_FN_MAX, x[0], x[1]);
    case FXLVM_LT: return add_node(m, (node){.kind = N_CONVERT, .kids = {op2(m, N_BINARY, HFX_EV_LT, x[0], x[1])}, .kid_count = 1});
    case FXLVM_GE: return add_node(m, (node){.kind = N_CONVERT, .kids = {op2(m, N_BINARY, HFX_EV_GE, x[0], x[1])}, .kid_count = 1});
    case FXLVM_ADD: return op2(m, N_BINARY, HFX_EV_ADD, x[0], x[1]);
    case FXLVM_MUL: return op2(m, N_BINARY, HFX_EV_MUL, x[0], x[1]);
    case FXLVM_ATAN2: return op2(m, N_CALL, HFX_EV_FN_ATAN2, x[0], x[1]);
    case FXLVM_DIV: return op2(m, N_BINARY, HFX_EV_DIV, x[0], x[1]);
    case FXLVM_CMP:
        if (x[0] == HFX_NONE || x[1] == HFX_NONE || x[2] == HFX_NONE) return HFX_NONE;
        return add_node(m, (node){.kind = N_SELECT_GE, .kids = {x[1], x[2], x[0]}, .kid_count = 3});
    default: { /* dot products: the sum of the products of the two halves */
        uint32_t half = n / 2, sum = op2(m, N_BINARY, HFX_EV_MUL, x[0], x[half]);
        for (uint32_t i = 1; i < half; i++) sum = op2(m, N_BINARY, HFX_EV_ADD, sum, op2(m, N_BINARY, HFX_EV_MUL, x[i], x[half + i]));
        return sum;
    }
    }
}

/* One instruction at *i: every component's node into the output register. */
static void run_instruction(vm *m, uint32_t *i, uint32_t end) {
    uint32_t at = *i;
    if (end - *i < 2) { fail(m, at, "%san instruction past the end of the code", ""); return; }
    uint32_t word = m->w[(*i)++], inputs = m->w[(*i)++];
    uint32_t code = (word >> 20) & 0x7ff, comps = word & 0xffff;
    bool scalar = (word >> 31) != 0;
    const opinfo *op = find_op(code, inputs);
    if (!op) { fail(m, at, "%san unknown instruction", ""); return; }
    if (comps < 1 || comps > 4) { fail(m, at, "%san instruction of more than 4 components", ""); return; }
    operand in[8], out;
    for (uint32_t k = 0; k < inputs; k++)
        if (!read_operand(m, i, end, &in[k])) return;
    if (!read_operand(m, i, end, &out)) return;
    if (out.indexed || (out.table != T_TEMP && !is_out(out.table)) || out.offset >= MAX_COMPONENTS - 4)
        { fail(m, out.at, "%san output that is no temporary or output register", ""); return; }
    bool whole = code == 0x500 || code == 0x70e; /* dot products write one component */
    uint32_t results[4], count = whole ? 1 : comps;
    for (uint32_t c = 0; c < count && !m->failed; c++) {
        uint32_t x[8], n = 0;
        if (whole && code == 0x500)
            for (uint32_t half = 0; half < 2; half++)
                for (uint32_t k = 0; k < comps; k++) x[n++] = fetch(m, &in[half], scalar && !half ? 0 : k);
        else
            for (uint32_t k = 0; k < inputs; k++) x[n++] = fetch(m, &in[k], whole || (scalar && !k) ? 0 : c);
        results[c] = compute(m, code, x, n);
    }
    uint32_t *regs = out.table == T_TEMP ? m->temp : m->out + out_base(out.table);
    for (uint32_t c = 0; c < count && !m->failed; c++) regs[out.offset + c] = results[c]; /* after: inputs may alias */
}

/* --- writing eval_code ----------------------------------------------------------------------- */

static void put(vm *m, uint32_t w) {
    if (!m->failed && HFX_ARENA_GROW(m->r->arena, m->code, m->code_count, m->code_cap, 64)) m->code[m->code_count++] = w;
}

static void put_float(vm *m, double v) { put(m, hfx_evc_bits(HFX_EV_FLOAT, v)); }

static void emit(vm *m, uint32_t id) {
    const node *n = &m->nodes[id];
    switch (n->kind) {
    case N_CONST:
        put(m, hfx_evc_word(HFX_EVC_CONST, HFX_EV_FLOAT, 1));
        put_float(m, n->value);
        return;
    case N_PARAM:
        put(m, hfx_evc_word(HFX_EVC_PARAM, n->base, 1));
        put(m, n->offset);
        put(m, hfx_evc_word(HFX_EVC_CONVERT, HFX_EV_FLOAT, 1));
        return;
    case N_ELEMENT:
        emit(m, n->kids[0]);
        put(m, hfx_evc_word(HFX_EVC_ELEMENT, n->base, 1));
        put(m, n->offset);
        put(m, n->count);
        put(m, n->stride);
        put(m, hfx_evc_word(HFX_EVC_CONVERT, HFX_EV_FLOAT, 1));
        return;
    case N_TABLE:
        emit(m, n->kids[0]);
        put(m, hfx_evc_word(HFX_EVC_TABLE, HFX_EV_FLOAT, 1));
        put(m, n->count);
        for (uint32_t i = 0; i < n->count; i++)
            put_float(m, n->offset + 4 * i < m->lit_count ? m->lit[n->offset + 4 * i] : 0.0);
        return;
    case N_CALL: case N_BINARY: {
        /* the operand needing more of the stack first, where that changes nothing: x < y is y > x */
        bool swap = swappable(n) && m->nodes[n->kids[1]].need > m->nodes[n->kids[0]].need;
        uint32_t op = n->op;
        if (swap && n->kind == N_BINARY && (op == HFX_EV_LT || op == HFX_EV_GE)) op = op == HFX_EV_LT ? HFX_EV_GT : HFX_EV_LE;
        for (uint32_t k = 0; k < n->kid_count; k++) emit(m, n->kids[swap ? n->kid_count - 1 - k : k]);
        put(m, hfx_evc_word(n->kind == N_CALL ? HFX_EVC_CALL : HFX_EVC_BINARY, op, 0));
        return;
    }
    case N_NEG:
        emit(m, n->kids[0]);
        put(m, hfx_evc_word(HFX_EVC_UNARY, HFX_EV_NEG, 0));
        return;
    case N_SELECT_GE: /* kids: value if >= 0, value if < 0, the tested value */
        emit(m, n->kids[0]);
        emit(m, n->kids[1]);
        emit(m, n->kids[2]);
        put(m, hfx_evc_word(HFX_EVC_CONST, HFX_EV_FLOAT, 1));
        put_float(m, 0.0);
        put(m, hfx_evc_word(HFX_EVC_BINARY, HFX_EV_GE, 0));
        put(m, hfx_evc_word(HFX_EVC_SELECT, 0, 0));
        return;
    case N_CONVERT:
        emit(m, n->kids[0]);
        put(m, hfx_evc_word(HFX_EVC_CONVERT, HFX_EV_FLOAT, 1));
        return;
    }
}

/* --- the whole ------------------------------------------------------------------------------- */

static bool load(vm *m, fx2_reader *r, const fx2_blob *blob) {
    memset(m, 0, sizeof *m);
    m->r = r;
    m->blob = blob;
    m->n = blob->size / 4;
    if (m->n < 2 || (blob->data[2] | blob->data[3] << 8) != 0x4658) {
        fail(m, 0, "%snot an FXLVM program (fxc's expressions start with 'FX')", "");
        return false;
    }
    uint32_t *w = HFX_NEW_ARRAY(r->arena, uint32_t, m->n);
    memcpy(w, blob->data, (size_t)m->n * 4);
    m->w = w;
    uint32_t at, words;
    if (find_comment(m, FXLVM_CLIT, &at, &words) && words >= 1) {
        uint32_t count = m->w[at];
        if (count > (words - 1) / 2) {
            fail(m, at, "%sliterals run past their block", "");
            return false;
        }
        double *lit = HFX_NEW_ARRAY(r->arena, double, count ? count : 1);
        memcpy(lit, m->w + at + 1, (size_t)count * sizeof(double));
        m->lit = lit, m->lit_count = count;
    }
    read_ctab(m);
    m->temp = HFX_NEW_ARRAY(r->arena, uint32_t, MAX_COMPONENTS);
    m->out = HFX_NEW_ARRAY(r->arena, uint32_t, OUT_FILES * MAX_COMPONENTS);
    memset(m->temp, 0xff, MAX_COMPONENTS * sizeof *m->temp);
    memset(m->out, 0xff, OUT_FILES * MAX_COMPONENTS * sizeof *m->out);
    return !m->failed;
}

/* Loads and runs the program over symbolic registers: m->out holds the outputs' trees. */
static bool execute(vm *m, fx2_reader *r, const fx2_blob *blob) {
    if (!load(m, r, blob)) return false;
    uint32_t at, size;
    if (!find_comment(m, FXLVM_FXLC, &at, &size) || size < 1) {
        fail(m, 0, "%sno FXLC block (the code)", "");
        return false;
    }
    uint32_t count = m->w[at], i = at + 1, end = at + size;
    for (uint32_t k = 0; k < count && !m->failed; k++) run_instruction(m, &i, end);
    return !m->failed;
}

/* Output components first .. first + n - 1 as one program of base `base` (n <= 16), in the
 * arena; an output the program never writes is D3DX's zero. */
static uint32_t *write_outputs(vm *m, uint32_t first, uint32_t n, hfx_ev_base base, uint32_t *words) {
    m->code_count = 0;
    for (uint32_t c = 0; c < n && !m->failed; c++) {
        uint32_t node = m->out[first + c] != HFX_NONE ? m->out[first + c] : constant(m, 0.0);
        if (node == HFX_NONE) break;
        emit(m, node);
        if (c) put(m, hfx_evc_word(HFX_EVC_CONCAT, 0, c + 1));
    }
    put(m, hfx_evc_word(HFX_EVC_CONVERT, base, n));
    if (m->failed) return NULL;
    char err[160];
    if (hfx_evc_validate(m->code, m->code_count, m->r->fx->value_words, err, sizeof err)) {
        fail(m, 0, "%s", err);
        return NULL;
    }
    uint32_t *code = HFX_NEW_ARRAY(m->r->arena, uint32_t, m->code_count);
    memcpy(code, m->code, m->code_count * sizeof *code);
    *words = m->code_count;
    return code;
}

bool hfx_fxlvm_translate(fx2_reader *r, const fx2_blob *blob, uint32_t n, hfx_ev_base base, uint32_t *first,
                         uint32_t *words) {
    vm m;
    if (!execute(&m, r, blob)) return false;
    uint32_t count;
    const uint32_t *code = write_outputs(&m, 0, n, base, &count);
    if (!code) return false;
    hfx_fx_effect *fx = r->fx;
    *first = fx->expr_words;
    for (uint32_t k = 0; k < count; k++) {
        if (!FX2_GROW(r, fx->exprs, fx->expr_words, r->expr_cap)) return false;
        fx->exprs[fx->expr_words++] = code[k];
    }
    *words = count;
    return true;
}

/* Whether the program writes any component of register reg of the output file starting at base. */
static bool out_written(const vm *m, uint32_t base, uint32_t reg) {
    for (uint32_t k = 0; k < 4; k++)
        if (m->out[base + reg * 4 + k] != HFX_NONE) return true;
    return false;
}

bool hfx_fxlvm_preshader(fx2_reader *r, const fx2_blob *blob, d3d9_preshader_out **outs, uint32_t *count) {
    vm m;
    *outs = NULL, *count = 0;
    if (!execute(&m, r, blob)) return false;
    uint32_t runs = 0;
    d3d9_preshader_out *list = HFX_NEW_ARRAY(r->arena, d3d9_preshader_out, OUT_FILES * MAX_REGS);
    for (uint32_t reg = 0; reg < MAX_REGS;) { /* c#: runs of written registers, 4 at most (16 components) */
        if (!out_written(&m, 0, reg)) {
            reg++;
            continue;
        }
        uint32_t n = 1;
        while (n < 4 && reg + n < MAX_REGS && out_written(&m, 0, reg + n)) n++;
        d3d9_preshader_out *o = &list[runs++];
        *o = (d3d9_preshader_out){.reg = reg, .count = n, .file = D3D9_PRE_C};
        if (!(o->code = write_outputs(&m, reg * 4, n * 4, HFX_EV_FLOAT, &o->words))) return false;
        reg += n;
    }
    static const uint32_t tables[2] = {T_OUT_BOOL, T_OUT_INT};
    for (int f = 0; f < 2; f++) /* b# and i#: one register each, computed as 4 floats like c# */
        for (uint32_t reg = 0; reg < MAX_REGS; reg++) {
            uint32_t base = out_base(tables[f]);
            if (!out_written(&m, base, reg)) continue;
            d3d9_preshader_out *o = &list[runs++];
            *o = (d3d9_preshader_out){.reg = reg, .count = 1, .file = f ? D3D9_PRE_I : D3D9_PRE_B};
            if (!(o->code = write_outputs(&m, base + reg * 4, 4, HFX_EV_FLOAT, &o->words))) return false;
        }
    *outs = list, *count = runs;
    return true;
}

/* --- text ------------------------------------------------------------------------------------ */

static void print_operand(vm *m, char *buf, size_t size, const operand *o, uint32_t comps) {
    static const char *const tables[8] = {"?", "imm", "c", "?", "oc", "ob", "oi", "r"};
    const char *t = o->table < 8 ? tables[o->table] : "?";
    size_t len = 0;
    if (o->table == T_IMM && !o->indexed) {
        len += (size_t)snprintf(buf + len, size - len, "(");
        for (uint32_t k = 0; k < comps && len < size; k++)
            len += (size_t)snprintf(buf + len, size - len, "%s%g", k ? ", " : "",
                                    o->offset + k < m->lit_count ? m->lit[o->offset + k] : 0.0);
        if (len < size) snprintf(buf + len, size - len, ")");
        return;
    }
    if (o->indexed)
        len = (size_t)snprintf(buf, size, "%s[%u + %s%u.%c]", t, o->offset / 4, o->index_table < 8 ? tables[o->index_table] : "?",
                               o->index_offset / 4, "xyzw"[o->index_offset % 4]);
    else
        len = (size_t)snprintf(buf, size, "%s%u", t, o->offset / 4);
    if (len < size) len += (size_t)snprintf(buf + len, size - len, ".");
    for (uint32_t k = 0; k < comps && len + 1 < size; k++) buf[len++] = "xyzw"[(o->offset + k) % 4], buf[len] = 0;
}

char *hfx_fxlvm_text(fx2_reader *r, const fx2_blob *blob) {
    vm m;
    if (!load(&m, r, blob)) return NULL;
    uint32_t at, size;
    if (!find_comment(&m, FXLVM_FXLC, &at, &size) || size < 1) return hfx_arena_strdup(r->arena, "");
    char *text = hfx_arena_strdup(r->arena, "");
    uint32_t count = m.w[at], i = at + 1, end = at + size;
    for (uint32_t k = 0; k < count && !m.failed; k++) {
        if (end - i < 2) break;
        uint32_t word = m.w[i++], inputs = m.w[i++];
        const opinfo *op = find_op((word >> 20) & 0x7ff, inputs);
        uint32_t comps = word & 0xffff;
        operand o[9];
        bool ok = op && inputs <= 8;
        for (uint32_t j = 0; ok && j <= inputs; j++) ok = read_operand(&m, &i, end, &o[j]);
        if (!ok) break;
        char line[512], part[128];
        bool whole = op->code == 0x500 || op->code == 0x70e;
        print_operand(&m, part, sizeof part, &o[inputs], whole ? 1 : comps);
        int len = snprintf(line, sizeof line, "    %s %s", op->name, part);
        for (uint32_t j = 0; j < inputs && len > 0 && (size_t)len < sizeof line; j++) {
            print_operand(&m, part, sizeof part, &o[j], (word >> 31) && !j ? 1 : op->code == 0x70e ? 1 : comps);
            len += snprintf(line + len, sizeof line - (size_t)len, ", %s", part);
        }
        text = hfx_arena_printf(r->arena, "%s%s\n", text, line);
    }
    return text;
}
