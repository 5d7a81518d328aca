/* glsl.c: one stage of a program as GLSL text: header, structs, uniforms, the stage interface
 * (attributes at the Cg locations, varyings named by semantic, fragment outputs), helper
 * functions, the user functions, and a main() that feeds the HLSL entry from the interface,
 * calls it and writes its results. See docs/conventions.md for the conventions. */
#include <stdlib.h>
#include <string.h>

#include "glsl/glsl_int.h"

static void line_start(gp *p) {
    for (int i = 0; i < p->indent; i++) hfx_sb_put(p->out, "    ");
}

static void print_stmt(gp *p, const ir_stmt *s);

/* `{ statements }` on lines of their own: blocks and switch bodies. */
static void print_braced(gp *p, const ir_stmt *s) {
    line_start(p);
    hfx_sb_put(p->out, "{\n");
    p->indent++;
    for (uint32_t i = 0; i < s->count; i++) print_stmt(p, s->body[i]);
    p->indent--;
    line_start(p);
    hfx_sb_put(p->out, "}\n");
}

static void print_body(gp *p, const ir_stmt *s) {
    if (s && s->kind == IS_BLOCK) { print_stmt(p, s); return; }
    line_start(p);
    hfx_sb_put(p->out, "{\n");
    p->indent++;
    if (s) print_stmt(p, s);
    p->indent--;
    line_start(p);
    hfx_sb_put(p->out, "}\n");
}

/* GLSL 110 cannot write an array's value in one expression (no array constructors; found by
 * fuzz/fuzz_diff.c), so there arrays, and structs holding one, keep HLSL's undefined start. */
static bool zero_printable(gp *p, const hfx_type *t) {
    if (!p->legacy || t->kind == TY_ARRAY) return !p->legacy;
    for (uint32_t i = 0; t->kind == TY_STRUCT && i < t->st->field_count; i++)
        if (!zero_printable(p, t->st->fields[i].type)) return false;
    return true;
}

static void print_decl(gp *p, const ir_var *v, const ir_expr *init, bool zero, const char *end) {
    hfx_glsl_decl(p, p->out, v->type, v->glsl);
    if (init) {
        hfx_sb_put(p->out, " = ");
        hfx_glsl_expr(p, init, PREC_ASSIGN);
    } else if (zero && zero_printable(p, v->type)) { /* HLSL leaves it undefined; zero keeps the output deterministic */
        hfx_sb_put(p->out, " = ");
        hfx_glsl_zero(p, v->type);
    }
    hfx_sb_put(p->out, end);
}

static void print_for(gp *p, const ir_stmt *s) {
    const ir_stmt *init = s->init;
    if (init && init->kind == IS_DECL && init->var->hoisted) { /* used after the loop (HLSL scoping) */
        line_start(p);
        print_decl(p, init->var, init->expr, true, ";\n");
        init = NULL;
    } else if (init && init->kind == IS_BLOCK) {
        for (uint32_t i = 0; i < init->count; i++) print_stmt(p, init->body[i]);
        init = NULL;
    }
    unsigned counter = s->max_iterations ? ++p->loop_counters : 0; /* [unroll(n)]: hfx_iterK counts to n */
    if (counter) {
        line_start(p);
        hfx_sb_printf(p->out, "int hfx_iter%u = 0;\n", counter);
    }
    line_start(p);
    hfx_sb_put(p->out, "for (");
    if (init && init->kind == IS_DECL) print_decl(p, init->var, init->expr, true, "");
    else if (init && init->kind == IS_EXPR) hfx_glsl_expr(p, init->expr, PREC_COMMA);
    hfx_sb_put(p->out, ";");
    if (s->expr) { hfx_sb_put(p->out, " "); hfx_glsl_expr(p, s->expr, counter ? PREC_AND : PREC_COMMA); }
    if (counter) hfx_sb_printf(p->out, "%shfx_iter%u < %u", s->expr ? " && " : " ", counter, (unsigned)s->max_iterations);
    hfx_sb_put(p->out, ";");
    if (s->step) { hfx_sb_put(p->out, " "); hfx_glsl_expr(p, s->step, counter ? PREC_ASSIGN : PREC_COMMA); }
    if (counter) hfx_sb_printf(p->out, "%shfx_iter%u++", s->step ? ", " : " ", counter);
    hfx_sb_put(p->out, ")\n");
    print_body(p, s->then_s);
}

