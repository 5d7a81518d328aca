/* spirv.c: the SPIR-V target. See spirv.h; the rules are in docs/conventions.md ("SPIR-V"). */
#include "glsl/spirv.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/sbuf.h"
#include "glsl/glslang.h"
#include "spirv_loc.h"

#ifdef HFX_HAVE_GLSLANG
#include <glslang/Include/glslang_c_interface.h>
#include <glslang/Public/resource_limits_c.h>
#endif

/* --- uniform locations: common/spirv_loc.c, shared with the runtime ----------------------------- */

enum { KNOWN_INTERNAL = HFX_SPIRV_KNOWN_COUNT };

int32_t hfx_spirv_location(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *glsl_name) {
    return hfx_fx_spirv_location(fx, p, glsl_name);
}

/* --- scanning the GLSL's top-level uniform declarations -------------------------------------- */

typedef struct uniform_decl {
    const char *line, *end;        /* the declaration's line, without its newline */
    const char *type; size_t type_len;
    const char *name; size_t name_len;
    const char *rest;              /* after the name: array sizes and ';' */
} uniform_decl;

static bool ident_start(char c) { return isalpha((unsigned char)c) || c == '_'; }
static bool ident_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* Parses `uniform TYPE NAME...;` (no layout, no block) on one line. */
static bool parse_uniform(const char *s, const char *end, uniform_decl *u) {
    if ((size_t)(end - s) < 8 || strncmp(s, "uniform", 7) != 0 || (s[7] != ' ' && s[7] != '\t')) return false;
    if (memchr(s, '{', (size_t)(end - s))) return false;
    const char *q = s + 7;
    while (q < end && (*q == ' ' || *q == '\t')) q++;
    if (q >= end || !ident_start(*q)) return false;
    u->type = q;
    while (q < end && ident_char(*q)) q++;
    u->type_len = (size_t)(q - u->type);
    while (q < end && (*q == ' ' || *q == '\t')) q++;
    if (q >= end || !ident_start(*q)) return false;
    u->name = q;
    while (q < end && ident_char(*q)) q++;
    u->name_len = (size_t)(q - u->name);
    u->rest = q;
    u->line = s;
    u->end = end;
    return true;
}

typedef void (*uniform_fn)(void *ctx, const uniform_decl *u, const char *line, const char *next);

/* Calls fn for every line of src: u is set for a top-level uniform declaration, else NULL. */
static void scan_lines(const char *src, uniform_fn fn, void *ctx) {
    int depth = 0;
    bool in_comment = false;
    for (const char *line = src; *line;) {
        const char *end = strchr(line, '\n');
        if (!end) end = line + strlen(line);
        const char *next = *end ? end + 1 : end;
        uniform_decl u;
        bool is_uniform = depth == 0 && !in_comment && parse_uniform(line, end, &u);
        fn(ctx, is_uniform ? &u : NULL, line, next);
        for (const char *c = line; c < end; c++) {
            if (in_comment) {
                if (c[0] == '*' && c + 1 < end && c[1] == '/') in_comment = false, c++;
            } else if (c[0] == '/' && c + 1 < end && c[1] == '/') {
                break;
            } else if (c[0] == '/' && c + 1 < end && c[1] == '*') {
                in_comment = true;
                c++;
            } else if (*c == '{') {
                depth++;
            } else if (*c == '}' && depth > 0) {
                depth--;
            }
        }
        line = next;
    }
}

/* --- the code generator's own uniforms (hfx_pos_fixup...) and any other ------------------------ */

enum { MAX_OTHER = 64 };

/* Uniforms that are neither the program's parameters nor its samplers nor known internal ones,
 * in order of first appearance (vertex shader first): they follow the known ones. */
typedef struct other_set {
    const char *names[MAX_OTHER];
    size_t lens[MAX_OTHER];
    uint32_t count;
    const hfx_fx_effect *fx;
    const hfx_fx_program *prog;
} other_set;

static int64_t other_index(const other_set *s, const char *name, size_t len) {
    for (uint32_t i = 0; i < s->count; i++)
        if (s->lens[i] == len && strncmp(s->names[i], name, len) == 0) return i;
    return -1;
}

