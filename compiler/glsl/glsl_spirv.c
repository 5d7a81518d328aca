/* glsl_spirv.c: the SPIR-V targets as modes of the printer. glslang turns this GLSL into SPIR-V
 * (spirv.c); what differs from GLSL 330 is decided here from the program, never from printed
 * text:
 * - OpenGL (HFX_TARGET_SPIRV): every uniform at its location (common/spirv_loc.c: parameters,
 *   hfx_c, samplers, the known internal ones, then any other in order of first appearance over
 *   both stages), samplers at their texture unit; SPIR-V has no bool in externally visible
 *   storage (spirv-val rejects a bool UniformConstant), so a bool / bvecN uniform, or a
 *   one-dimensional array of them, is declared int / ivecN and read converted.
 * - Vulkan (HFX_TARGET_SPIRV_VK): one std140 block of both stages' loose uniforms (the stages
 *   link, one buffer slice serves the program), samplers at bindings, varyings at the vertex
 *   outputs' locations, no GL depth remap.
 * Both stages' uniforms and struct types come from the records their GLSL 330 print made. */
#include <stdio.h>
#include <string.h>

#include "glsl/glsl_int.h"
#include "spirv_loc.h"

enum { MAX_OTHER = 64, KNOWN_INTERNAL = HFX_SPIRV_KNOWN_COUNT };

/* A parameter, hfx_c, a sampler or a known internal one: spirv_loc.c's rules place it. */
static bool placed_by_program(const gp *p, const char *name) {
    return hfx_fx_spirv_location(p->io->fx, p->io->prog, name) >= 0;
}

/* name's place among the uniforms the program does not place, in order of first appearance
 * (vertex stage first), or -1. */
static int64_t other_index(const gp *p, const char *name) {
    const char *seen[MAX_OTHER];
    uint32_t n = 0;
    for (int s = 0; s < 2; s++) {
        const glsl_record *r = p->io->records[s];
        for (uint32_t i = 0; r && i < r->uniform_count && n < MAX_OTHER; i++) {
            const char *u = r->uniforms[i].name;
            bool dup = false;
            for (uint32_t k = 0; k < n && !dup; k++) dup = strcmp(seen[k], u) == 0;
            if (!dup && !placed_by_program(p, u)) seen[n++] = u;
        }
    }
    for (uint32_t k = 0; k < n; k++)
        if (strcmp(seen[k], name) == 0) return k;
    return -1;
}

/* A bool / bvecN uniform or a one-dimensional array of them: the vector size (1 for bool), else
 * 0; *elements gets the array length (0: not an array). */
static int bool_uniform(gp *p, const ir_var *v, uint32_t *elements) {
    *elements = 0;
    if (!v || v->kind != IRV_UNIFORM) return 0;
    const hfx_type *t = v->type;
    if (t->kind == TY_ARRAY) {
        *elements = t->array_len;
        t = t->elem;
        if (t->kind == TY_ARRAY || !*elements || *elements > 65536) return 0;
    }
    const char *tn = hfx_glsl_type(p, t);
    if (strcmp(tn, "bool") == 0) return 1;
    if (strncmp(tn, "bvec", 4) == 0 && tn[4] >= '2' && tn[4] <= '4' && !tn[5]) return tn[4] - '0';
    return 0;
}

static void declare_bool(gp *p, const ir_var *v, int n, uint32_t elements) {
    const char *name = v->glsl;
    char btype[8], itype[8];
    snprintf(btype, sizeof btype, n == 1 ? "bool" : "bvec%d", n);
    snprintf(itype, sizeof itype, n == 1 ? "int" : "ivec%d", n);
    if (HFX_ARENA_GROW(p->c->arena, p->bools, p->bool_count, p->bool_cap, 4)) p->bools[p->bool_count++] = v;
    if (!elements) {
        hfx_sb_printf(p->out, "uniform %s %s;\n", itype, name);
        return;
    }
    hfx_sb_printf(p->out, "uniform %s %s[%u];\n", itype, name, elements);
    hfx_sb_printf(p->out, "%s[%u] hfx_bools_%s() { %s r[%u]; for (int i = 0; i < %u; i++) r[i] = ", btype, elements, name,
              btype, elements, elements);
    if (n == 1) hfx_sb_printf(p->out, "%s[i] != 0;", name);
    else hfx_sb_printf(p->out, "%s(%s[i]);", btype, name);
    hfx_sb_put(p->out, " return r; }\n");
}

void hfx_glsl_uniform_read(gp *p, sbuf *out, const ir_var *v) {
    bool converted = false;
    for (uint32_t i = 0; i < p->bool_count && !converted; i++) converted = p->bools[i] == v;
    uint32_t elements;
    int n = converted ? bool_uniform(p, v, &elements) : 0;
    if (!n) hfx_sb_put(out, v->glsl);
    else if (elements) hfx_sb_printf(out, "hfx_bools_%s()", v->glsl);
    else if (n == 1) hfx_sb_printf(out, "(%s != 0)", v->glsl);
    else hfx_sb_printf(out, "bvec%d(%s)", n, v->glsl);
}

