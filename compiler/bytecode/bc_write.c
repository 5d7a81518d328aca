/* bc_write.c: one stage to bytecode: the model from the profile, the entry's interface,
 * parameters and samplers, the body, then the encoded shader decoded again by compiler/d3d9
 * (a malformed stream is hfx's bug: an internal error at the entry) and held to fxc's limits
 * for the model (instruction slots, temporaries, constants). */
#include <stdlib.h>

#include "bytecode/bc_int.h"

typedef struct bc_model { const char *name; d3d9_stage stage; uint8_t model; uint32_t consts, arith, tex; } bc_model;

/* fxc's limits (Microsoft's "Shader model" pages: instruction slots, constant registers). */
static const bc_model models[] = {
    {"vs_2_0", D3D9_VS, D3D9_SM(2, 0), 256, 256, 0}, {"vs_2_a", D3D9_VS, D3D9_SM(2, 1), 256, 256, 0},
    {"vs_3_0", D3D9_VS, D3D9_SM(3, 0), 256, 512, 0}, {"ps_2_0", D3D9_PS, D3D9_SM(2, 0), 32, 64, 32},
    {"ps_2_a", D3D9_PS, D3D9_SM(2, 1), 32, 512, 512}, {"ps_2_b", D3D9_PS, D3D9_SM(2, 1), 32, 512, 512},
    {"ps_3_0", D3D9_PS, D3D9_SM(3, 0), 224, 512, 512},
};

static const bc_model *find_model(bc_gen *g, const char *profile, hfx_loc loc) {
    for (size_t i = 0; i < sizeof models / sizeof *models; i++)
        if (strcmp(models[i].name, profile) == 0) return &models[i];
    bool vs1 = strcmp(profile, "vs_1_1") == 0, ps1 = strncmp(profile, "ps_1_", 5) == 0 && profile[5] >= '1' && profile[5] <= '4' && !profile[6];
    if (vs1 || ps1) {
        hfx_warning(g->c->diags, loc, 3206 + 1, "%s is written as %s (hfx does not write the 1.x models)", profile,
                    vs1 ? "vs_2_0" : "ps_2_0");
        return &models[vs1 ? 0 : 3];
    }
    hfx_bc_fail(g, loc, 3506, "the bytecode writer has no model '%s' (vs_2_0, vs_2_a, vs_3_0, ps_2_0, ps_2_a, ps_2_b, ps_3_0)",
            profile);
    return NULL;
}

static void gen_entry(bc_gen *g) {
    const ir_func *f = g->sh->entry;
    ir_leaf *in = NULL, *out = NULL;
    int nin = hfx_ir_entry_leaves(g->c, f, false, &in), nout = hfx_ir_entry_leaves(g->c, f, true, &out);
    if (nin < 0 || nout < 0) { g->failed = true; return; }
    bc_obj *outs = HFX_NEW_ARRAY(g->c->arena, bc_obj, f->param_count ? f->param_count : 1);
    for (uint32_t i = 0; i < f->param_count && !g->failed; i++) {
        const ir_var *p = f->params[i];
        bool is_out = (p->mods & MOD_OUT) != 0, is_in = !is_out || (p->mods & MOD_IN);
        bc_obj o = {0};
        if (is_in) o = hfx_bc_obj_inputs(g, in, nin, p, p->type);
        if (is_out) outs[i] = hfx_bc_obj_outputs(g, out, nout, p, p->type);
        /* outputs are write only: temporaries the body writes; an input the body writes is
         * copied slot by slot when written (the bindings copy on write) */
        if (!is_in) o = hfx_bc_alloc_obj(g, p->type);
        hfx_bc_bind_entry(g, p, o, !is_in);
    }
    bc_obj ret = {0}, regs = {0};
    if (f->ret && f->ret->kind != TY_VOID) {
        regs = hfx_bc_obj_outputs(g, out, nout, NULL, f->ret);
        ret = hfx_bc_straight_return(f->body) ? regs : hfx_bc_alloc_obj(g, f->ret);
    }
    g->ret = &ret;
    hfx_bc_init_privates(g);
    hfx_bc_gen_body(g, f->body);
    if (ret.count && ret.slot != regs.slot) hfx_bc_assign(g, regs, ret, f->ret, false);
    for (uint32_t i = 0; i < f->param_count && !g->failed; i++) {
        bc_binding *b = (f->params[i]->mods & MOD_OUT) ? hfx_bc_bind(g, f->params[i]) : NULL;
        if (b) hfx_bc_assign(g, outs[i], b->obj, f->params[i]->type, false);
    }
}

/* The encoded shader read back: the decoder's checks, then the model's limits. */
static bool verify(bc_gen *g, const bc_model *m, const uint32_t *w, uint32_t n, hfx_loc at) {
    hfx_diags d;
    hfx_diags_init(&d, g->c->arena, 0);
    d3d9_input input = {w, n * 4, hfx_diags_add_file(&d, "bytecode", NULL, "", 0), 0};
    d3d9_shader *s = hfx_d3d9_decode(g->c->arena, &d, &input);
    if (!s) {
        hfx_error(g->c->diags, at, 5999, "internal error: the bytecode written for %s does not validate: %s", m->name,
                  d.count ? d.items[0].message : "?");
        return false;
    }
    uint32_t arith, tex;
    hfx_d3d9_count_slots(s, &arith, &tex);
    if (m->tex) {
        if (arith > m->arith)
            hfx_error(g->c->diags, at, 5608, "Compiled shader code uses too many arithmetic instruction slots (%u). Max. allowed by the target (%s) is %u.", arith, m->name, m->arith);
        if (tex > m->tex)
            hfx_error(g->c->diags, at, 5609, "Compiled shader code uses too many texture instruction slots (%u). Max. allowed by the target (%s) is %u.", tex, m->name, m->tex);
        return arith <= m->arith && tex <= m->tex;
    }
    if (arith + tex > m->arith) {
        hfx_error(g->c->diags, at, 5608, "Compiled shader code uses too many instruction slots (%u). Max. allowed by the target (%s) is %u.", arith + tex, m->name, m->arith);
        return false;
    }
    return true;
}