static void print_if(gp *p, const ir_stmt *s, bool chained) {
    if (!chained) line_start(p);
    hfx_sb_put(p->out, "if (");
    hfx_glsl_expr(p, s->expr, PREC_COMMA);
    hfx_sb_put(p->out, ")\n");
    print_body(p, s->then_s);
    if (!s->else_s) return;
    line_start(p);
    if (s->else_s->kind == IS_IF) {
        hfx_sb_put(p->out, "else ");
        print_if(p, s->else_s, true);
        return;
    }
    hfx_sb_put(p->out, "else\n");
    print_body(p, s->else_s);
}

static void print_stmt(gp *p, const ir_stmt *s) {
    if (s->hint) {
        line_start(p);
        hfx_sb_printf(p->out, "// [%s]\n", s->hint);
    }
    switch (s->kind) {
    case IS_BLOCK:
        print_braced(p, s);
        return;
    case IS_DECL: line_start(p); print_decl(p, s->var, s->expr, true, ";\n"); return;
    case IS_EXPR: line_start(p); hfx_glsl_expr(p, s->expr, PREC_COMMA); hfx_sb_put(p->out, ";\n"); return;
    case IS_IF: print_if(p, s, false); return;
    case IS_FOR: print_for(p, s); return;
    case IS_WHILE:
        line_start(p);
        hfx_sb_put(p->out, "while (");
        hfx_glsl_expr(p, s->expr, PREC_COMMA);
        hfx_sb_put(p->out, ")\n");
        print_body(p, s->then_s);
        return;
    case IS_DO:
        line_start(p);
        hfx_sb_put(p->out, "do\n");
        print_body(p, s->then_s);
        line_start(p);
        hfx_sb_put(p->out, "while (");
        hfx_glsl_expr(p, s->expr, PREC_COMMA);
        hfx_sb_put(p->out, ");\n");
        return;
    case IS_SWITCH:
        if (p->legacy) { /* found by fuzz/fuzz_diff.c: glslang's "Reserved word" */
            hfx_glsl_error(p, s->loc, "switch statements need GLSL 330 or ES 300");
            return;
        }
        line_start(p);
        hfx_sb_put(p->out, "switch (");
        if (s->expr->type->base != B_INT) hfx_sb_put(p->out, "int(");
        hfx_glsl_expr(p, s->expr, PREC_COMMA);
        hfx_sb_put(p->out, s->expr->type->base != B_INT ? "))\n" : ")\n");
        print_braced(p, s);
        return;
    case IS_CASE:
        p->indent--;
        line_start(p);
        hfx_sb_put(p->out, "case ");
        if (hfx_ir_is_const(s->expr)) hfx_sb_printf(p->out, "%d", (int)hfx_ev_int(s->expr->cval[0])); /* the switch is on int */
        else hfx_glsl_expr(p, s->expr, PREC_COMMA);
        hfx_sb_put(p->out, ":\n");
        p->indent++;
        return;
    case IS_DEFAULT: p->indent--; line_start(p); hfx_sb_put(p->out, "default:\n"); p->indent++; return;
    case IS_BREAK: line_start(p); hfx_sb_put(p->out, "break;\n"); return;
    case IS_CONTINUE: line_start(p); hfx_sb_put(p->out, "continue;\n"); return;
    case IS_DISCARD:
        if (p->stage != IR_PIXEL) hfx_glsl_error(p, s->loc, "discard is only allowed in a pixel shader");
        line_start(p);
        hfx_sb_put(p->out, "discard;\n");
        return;
    case IS_RETURN:
        line_start(p);
        hfx_sb_put(p->out, "return");
        if (s->expr) { hfx_sb_put(p->out, " "); hfx_glsl_expr(p, s->expr, PREC_COMMA); }
        hfx_sb_put(p->out, ";\n");
        return;
    }
}

