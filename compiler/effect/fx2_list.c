/* fx2_list.c: `hfxc --disassemble X.fxb` (fxc's /dumpbin): an fxc-compiled effect as text, in
 * the manner of fxc's effect listings: a header, the parameters with their types, semantics,
 * annotations and default values (samplers with their sampler_state), the shaders of shader
 * parameters, then the techniques and passes with every state, shaders as `asm { }` blocks
 * (compiler/d3d9's listing) and expressions as their FXLVM instructions. */
#include <stdio.h>
#include <string.h>

#include "base/sbuf.h"
#include "d3d9/d3d9.h"
#include "effect/fx2_int.h"
#include "states.h"

static void indent_text(sbuf *out, const char *text, const char *indent) {
    for (const char *line = text; *line;) {
        size_t n = strcspn(line, "\n");
        if (n) hfx_sb_put(out, indent);
        hfx_sb_putn(out, line, n);
        hfx_sb_put(out, "\n");
        line += n + (line[n] == '\n');
    }
}

/* A shader blob as `asm { ... }` (its decode errors, if any, are the listing's). */
static void put_shader(fx2_reader *r, sbuf *out, const fx2_blob *b, const char *indent) {
    if (!b || !b->size) {
        hfx_sb_printf(out, "%sNULL", indent);
        return;
    }
    d3d9_input in = {b->data, b->size, r->file, b->at};
    d3d9_shader *s = hfx_d3d9_decode(r->arena, r->diags, &in);
    sbuf text = {.arena = r->arena};
    if (s) hfx_d3d9_disassemble(s, &text);
    hfx_sb_printf(out, "%sasm {\n", indent);
    char deeper[64];
    snprintf(deeper, sizeof deeper, "%s    ", indent);
    indent_text(out, text.d ? text.d : "// (bytecode that does not decode: see the errors)\n", deeper);
    hfx_sb_printf(out, "%s}", indent);
}

static const char *base_name(hfx_param_type t) {
    return t == HFX_TYPE_BOOL ? "bool" : t == HFX_TYPE_INT ? "int" : t == HFX_TYPE_FLOAT ? "float" : "void";
}

static void put_word(sbuf *out, hfx_param_type t, uint32_t w);

static void put_type(sbuf *out, const hfx_fx_param *p) {
    if (p->klass == HFX_CLASS_SCALAR) hfx_sb_put(out, base_name(p->type));
    else if (p->klass == HFX_CLASS_VECTOR) hfx_sb_printf(out, "%s%u", base_name(p->type), p->cols);
    else if (p->klass == HFX_CLASS_MATRIX)
        hfx_sb_printf(out, "%s%s%ux%u", p->flags & HFX_FX_PARAM_ROW_MAJOR ? "row_major " : "", base_name(p->type), p->rows, p->cols);
    else if (p->klass == HFX_CLASS_STRUCT) hfx_sb_put(out, "struct");
    else hfx_sb_put(out, hfx_fx2_type_name(p->type));
}

/* A struct's members: `struct { float a; float2 b; }`. */
static void put_full_type(sbuf *out, const hfx_fx_effect *fx, const hfx_fx_param *p) {
    if (p->klass != HFX_CLASS_STRUCT) {
        put_type(out, p);
        return;
    }
    const hfx_fx_param *members = p->elements ? &fx->params[p->first_child] : p; /* an array's element holds them */
    hfx_sb_put(out, "struct {");
    for (uint32_t m = 0; m < members->child_count; m++) {
        const hfx_fx_param *q = &fx->params[members->first_child + m];
        hfx_sb_put(out, " ");
        put_full_type(out, fx, q);
        hfx_sb_printf(out, " %s", q->name);
        if (q->elements) hfx_sb_printf(out, "[%u]", q->elements);
        hfx_sb_put(out, ";");
    }
    hfx_sb_put(out, " }");
}

/* Every leaf's words, in order, each in its own type. */
static void put_leaf_words(sbuf *out, const hfx_fx_effect *fx, const hfx_fx_param *p, bool *first) {
    if (p->child_count) {
        for (uint32_t c = 0; c < p->child_count; c++) put_leaf_words(out, fx, &fx->params[p->first_child + c], first);
        return;
    }
    for (uint32_t k = 0; k < p->words; k++) {
        hfx_sb_put(out, *first ? "" : ", ");
        put_word(out, p->type, fx->values[p->offset + k]);
        *first = false;
    }
}