static void collect_other(void *ctx, const uniform_decl *u, const char *line, const char *next) {
    other_set *s = ctx;
    uint64_t loc;
    (void)line, (void)next;
    if (!u || hfx_fx_spirv_uniform(s->fx, s->prog, u->name, u->name_len, &loc) >= 0 ||
        hfx_fx_spirv_is_regs(s->prog, u->name, u->name_len) ||
        hfx_fx_spirv_sampler(s->prog, u->name, u->name_len) >= 0 || hfx_fx_spirv_known(u->name, u->name_len) >= 0)
        return;
    if (other_index(s, u->name, u->name_len) >= 0 || s->count == MAX_OTHER) return;
    s->names[s->count] = u->name;
    s->lens[s->count++] = u->name_len;
}

/* --- the rewrite ------------------------------------------------------------------------------ */

typedef struct rewrite {
    sbuf out;
    const hfx_fx_effect *fx;
    const hfx_fx_program *prog;
    const other_set *other;
    const char *src;
} rewrite;

/* Would a macro named `name`, defined at `from`, break anything after it? It would in a field
 * access (`x.name`) or a declaration (`bool name`, a local or a parameter shadowing it). */
static bool macro_unsafe(const char *from, const char *name, size_t len) {
    for (const char *p = strchr(from, name[0]); p; p = strchr(p + 1, name[0])) {
        if (strncmp(p, name, len) != 0) continue;
        if (ident_char(p[len]) || (p > from && ident_char(p[-1]))) continue; /* not the whole word */
        const char *q = p;
        while (q > from && (q[-1] == ' ' || q[-1] == '\t' || q[-1] == '\n')) q--;
        if (q > from && q[-1] == '.') return true;
        if (q > from && ident_char(q[-1])) {
            const char *w = q;
            while (w > from && ident_char(w[-1])) w--;
            size_t n = (size_t)(q - w);
            if (!(n == 6 && strncmp(w, "return", 6) == 0) && !(n == 4 && strncmp(w, "else", 4) == 0)) return true;
        }
    }
    return false;
}

/* SPIR-V has no bool in externally visible storage (spirv-val rejects a bool UniformConstant).
 * A bool / bvecN uniform, or a one-dimensional array of them, is declared int / ivecN under its
 * own name and read through a macro of that name (a macro does not expand itself again): a
 * conversion for one value, a function building the bool array for an array. Returns the vector
 * size (1 for bool), 0 when the uniform is not such a case; *elements gets the array length. */
static int bool_uniform(const uniform_decl *u, unsigned long *elements) {
    int n = 0;
    if (u->type_len == 4 && strncmp(u->type, "bool", 4) == 0) n = 1;
    else if (u->type_len == 5 && strncmp(u->type, "bvec", 4) == 0 && u->type[4] >= '2' && u->type[4] <= '4')
        n = u->type[4] - '0';
    if (!n) return 0;
    *elements = 0;
    const char *q = u->rest;
    if (*q == '[') {
        char *end;
        *elements = strtoul(q + 1, &end, 10);
        if (end == q + 1 || *end != ']' || !*elements || *elements > 65536) return 0;
        q = end + 1;
    }
    if (*q != ';' || macro_unsafe(u->end, u->name, u->name_len)) return 0;
    return n;
}

static void write_bool_uniform(sbuf *out, const uniform_decl *u, int n, unsigned long elements) {
    int len = (int)u->name_len;
    const char *name = u->name;
    char btype[8], itype[8];
    snprintf(btype, sizeof btype, n == 1 ? "bool" : "bvec%d", n);
    snprintf(itype, sizeof itype, n == 1 ? "int" : "ivec%d", n);
    if (!elements) {
        sb_printf(out, "uniform %s %.*s;\n", itype, len, name);
        if (n == 1) sb_printf(out, "#define %.*s (%.*s != 0)\n", len, name, len, name);
        else sb_printf(out, "#define %.*s %s(%.*s)\n", len, name, btype, len, name);
        return;
    }
    sb_printf(out, "uniform %s %.*s[%lu];\n", itype, len, name, elements);
    sb_printf(out, "%s[%lu] hfx_bools_%.*s() { %s r[%lu]; for (int i = 0; i < %lu; i++) r[i] = ", btype, elements, len,
              name, btype, elements, elements);
    if (n == 1) sb_printf(out, "%.*s[i] != 0;", len, name);
    else sb_printf(out, "%s(%.*s[i]);", btype, len, name);
    sb_printf(out, " return r; }\n#define %.*s hfx_bools_%.*s()\n", len, name, len, name);
}