static void print_func(gp *p, const ir_func *f) {
    hfx_sb_printf(p->out, "// %s%s\n", f->name, f->is_entry ? " (entry point)" : "");
    hfx_sb_printf(p->out, "%s %s(", hfx_glsl_ctor_type(p, f->ret), f->glsl);
    for (uint32_t i = 0; i < f->param_count; i++) {
        const ir_var *v = f->params[i];
        if (i) hfx_sb_put(p->out, ", ");
        if (v->mods & MOD_OUT) hfx_sb_put(p->out, (v->mods & MOD_IN) ? "inout " : "out ");
        const hfx_type *t = v->type;
        if (t->kind == TY_SAMPLER && t->dim == DIM_GENERIC && v->dim != DIM_GENERIC) /* `sampler s` sampled as a cube */
            t = hfx_type_object(p->c->types, TY_SAMPLER, v->dim);
        hfx_glsl_decl(p, p->out, t, v->glsl);
    }
    hfx_sb_put(p->out, ")\n");
    print_stmt(p, f->body);
    hfx_sb_put(p->out, "\n");
}

/* ---- the stage interface ---- */

static bool is_vpos(const char *sem) { return strncmp(sem, "POSITION", 8) == 0 || strncmp(sem, "VPOS", 4) == 0; }

static const char *varying_name(gp *p, const char *sem) { return hfx_arena_printf(p->c->arena, "hfx_v_%s", sem); }

/* `value` (a vec4 source) narrowed and converted to the leaf's type. */
static void read_as(gp *p, const hfx_type *t, const char *vec4_src) {
    unsigned n = hfx_type_components(t);
    const char *tn = hfx_glsl_type(p, t);
    bool is_f = t->base == B_FLOAT || t->base == B_HALF || t->base == B_DOUBLE || t->base == B_MIN16FLOAT;
    if (!is_f || hfx_glsl_is_matrix(t)) hfx_sb_printf(p->out, "%s(", tn);
    hfx_sb_put(p->out, vec4_src);
    if (n < 4 && !hfx_glsl_is_matrix(t)) hfx_sb_printf(p->out, ".%.*s", (int)n, "xyzw");
    if (!is_f || hfx_glsl_is_matrix(t)) hfx_sb_put(p->out, ")");
}

/* A leaf's value as a vec4: missing components are 0, and w is 1 for positions. */
static void write_vec4(gp *p, const ir_leaf *l, const char *dst, bool clamp) {
    unsigned n = hfx_type_components(l->type);
    bool pos = strncmp(l->semantic, "POSITION", 8) == 0;
    line_start(p);
    hfx_sb_printf(p->out, "%s = ", dst);
    if (clamp) hfx_sb_put(p->out, "clamp(");
    bool plain_vec4 = l->type->kind == TY_VECTOR && l->type->base == B_FLOAT;
    if (n >= 4) hfx_sb_printf(p->out, plain_vec4 ? "%s" : "vec4(%s)", l->path);
    else if (n == 1) hfx_sb_printf(p->out, "vec4(float(%s), 0.0, 0.0, %s)", l->path, pos ? "1.0" : "0.0");
    else if (n == 2) hfx_sb_printf(p->out, "vec4(%s, 0.0, %s)", l->path, pos ? "1.0" : "0.0");
    else hfx_sb_printf(p->out, "vec4(%s, %s)", l->path, pos ? "1.0" : "0.0");
    if (clamp) hfx_sb_put(p->out, ", 0.0, 1.0)");
    hfx_sb_put(p->out, ";\n");
}

bool hfx_glsl_iface_derived(const glsl_iface *io, const char *sem) {
    for (uint32_t i = 0; i < io->derived_count; i++)
        if (strcmp(io->derived[i], sem) == 0) return true;
    return false;
}

/* GLSL 110 has no flat varyings: there nointerpolation is ignored. */
static bool is_flat(const glsl_iface *io, const char *sem) {
    for (uint32_t i = 0; i < io->flat_count; i++)
        if (strcmp(io->flat[i], sem) == 0) return true;
    return false;
}

/* The render target of a pixel shader output, COLOR0..COLOR3, or -1: one rule for declaring
 * and writing (atoi once read "COLOR0X" as COLOR0 and wrote an undeclared output; found by
 * fuzz/fuzz_diff.c). */
