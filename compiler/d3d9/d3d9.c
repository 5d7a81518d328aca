/* d3d9.c: the opcode table and the decoder. A token stream becomes a d3d9_shader; every
 * instruction is checked against d3d9_ops.def (model, operand counts) and every operand against
 * the registers its model and stage have. Errors are located by byte offset (d3d9.h). */
#include "d3d9/d3d9_int.h"

#include <stdio.h>

#include "bytes.h"

static const d3d9_op_info ops[] = {
#define D3D9_OP(id, name, token, dst, src, slots, vs0, vs1, ps0, ps1, flags) \
    {name, token, dst, src, slots, vs0, vs1, ps0, ps1, flags},
#include "d3d9/d3d9_ops.def"
};

const d3d9_op_info *hfx_d3d9_op_find(uint32_t opcode) {
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++)
        if (ops[i].token == opcode) return &ops[i];
    return NULL;
}

const char *hfx_d3d9_model_name(d3d9_stage stage, uint8_t model) {
    static const char *const vs[] = {"vs_1_1", "vs_2_0", "vs_2_x", "vs_3_0"};
    static const char *const ps[] = {"ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4", "ps_2_0", "ps_2_x", "ps_3_0"};
    switch (model) {
    case D3D9_SM(1, 1): return stage == D3D9_VS ? vs[0] : ps[0];
    case D3D9_SM(1, 2): return ps[1];
    case D3D9_SM(1, 3): return ps[2];
    case D3D9_SM(1, 4): return ps[3];
    case D3D9_SM(2, 0): return stage == D3D9_VS ? vs[1] : ps[4];
    case D3D9_SM(2, 1): return stage == D3D9_VS ? vs[2] : ps[5];
    case D3D9_SM(3, 0): return stage == D3D9_VS ? vs[3] : ps[6];
    default: return "?";
    }
}

uint32_t hfx_d3d9_word(const d3d9_reader *r, uint32_t i) {
    return hfx_le32(r->bytes + (size_t)i * 4);
}

void hfx_d3d9_fail(d3d9_reader *r, uint32_t word, unsigned code, const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    hfx_loc loc = {r->in->file, 0, r->in->base + word * 4};
    hfx_error(r->diags, loc, code, "%s", msg);
}

static bool model_known(d3d9_stage st, uint8_t m) {
    if (st == D3D9_VS) return m == D3D9_SM(1, 1) || m == D3D9_SM(2, 0) || m == D3D9_SM(2, 1) || m == D3D9_SM(3, 0);
    return (m >= D3D9_SM(1, 1) && m <= D3D9_SM(1, 4)) || m == D3D9_SM(2, 0) || m == D3D9_SM(2, 1) || m == D3D9_SM(3, 0);
}

static bool op_allowed(const d3d9_op_info *op, d3d9_stage st, uint8_t m) {
    uint8_t first = st == D3D9_VS ? op->vs_first : op->ps_first;
    uint8_t last = st == D3D9_VS ? op->vs_last : op->ps_last;
    return first && m >= first && m <= last;
}

/* Operand counts for this model: texture instructions and sincos changed shape across models. */
void hfx_d3d9_operand_counts(const d3d9_op_info *op, uint8_t model, unsigned *dst, unsigned *src) {
    *dst = op->dst;
    *src = op->src;
    if (op->token == D3D9_TEX) *src = model < D3D9_SM(1, 4) ? 0 : model == D3D9_SM(1, 4) ? 1 : 2;
    else if (op->token == D3D9_TEXCOORD) *src = model == D3D9_SM(1, 4) ? 1 : 0;
    else if (op->token == D3D9_SINCOS) *src = model >= D3D9_SM(3, 0) ? 1 : 3;
}

static d3d9_inst *new_inst(d3d9_reader *r) {
    d3d9_shader *s = r->sh;
    HFX_ARENA_GROW(r->arena, s->insts, s->inst_count, r->inst_cap, 16);
    d3d9_inst *in = &s->insts[s->inst_count++];
    memset(in, 0, sizeof *in);
    return in;
}

