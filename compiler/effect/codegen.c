/* codegen.c: one GLSL program per pass. Builds the IR of both stages, lowers it, agrees on
 * the interface between them (attributes at the Cg/NVIDIA locations, varyings by semantic, less
 * the derived ones the pixel stage computes: ir/lower/varyings.c, on per-program copies of the
 * shared stages) and prints every requested target; records attributes, samplers and uniforms
 * read. */
#include "effect/codegen.h"

#include <stdlib.h>
#include <string.h>

#include "bytecode/bytecode.h"
#include "glsl/glsl.h"

/* A stage built and lowered once: programs share it (BasicEffect's 32 programs use 20 vertex
 * and 4 pixel shaders; the IR is only read after lowering). */
typedef struct built_stage {
    const hfx_expr *compile;
    ir_stage stage;
    ir_shader *sh;  /* NULL when it failed */
    const uint32_t *code; uint32_t words; bool code_tried; /* its D3D9 bytecode (HFXC_D3D9_BYTECODE) */
} built_stage;

struct hfx_codegen {
    ir_ctx c;
    unsigned targets;
    bool pack;
    hfx_same_compile_fn same;
    void *same_ctx;
    built_stage *built;
    uint32_t built_count, built_cap;
    bool alpha_test;
};

void hfx_codegen_set_alpha_test(hfx_codegen *cg, bool on) { cg->alpha_test = on; }

hfx_codegen *hfx_codegen_new(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                             hfx_fx_effect *fx, unsigned targets, bool pack, hfx_same_compile_fn same, void *same_ctx) {
    hfx_codegen *cg = HFX_NEW(arena, hfx_codegen);
    if (!cg) return NULL;
    cg->c = (ir_ctx){ arena, diags, types, ast, fx };
    cg->targets = targets;
    cg->pack = pack;
    cg->same = same;
    cg->same_ctx = same_ctx;
    return cg;
}

typedef struct strset { const char **items; uint32_t count, cap; } strset;

static bool set_has(const strset *s, const char *x) {
    for (uint32_t i = 0; i < s->count; i++)
        if (strcmp(s->items[i], x) == 0) return true;
    return false;
}