static int color_target(const char *semantic) {
    bool color = strncmp(semantic, "COLOR", 5) == 0 && semantic[5] >= '0' && semantic[5] <= '3' && !semantic[6];
    return color ? semantic[5] - '0' : -1;
}

static void declare_interface(gp *p) {
    bool modern = !p->legacy;
    const glsl_iface *io = p->io;
    if (p->stage == IR_VERTEX) {
        for (uint32_t i = 0; i < io->attr_count; i++) {
            if (modern) hfx_sb_printf(p->out, "layout(location = %d) in vec4 %s;\n", io->attrs[i].location, io->attrs[i].glsl_name);
            else hfx_sb_printf(p->out, "attribute vec4 %s;\n", io->attrs[i].glsl_name);
        }
        hfx_glsl_uniform(p, NULL, "hfx_pos_fixup", "vec4 hfx_pos_fixup", false);
    }
    for (uint32_t i = 0; i < io->varying_count; i++) {
        if (p->vulkan) hfx_sb_printf(p->out, "layout(location = %u) ", (unsigned)i); /* both stages list them alike */
        hfx_sb_printf(p->out, "%s%s vec4 %s;\n", modern && is_flat(io, io->varyings[i]) ? "flat " : "",
                  !modern ? "varying" : p->stage == IR_VERTEX ? "out" : "in", varying_name(p, io->varyings[i]));
    }
    if (p->stage == IR_PIXEL) {
        bool vpos = false, color[4] = { !p->sh, false, false, false };
        for (int i = 0; i < p->in_count; i++) vpos |= is_vpos(p->in[i].semantic);
        for (int i = 0; i < p->out_count; i++)
            if (color_target(p->outv[i].semantic) >= 0) color[color_target(p->outv[i].semantic)] = true;
        if (vpos || p->uses_fixup) hfx_glsl_uniform(p, NULL, "hfx_pos_fixup", "vec4 hfx_pos_fixup", false);
        if (p->io->alpha_test) {
            hfx_glsl_uniform(p, NULL, "hfx_alpha_func", "int hfx_alpha_func", false);
            hfx_glsl_uniform(p, NULL, "hfx_alpha_ref", "float hfx_alpha_ref", false);
        }
        for (int i = 0; i < 4 && modern; i++)
            if (color[i]) hfx_sb_printf(p->out, "layout(location = %d) out vec4 hfx_o_COLOR%d;\n", i, i);
    }
}

static const char *attr_glsl(gp *p, const char *sem) {
    for (uint32_t i = 0; i < p->io->attr_count; i++)
        if (strcmp(p->io->attrs[i].semantic, sem) == 0) return p->io->attrs[i].glsl_name;
    return NULL;
}

static void feed_input(gp *p, const ir_leaf *l) {
    if (p->stage == IR_PIXEL && hfx_glsl_iface_derived(p->io, l->semantic)) return; /* the entry computes it */
    line_start(p);
    hfx_sb_printf(p->out, "%s = ", l->path);
    if (p->stage == IR_VERTEX) {
        const char *a = attr_glsl(p, l->semantic);
        read_as(p, l->type, a ? a : "vec4(0.0)");
    } else if (is_vpos(l->semantic)) { /* D3D9: pixel centres at integers, y down from the top */
        read_as(p, l->type, "vec4(gl_FragCoord.x - 0.5, mix(hfx_pos_fixup.w - gl_FragCoord.y, gl_FragCoord.y, "
                            "hfx_pos_fixup.z) - 0.5, gl_FragCoord.z, gl_FragCoord.w)");
    } else if (strncmp(l->semantic, "VFACE", 5) == 0) {
        read_as(p, l->type, "vec4(gl_FrontFacing ? 1.0 : -1.0)");
    } else if (p->io->clamp_ps1_texcoords && p->sh && hfx_glsl_ps1_value_only(p->c, p->sh, l)) {
        read_as(p, l->type, hfx_arena_printf(p->c->arena, "vec4(clamp(%s.xyz, 0.0, 1.0), 1.0)", varying_name(p, l->semantic)));
    } else {
        read_as(p, l->type, varying_name(p, l->semantic));
    }
    hfx_sb_put(p->out, ";\n");
}