/* The comment block at word i (length n words after the token). */
static void read_comment(d3d9_reader *r, uint32_t i, uint32_t n) {
    d3d9_shader *s = r->sh;
    uint32_t *w = HFX_NEW_ARRAY(r->arena, uint32_t, n ? n : 1);
    for (uint32_t k = 0; k < n; k++) w[k] = hfx_d3d9_word(r, i + 1 + k);
    HFX_ARENA_GROW(r->arena, s->comments, s->comment_count, r->comment_cap, 4);
    d3d9_comment *c = &s->comments[s->comment_count++];
    c->fourcc = n ? w[0] : 0;
    c->words = w;
    c->word_count = n;
    c->offset = i * 4;
    if (c->fourcc == D3D9_FOURCC_CTAB && !s->constants) hfx_d3d9_read_ctab(r, c, i);
}

/* Flow-control nesting: ifs, loops and reps must close in order; else only inside an if. */
static void track_flow(d3d9_reader *r, const d3d9_op_info *op, uint32_t at) {
    uint16_t t = op->token;
    if (op->flags & D3D9_OPF_OPEN) {
        if (r->depth < D3D9_MAX_DEPTH) r->stack[r->depth] = t == D3D9_IFC ? D3D9_IF : t;
        r->depth++;
        return;
    }
    uint16_t want = t == D3D9_ENDIF || t == D3D9_ELSE ? D3D9_IF : t == D3D9_ENDLOOP ? D3D9_LOOP
                  : t == D3D9_ENDREP ? D3D9_REP : 0;
    if (!want) {
        if ((t == D3D9_BREAK || t == D3D9_BREAKC || t == D3D9_BREAKP) && !r->loops)
            hfx_d3d9_fail(r, at, X_D3D9_FLOW, "%s outside a loop or rep", op->name);
        return;
    }
    uint16_t top = r->depth && r->depth <= D3D9_MAX_DEPTH ? r->stack[r->depth - 1] : 0;
    if (!r->depth || top != want) {
        hfx_d3d9_fail(r, at, X_D3D9_FLOW, "%s without a matching %s", op->name,
                  want == D3D9_IF ? "if" : want == D3D9_LOOP ? "loop" : "rep");
        return;
    }
    if (t != D3D9_ELSE) r->depth--;
}

static void count_loops(d3d9_reader *r) {
    r->loops = 0;
    for (uint32_t k = 0; k < r->depth && k < D3D9_MAX_DEPTH; k++)
        if (r->stack[k] == D3D9_LOOP || r->stack[k] == D3D9_REP) r->loops++;
}

/* Length in words of the instruction at i (after its token), or UINT32_MAX if unknown. */
static uint32_t inst_length(d3d9_reader *r, uint32_t i, uint32_t tok, const d3d9_op_info *op) {
    if (r->sh->model >= D3D9_SM(2, 0)) return (tok >> 24) & 0xf;
    if (!op) return UINT32_MAX;
    if (op->token == D3D9_DEF) return 5;
    /* ps_1_x / vs_1_1: no length field; operands are the following tokens with bit 31 set. */
    uint32_t n = 0;
    while (i + 1 + n < r->words && (hfx_d3d9_word(r, i + 1 + n) & 0x80000000u)) n++;
    return n;
}

/* One instruction at word i; returns the index of the next token, or UINT32_MAX to stop. */
static uint32_t read_inst(d3d9_reader *r, uint32_t i) {
    uint32_t tok = hfx_d3d9_word(r, i);
    uint32_t opcode = tok & 0xffff;
    const d3d9_op_info *op = hfx_d3d9_op_find(opcode);
    uint32_t len = inst_length(r, i, tok, op);
    if (len == UINT32_MAX) {
        hfx_d3d9_fail(r, i, X_D3D9_OPCODE, "unknown opcode 0x%04x", opcode);
        return UINT32_MAX;
    }
    if ((uint64_t)i + 1 + len > r->words) {
        hfx_d3d9_fail(r, i, X_D3D9_TRUNCATED, "instruction runs past the end of the shader (%u words, %u left)",
                  len, r->words - i - 1);
        return UINT32_MAX;
    }
    if (!op) {
        hfx_d3d9_fail(r, i, X_D3D9_OPCODE, "unknown opcode 0x%04x", opcode);
        return i + 1 + len;
    }
    if (!op_allowed(op, r->sh->stage, r->sh->model)) {
        hfx_d3d9_fail(r, i, X_D3D9_OPCODE, "%s is not allowed in %s", op->name,
                  hfx_d3d9_model_name(r->sh->stage, r->sh->model));
        return i + 1 + len;
    }
    if (tok & 0x80000000u) {
        hfx_d3d9_fail(r, i, X_D3D9_OPCODE, "instruction token with bit 31 set");
        return i + 1 + len;
    }
    d3d9_inst *in = new_inst(r);
    in->op = (uint16_t)opcode;
    in->control = (uint8_t)(tok >> 16);
    in->coissue = (tok >> 30) & 1;
    in->predicated = (tok >> 28) & 1;
    in->offset = i * 4;
    uint32_t errors = r->diags->errors;
    hfx_d3d9_read_operands(r, in, op, i, len);
    if (r->diags->errors == errors) hfx_d3d9_check_ports(r, in, op, i);
    if (r->diags->errors == errors) hfx_d3d9_check_scalar_sources(r, in, op, i);
    track_flow(r, op, i);
    count_loops(r);
    return i + 1 + len;
}