static void put_word(sbuf *out, hfx_param_type t, uint32_t w) {
    if (t == HFX_TYPE_FLOAT) {
        float f;
        memcpy(&f, &w, sizeof f);
        hfx_sb_printf(out, "%.9g", (double)f);
    } else if (t == HFX_TYPE_BOOL) {
        hfx_sb_put(out, w ? "true" : "false");
    } else {
        hfx_sb_printf(out, "%d", (int32_t)w);
    }
}

static void put_words(sbuf *out, hfx_param_type t, const uint32_t *w, uint32_t n) {
    if (n != 1) hfx_sb_put(out, "{ ");
    for (uint32_t i = 0; i < n; i++) {
        if (i) hfx_sb_put(out, ", ");
        put_word(out, t, w[i]);
    }
    if (n != 1) hfx_sb_put(out, " }");
}

static void put_annotations(sbuf *out, const hfx_fx_effect *fx, uint32_t first, uint32_t count, const char *indent) {
    if (!count) return;
    hfx_sb_printf(out, "%s<\n", indent);
    for (uint32_t i = first; i < first + count; i++) {
        const hfx_fx_annotation *a = &fx->annotations[i];
        hfx_sb_printf(out, "%s    ", indent);
        if (a->type == HFX_TYPE_STRING) {
            hfx_sb_printf(out, "string %s = \"%s\";\n", a->name, a->string ? a->string : "");
            continue;
        }
        hfx_fx_param shape = {.klass = a->klass, .type = a->type, .rows = a->rows, .cols = a->cols};
        put_type(out, &shape);
        hfx_sb_printf(out, " %s = ", a->name);
        put_words(out, a->type, a->data, a->count);
        hfx_sb_put(out, ";\n");
    }
    hfx_sb_printf(out, "%s>\n", indent);
}

/* One state: `Name[index] = value;`, the value as the file gives it. */
static void put_state(fx2_reader *r, sbuf *out, const fx2_raw *raw, const char *indent, bool in_sampler) {
    const hfx_fx_effect *fx = r->fx;
    const hfx_fx_state *st = raw->state != HFX_NONE ? &fx->states[raw->state] : NULL;
    const hfx_state_info *info = hfx_state_by_id(hfx_fx2_state_id(raw->op));
    char deeper[64];
    snprintf(deeper, sizeof deeper, "%s    ", indent);
    hfx_sb_printf(out, "%s%s", indent, hfx_fx2_op_name(raw->op));
    if (info && info->max_index && !in_sampler) hfx_sb_printf(out, "[%u]", raw->index);
    hfx_sb_put(out, " = ");
    if (raw->usage == USE_PARAM) {
        hfx_sb_printf(out, "<%.*s>;\n", (int)strnlen((const char *)raw->blob.data, raw->blob.size), (const char *)raw->blob.data);
    } else if (raw->usage == USE_SELECTOR && raw->object != HFX_NONE) {
        uint32_t len = hfx_fx2_name_len(&raw->blob),
                 skip = 4 + ((len + 3) & ~3u);
        if (skip > raw->blob.size) skip = raw->blob.size;
        fx2_blob code = {raw->blob.data + skip, raw->blob.size - skip, raw->blob.at + skip};
        char *text = hfx_fxlvm_text(r, &code);
        hfx_sb_printf(out, "%s[\n%sexpression {\n", fx->params[raw->object].name, deeper);
        indent_text(out, text ? text : "", deeper);
        hfx_sb_printf(out, "%s}];\n", deeper);
    } else if (raw->usage == USE_DATA && raw->type.klass != PC_OBJECT) {
        char *text = hfx_fxlvm_text(r, &raw->blob);
        hfx_sb_printf(out, "\n%sexpression {\n", deeper);
        indent_text(out, text ? text : "", deeper);
        hfx_sb_printf(out, "%s};\n", deeper);
    } else if (raw->op == OP_VERTEXSHADER || raw->op == OP_PIXELSHADER) {
        const fx2_blob *b = raw->usage == USE_DATA ? &raw->blob
                            : raw->object < r->object_count && r->objects[raw->object].has_data
                                ? &r->objects[raw->object].blob : NULL;
        hfx_sb_put(out, "\n");
        put_shader(r, out, b, deeper);
        hfx_sb_put(out, ";\n");
    } else if (st && st->kind == HFX_FX_VALUE_INT) {
        const char *name = info ? hfx_state_value_name(info, st->i) : NULL;
        if (name) hfx_sb_printf(out, "%s;\n", name);
        else hfx_sb_printf(out, "%d;\n", st->i);
    } else if (st && st->kind == HFX_FX_VALUE_FLOAT) {
        if (st->count > 1) hfx_sb_printf(out, "float%u(", st->count);
        for (uint32_t i = 0; i < st->count; i++) hfx_sb_printf(out, "%s%.9g", i ? ", " : "", (double)st->f[i]);
        hfx_sb_printf(out, "%s;\n", st->count > 1 ? ")" : "");
    } else {
        hfx_sb_put(out, "NULL;\n");
    }
}