/* A matrix vertex input: its registers (TEXCOORD1..4 of `float4x4 world : TEXCOORD1`, as
 * hardware instancing sends them) hold the HLSL matrix's columns under D3D9's default
 * column_major packing, and were fed in as rows: transposed into place. */
static void transpose_input(gp *p, const ir_leaf *l) {
    if (!l->matrix_path) return;
    if (l->matrix_type->rows != l->matrix_type->cols) {
        hfx_glsl_error(p, l->loc, "a non-square matrix as a vertex input is not supported");
        return;
    }
    if (p->legacy) { hfx_glsl_error(p, l->loc, "a matrix vertex input needs GLSL 330 or ES 300"); return; }
    line_start(p);
    hfx_sb_printf(p->out, "%s = transpose(%s); // D3D9's registers hold its columns\n", l->matrix_path, l->matrix_path);
}

static bool written_by_vs(const glsl_iface *io, const char *sem) {
    for (uint32_t i = 0; i < io->vs_write_count; i++)
        if (strcmp(io->vs_writes[i], sem) == 0) return true;
    return false;
}

static void write_vertex_output(gp *p, const ir_leaf *l) {
    if (strcmp(l->semantic, "POSITION0") == 0) { write_vec4(p, l, "gl_Position", false); return; }
    if (strncmp(l->semantic, "PSIZE", 5) == 0) {
        line_start(p);
        hfx_sb_printf(p->out, "gl_PointSize = float(%s%s);\n", l->path, hfx_type_components(l->type) > 1 ? ".x" : "");
        return;
    }
    if (hfx_glsl_iface_derived(p->io, l->semantic)) return; /* the pixel entry computes it */
    bool clamp = p->io->clamp_vs_colors && strncmp(l->semantic, "COLOR", 5) == 0;
    write_vec4(p, l, varying_name(p, l->semantic), clamp);
}

static void write_pixel_output(gp *p, const ir_leaf *l) {
    if (strncmp(l->semantic, "DEPTH", 5) == 0) {
        line_start(p);
        hfx_sb_printf(p->out, "gl_FragDepth = float(%s%s);\n", l->path, hfx_type_components(l->type) > 1 ? ".x" : "");
        return;
    }
    int n = color_target(l->semantic);
    if (n < 0) { hfx_glsl_error(p, l->loc, hfx_arena_printf(p->c->arena, "'%s': invalid pixel shader output semantic", l->semantic)); return; }
    const char *dst = p->legacy ? hfx_arena_printf(p->c->arena, "gl_FragData[%d]", n) : hfx_arena_printf(p->c->arena, "hfx_o_COLOR%d", n);
    write_vec4(p, l, dst, false);
}

static void init_privates(gp *p) {
    for (uint32_t i = 0; i < p->sh->global_count; i++) {
        const ir_var *v = p->sh->globals[i];
        if (v->kind != IRV_PRIVATE || v->pre || (!v->copy_of && !v->init && !zero_printable(p, v->type))) continue;
        line_start(p);
        hfx_sb_printf(p->out, "%s = ", v->glsl);
        if (v->copy_of) hfx_glsl_uniform_read(p, p->out, v->copy_of);
        else if (v->init) hfx_glsl_expr(p, v->init, PREC_ASSIGN);
        else hfx_glsl_zero(p, v->type);
        hfx_sb_put(p->out, ";\n");
    }
}

static void alpha_test(gp *p, const char *color) {
    if (!p->io->alpha_test) return; /* no pass of the effect turns it on: no code, no cost */
    /* D3DCMPFUNC in hfx_alpha_func (0 or ALWAYS: off); reference in 0..1 */
    if (hfx_glsl_helper(p, "alpha"))
        hfx_sb_put(&p->helpers,
               "bool hfx_alpha_pass(float a)\n{\n"
               "    float r = hfx_alpha_ref;\n"
               "    if (hfx_alpha_func == 1) return false;\n"
               "    if (hfx_alpha_func == 2) return a < r;\n"
               "    if (hfx_alpha_func == 3) return a == r;\n"
               "    if (hfx_alpha_func == 4) return a <= r;\n"
               "    if (hfx_alpha_func == 5) return a > r;\n"
               "    if (hfx_alpha_func == 6) return a != r;\n"
               "    if (hfx_alpha_func == 7) return a >= r;\n"
               "    return true;\n}\n");
    line_start(p);
    hfx_sb_printf(p->out, "if (!hfx_alpha_pass(%s.a)) discard;\n", color);
}