static void set_add(hfx_arena *a, strset *s, const char *x) {
    if (set_has(s, x)) return;
    if (!HFX_ARENA_GROW(a, s->items, s->count, s->cap, 16)) return;
    s->items[s->count++] = x;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

static bool is_varying(const char *sem, bool pixel_input) {
    if (pixel_input) return strncmp(sem, "VPOS", 4) != 0 && strncmp(sem, "POSITION", 8) != 0 && strncmp(sem, "VFACE", 5) != 0;
    return strcmp(sem, "POSITION0") != 0 && strncmp(sem, "PSIZE", 5) != 0;
}

/* The Cg / NVIDIA attribute aliasing: POSITION0=0, BLENDWEIGHT0=1, NORMAL0=2, COLOR0=3,
 * COLOR1=4, FOG0=5, PSIZE0=6, BLENDINDICES0=7, TEXCOORD0..7=8..15; TANGENT0 / BINORMAL0 take
 * 14 / 15 when TEXCOORD6 / 7 are free; anything else the lowest free location. */
static int fixed_location(const char *sem) {
    static const struct { const char *s; int loc; } t[] = {
        {"POSITION0", 0}, {"BLENDWEIGHT0", 1}, {"NORMAL0", 2}, {"COLOR0", 3}, {"COLOR1", 4}, {"FOG0", 5},
        {"PSIZE0", 6}, {"BLENDINDICES0", 7},
    };
    for (size_t i = 0; i < sizeof t / sizeof *t; i++)
        if (strcmp(t[i].s, sem) == 0) return t[i].loc;
    if (strncmp(sem, "TEXCOORD", 8) == 0 && sem[8] >= '0' && sem[8] <= '7' && !sem[9]) return 8 + sem[8] - '0';
    return -1;
}

static int cmp_attr(const void *a, const void *b) {
    return ((const hfx_fx_attribute *)a)->location - ((const hfx_fx_attribute *)b)->location;
}

static hfx_fx_attribute *assign_locations(hfx_arena *a, const strset *sems) {
    hfx_fx_attribute *at = HFX_NEW_ARRAY(a, hfx_fx_attribute, sems->count + 1);
    bool taken[64] = {0};
    for (uint32_t i = 0; i < sems->count; i++) {
        at[i].semantic = (char *)sems->items[i];
        at[i].glsl_name = hfx_arena_printf(a, "hfx_a_%s", sems->items[i]);
        at[i].location = fixed_location(sems->items[i]);
        if (at[i].location >= 0) taken[at[i].location] = true;
    }
    for (uint32_t i = 0; i < sems->count; i++) {
        if (at[i].location >= 0) continue;
        if (strcmp(at[i].semantic, "TANGENT0") == 0 && !taken[14]) at[i].location = 14;
        else if (strcmp(at[i].semantic, "BINORMAL0") == 0 && !taken[15]) at[i].location = 15;
        else for (int l = 0; l < 64; l++) if (!taken[l]) { at[i].location = l; break; }
        if (at[i].location >= 0) taken[at[i].location] = true;
    }
    qsort(at, sems->count, sizeof *at, cmp_attr);
    return at;
}

static ir_shader *build_stage(hfx_codegen *cg, const hfx_expr *e, ir_stage st) {
    uint32_t errors = cg->c.diags->errors;
    ir_shader *sh = hfx_ir_build(&cg->c, e, st);
    bool preshade = cg->pack && !(cg->c.diags->flags & HFXC_NO_PRESHADERS);
    unsigned opts = (cg->pack ? IR_LOWER_PACKED : 0) | (preshade ? IR_LOWER_PRESHADE : 0);
    if (!sh || cg->c.diags->errors > errors || hfx_ir_lower(&cg->c, sh, opts) != 0) return NULL;
    return sh;
}

static const built_stage *find_built(const hfx_codegen *cg, const hfx_expr *e, ir_stage st) {
    for (uint32_t i = 0; i < cg->built_count; i++) {
        const built_stage *b = &cg->built[i];
        if (b->stage == st && (b->compile == e || (cg->same && cg->same(cg->same_ctx, b->compile, e)))) return b;
    }
    return NULL;
}

/* The lowered shader of a compile expression (*sh NULL for no shader); false when it failed. */
static bool stage(hfx_codegen *cg, const hfx_expr *e, ir_stage st, ir_shader **sh) {
    *sh = NULL;
    if (!e || e->kind == EX_NULL) return true;
    if (e->kind != EX_COMPILE) {
        hfx_error(cg->c.diags, e->loc, X_UNSUPPORTED, "%s", e->kind == EX_ASM ? "asm blocks are not supported"
                                                                                 : "shader must be a compile expression");
        return false;
    }
    const built_stage *b = find_built(cg, e, st);
    if (b) return (*sh = b->sh) != NULL;
    *sh = build_stage(cg, e, st);
    if (HFX_ARENA_GROW(cg->c.arena, cg->built, cg->built_count, cg->built_cap, 8))
        cg->built[cg->built_count++] = (built_stage){e, st, *sh, NULL, 0, false};
    return *sh != NULL;
}

static char *dup_str(const char *s) {
    size_t n = strlen(s);
    char *d = malloc(n + 1);
    if (d) memcpy(d, s, n + 1);
    return d;
}

/* Samplers and uniforms the program reads: vertex stage first, in first-use order. */
static int record_uses(hfx_codegen *cg, ir_shader *const sh[2], hfx_fx_program *out) {
    hfx_fx_effect *fx = cg->c.fx;
    uint32_t total = 0;
    for (int s = 0; s < 2; s++) if (sh[s]) total += sh[s]->global_count;
    out->samplers = calloc(total + 1, sizeof *out->samplers);
    out->uniforms = calloc(total + 1, sizeof *out->uniforms);
    if (!out->samplers || !out->uniforms) return -1;
    for (int s = 0; s < 2; s++) {
        if (!sh[s]) continue;
        for (uint32_t i = 0; i < sh[s]->global_count; i++) {
            const ir_var *v = sh[s]->globals[i];
            if (v->param == HFX_NONE || (v->kind != IRV_SAMPLER && v->kind != IRV_UNIFORM)) continue;
            if (v->kind == IRV_SAMPLER) {
                uint32_t si = fx->params[v->param].sampler;
                bool seen = false;
                for (uint32_t k = 0; k < out->sampler_count; k++) seen |= strcmp(out->samplers[k].glsl_name, v->glsl) == 0;
                if (seen) continue;
                hfx_fx_sampler_use *u = &out->samplers[out->sampler_count];
                if (!(u->glsl_name = dup_str(v->glsl))) return -1;
                u->sampler = si;
                u->unit = (int32_t)out->sampler_count++;
                if (si != HFX_NONE && si < fx->sampler_count)
                    fx->samplers[si].dim = v->dim == DIM_CUBE ? HFX_FX_DIM_CUBE : v->dim == DIM_3D ? HFX_FX_DIM_3D
                                          : v->dim == DIM_1D ? HFX_FX_DIM_1D : HFX_FX_DIM_2D;
            } else {
                bool seen = false;
                for (uint32_t k = 0; k < out->uniform_count; k++) seen |= out->uniforms[k].param == v->param;
                if (!seen) out->uniforms[out->uniform_count++] = (hfx_fx_uniform_use){.param = v->param, .reg = HFX_NONE};
            }
        }
    }
    return 0;
}

static int cmp_uniform(const void *a, const void *b) {
    uint32_t x = ((const hfx_fx_uniform_use *)a)->param, y = ((const hfx_fx_uniform_use *)b)->param;
    return x < y ? -1 : x > y;
}

/* D3D9's vs_3_0 has 256 float constant registers; past them the rest stay separate uniforms,
 * so a program reading more than that still links wherever it did before. */
enum { MAX_PACKED_REGS = 256 };

/* How the pixel stage reads a parameter, which decides where its registers go. */
typedef enum { READ_BY_PIXELS, COPIED_BY_PIXELS, VERTEX_ONLY } pixel_read;

static pixel_read pixel_read_of(const ir_shader *ps, uint32_t param) {
    for (uint32_t i = 0; ps && i < ps->global_count; i++) {
        const ir_var *v = ps->globals[i];
        if (v->kind == IRV_UNIFORM && v->param == param) return v->priv ? COPIED_BY_PIXELS : READ_BY_PIXELS;
    }
    return VERTEX_ONLY;
}

/* HFXC_PACK_UNIFORMS: the next registers for the parameters read as `how` (reads[k] for
 * uniform k), in the order of the uniform table; once one does not fit (*full), no later one is
 * packed. */
static void assign_registers(const hfx_fx_effect *fx, const pixel_read *reads, pixel_read how, hfx_fx_program *p,
                             bool *full) {
    for (uint32_t k = 0; k < p->uniform_count; k++) {
        uint32_t n = hfx_fx_param_packable(fx, p->uniforms[k].param);
        if (*full || !n || reads[k] != how) continue;
        if (p->reg_count + n > MAX_PACKED_REGS) { *full = true; continue; }
        p->uniforms[k].reg = p->reg_count;
        p->reg_count += n;
    }
}

/* The preshaders' variables and registers, for the GLSL printer. */
typedef struct pre_file { const ir_var **vars; uint32_t *regs, count; } pre_file;

/* The next registers for a stage's preshaders; their code is copied into out. */
static void assign_preshaders(const ir_shader *sh, hfx_fx_program *out, pre_file *f) {
    for (uint32_t i = 0; sh && i < sh->pre_count; i++) {
        const ir_var *v = sh->pres[i];
        const hfx_type *t = v->type;
        hfx_fx_preshader *q = &out->preshaders[out->preshader_count];
        *q = (hfx_fx_preshader){out->pre_words, v->pre_words, out->reg_count, t->kind == TY_MATRIX ? t->rows : 1, t->cols};
        memcpy(out->pre_code + out->pre_words, v->pre_code, v->pre_words * sizeof *v->pre_code);
        out->pre_words += v->pre_words;
        f->vars[f->count] = v;
        f->regs[f->count++] = out->reg_count;
        out->preshader_count++;
        out->reg_count += q->rows;
    }
}

static int alloc_preshaders(hfx_codegen *cg, ir_shader *const sh[2], hfx_fx_program *out, pre_file *f) {
    uint32_t n = 0, words = 0;
    for (int s = 0; s < 2; s++)
        for (uint32_t i = 0; sh[s] && i < sh[s]->pre_count; i++) n++, words += sh[s]->pres[i]->pre_words;
    if (!n) return 0;
    f->vars = HFX_NEW_ARRAY(cg->c.arena, const ir_var *, n);
    f->regs = HFX_NEW_ARRAY(cg->c.arena, uint32_t, n);
    out->preshaders = calloc(n, sizeof *out->preshaders);
    out->pre_code = malloc(words * sizeof *out->pre_code);
    return f->vars && f->regs && out->preshaders && out->pre_code ? 0 : -1;
}

/* The register file, pixel stage first: what it reads as is, its preshaders, the parameters it
 * copies before writing them, then the vertex stage's parameters and preshaders. A fragment
 * shader runs for every pixel, and llvmpipe (Mesa 22.3) compiles it measurably worse when it
 * does not read hfx_c[0]: the directional seed's pixel shader took 12 M instructions more per
 * 2048 x 2048 frame (5 %) with its registers at 5, 6 and 11 than at 0, 1 and 11
 * (bench/gpu_instructions.sh). Preshaders are never left out: the preshade pass keeps each
 * stage's parameters and preshaders within half of MAX_PACKED_REGS, so they fit. */
static int assign_register_file(hfx_codegen *cg, ir_shader *const sh[2], hfx_fx_program *out, glsl_iface *io) {
    pre_file f = {0};
    bool full = !cg->pack; /* without packing no parameter takes a register */
    if (alloc_preshaders(cg, sh, out, &f) != 0) return -1;
    pixel_read *reads = HFX_NEW_ARRAY(cg->c.arena, pixel_read, out->uniform_count ? out->uniform_count : 1);
    if (!reads) return -1;
    for (uint32_t k = 0; k < out->uniform_count; k++) reads[k] = pixel_read_of(sh[1], out->uniforms[k].param);
    assign_registers(cg->c.fx, reads, READ_BY_PIXELS, out, &full);
    assign_preshaders(sh[1], out, &f);
    assign_registers(cg->c.fx, reads, COPIED_BY_PIXELS, out, &full);
    assign_registers(cg->c.fx, reads, VERTEX_ONLY, out, &full);
    assign_preshaders(sh[0], out, &f);
    io->pre_vars = f.vars;
    io->pre_regs = f.regs;
    io->pre_count = f.count;
    return 0;
}

/* Whether a stage keeps a private copy of parameter `param` (a function writes it). */
static bool copied_by(const ir_shader *sh, uint32_t param) {
    for (uint32_t i = 0; sh && i < sh->global_count; i++)
        if (sh->globals[i]->kind == IRV_UNIFORM && sh->globals[i]->param == param && sh->globals[i]->priv) return true;
    return false;
}

/* Switches (common/effect.h): the first HFX_FX_MAX_SWITCHES bool parameters the program reads
 * as they are. A branch on a uniform bool costs a pixel shader on llvmpipe about as much as a
 * distance and a division (point.fx's `if (atenuado)`: 2.8 % of a frame); a variant with the
 * bool a constant costs nothing, as the #ifdef a graphics programmer would write. */
static void mark_switches(const hfx_fx_effect *fx, ir_shader *const sh[2], hfx_fx_program *out) {
    uint32_t n = 0;
    for (uint32_t k = 0; k < out->uniform_count && n < HFX_FX_MAX_SWITCHES; k++) {
        hfx_fx_uniform_use *u = &out->uniforms[k];
        if (hfx_fx_use_packed(out, u) || !hfx_fx_param_switchable(fx, u->param)) continue;
        if (copied_by(sh[0], u->param) || copied_by(sh[1], u->param)) continue;
        u->flags |= HFX_FX_USE_SWITCH;
        n++;
    }
}

/* The derived varyings (io->derived) out of a set of semantics. */
static void drop_derived(strset *s, const glsl_iface *io) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->count; i++)
        if (!hfx_glsl_iface_derived(io, s->items[i])) s->items[n++] = s->items[i];
    s->count = n;
}