static void rewrite_line(void *ctx, const uniform_decl *u, const char *line, const char *next) {
    rewrite *r = ctx;
    if (line == r->src && strncmp(line, "#version ", 9) == 0) {
        sb_printf(&r->out, "#version 450 core\n");
        return;
    }
    if (!u) {
        sb_putn(&r->out, line, (size_t)(next - line));
        return;
    }
    /* Uniforms, then samplers, then the known internal ones, then any other: see spirv.h. */
    uint64_t end;
    int64_t loc = -1, k = hfx_fx_spirv_uniform(r->fx, r->prog, u->name, u->name_len, &end), unit = -1;
    if (k >= 0) {
        loc = (int64_t)end;
    } else if (hfx_fx_spirv_is_regs(r->prog, u->name, u->name_len)) {
        loc = (int64_t)hfx_fx_spirv_regs_location(r->fx, r->prog);
    } else if ((k = hfx_fx_spirv_sampler(r->prog, u->name, u->name_len)) >= 0) {
        loc = (int64_t)end + k;
        unit = r->prog->samplers[k].unit;
    } else if ((k = hfx_fx_spirv_known(u->name, u->name_len)) >= 0) {
        loc = (int64_t)(end + r->prog->sampler_count) + k;
    } else if ((k = other_index(r->other, u->name, u->name_len)) >= 0) {
        loc = (int64_t)(end + r->prog->sampler_count + KNOWN_INTERNAL) + k;
    }
    if (loc > INT32_MAX) loc = -1;
    if (loc < 0 && unit < 0) { /* not ours to place: glslang's auto-mapping does it */
        sb_putn(&r->out, line, (size_t)(next - line));
        return;
    }
    sb_putn(&r->out, "layout(", 7);
    if (loc >= 0) sb_printf(&r->out, "location = %lld", (long long)loc);
    if (unit >= 0) sb_printf(&r->out, "%sbinding = %lld", loc >= 0 ? ", " : "", (long long)unit);
    sb_putn(&r->out, ") ", 2);
    unsigned long elements = 0;
    int bools = bool_uniform(u, &elements);
    if (bools) write_bool_uniform(&r->out, u, bools, elements);
    else sb_putn(&r->out, u->line, (size_t)(next - u->line));
}

char *hfx_spirv_glsl(const hfx_fx_effect *fx, const hfx_fx_program *p, int stage) {
    if (!fx || !p || stage < 0 || stage >= HFX_STAGE_COUNT || !p->code[stage][HFX_TARGET_GLSL330].data) return NULL;
    other_set other;
    memset(&other, 0, sizeof other);
    other.fx = fx;
    other.prog = p;
    for (int st = 0; st < HFX_STAGE_COUNT; st++)
        if (p->code[st][HFX_TARGET_GLSL330].data) scan_lines(p->code[st][HFX_TARGET_GLSL330].data, collect_other, &other);
    rewrite r;
    memset(&r, 0, sizeof r);
    r.fx = fx;
    r.prog = p;
    r.other = &other;
    r.src = p->code[stage][HFX_TARGET_GLSL330].data;
    scan_lines(r.src, rewrite_line, &r);
    if (r.out.oom || !r.out.d) {
        free(r.out.d);
        return NULL;
    }
    return r.out.d;
}

/* --- Vulkan: one uniform block for both stages, samplers at bindings ---------------------------- */

enum { MAX_MEMBERS = 1024 };

