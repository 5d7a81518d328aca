/* hfxc.c: the compiler library's public face: runs the phases in a straight line
 * (preprocess -> parse -> check -> build) over one arena and one diagnostics list. */
#include "hfx/hfxc.h"

#include <setjmp.h>
#include <stdio.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "parse/ast.h"
#include "effect/build.h"
#include "effect/codegen.h"
#include "effect/fx2.h"
#include "effect/fx2_write.h"
#include "check/check.h"
#include "effect.h"
#include "ir/ir.h"
#include "pp/token_cache.h"

struct hfxc_result {
    hfx_arena arena;
    hfx_diags diags;
    hfx_ast *ast;
    hfx_fx_effect *effect;
    bool oom;         /* an allocation failed: never ok, even if the message could not be stored */
    const char **deps;     /* hfxc_dependency_at: unique paths, in the order first read */
    size_t dep_count;
    const uint32_t *bytecode; /* fxc /T vs_* | ps_*: the shader's tokens (arena) */
    uint32_t bytecode_words;
};

struct hfxc_session {
    hfx_token_cache *tokens;
};

const char *hfxc_version(void) { return "hfxc 0.1.0"; }

hfxc_session *hfxc_session_new(void) {
    hfxc_session *s = calloc(1, sizeof *s);
    if (s) s->tokens = hfx_token_cache_new();
    if (s && !s->tokens) {
        free(s);
        return NULL;
    }
    return s;
}

void hfxc_session_free(hfxc_session *s) {
    if (!s) return;
    hfx_token_cache_free(s->tokens);
    free(s);
}

static unsigned default_targets(const hfxc_options *opt) {
    if (opt && opt->targets) return opt->targets;
    return (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300);
}

/* The phases in a straight line; an allocation failure anywhere longjmps out (base/arena.h). */
static void run_phases(hfxc_result *r, const char *name, const char *text, size_t size, const hfxc_options *opt) {
    hfx_pp_options pp;
    memset(&pp, 0, sizeof pp);
    if (opt) {
        pp.defines = opt->defines;
        pp.define_count = (uint32_t)opt->define_count;
        pp.include_dirs = opt->include_dirs;
        pp.include_dir_count = (uint32_t)opt->include_dir_count;
        pp.cache = opt->session ? opt->session->tokens : NULL;
    }
    hfx_types *types = hfx_types_new(&r->arena);
    hfx_token *tokens = hfx_preprocess(&r->arena, &r->diags, name, text, (uint32_t)size, &pp);
    r->ast = hfx_parse(&r->arena, &r->diags, types, tokens);
    if (opt && (opt->flags & HFXC_PARSE_ONLY)) return;
    if (r->diags.errors) return;
    if (!hfx_check(&r->arena, &r->diags, types, r->ast) || r->diags.errors) return;
    if (opt && opt->entry)  /* fxc /E: one entry point, one profile */
    {
        r->effect = hfx_build_entry_effect(&r->arena, &r->diags, types, r->ast, name, default_targets(opt),
                                           opt->entry, opt->profile);
        bool shader = opt->profile && (opt->profile[0] == 'v' || opt->profile[0] == 'p') && opt->profile[1] == 's';
        if (r->effect && shader && !r->diags.errors)
            r->bytecode = hfx_codegen_entry_bytecode(&r->arena, &r->diags, types, r->ast, r->effect, opt->entry,
                                                     opt->profile, &r->bytecode_words);
    }
    else
        r->effect = hfx_build_effect(&r->arena, &r->diags, types, r->ast, name, default_targets(opt));
}

/* An effect fxc compiled (fx_2_0, or inside an XNA .xnb): read, not compiled. A file's bytes
 * go in the arena, which grows its limit by what a source of that size may use. */
static void run_binary(hfxc_result *r, const char *name, const char *text, size_t size, const hfxc_options *opt) {
    const char *path = text ? NULL : name;
    if (path) {
        FILE *f = fopen(path, "rb");
        long len = -1;
        if (f && fseek(f, 0, SEEK_END) == 0) len = ftell(f);
        char *data = len >= 0 && (size_t)len <= HFXC_MAX_SOURCE_BYTES ? hfx_arena_alloc_raw(&r->arena, (size_t)len + 1) : NULL;
        if (!data || fseek(f, 0, SEEK_SET) != 0 || fread(data, 1, (size_t)len, f) != (size_t)len) {
            hfx_error(&r->diags, (hfx_loc){hfx_diags_add_file(&r->diags, name, path, NULL, 0), 0, 0}, X_PP_INCLUDE,
                      len > (long)HFXC_MAX_SOURCE_BYTES ? "the effect is larger than hfx reads" : "cannot read the file");
            if (f) fclose(f);
            return;
        }
        fclose(f);
        text = data;
        size = (size_t)len;
    }
    r->arena.limit += size * HFXC_MEMORY_PER_BYTE;
    r->effect = hfx_fx2_read(&r->arena, &r->diags, name, path, text, size, default_targets(opt), opt ? opt->flags : 0);
}

