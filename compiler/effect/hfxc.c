/* hfxc.c: the compiler library's public face: runs the phases in a straight line
 * (preprocess -> parse -> check -> build) over one arena and one diagnostics list. */
#include "hfx/hfxc.h"

#include <stdlib.h>
#include <string.h>

#include "parse/ast.h"
#include "effect/build.h"
#include "check/check.h"
#include "effect.h"

struct hfxc_result {
    hfx_arena arena;
    hfx_diags diags;
    hfx_ast *ast;
    hfx_fx_effect *effect;
    const char **deps;     /* hfxc_dependency_at: unique paths, in the order first read */
    size_t dep_count;
};

const char *hfxc_version(void) { return "hfxc 0.1.0"; }

static hfxc_result *run_phases(const char *name, const char *text, size_t size, const hfxc_options *opt);

static unsigned default_targets(const hfxc_options *opt) {
    if (opt && opt->targets) return opt->targets;
    return (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300);
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
    hfxc_result *r = run_phases(name, text, size, opt);
    if (r) collect_dependencies(r);
    return r;
}

static hfxc_result *run_phases(const char *name, const char *text, size_t size, const hfxc_options *opt) {
    hfxc_result *r = calloc(1, sizeof *r);
    if (!r) return NULL;
    hfx_arena_init(&r->arena);
    hfx_diags_init(&r->diags, &r->arena, opt ? opt->flags : 0);
    hfx_pp_options pp;
    memset(&pp, 0, sizeof pp);
    if (opt) {
        pp.defines = opt->defines;
        pp.define_count = (uint32_t)opt->define_count;
        pp.include_dirs = opt->include_dirs;
        pp.include_dir_count = (uint32_t)opt->include_dir_count;
    }
    hfx_types *types = hfx_types_new(&r->arena);
    hfx_token *tokens = hfx_preprocess(&r->arena, &r->diags, name, text, (uint32_t)size, &pp);
    r->ast = hfx_parse(&r->arena, &r->diags, types, tokens);
    if (opt && (opt->flags & HFXC_PARSE_ONLY)) return r;
    if (r->diags.errors) return r;
    if (!hfx_check(&r->arena, &r->diags, types, r->ast) || r->diags.errors) return r;
    if (opt && opt->entry)  /* fxc /E: one entry point, one profile */
        r->effect = hfx_build_entry_effect(&r->arena, &r->diags, types, r->ast, name, default_targets(opt),
                                           opt->entry, opt->profile);
    else
        r->effect = hfx_build_effect(&r->arena, &r->diags, types, r->ast, name, default_targets(opt));
    if (r->diags.errors && r->effect) {
        hfx_fx_effect_free(r->effect);
        r->effect = NULL;
    }
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
    return r && r->diags.errors == 0 && (r->effect || r->ast);
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

struct hfx_fx_effect *hfxc_result_take_effect(hfxc_result *r) {
    if (!r) return NULL;
    hfx_fx_effect *fx = r->effect;
    r->effect = NULL;
    return fx;
}

char *hfxc_result_ast_dump(const hfxc_result *r) {
    return r && r->ast ? hfx_ast_dump(r->ast) : strdup("");
}

size_t hfxc_dependency_count(const hfxc_result *r) { return r ? r->dep_count : 0; }

const char *hfxc_dependency_at(const hfxc_result *r, size_t i) {
    return r && i < r->dep_count ? r->deps[i] : NULL;
}