/* The loose (non-sampler) uniforms of both stages, vertex first, each name once: both stages
 * declare the same block, so one buffer slice serves the program and the stages link. */
typedef struct vk_members {
    sbuf text, structs;     /* the members; every stage's struct types, for a stage that lacks one */
    const char *vary[MAX_MEMBERS]; /* the vertex stage's outputs in order: their locations */
    size_t vary_lens[MAX_MEMBERS];
    uint32_t vary_count;
    const char *names[MAX_MEMBERS];
    size_t lens[MAX_MEMBERS];
    uint32_t count;
} vk_members;

typedef struct vk_rewrite {
    sbuf out;
    int stage;
    uint32_t extra_inputs;  /* pixel inputs no vertex output matches: after the others */
    const vk_members *members;
    const hfx_fx_program *prog;
    const char *src;
    uint32_t loose, seen;   /* loose uniforms in this stage, and those passed so far */
} vk_rewrite;

static bool is_sampler(const uniform_decl *u) { return u->type_len >= 7 && strncmp(u->type, "sampler", 7) == 0; }

static void collect_member(void *ctx, const uniform_decl *u, const char *line, const char *next) {
    vk_members *m = ctx;
    (void)line;
    if (!u || is_sampler(u) || m->count == MAX_MEMBERS) return;
    for (uint32_t i = 0; i < m->count; i++)
        if (m->lens[i] == u->name_len && strncmp(m->names[i], u->name, u->name_len) == 0) return;
    m->names[m->count] = u->name;
    m->lens[m->count++] = u->name_len;
    sb_put(&m->text, "    ");
    sb_putn(&m->text, u->type, (size_t)(next - u->type));
    if (next == u->type || next[-1] != '\n') sb_put(&m->text, "\n");
}

static void count_loose(void *ctx, const uniform_decl *u, const char *line, const char *next) {
    (void)line, (void)next;
    if (u && !is_sampler(u)) ((vk_rewrite *)ctx)->loose++;
}

/* GL's remap of D3D's 0..1 depth to -1..1: Vulkan's clip space already has D3D's depth. */
static bool is_depth_remap(const char *line, const char *next) {
    static const char remap[] = "gl_Position.z = gl_Position.z * 2.0 - gl_Position.w;";
    for (const char *q = line; q + sizeof remap - 1 <= next; q++)
        if (memcmp(q, remap, sizeof remap - 1) == 0) return true;
    return false;
}

/* The text of a top-level `struct NAME ... };` starting at s, up to its end; NULL when s does
 * not start one. *name / *len get the name. */
static const char *struct_end(const char *s, const char **name, size_t *len) {
    if (strncmp(s, "struct ", 7) != 0 || !ident_start(s[7])) return NULL;
    *name = s + 7;
    for (*len = 0; ident_char((*name)[*len]); ++*len) {}
    const char *e = strstr(s, "\n};");
    return e ? e + 4 : NULL;
}

/* Whether src defines struct name[0..len) at the start of a line. */
static bool defines_struct(const char *src, const char *name, size_t len) {
    for (const char *q = src; q; q = strchr(q, '\n'), q = q ? q + 1 : NULL) {
        const char *n;
        size_t l;
        if (struct_end(q, &n, &l) && l == len && strncmp(n, name, len) == 0) return true;
    }
    return false;
}

/* Every stage's struct types, each once, so a stage can declare the block's members whose
 * type only the other stage defines. */
static void collect_structs(vk_members *m, const char *src) {
    for (const char *q = src; q; q = strchr(q, '\n'), q = q ? q + 1 : NULL) {
        const char *name;
        size_t len;
        const char *end = struct_end(q, &name, &len);
        if (!end) continue;
        if (m->structs.d && defines_struct(m->structs.d, name, len)) continue;
        sb_putn(&m->structs, q, (size_t)(end - q));
        sb_put(&m->structs, "\n");
    }
}