static bool is_binary(const char *name, const char *text, size_t size) {
    return text ? hfx_fx2_is_binary(text, size) != 0 : hfx_fx2_file_is_binary(name) != 0;
}

/* After a failed allocation: nothing of the partial work is kept, and one located error says
 * why (the arena's limit is lifted so that the message itself can be stored). */
static void out_of_memory(hfxc_result *r) {
    hfx_arena_run_cleanups(&r->arena);
    hfx_fx_effect_free(r->effect);
    r->effect = NULL;
    r->ast = NULL;
    r->oom = true;
    size_t limit = r->arena.limit;
    r->arena.limit = 0;
    if (r->arena.over_limit)
        hfx_error(&r->diags, (hfx_loc){0, 1, 1}, X_MEMORY_LIMIT,
                  "out of memory: compiling this source needs more than %zu MiB (hfx allows %u MiB plus %u times the "
                  "size of the source files)", limit >> 20, HFXC_MEMORY_FLOOR >> 20, HFXC_MEMORY_PER_BYTE);
    else
        hfx_error(&r->diags, (hfx_loc){0, 1, 1}, X_MEMORY_LIMIT, "out of memory");
}

/* Every file the preprocessor read, by the path it opened, once each (a #line entry repeats its
 * file's path; a file included twice has two entries; text from memory or -D has none). */
static void collect_dependencies(hfxc_result *r) {
    const hfx_diags *d = &r->diags;
    r->deps = HFX_NEW_ARRAY(&r->arena, const char *, d->file_count ? d->file_count : 1);
    if (!r->deps) return;
    for (uint32_t i = 0; i < d->file_count; i++) {
        const char *path = d->files[i].path;
        if (!path) continue;
        size_t k = 0;
        while (k < r->dep_count && strcmp(r->deps[k], path) != 0) k++;
        if (k == r->dep_count) r->deps[r->dep_count++] = path;
    }
}

static hfxc_result *compile(const char *name, const char *text, size_t size, const hfxc_options *opt) {
    hfxc_result *r = calloc(1, sizeof *r);
    if (!r) return NULL;
    hfx_arena_init(&r->arena);
    r->arena.limit = HFXC_MEMORY_FLOOR; /* the preprocessor adds HFXC_MEMORY_PER_BYTE per byte it reads */
    hfx_diags_init(&r->diags, &r->arena, opt ? opt->flags : 0);
    r->diags.dump_ir = opt ? opt->dump_ir : NULL;
    jmp_buf escape;
    r->arena.escape = &escape;
    if (setjmp(escape) == 0) {
        hfx_arena_escape_on(&r->arena);
        if (is_binary(name, text, size)) run_binary(r, name, text, size, opt);
        else run_phases(r, name, text, size, opt);
        hfx_arena_escape_off(&r->arena);
    } else {
        r->arena.escape_depth = 0;
    }
    r->arena.escape = NULL;
    if (r->arena.failed) out_of_memory(r);
    if (r->diags.errors && r->effect) {
        hfx_fx_effect_free(r->effect);
        r->effect = NULL;
    }
    collect_dependencies(r); /* outside the escape: a failure leaves the list empty */
    return r;
}

hfxc_result *hfxc_compile_file(const char *path, const hfxc_options *opt) {
    return compile(path, NULL, 0, opt);
}

hfxc_result *hfxc_compile_memory(const char *src, size_t size, const char *name, const hfxc_options *opt) {
    return compile(name ? name : "memory", src ? src : "", src ? size : 0, opt);
}

void hfxc_result_free(hfxc_result *r) {
    if (!r) return;
    hfx_fx_effect_free(r->effect);
    hfx_arena_free(&r->arena);
    free(r);
}

int hfxc_result_ok(const hfxc_result *r) {
    return r && !r->oom && r->diags.errors == 0 && (r->effect || r->ast);
}

size_t hfxc_diag_count(const hfxc_result *r) { return r ? r->diags.count : 0; }

const hfxc_diag *hfxc_diag_at(const hfxc_result *r, size_t i) {
    return r && i < r->diags.count ? &r->diags.items[i] : NULL;
}