/* flat_colors: the pass sets ShadeMode = FLAT, under which D3D9 does not interpolate COLOR inputs. */
static int build_interface(hfx_codegen *cg, ir_shader *vs, ir_shader *ps, bool flat_colors, glsl_iface *io) {
    hfx_arena *a = cg->c.arena;
    strset vary = {0}, writes = {0}, attrs = {0}, flat = {0};
    ir_leaf *l;
    int n;
    if (ps) {
        if ((n = hfx_ir_entry_leaves(&cg->c, ps->entry, false, &l)) < 0) return -1;
        for (int i = 0; i < n; i++) {
            if (!is_varying(l[i].semantic, true)) continue;
            set_add(a, &vary, l[i].semantic);
            if (l[i].flat) set_add(a, &flat, l[i].semantic);
        }
    }
    if (vs) {
        if ((n = hfx_ir_entry_leaves(&cg->c, vs->entry, true, &l)) < 0) return -1;
        for (int i = 0; i < n; i++)
            if (is_varying(l[i].semantic, false)) {
                set_add(a, &vary, l[i].semantic);
                set_add(a, &writes, l[i].semantic);
                if (l[i].flat) set_add(a, &flat, l[i].semantic); /* either stage's nointerpolation makes it flat */
            }
        if ((n = hfx_ir_entry_leaves(&cg->c, vs->entry, false, &l)) < 0) return -1;
        for (int i = 0; i < n; i++) set_add(a, &attrs, l[i].semantic);
    } else { /* fixed-function stand-in: position plus whatever the pixel shader reads */
        set_add(a, &attrs, "POSITION0");
        for (uint32_t i = 0; i < vary.count; i++) { set_add(a, &attrs, vary.items[i]); set_add(a, &writes, vary.items[i]); }
    }
    for (uint32_t i = 0; i < vary.count && flat_colors; i++)
        if (strncmp(vary.items[i], "COLOR", 5) == 0) set_add(a, &flat, vary.items[i]);
    drop_derived(&vary, io);
    drop_derived(&writes, io);
    if (vary.count) qsort(vary.items, vary.count, sizeof *vary.items, cmp_str);
    io->varyings = vary.items;
    io->varying_count = vary.count;
    io->vs_writes = writes.items;
    io->vs_write_count = writes.count;
    io->flat = flat.items;
    io->flat_count = flat.count;
    io->attrs = assign_locations(a, &attrs);
    io->attr_count = attrs.count;
    const char *prof = vs && vs->compile && vs->compile->profile ? vs->compile->profile : "vs_3_0";
    io->stages[0] = vs, io->stages[1] = ps;
    io->clamp_vs_colors = strncmp(prof, "vs_1", 4) == 0 || strncmp(prof, "vs_2", 4) == 0;
    io->clamp_ps1_texcoords = ps && ps->compile && hfx_glsl_ps1_clamps(ps->compile->profile);
    return 0;
}