/* Every vertex shader, the stand-in too, ends in D3D9's clip space made GL's (hfx_pos_fixup). */
static void print_pos_fixup(gp *p) {
    line_start(p);
    hfx_sb_put(p->out, "gl_Position.y *= 1.0 - 2.0 * hfx_pos_fixup.z; // render targets: D3D9's row order\n");
    line_start(p);
    hfx_sb_put(p->out, "gl_Position.xy += hfx_pos_fixup.xy * gl_Position.w; // D3D9 pixel centres\n");
    if (p->vulkan) return; /* Vulkan's clip space has D3D's depth already */
    line_start(p);
    hfx_sb_put(p->out, "gl_Position.z = gl_Position.z * 2.0 - gl_Position.w; // D3D depth 0..1 to GL -1..1\n");
}

static void print_main(gp *p) {
    const ir_func *f = p->sh->entry;
    ir_leaf *in = p->in, *out = p->outv;
    int nin = p->in_count, nout = p->out_count;
    hfx_sb_put(p->out, "void main()\n{\n");
    p->indent = 1;
    hfx_glsl_init_packed(p); /* before the privates: their initialisers may read them */
    init_privates(p);
    for (uint32_t i = 0; i < f->param_count; i++) {
        line_start(p);
        hfx_glsl_decl(p, p->out, f->params[i]->type, hfx_arena_printf(p->c->arena, "hfx_arg%u", i));
        hfx_sb_put(p->out, " = ");
        hfx_glsl_zero(p, f->params[i]->type);
        hfx_sb_put(p->out, ";\n");
    }
    for (int i = 0; i < nin; i++) feed_input(p, &in[i]);
    for (int i = 0; p->stage == IR_VERTEX && i < nin; i++) transpose_input(p, &in[i]);
    line_start(p);
    if (f->ret && f->ret->kind != TY_VOID) { hfx_glsl_decl(p, p->out, f->ret, "hfx_ret"); hfx_sb_put(p->out, " = "); }
    hfx_sb_printf(p->out, "%s(", f->glsl);
    for (uint32_t i = 0; i < f->param_count; i++) hfx_sb_printf(p->out, "%shfx_arg%u", i ? ", " : "", i);
    hfx_sb_put(p->out, ");\n");
    if (p->stage == IR_VERTEX) {
        for (int i = 0; i < nout; i++) write_vertex_output(p, &out[i]);
        for (uint32_t i = 0; i < p->io->varying_count; i++) /* read by the pixel shader, never written */
            if (!written_by_vs(p->io, p->io->varyings[i])) {
                line_start(p);
                hfx_sb_printf(p->out, "%s = vec4(0.0);\n", varying_name(p, p->io->varyings[i]));
            }
        print_pos_fixup(p);
    } else {
        bool color0 = false;
        for (int i = 0; i < nout; i++) {
            write_pixel_output(p, &out[i]);
            color0 |= strcmp(out[i].semantic, "COLOR0") == 0;
        }
        if (color0) alpha_test(p, p->legacy ? "gl_FragData[0]" : "hfx_o_COLOR0");
    }
    hfx_sb_put(p->out, "}\n");
}

/* D3D9 without a vertex or pixel shader runs fixed-function; these stand-ins pass positions
 * through untransformed (D3D9's vertex processing with its identity transform states: the
 * position is already clip space, depth 0..1) and texture coordinates and colours along. The
 * vertex stand-in ends with hfx_pos_fixup as every vertex shader does, so it draws the same
 * pixels on every back end and in render targets. */