/* OpenGL's SPIR-V: uniforms, then samplers, then the known internal ones, then any other. */
static void gl_uniform(gp *p, const ir_var *v, const char *name, const char *decl) {
    const hfx_fx_program *prog = p->io->prog;
    size_t len = strlen(name);
    uint64_t end;
    int64_t loc = -1, k = hfx_fx_spirv_uniform(p->io->fx, prog, name, len, &end), unit = -1;
    if (k >= 0) {
        loc = (int64_t)end;
    } else if (hfx_fx_spirv_is_regs(prog, name, len)) {
        loc = (int64_t)hfx_fx_spirv_regs_location(p->io->fx, prog);
    } else if ((k = hfx_fx_spirv_sampler(prog, name, len)) >= 0) {
        loc = (int64_t)end + k;
        unit = prog->samplers[k].unit;
    } else if ((k = hfx_fx_spirv_known(name, len)) >= 0) {
        loc = (int64_t)(end + prog->sampler_count) + k;
    } else if ((k = other_index(p, name)) >= 0) {
        loc = (int64_t)(end + prog->sampler_count + KNOWN_INTERNAL) + k;
    }
    if (loc > INT32_MAX) loc = -1;
    if (loc < 0 && unit < 0) { /* not ours to place: glslang's auto-mapping does it */
        hfx_sb_printf(p->out, "uniform %s;\n", decl);
        return;
    }
    hfx_sb_put(p->out, "layout(");
    if (loc >= 0) hfx_sb_printf(p->out, "location = %lld", (long long)loc);
    if (unit >= 0) hfx_sb_printf(p->out, "%sbinding = %lld", loc >= 0 ? ", " : "", (long long)unit);
    hfx_sb_put(p->out, ") ");
    uint32_t elements;
    int n = bool_uniform(p, v, &elements);
    if (n) declare_bool(p, v, n, elements);
    else hfx_sb_printf(p->out, "uniform %s;\n", decl);
}

void hfx_glsl_uniform(gp *p, const ir_var *v, const char *name, const char *decl, bool sampler) {
    glsl_record *r = p->io ? p->io->record : NULL;
    if (r && p->target == HFX_TARGET_GLSL330 &&
        HFX_ARENA_GROW(p->c->arena, r->uniforms, r->uniform_count, r->uniform_cap, 8))
        r->uniforms[r->uniform_count++] = (struct glsl_rec_uniform){name, decl, sampler};
    if (!p->spirv) {
        hfx_sb_printf(p->out, "uniform %s;\n", decl);
    } else if (!p->vulkan) {
        gl_uniform(p, v, name, decl);
    } else if (sampler) {
        int64_t k = hfx_fx_spirv_sampler(p->io->prog, name, strlen(name));
        hfx_sb_printf(p->out, "layout(set = 0, binding = %lld) uniform %s;\n",
                  (long long)HFX_VK_BINDING_SAMPLER0 + (k >= 0 ? k : (int64_t)p->io->prog->sampler_count), decl);
    } else { /* a member of the block, which takes the stage's last loose uniform's place */
        p->block_at = p->out->len;
        p->has_block = true;
    }
}

void hfx_glsl_record_struct(gp *p, const char *name, size_t text_from) {
    glsl_record *r = p->io ? p->io->record : NULL;
    if (!r || p->target != HFX_TARGET_GLSL330 || p->structs_text.oom || !p->structs_text.d) return;
    const char *text = hfx_arena_strndup(p->c->arena, p->structs_text.d + text_from, p->structs_text.len - text_from);
    if (text && HFX_ARENA_GROW(p->c->arena, r->structs, r->struct_count, r->struct_cap, 4))
        r->structs[r->struct_count++] = (struct glsl_rec_struct){name, text};
}

static bool stage_defines(gp *p, const char *name) {
    for (uint32_t i = 0; i < p->struct_count; i++)
        if (strcmp(hfx_glsl_type(p, p->structs[i]), name) == 0) return true;
    return false;
}

/* Whether records[0..s] before (s, i) hold a struct or (loose) uniform named `name`. */
static bool earlier_struct(const gp *p, int s, uint32_t i, const char *name) {
    for (int t = 0; t <= s; t++)
        for (uint32_t k = 0; p->io->records[t] && k < (t < s ? p->io->records[t]->struct_count : i); k++)
            if (strcmp(p->io->records[t]->structs[k].name, name) == 0) return true;
    return false;
}

static bool earlier_member(const gp *p, int s, uint32_t i, const char *name) {
    for (int t = 0; t <= s; t++) {
        const glsl_record *r = p->io->records[t];
        for (uint32_t k = 0; r && k < (t < s ? r->uniform_count : i); k++)
            if (!r->uniforms[k].sampler && strcmp(r->uniforms[k].name, name) == 0) return true;
    }
    return false;
}

/* The block: the other stage's struct types this one lacks, then every loose uniform of both
 * stages, each once, vertex stage first. Every type its members use is declared by then, and no
 * function reads a uniform before all are declared. */
static void vk_block(gp *p, sbuf *all) {
    for (int s = 0; s < 2; s++)
        for (uint32_t i = 0; p->io->records[s] && i < p->io->records[s]->struct_count; i++) {
            const struct glsl_rec_struct *st = &p->io->records[s]->structs[i];
            if (!earlier_struct(p, s, i, st->name) && !stage_defines(p, st->name)) hfx_sb_printf(all, "%s\n", st->text);
        }
    hfx_sb_printf(all, "layout(std140, set = 0, binding = %d) uniform hfx_block\n{\n", HFX_VK_BINDING_BLOCK);
    for (int s = 0; s < 2; s++)
        for (uint32_t i = 0; p->io->records[s] && i < p->io->records[s]->uniform_count; i++) {
            const struct glsl_rec_uniform *u = &p->io->records[s]->uniforms[i];
            if (!u->sampler && !earlier_member(p, s, i, u->name)) hfx_sb_printf(all, "    %s;\n", u->decl);
        }
    hfx_sb_put(all, "};\n");
}

void hfx_glsl_spirv_decls(gp *p, sbuf *all, const sbuf *decls) {
    size_t at = p->vulkan && p->has_block ? p->block_at : decls->len;
    if (decls->d) hfx_sb_putn(all, decls->d, at);
    if (p->vulkan && p->has_block) vk_block(p, all);
    if (decls->d && at < decls->len) hfx_sb_putn(all, decls->d + at, decls->len - at);
}