static int copy_attributes(const glsl_iface *io, hfx_fx_program *out) {
    out->attributes = calloc(io->attr_count + 1, sizeof *out->attributes);
    if (!out->attributes) return -1;
    for (uint32_t i = 0; i < io->attr_count; i++) {
        out->attributes[i].semantic = dup_str(io->attrs[i].semantic);
        out->attributes[i].glsl_name = dup_str(io->attrs[i].glsl_name);
        out->attributes[i].location = io->attrs[i].location;
        out->attribute_count++;
        if (!out->attributes[i].semantic || !out->attributes[i].glsl_name) return -1;
    }
    return 0;
}

/* The pixel stage carries the alpha test when it writes COLOR0 (the stand-in always does). */
static bool writes_color0(hfx_codegen *cg, const ir_shader *ps) {
    if (!ps) return true;
    ir_leaf *l;
    int n = hfx_ir_entry_leaves(&cg->c, ps->entry, true, &l);
    for (int i = 0; i < n; i++)
        if (strcmp(l[i].semantic, "COLOR0") == 0) return true;
    return false;
}

/* HFXC_TEST_BREAK_GLSL: a code generator with a bug, for the self-check's own test. */
static char *spoil(char *text) {
    static const char bad[] = "\nhfx_broken_token\n";
    size_t n = strlen(text);
    char *p = realloc(text, n + sizeof bad);
    if (!p) return text;
    memcpy(p + n, bad, sizeof bad);
    return p;
}

