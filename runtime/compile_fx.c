/* compile_fx.c: the runtime's .fx loads, through the compiler library (linked into `hfx`). */
#include <stdlib.h>
#include <string.h>

#include "compile.h"
#include "hfx/hfxc.h"

/* The files r read, copied out of the result (which the caller frees). */
static void take_dependencies(const hfxc_result *r, hfx_rt_files *deps) {
    size_t n = hfxc_dependency_count(r);
    deps->paths = calloc(n ? n : 1, sizeof *deps->paths);
    deps->count = 0;
    for (size_t i = 0; deps->paths && i < n; i++) {
        char *p = strdup(hfxc_dependency_at(r, i));
        if (p) deps->paths[deps->count++] = p;
    }
}

hfx_fx_effect *hfx_rt_compile_fx(const char *path, const void *data, size_t size, const char *name,
                                 const hfx_load_options *opt, char **errors) {
    return hfx_rt_compile_fx_deps(path, data, size, name, opt, errors, NULL);
}

hfx_fx_effect *hfx_rt_compile_fx_deps(const char *path, const void *data, size_t size, const char *name,
                                      const hfx_load_options *opt, char **errors, hfx_rt_files *deps) {
    hfxc_options co;
    memset(&co, 0, sizeof co);
    /* D3D9's register model: every changed float parameter of a program goes up in one call */
    if (!opt || !opt->separate_uniforms) co.flags |= HFXC_PACK_UNIFORMS;
    if (opt && opt->no_self_check) co.flags |= HFXC_NO_SELF_CHECK;
    if (opt && opt->no_preshaders) co.flags |= HFXC_NO_PRESHADERS;
    if (opt) {
        co.defines = opt->defines;
        co.define_count = opt->define_count;
        co.include_dirs = opt->include_dirs;
        co.include_dir_count = opt->include_dir_count;
        co.targets = 1u << opt->target;
    }
    hfxc_result *r = data ? hfxc_compile_memory(data, size, name, &co) : hfxc_compile_file(path, &co);
    if (!r) {
        if (errors) *errors = NULL;
        return NULL;
    }
    hfx_fx_effect *fx = hfxc_result_ok(r) ? hfxc_result_take_effect(r) : NULL;
    if (errors) *errors = hfxc_diagnostics_text(r);
    if (deps) take_dependencies(r, deps);
    hfxc_result_free(r);
    return fx;
}