/* The structs of the other stage this one lacks (whole definitions, in their order). */
static void missing_structs(vk_rewrite *r) {
    const char *all = r->members->structs.d;
    for (const char *q = all; q; q = strchr(q, '\n'), q = q ? q + 1 : NULL) {
        const char *name, *end;
        size_t len;
        if (!(end = struct_end(q, &name, &len)) || defines_struct(r->src, name, len)) continue;
        sb_putn(&r->out, q, (size_t)(end - q));
        sb_put(&r->out, "\n");
    }
}

/* A varying declared without a location (`out vec4 hfx_v_X;`, maybe `flat`): the name's
 * start and length, and where the declaration starts; false for any other line. */
static bool parse_varying(const char *line, const char *next, const char *word, const char **decl, const char **name,
                          size_t *len) {
    const char *q = line;
    if (strncmp(q, "flat ", 5) == 0) q += 5;
    else if (strncmp(q, "noperspective ", 14) == 0) q += 14;
    size_t w = strlen(word);
    if (strncmp(q, word, w) != 0 || q[w] != ' ') return false;
    const char *semi = memchr(q, ';', (size_t)(next - q));
    if (!semi) return false;
    const char *e = semi;
    while (e > q && !ident_char(e[-1])) e--;
    const char *b = e;
    while (b > q && ident_char(b[-1])) b--;
    *decl = line, *name = b, *len = (size_t)(e - b);
    return *len > 0;
}

static void collect_varying(void *ctx, const uniform_decl *u, const char *line, const char *next) {
    vk_members *m = ctx;
    const char *decl, *name;
    size_t len;
    if (u || m->vary_count == MAX_MEMBERS || !parse_varying(line, next, "out", &decl, &name, &len)) return;
    m->vary[m->vary_count] = name;
    m->vary_lens[m->vary_count++] = len;
}

/* Varyings get explicit locations (Vulkan needs them; glslang's automatic ones would reach
 * the samplers too): the vertex outputs' order, which the pixel inputs look up by name. */
static bool vk_varying(vk_rewrite *r, const char *line, const char *next) {
    const char *decl, *name;
    size_t len;
    if (!parse_varying(line, next, r->stage == HFX_STAGE_VERTEX ? "out" : "in", &decl, &name, &len)) return false;
    uint32_t loc = r->members->vary_count + r->extra_inputs;
    for (uint32_t i = 0; i < r->members->vary_count; i++)
        if (r->members->vary_lens[i] == len && strncmp(r->members->vary[i], name, len) == 0) loc = i;
    if (loc >= r->members->vary_count) r->extra_inputs++;
    sb_printf(&r->out, "layout(location = %u) ", (unsigned)loc);
    sb_putn(&r->out, decl, (size_t)(next - decl));
    return true;
}

/* The block takes the stage's last loose uniform's place: every type its members use is
 * declared by then, and no function reads a uniform before all are declared. */
static void vk_uniform(vk_rewrite *r) {
    if (++r->seen < r->loose) return;
    missing_structs(r);
    sb_printf(&r->out, "layout(std140, set = 0, binding = %d) uniform hfx_block\n{\n%s};\n", HFX_VK_BINDING_BLOCK,
              r->members->text.d ? r->members->text.d : "");
}

static void vk_line(void *ctx, const uniform_decl *u, const char *line, const char *next) {
    vk_rewrite *r = ctx;
    if (line == r->src && strncmp(line, "#version ", 9) == 0) {
        sb_printf(&r->out, "#version 450 core\n");
    } else if (!u) {
        if (!is_depth_remap(line, next) && !vk_varying(r, line, next)) sb_putn(&r->out, line, (size_t)(next - line));
    } else if (is_sampler(u)) {
        int64_t k = hfx_fx_spirv_sampler(r->prog, u->name, u->name_len);
        sb_printf(&r->out, "layout(set = 0, binding = %lld) ",
                  (long long)HFX_VK_BINDING_SAMPLER0 + (k >= 0 ? k : (int64_t)r->prog->sampler_count));
        sb_putn(&r->out, u->line, (size_t)(next - u->line));
    } else {
        vk_uniform(r);
    }
}