/* One stage for one target; ES 300 from the GLSL 330 text already printed, when there is one. */
static char *print_stage(hfx_codegen *cg, const ir_shader *sh, int s, const glsl_iface *io, hfx_target t,
                         const hfx_fx_program *out) {
    const char *twin = t == HFX_TARGET_GLSLES300 ? out->code[s][HFX_TARGET_GLSL330].data : NULL;
    char *text = twin && !(cg->c.diags->flags & HFXC_TEST_BREAK_GLSL) ? hfx_glsl_retarget(twin, HFX_TARGET_GLSL330, t) : NULL;
    return text ? text : hfx_glsl_print(&cg->c, sh, s == 0 ? IR_VERTEX : IR_PIXEL, io, t);
}

/* The program of two lowered stages (either may be NULL: the fixed-function stand-in); `loc`
 * for an out-of-memory error. */
static int program_of(hfx_codegen *cg, ir_shader *sh[2], bool flat_colors, hfx_loc loc, hfx_fx_program *out) {
    glsl_iface io = {0};
    ir_program p = {sh[0], sh[1], (cg->pack ? IR_LOWER_PACKED : 0) |
                    (cg->c.diags->flags & HFXC_NO_DERIVED_VARYINGS ? 0 : IR_LOWER_DERIVE), NULL, 0};
    hfx_ir_lower_program(&cg->c, &p);
    sh[0] = p.vs;
    sh[1] = p.ps;
    io.derived = p.derived;
    io.derived_count = p.derived_count;
    if (build_interface(cg, sh[0], sh[1], flat_colors, &io) != 0) return -1;
    if (copy_attributes(&io, out) != 0 || record_uses(cg, sh, out) != 0) goto oom;
    qsort(out->uniforms, out->uniform_count, sizeof *out->uniforms, cmp_uniform);
    if (assign_register_file(cg, sh, out, &io) != 0) goto oom;
    mark_switches(cg->c.fx, sh, out);
    io.uniforms = out->uniforms;
    io.uniform_count = out->uniform_count;
    io.reg_count = out->reg_count;
    io.alpha_test = cg->alpha_test;
    /* The SPIR-V targets' GLSL (glsl_spirv.c) needs both stages' uniforms and structs, which
     * their GLSL 330 records; glslang makes the words later (build.c). */
    glsl_record rec[2] = {{0}};
    bool spirv = cg->targets & (3u << HFX_TARGET_SPIRV);
    io.fx = cg->c.fx;
    io.prog = out;
    io.records[0] = &rec[0];
    io.records[1] = &rec[1];
    for (int t = 0; t < HFX_TARGET_COUNT; t++) {
        if (!(cg->targets & (1u << t))) continue;
        for (int s = 0; s < 2; s++) {
            io.record = spirv && t == HFX_TARGET_GLSL330 ? &rec[s] : NULL;
            char *text = print_stage(cg, sh[s], s, &io, (hfx_target)t, out);
            if (!text) return -1;
            if (cg->c.diags->flags & HFXC_TEST_BREAK_GLSL) text = spoil(text);
            out->code[s][t].data = text;
            out->code[s][t].size = strlen(text);
        }
    }
    if (cg->alpha_test && writes_color0(cg, sh[1])) out->flags |= HFX_FX_PROGRAM_ALPHA_TEST;
    return 0;
oom:
    hfx_error(cg->c.diags, loc, X_MEMORY_LIMIT, "out of memory");
    return -1;
}