static bool read_version(d3d9_reader *r) {
    if (r->words < 1) {
        hfx_d3d9_fail(r, 0, X_D3D9_TRUNCATED, "shader shorter than its version token (%u bytes)", r->in->size);
        return false;
    }
    uint32_t v = hfx_d3d9_word(r, 0);
    d3d9_shader *s = r->sh;
    s->version = v;
    uint32_t kind = v >> 16;
    unsigned major = (v >> 8) & 0xff, minor = v & 0xff;
    if (kind != 0xfffe && kind != 0xffff) {
        hfx_d3d9_fail(r, 0, X_D3D9_VERSION, "not a D3D9 shader: version token 0x%08x", v);
        return false;
    }
    s->stage = kind == 0xfffe ? D3D9_VS : D3D9_PS;
    s->model = major < 16 && minor < 16 ? (uint8_t)D3D9_SM(major, minor) : 0;
    if (!model_known(s->stage, s->model)) {
        hfx_d3d9_fail(r, 0, X_D3D9_VERSION, "unsupported shader model %s_%u_%u", s->stage == D3D9_VS ? "vs" : "ps",
                  major, minor);
        return false;
    }
    return true;
}

d3d9_shader *hfx_d3d9_decode(hfx_arena *arena, hfx_diags *diags, const d3d9_input *in) {
    d3d9_reader r = {0};
    r.arena = arena;
    r.diags = diags;
    r.in = in;
    r.bytes = in->data;
    r.words = in->size / 4;
    r.sh = HFX_NEW(arena, d3d9_shader);
    r.sh->file_index = in->file;
    r.sh->base = in->base;
    r.sh->file = in->file < diags->file_count ? diags->files[in->file].name : "";
    uint32_t errors = diags->errors;
    if (!read_version(&r)) return NULL;
    uint32_t i = 1;
    bool ended = false;
    while (i < r.words) {
        uint32_t tok = hfx_d3d9_word(&r, i);
        if (tok == 0x0000ffffu) { ended = true; break; }
        if ((tok & 0xffff) == D3D9_COMMENT) {
            uint32_t n = (tok >> 16) & 0x7fff;
            if ((uint64_t)i + 1 + n > r.words) {
                hfx_d3d9_fail(&r, i, X_D3D9_TRUNCATED, "comment of %u words runs past the end of the shader", n);
                return NULL;
            }
            read_comment(&r, i, n);
            i += 1 + n;
            continue;
        }
        i = read_inst(&r, i);
        if (i == UINT32_MAX) return NULL;
    }
    if (!ended) hfx_d3d9_fail(&r, r.words, X_D3D9_TRUNCATED, "no END token");
    else if (r.depth) hfx_d3d9_fail(&r, i, X_D3D9_FLOW, "%u flow-control block%s not closed at END", r.depth,
                                r.depth == 1 ? "" : "s");
    return diags->errors == errors ? r.sh : NULL;
}

bool hfx_d3d9_is_shader(const void *data, size_t size) {
    if (size < 8) return false;
    const unsigned char *p = data;
    uint32_t kind = (uint32_t)p[2] | (uint32_t)p[3] << 8;
    if (kind != 0xfffe && kind != 0xffff) return false;
    return p[1] < 16 && p[0] < 16 && model_known(kind == 0xfffe ? D3D9_VS : D3D9_PS, (uint8_t)D3D9_SM(p[1], p[0]));
}

int hfx_d3d9_disassemble_blob(hfx_arena *arena, hfx_diags *diags, const d3d9_input *in, sbuf *out) {
    d3d9_shader *s = hfx_d3d9_decode(arena, diags, in);
    if (!s) return -1;
    hfx_d3d9_disassemble(s, out);
    return 0;
}