char *hfx_spirv_vk_glsl(const hfx_fx_effect *fx, const hfx_fx_program *p, int stage) {
    if (!fx || !p || stage < 0 || stage >= HFX_STAGE_COUNT || !p->code[stage][HFX_TARGET_GLSL330].data) return NULL;
    vk_members *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    for (int st = 0; st < HFX_STAGE_COUNT; st++)
        if (p->code[st][HFX_TARGET_GLSL330].data) {
            scan_lines(p->code[st][HFX_TARGET_GLSL330].data, collect_member, m);
            collect_structs(m, p->code[st][HFX_TARGET_GLSL330].data);
        }
    if (p->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data)
        scan_lines(p->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data, collect_varying, m);
    vk_rewrite r;
    memset(&r, 0, sizeof r);
    r.members = m;
    r.stage = stage;
    r.prog = p;
    r.src = p->code[stage][HFX_TARGET_GLSL330].data;
    scan_lines(r.src, count_loose, &r);
    scan_lines(r.src, vk_line, &r);
    bool bad = r.out.oom || m->text.oom || m->structs.oom || !r.out.d;
    sb_free(&m->text);
    sb_free(&m->structs);
    free(m);
    if (bad) {
        sb_free(&r.out);
        return NULL;
    }
    return r.out.d;
}

/* --- reflection ------------------------------------------------------------------------------- */

enum { OP_NAME = 5, OP_DECORATE = 71, DEC_BINDING = 33, DEC_LOCATION = 30 };

int hfx_spirv_find(const uint32_t *words, size_t count, const char *name, int32_t *location, int32_t *binding) {
    if (location) *location = -1;
    if (binding) *binding = -1;
    if (!words || count < 5 || words[0] != HFX_SPIRV_MAGIC || !name) return -1;
    size_t len = strlen(name);
    uint32_t id = 0;
    for (size_t i = 5; i < count;) { /* OpName first: it precedes every decoration */
        uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) return -1;
        if (op == OP_NAME && n >= 3) {
            const char *s = (const char *)&words[i + 2];
            size_t max = (n - 2) * 4;
            if (len < max && memcmp(s, name, len) == 0 && s[len] == 0) {
                id = words[i + 1];
                break;
            }
        }
        i += n;
    }
    if (!id) return 0;
    for (size_t i = 5; i < count;) {
        uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) return -1;
        if (op == OP_DECORATE && n >= 4 && words[i + 1] == id) {
            if (words[i + 2] == DEC_LOCATION && location) *location = (int32_t)words[i + 3];
            if (words[i + 2] == DEC_BINDING && binding) *binding = (int32_t)words[i + 3];
        }
        i += n;
    }
    return 1;
}

/* Does a UniformConstant variable hold a bool somewhere (a struct member, say)? Strict
 * validators reject that; glslang emits it for a uniform struct with bool members. */
enum { OP_TYPE_BOOL = 20, OP_TYPE_VECTOR = 23, OP_TYPE_MATRIX = 24, OP_TYPE_ARRAY = 28, OP_TYPE_STRUCT = 30,
       OP_TYPE_POINTER = 32, OP_VARIABLE = 59, STORAGE_UNIFORM_CONSTANT = 0 };

/* The OpType* instruction defining `id` (types have their result id in word 1). */
static const uint32_t *type_def(const uint32_t *w, size_t count, uint32_t id) {
    for (size_t i = 5; i < count;) {
        uint32_t n = w[i] >> 16, op = w[i] & 0xffffu;
        if (n == 0 || i + n > count) return NULL;
        if (op >= 19 && op <= 39 && n >= 2 && w[i + 1] == id) return &w[i];
        i += n;
    }
    return NULL;
}

static bool type_has_bool(const uint32_t *w, size_t count, uint32_t type, int depth) {
    const uint32_t *d = depth < 16 ? type_def(w, count, type) : NULL;
    if (!d) return false;
    uint32_t n = d[0] >> 16, op = d[0] & 0xffffu;
    switch (op) {
    case OP_TYPE_BOOL: return true;
    case OP_TYPE_VECTOR: case OP_TYPE_MATRIX: case OP_TYPE_ARRAY:
        return n >= 3 && type_has_bool(w, count, d[2], depth + 1);
    case OP_TYPE_STRUCT:
        for (uint32_t m = 2; m < n; m++)
            if (type_has_bool(w, count, d[m], depth + 1)) return true;
        return false;
    default: return false;
    }
}