static int via_bytecode(hfx_codegen *cg, const hfx_expr *vs, const hfx_expr *ps, bool flat_colors, hfx_fx_program *out);
static bool keep_bytecode(hfx_codegen *cg, const hfx_expr *e, bool pixel, hfx_fx_code *out);

int hfx_codegen_program(hfx_codegen *cg, const hfx_expr *vs, const hfx_expr *ps, bool flat_colors, hfx_fx_program *out) {
    int r = (cg->c.diags->flags & HFXC_VIA_D3D9) ? via_bytecode(cg, vs, ps, flat_colors, out) : -1;
    if (!(cg->c.diags->flags & HFXC_VIA_D3D9)) {
        memset(out, 0, sizeof *out);
        ir_shader *sh[2];
        bool vs_ok = stage(cg, vs, IR_VERTEX, &sh[0]), ps_ok = stage(cg, ps, IR_PIXEL, &sh[1]);
        if (!vs_ok || !ps_ok) return -1;
        r = program_of(cg, sh, flat_colors, vs ? vs->loc : ps ? ps->loc : (hfx_loc){0, 1, 1}, out);
    }
    if (r != 0 || !(cg->c.diags->flags & HFXC_D3D9_BYTECODE)) return r;
    /* both stages tried, so that each reports its own errors */
    bool vs_ok = keep_bytecode(cg, vs, false, &out->d3d9[0]), ps_ok = keep_bytecode(cg, ps, true, &out->d3d9[1]);
    return vs_ok && ps_ok ? 0 : -1;
}