static void print_fixed_main(gp *p) {
    hfx_sb_put(p->out, "void main()\n{\n");
    p->indent = 1;
    if (p->stage == IR_VERTEX) {
        const char *pos = attr_glsl(p, "POSITION0");
        line_start(p);
        hfx_sb_printf(p->out, "gl_Position = %s;\n", pos ? pos : "vec4(0.0, 0.0, 0.0, 1.0)");
        for (uint32_t i = 0; i < p->io->varying_count; i++) {
            const char *a = attr_glsl(p, p->io->varyings[i]);
            line_start(p);
            hfx_sb_printf(p->out, "%s = %s;\n", varying_name(p, p->io->varyings[i]), a ? a : "vec4(0.0)");
        }
        print_pos_fixup(p);
    } else {
        bool has_color = false;
        for (uint32_t i = 0; i < p->io->varying_count; i++) has_color |= strcmp(p->io->varyings[i], "COLOR0") == 0;
        line_start(p);
        hfx_sb_printf(p->out, "%s = %s;\n", p->legacy ? "gl_FragData[0]" : "hfx_o_COLOR0", has_color ? "hfx_v_COLOR0" : "vec4(1.0)");
        alpha_test(p, p->legacy ? "gl_FragData[0]" : "hfx_o_COLOR0");
    }
    hfx_sb_put(p->out, "}\n");
}

/* The program's switch number of a uniform (HFX_FX_USE_SWITCH, counted in uniform order), or -1. */
static int switch_number(const gp *p, const ir_var *v) {
    int k = 0;
    for (uint32_t i = 0; i < p->io->uniform_count; i++) {
        if (!(p->io->uniforms[i].flags & HFX_FX_USE_SWITCH)) continue;
        if (p->io->uniforms[i].param == v->param) return k;
        k++;
    }
    return -1;
}

static bool is_sampler_type(const hfx_type *t) {
    while (t->kind == TY_ARRAY) t = t->elem;
    return t->kind == TY_SAMPLER;
}

/* A switch is a constant when the runtime defines HFX_SWITCH_k (a program variant), else the
 * uniform; SPIR-V is compiled once, without variants: the uniform. */
static void declare_uniform(gp *p, const ir_var *v) {
    int k = v->param != HFX_NONE && !p->spirv ? switch_number(p, v) : -1;
    if (k >= 0) hfx_sb_printf(p->out, "#ifdef HFX_SWITCH_%d\nconst bool %s = HFX_SWITCH_%d;\n#else\n", k, v->glsl, k);
    sbuf decl = {.arena = p->c->arena};
    if (hfx_glsl_is_padded(p, v)) /* one zero element past the end (hfx_glsl_find_padded) */
        hfx_glsl_decl(p, &decl, v->type->elem, hfx_arena_printf(p->c->arena, "%s[%u]", v->glsl, v->type->array_len + 1));
    else
        hfx_glsl_decl(p, &decl, v->type, v->glsl);
    hfx_glsl_uniform(p, v, v->glsl, decl.d ? decl.d : "", is_sampler_type(v->type));
    if (k >= 0) hfx_sb_put(p->out, "#endif\n");
}

static void declare_globals(gp *p) {
    hfx_glsl_declare_regs(p);
    for (uint32_t i = 0; i < p->sh->global_count; i++) {
        const ir_var *v = p->sh->globals[i];
        uint32_t reg = hfx_glsl_packed_reg(p, v);
        if (reg != HFX_NONE) {
            hfx_glsl_declare_packed(p, v, reg);
        } else if (v->kind == IRV_SAMPLER) {
            const char *type = v->dim == DIM_CUBE ? "samplerCube" : v->dim == DIM_3D ? "sampler3D" : "sampler2D";
            hfx_glsl_uniform(p, v, v->glsl, hfx_arena_printf(p->c->arena, "%s %s", type, v->glsl), true);
        } else if (v->kind == IRV_UNIFORM) {
            declare_uniform(p, v);
        } else if (v->kind == IRV_PRIVATE) {
            hfx_glsl_decl(p, p->out, v->type, v->glsl);
            hfx_sb_put(p->out, v->copy_of ? "; // written by the shader: a private copy of the uniform\n" : ";\n");
        }
    }
}

/* ES 300 has no default precision for sampler3D in either stage (vertex texture fetch included),
 * and only lowp ones for sampler2D / samplerCube: both stages declare all three. */