/* The code and the constants as they are before a pass the writer may take back. */
typedef struct bc_saved { d3d9_inst *insts; uint32_t inst_count; bc_ctab *ctab; uint32_t ctab_count; bc_def *defs; uint32_t def_count; } bc_saved;

static bool save(bc_gen *g, bc_saved *s) {
    s->inst_count = g->inst_count;
    s->ctab_count = g->ctab_count;
    s->def_count = g->def_count;
    s->insts = HFX_NEW_ARRAY(g->c->arena, d3d9_inst, g->inst_count ? g->inst_count : 1);
    s->ctab = HFX_NEW_ARRAY(g->c->arena, bc_ctab, g->ctab_count ? g->ctab_count : 1);
    s->defs = HFX_NEW_ARRAY(g->c->arena, bc_def, g->def_count ? g->def_count : 1);
    if (!s->insts || !s->ctab || !s->defs) return false;
    /* memcpy's pointers must not be NULL even for 0 bytes, and an empty array is */
    if (g->inst_count) memcpy(s->insts, g->insts, g->inst_count * sizeof *g->insts);
    if (g->ctab_count) memcpy(s->ctab, g->ctab, g->ctab_count * sizeof *g->ctab);
    if (g->def_count) memcpy(s->defs, g->defs, g->def_count * sizeof *g->defs);
    return true;
}

static void restore(bc_gen *g, const bc_saved *s) { /* the arrays only shrank since (their space stays) */
    if (s->inst_count) memcpy(g->insts, s->insts, s->inst_count * sizeof *g->insts);
    if (s->ctab_count) memcpy(g->ctab, s->ctab, s->ctab_count * sizeof *g->ctab);
    if (s->def_count) memcpy(g->defs, s->defs, s->def_count * sizeof *g->defs);
    g->inst_count = s->inst_count;
    g->ctab_count = s->ctab_count;
    g->def_count = s->def_count;
}

/* Fewer instructions, as fxc writes them: copies sunk into their writers, per-component
 * operations on one register as one (then a mad where a product is added), values computed twice
 * read once (twice: a value read from elsewhere frees a copy the first pass kept). */
static void shorten(bc_gen *g) {
    hfx_bc_sink(g);
    hfx_bc_vectorize(g);
    hfx_bc_fuse_mad(g);
    hfx_bc_nrm_into_adds(g);
    hfx_bc_dead_code(g);
    for (int pass = 0; pass < 2 && hfx_bc_cse(g); pass++) hfx_bc_dead_code(g);
}

/* From the selected code to registers: copies folded, bones' indices merged, unread constants
 * dropped, temporaries packed, read ports met. How many temporaries. */
static uint32_t finish(bc_gen *g) {
    hfx_bc_dead_code(g);
    hfx_bc_sink(g);
    hfx_bc_dead_code(g);
    hfx_bc_merge_mova(g);
    hfx_bc_gather_literals(g);
    hfx_bc_prune_constants(g);
    uint32_t temps = hfx_bc_allocate(g);
    hfx_bc_vectorize(g);
    temps = hfx_bc_read_ports(g, temps);
    hfx_bc_replicate_scalars(g);
    return temps;
}

const uint32_t *hfx_bc_write(ir_ctx *c, const ir_shader *sh, const char *profile, uint32_t *count) {
    bc_gen g;
    memset(&g, 0, sizeof g);
    g.c = c;
    g.sh = sh;
    g.last_fresh = -1;
    hfx_loc at = sh->compile ? sh->compile->loc : sh->entry->src ? sh->entry->src->loc : (hfx_loc){0, 1, 1};
    if (sh->entry->src) at = sh->entry->src->loc;
    g.loc = at;
    const bc_model *m = find_model(&g, profile ? profile : "vs_3_0", at);
    if (!m) return NULL;
    if ((m->stage == D3D9_VS) != (sh->stage == IR_VERTEX)) {
        hfx_bc_fail(&g, at, 3506, "'%s' is not a %s profile", m->name, sh->stage == IR_VERTEX ? "vertex" : "pixel");
        return NULL;
    }
    g.stage = m->stage;
    g.model = m->model;
    g.profile = m->name;
    g.max_consts = m->consts;
    hfx_bc_bind_globals(&g);
    if (!g.failed) gen_entry(&g);
    if (g.failed) return NULL;
    hfx_bc_fold(&g);
    hfx_bc_fuse_mad(&g);
    hfx_bc_dead_code(&g);
    bc_saved saved;
    bool undo = save(&g, &saved);
    if (undo) shorten(&g);
    uint32_t temps = finish(&g);
    if (undo && temps > hfx_bc_temp_limit(&g)) { /* values read once live longer: without, when they do not fit */
        restore(&g, &saved);
        temps = finish(&g);
    }
    if (temps > hfx_bc_temp_limit(&g)) {
        hfx_error(c->diags, at, X_BC_TEMPS, "this shader needs %u temporary registers; %s has %u", temps, m->name,
                  hfx_bc_temp_limit(&g));
        return NULL;
    }
    const uint32_t *w = hfx_bc_encode(&g, count);
    return verify(&g, m, w, *count, at) ? w : NULL;
}