/* A bytecode stage: translated (d3d9/d3d9_ir.c), lowered like a compiled one. */
static bool bytecode_stage(hfx_codegen *cg, const d3d9_shader *s, ir_shader **sh) {
    *sh = NULL;
    if (!s) return true;
    uint32_t errors = cg->c.diags->errors;
    ir_shader *x = hfx_d3d9_to_ir(&cg->c, s, cg->pack);
    /* fxc made its preshaders already (d3d9_ir.c reads them): no preshade rows */
    if (!x || cg->c.diags->errors > errors || hfx_ir_lower(&cg->c, x, cg->pack ? IR_LOWER_PACKED : 0) != 0) return false;
    return (*sh = x) != NULL;
}

int hfx_codegen_d3d9_program(hfx_codegen *cg, const d3d9_shader *vs, const d3d9_shader *ps, bool flat_colors,
                             hfx_fx_program *out) {
    memset(out, 0, sizeof *out);
    ir_shader *sh[2];
    bool vs_ok = bytecode_stage(cg, vs, &sh[0]), ps_ok = bytecode_stage(cg, ps, &sh[1]);
    if (!vs_ok || !ps_ok) return -1;
    const d3d9_shader *at = vs ? vs : ps;
    hfx_loc loc = at ? (hfx_loc){at->file_index, 0, at->base} : (hfx_loc){0, 1, 1};
    return program_of(cg, sh, flat_colors, loc, out);
}

const uint32_t *hfx_codegen_bytecode(hfx_codegen *cg, const hfx_expr *compile, bool pixel, uint32_t *count) {
    *count = 0;
    if (!compile || compile->kind != EX_COMPILE) return NULL;
    uint32_t errors = cg->c.diags->errors;
    ir_shader *sh = hfx_ir_build(&cg->c, compile, pixel ? IR_PIXEL : IR_VERTEX); /* lowered without preshaders */
    if (!sh || cg->c.diags->errors > errors || hfx_ir_lower(&cg->c, sh, 0) != 0) return NULL;
    return hfx_bc_write(&cg->c, sh, compile->profile, count);
}