static void name_of(const uint32_t *w, size_t count, uint32_t id, char *out, size_t size) {
    snprintf(out, size, "%%%u", id);
    for (size_t i = 5; i < count;) {
        uint32_t n = w[i] >> 16, op = w[i] & 0xffffu;
        if (n == 0 || i + n > count) return;
        if (op == OP_NAME && n >= 3 && w[i + 1] == id) {
            snprintf(out, size, "%.*s", (int)((n - 2) * 4), (const char *)&w[i + 2]);
            return;
        }
        i += n;
    }
}

int hfx_spirv_bool_uniform(const uint32_t *words, size_t count, char *name, size_t name_size) {
    if (!words || count < 5 || words[0] != HFX_SPIRV_MAGIC) return -1;
    for (size_t i = 5; i < count;) {
        uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) return -1;
        if (op == OP_VARIABLE && n >= 4 && words[i + 3] == STORAGE_UNIFORM_CONSTANT) {
            const uint32_t *ptr = type_def(words, count, words[i + 1]);
            if (ptr && (ptr[0] & 0xffffu) == OP_TYPE_POINTER && (ptr[0] >> 16) >= 4 &&
                type_has_bool(words, count, ptr[3], 0)) {
                if (name && name_size) name_of(words, count, words[i + 2], name, name_size);
                return 1;
            }
        }
        i += n;
    }
    return 0;
}

/* --- glslang ------------------------------------------------------------------------------------ */

#define append_log hfx_glslang_append_log

#ifdef HFX_HAVE_GLSLANG

bool hfx_spirv_available(void) { return true; }
bool hfx_spirv_begin(void) { return hfx_glslang_begin(); }
void hfx_spirv_end(void) { hfx_glslang_end(); }

static const glslang_stage_t stages[HFX_STAGE_COUNT] = {GLSLANG_STAGE_VERTEX, GLSLANG_STAGE_FRAGMENT};
static const char *const stage_names[HFX_STAGE_COUNT] = {"vertex", "fragment"};

#define MESSAGES GLSLANG_MSG_SPV_RULES_BIT

static glslang_shader_t *compile_stage(const char *src, int stage, bool vulkan, char **log) {
    glslang_input_t in;
    memset(&in, 0, sizeof in);
    in.language = GLSLANG_SOURCE_GLSL;
    in.stage = stages[stage];
    in.client = vulkan ? GLSLANG_CLIENT_VULKAN : GLSLANG_CLIENT_OPENGL;
    in.client_version = vulkan ? GLSLANG_TARGET_VULKAN_1_0 : GLSLANG_TARGET_OPENGL_450;
    in.target_language = GLSLANG_TARGET_SPV;
    in.target_language_version = GLSLANG_TARGET_SPV_1_0;
    in.code = src;
    in.default_version = 450;
    in.default_profile = GLSLANG_CORE_PROFILE;
    in.messages = MESSAGES;
    in.resource = glslang_default_resource();
    glslang_shader_t *sh = glslang_shader_create(&in);
    if (!sh) return NULL;
    /* Varyings carry no location in the GLSL: glslang gives them matching ones when linking.
     * Bindings are not auto-mapped: samplers have theirs (the texture unit), and a binding on
     * a loose non-opaque uniform means nothing to OpenGL. */
    if (!vulkan) glslang_shader_set_options(sh, GLSLANG_SHADER_AUTO_MAP_LOCATIONS); /* Vulkan's are explicit */
    if (!glslang_shader_preprocess(sh, &in) || !glslang_shader_parse(sh, &in)) {
        char what[64];
        snprintf(what, sizeof what, "%s shader: ", stage_names[stage]);
        *log = append_log(*log, what, glslang_shader_get_info_log(sh));
        *log = append_log(*log, what, glslang_shader_get_info_debug_log(sh));
        glslang_shader_delete(sh);
        return NULL;
    }
    return sh;
}