static void put_param(fx2_reader *r, sbuf *out, uint32_t i) {
    const hfx_fx_effect *fx = r->fx;
    const hfx_fx_param *p = &fx->params[i];
    put_full_type(out, fx, p);
    hfx_sb_printf(out, " %s", p->name);
    if (p->elements) hfx_sb_printf(out, "[%u]", p->elements);
    if (p->semantic) hfx_sb_printf(out, " : %s", p->semantic);
    if (p->annotation_count) hfx_sb_put(out, "\n");
    put_annotations(out, fx, p->first_annotation, p->annotation_count, "");
    if (p->type == HFX_TYPE_STRING && p->string) {
        hfx_sb_printf(out, " = \"%s\";\n", p->string);
    } else if (p->sampler != HFX_NONE) {
        hfx_sb_put(out, " = sampler_state\n{\n");
        for (uint32_t k = 0; k < r->param_raw_count[i]; k++) put_state(r, out, &r->raws[r->param_raw_first[i] + k], "    ", true);
        hfx_sb_put(out, "};\n");
    } else if ((p->type == HFX_TYPE_VERTEXSHADER || p->type == HFX_TYPE_PIXELSHADER) && (p->child_count || r->param_object[i] != HFX_NONE)) {
        hfx_sb_put(out, " =\n");
        uint32_t n = p->child_count ? p->child_count : 1;
        for (uint32_t e = 0; e < n; e++) {
            uint32_t id = r->param_object[p->child_count ? p->first_child + e : i];
            const fx2_blob *b = id < r->object_count && r->objects[id].has_data ? &r->objects[id].blob : NULL;
            if (p->child_count) hfx_sb_printf(out, "    // %s[%u]\n", p->name, e);
            put_shader(r, out, b, "    ");
            hfx_sb_put(out, e + 1 < n ? ",\n" : ";\n");
        }
    } else if (p->words) {
        bool first = true;
        hfx_sb_put(out, p->words > 1 ? " = { " : " = ");
        put_leaf_words(out, fx, p, &first);
        hfx_sb_put(out, p->words > 1 ? " };\n" : ";\n");
    } else {
        hfx_sb_put(out, ";\n");
    }
}

char *hfx_fx2_listing(hfx_arena *arena, hfx_diags *diags, const char *name, const void *data, size_t size) {
    fx2_reader r;
    if (!hfx_fx2_open(&r, arena, diags, name, NULL, data, size, 0, HFX_FX2_DECODE_ONLY)) return NULL;
    const hfx_fx_effect *fx = r.fx;
    hfx_arena_cleanup *cleanup = hfx_arena_on_escape(arena, (void (*)(void *))hfx_fx_effect_free, r.fx);
    sbuf out = {.arena = arena};
    hfx_sb_printf(&out, "//\n// FX Version: fx_2_0\n// Child effect (requires effect pool): false\n//\n");
    hfx_sb_printf(&out, "// %u local parameter(s)\n//\n", fx->top_param_count);
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        put_param(&r, &out, i);
        hfx_sb_put(&out, "\n");
    }
    hfx_sb_printf(&out, "//\n// %u technique(s)\n//\n", fx->technique_count);
    for (uint32_t t = 0; t < fx->technique_count; t++) {
        const hfx_fx_technique *tq = &fx->techniques[t];
        hfx_sb_printf(&out, "technique %s\n", tq->name);
        put_annotations(&out, fx, tq->first_annotation, tq->annotation_count, "");
        hfx_sb_put(&out, "{\n");
        for (uint32_t p = tq->first_pass; p < tq->first_pass + tq->pass_count; p++) {
            const hfx_fx_pass *pa = &fx->passes[p];
            hfx_sb_printf(&out, "    pass %s\n", pa->name);
            put_annotations(&out, fx, pa->first_annotation, pa->annotation_count, "    ");
            hfx_sb_put(&out, "    {\n");
            for (uint32_t s = 0; s < pa->state_count; s++) put_state(&r, &out, &r.raws[r.pass_raw_first[p] + s], "        ", false);
            hfx_sb_put(&out, "    }\n");
        }
        hfx_sb_put(&out, "}\n\n");
    }
    hfx_arena_forget(arena, cleanup);
    hfx_fx_effect_free(r.fx);
    return diags->errors ? NULL : out.d;
}