const uint32_t *hfx_codegen_entry_bytecode(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                           hfx_fx_effect *fx, const char *entry, const char *profile, uint32_t *count) {
    hfx_decl *fn = NULL;
    for (uint32_t i = 0; ast && i < ast->decl_count; i++) {
        hfx_decl *d = ast->decls[i];
        if (d->kind == DECL_FUNC && d->func && d->name && strcmp(d->name, entry) == 0 && (!fn || d->func->body)) fn = d;
    }
    hfx_codegen *cg = fn ? hfx_codegen_new(arena, diags, types, ast, fx, 0, false, NULL, NULL) : NULL;
    hfx_expr *c = cg ? HFX_NEW(arena, hfx_expr) : NULL;
    if (!c) return NULL;
    c->kind = EX_COMPILE;
    c->loc = fn->loc;
    c->name = entry;
    c->profile = profile;
    c->intrinsic = -1;
    c->fn = fn->func->definition ? fn->func->definition : fn->func;
    return hfx_codegen_bytecode(cg, c, profile[0] == 'p' || profile[0] == 'P', count);
}

/* HFXC_D3D9_BYTECODE: a stage's bytecode kept in the program (malloc'ed: the effect owns it) for
 * fx_2_0's writer. A stage that is no `compile` (NULL, absent) has none. */
static bool keep_bytecode(hfx_codegen *cg, const hfx_expr *e, bool pixel, hfx_fx_code *out) {
    if (!e || e->kind != EX_COMPILE) return true;
    /* once per distinct stage, as the GLSL: a shader shared by many programs reports its errors once */
    built_stage *b = (built_stage *)find_built(cg, e, pixel ? IR_PIXEL : IR_VERTEX);
    uint32_t n = b && b->code_tried ? b->words : 0;
    const uint32_t *w = b && b->code_tried ? b->code : hfx_codegen_bytecode(cg, e, pixel, &n);
    if (b) b->code = w, b->words = n, b->code_tried = true;
    if (!w) return false;
    if (!(out->data = malloc((size_t)n * 4))) {
        hfx_error(cg->c.diags, e->loc, X_MEMORY_LIMIT, "out of memory");
        return false;
    }
    memcpy(out->data, w, (size_t)n * 4);
    out->size = (size_t)n * 4;
    return true;
}

/* HFXC_VIA_D3D9: each stage written as bytecode for its profile, decoded and translated back
 * (hfx_codegen_d3d9_program), so every drawing test can run through the bytecode back end. */
static const d3d9_shader *bytecode_of(hfx_codegen *cg, const hfx_expr *e, bool pixel, bool *ok) {
    if (!e || e->kind == EX_NULL) return NULL;
    uint32_t n = 0;
    const uint32_t *w = hfx_codegen_bytecode(cg, e, pixel, &n);
    if (!w) { *ok = false; return NULL; }
    d3d9_input in = {w, n * 4, hfx_diags_add_file(cg->c.diags, pixel ? "ps.bytecode" : "vs.bytecode", NULL, "", 0), 0};
    const d3d9_shader *s = hfx_d3d9_decode(cg->c.arena, cg->c.diags, &in);
    *ok &= s != NULL;
    return s;
}

static int via_bytecode(hfx_codegen *cg, const hfx_expr *vs, const hfx_expr *ps, bool flat_colors, hfx_fx_program *out) {
    memset(out, 0, sizeof *out);
    bool ok = true;
    const d3d9_shader *v = bytecode_of(cg, vs, false, &ok), *p = bytecode_of(cg, ps, true, &ok);
    return ok ? hfx_codegen_d3d9_program(cg, v, p, flat_colors, out) : -1;
}