char *hfxc_diagnostics_text(const hfxc_result *r) {
    if (!r) return strdup("");
    return hfx_diags_format(&r->diags, (r->diags.flags & HFXC_CARET) != 0);
}

const struct hfx_fx_effect *hfxc_result_effect(const hfxc_result *r) { return r ? r->effect : NULL; }

const void *hfxc_result_bytecode(const hfxc_result *r, size_t *size) {
    *size = r && r->bytecode ? (size_t)r->bytecode_words * 4 : 0;
    return r ? r->bytecode : NULL;
}

/* A program compiled without HFXC_D3D9_BYTECODE has no shader to write. */
static int no_bytecode(void *ctx, const hfx_fx_effect *fx, uint32_t program, int stage, const void **data, size_t *size,
                       char *err, size_t err_size) {
    (void)ctx, (void)fx, (void)program, (void)stage, (void)data, (void)size;
    snprintf(err, err_size, "no Direct3D 9 bytecode for this shader: compile with HFXC_D3D9_BYTECODE");
    return -1;
}

void *hfxc_result_fx2(const hfxc_result *r, int row_major, size_t *size, char **errors) {
    *size = 0;
    if (errors) *errors = NULL;
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (!fx) {
        if (errors) *errors = r ? hfxc_diagnostics_text(r) : NULL;
        return NULL;
    }
    hfx_fx2_write_options opt = {no_bytecode, NULL, row_major ? 1 : -1};
    void *out = NULL;
    char err[2048] = "";
    if (hfx_fx2_write(fx, fx->source_name ? fx->source_name : "effect", &opt, &out, size, err, sizeof err) == 0) return out;
    if (errors) *errors = strdup(err);
    return NULL;
}

struct hfx_fx_effect *hfxc_result_take_effect(hfxc_result *r) {
    if (!r) return NULL;
    hfx_fx_effect *fx = r->effect;
    r->effect = NULL;
    return fx;
}

size_t hfxc_dependency_count(const hfxc_result *r) { return r ? r->dep_count : 0; }

const char *hfxc_dependency_at(const hfxc_result *r, size_t i) {
    return r && i < r->dep_count ? r->deps[i] : NULL;
}

char *hfxc_result_ast_dump(const hfxc_result *r) {
    return r && r->ast ? hfx_ast_dump(r->ast) : strdup("");
}

char *hfxc_result_ir_dump(const hfxc_result *r) {
    const sbuf *b = r ? &r->diags.dump_text : NULL;
    return strdup(b && b->d ? b->d : "");
}

const char *hfxc_pass_name(size_t i, const char **why) {
    if (why) *why = i < hfx_ir_pass_count() ? hfx_ir_pass_why((uint32_t)i) : NULL;
    return i < hfx_ir_pass_count() ? hfx_ir_pass_name((uint32_t)i) : NULL;
}

char *hfxc_disassemble(const void *data, size_t size, const char *name, char **diagnostics) {
    hfxc_result *r = calloc(1, sizeof *r);
    if (diagnostics) *diagnostics = NULL;
    if (!r) return NULL;
    hfx_arena_init(&r->arena);
    r->arena.limit = HFXC_MEMORY_FLOOR + (size <= HFXC_MAX_SOURCE_BYTES ? size * HFXC_MEMORY_PER_BYTE : 0);
    hfx_diags_init(&r->diags, &r->arena, 0);
    char *text = NULL, *listing = NULL;
    jmp_buf escape;
    r->arena.escape = &escape;
    if (setjmp(escape) == 0) {
        hfx_arena_escape_on(&r->arena);
        if (hfx_d3d9_is_shader(data, size)) { /* a raw shader (.vso / .pso, fxc /T vs_* | ps_*) */
            sbuf out = {.arena = &r->arena};
            d3d9_input in = {data, (uint32_t)size, hfx_diags_add_file(&r->diags, name ? name : "memory", NULL, "", 0), 0};
            listing = hfx_d3d9_disassemble_blob(&r->arena, &r->diags, &in, &out) == 0 && !out.oom ? out.d : NULL;
        } else listing = hfx_fx2_listing(&r->arena, &r->diags, name ? name : "memory", data, size);
        hfx_arena_escape_off(&r->arena);
    } else {
        r->arena.escape_depth = 0;
        listing = NULL;
    }
    r->arena.escape = NULL;
    if (r->arena.failed) out_of_memory(r);
    if (listing && !r->diags.errors) text = strdup(listing);
    if (diagnostics) *diagnostics = hfx_diags_format(&r->diags, 0);
    hfxc_result_free(r);
    return text;
}