static const char *header_of(hfx_target t) {
    if (t == HFX_TARGET_GLSLES300)
        return "#version 300 es\nprecision highp float;\nprecision highp int;\n"
               "precision highp sampler2D;\nprecision highp sampler3D;\nprecision highp samplerCube;\n";
    if (t == HFX_TARGET_GLSL110) return "#version 110\n";
    if (t == HFX_TARGET_SPIRV || t == HFX_TARGET_SPIRV_VK) return "#version 450 core\n";
    return "#version 330 core\n";
}

static const char *header(gp *p) { return header_of(p->target); }

/* GLSL 330 and ES 300 texts differ only in their headers: printing a stage once and swapping the
 * header halves the printer's work when an effect is compiled for both (the default). */
char *hfx_glsl_retarget(const char *text, hfx_target from, hfx_target to) {
    const char *have = header_of(from), *want = header_of(to);
    size_t h = strlen(have), w = strlen(want), n = strlen(text);
    if (strncmp(text, have, h) != 0) return NULL;
    char *out = malloc(n - h + w + 1);
    if (!out) return NULL;
    memcpy(out, want, w);
    memcpy(out + w, text + h, n - h + 1);
    return out;
}

char *hfx_glsl_print(ir_ctx *c, const ir_shader *sh, ir_stage stage, const glsl_iface *io, hfx_target target) {
    gp p = {0};
    p.c = c;
    p.sh = sh;
    p.stage = stage;
    p.io = io;
    p.target = target;
    p.legacy = target == HFX_TARGET_GLSL110;
    p.spirv = (target == HFX_TARGET_SPIRV || target == HFX_TARGET_SPIRV_VK) && io && io->fx && io->prog;
    p.vulkan = p.spirv && target == HFX_TARGET_SPIRV_VK;
    sbuf decls = {.arena = c->arena}, funcs = {.arena = c->arena}, all = {.arena = c->arena};
    p.helpers.arena = p.structs_text.arena = c->arena;
    if (sh) {
        p.in_count = hfx_ir_entry_leaves(c, sh->entry, false, &p.in);
        p.out_count = hfx_ir_entry_leaves(c, sh->entry, true, &p.outv);
        if (p.in_count < 0 || p.out_count < 0) return NULL;
    }
    p.out = &decls;
    hfx_glsl_find_padded(&p);
    if (sh) declare_globals(&p);
    p.out = &funcs;
    if (sh) {
        for (uint32_t i = 0; i < sh->func_count; i++) print_func(&p, sh->funcs[i]);
        print_main(&p);
    } else {
        print_fixed_main(&p);
    }
    p.out = &decls; /* after the code: it decides which built-in uniforms are needed */
    declare_interface(&p);
    if (p.nonsquare)
        hfx_glsl_error(&p, sh ? sh->entry->src->loc : (hfx_loc){0, 0, 0},
                   hfx_arena_printf(c->arena, "'%s': non-square matrices are not available in GLSL 110", sh ? sh->entry->name : "?"));
    p.out = &all;
    hfx_sb_put(&all, header(&p));
    hfx_sb_printf(&all, "// %s shader generated by hfx%s%s\n", stage == IR_VERTEX ? "vertex" : "pixel",
              sh ? " from " : " (fixed-function stand-in)", sh ? sh->entry->name : "");
    hfx_sb_put(&all, "\n");
    if (p.structs_text.d) { hfx_sb_put(&all, p.structs_text.d); }
    hfx_glsl_spirv_decls(&p, &all, &decls);
    hfx_sb_put(&all, "\n");
    if (p.helpers.d) { hfx_sb_put(&all, p.helpers.d); hfx_sb_put(&all, "\n"); }
    if (funcs.d) hfx_sb_put(&all, funcs.d);
    bool oom = decls.oom || funcs.oom || all.oom || p.helpers.oom || p.structs_text.oom;
    char *text = p.failed || oom ? NULL : hfx_sb_take(&all);
    if (!p.failed && !text) hfx_error(c->diags, (hfx_loc){0, 1, 1}, X_MEMORY_LIMIT, "out of memory printing GLSL");
    return text;
}