/* Both stages of p for `target` (HFX_TARGET_SPIRV or HFX_TARGET_SPIRV_VK). */
static int spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, int target, char **log) {
    bool vulkan = target == HFX_TARGET_SPIRV_VK;
    if (log) *log = NULL;
    char *dummy = NULL, **lg = log ? log : &dummy;
    glslang_shader_t *sh[HFX_STAGE_COUNT] = {NULL, NULL};
    glslang_program_t *prog = glslang_program_create();
    int rc = prog ? 0 : -1, stages_in = 0;
    for (int s = 0; s < HFX_STAGE_COUNT && rc == 0; s++) {
        if (!p->code[s][HFX_TARGET_GLSL330].data) continue;
        char *src = vulkan ? hfx_spirv_vk_glsl(fx, p, s) : hfx_spirv_glsl(fx, p, s);
        if (!src) {
            *lg = append_log(*lg, "", "out of memory rewriting the GLSL for SPIR-V");
            rc = -1;
            break;
        }
        sh[s] = compile_stage(src, s, vulkan, lg);
        free(src);
        if (!sh[s]) rc = -1;
        else glslang_program_add_shader(prog, sh[s]), stages_in++;
    }
    if (rc == 0 && !stages_in) {
        *lg = append_log(*lg, "", "the program has no GLSL 330 to compile");
        rc = -1;
    }
    if (rc == 0 && (!glslang_program_link(prog, MESSAGES) || !glslang_program_map_io(prog))) {
        *lg = append_log(*lg, "link: ", glslang_program_get_info_log(prog));
        *lg = append_log(*lg, "link: ", glslang_program_get_info_debug_log(prog));
        rc = -1;
    }
    for (int s = 0; s < HFX_STAGE_COUNT && rc == 0; s++) {
        if (!sh[s]) continue;
        /* glslang 12 appends each stage's module to the program's words: take the new tail. */
        size_t before = glslang_program_SPIRV_get_size(prog);
        glslang_program_SPIRV_generate(prog, stages[s]);
        *lg = append_log(*lg, "spirv: ", glslang_program_SPIRV_get_messages(prog));
        size_t words = glslang_program_SPIRV_get_size(prog);
        const unsigned *w = glslang_program_SPIRV_get_ptr(prog);
        if (w && before && words > before && w[before] == HFX_SPIRV_MAGIC) {
            w += before;
            words -= before;
        }
        char *data = words && w ? malloc(words * 4 + 1) : NULL; /* +1: code stays NUL-terminated */
        if (!data) {
            *lg = append_log(*lg, "", "SPIR-V generation failed");
            rc = -1;
            break;
        }
        memcpy(data, w, words * 4);
        data[words * 4] = 0;
        free(p->code[s][target].data);
        p->code[s][target].data = data;
        p->code[s][target].size = words * 4;
    }
    if (prog) glslang_program_delete(prog);
    for (int s = 0; s < HFX_STAGE_COUNT; s++)
        if (sh[s]) glslang_shader_delete(sh[s]);
    if (rc != 0)
        for (int s = 0; s < HFX_STAGE_COUNT; s++) {
            free(p->code[s][target].data);
            p->code[s][target].data = NULL;
            p->code[s][target].size = 0;
        }
    free(dummy);
    return rc;
}

int hfx_spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    return spirv_program(fx, p, HFX_TARGET_SPIRV, log);
}

int hfx_spirv_vk_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    return spirv_program(fx, p, HFX_TARGET_SPIRV_VK, log);
}

#else /* built without glslang */

bool hfx_spirv_available(void) { return false; }
bool hfx_spirv_begin(void) { return false; }
void hfx_spirv_end(void) {}

int hfx_spirv_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    (void)fx, (void)p;
    if (log) *log = append_log(NULL, "", "hfx was built without glslang: no SPIR-V");
    return -1;
}

int hfx_spirv_vk_program(const hfx_fx_effect *fx, hfx_fx_program *p, char **log) {
    return hfx_spirv_program(fx, p, log);
}

#endif
