/* hfxc_dependency_count / _at: the files a compile read, root first, each once, by the path it
 * was opened with; nothing for text from memory or from -D; what was read before an error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "files.h"
#include "hfx/hfxc.h"
#include "test.h"

static char *tmp;

static char *path_of(const char *name) { return test_path_in(tmp, name); }
static void write_text(const char *name, const char *text) { CHECK_INT(test_write_text(tmp, name, text), 0); }

/* The dependencies as one string, "a|b|c", with tmp/ cut from the front of each. */
static char *deps_text(const hfxc_result *r) {
    static char buf[4096];
    buf[0] = 0;
    size_t skip = strlen(tmp) + 1;
    for (size_t i = 0; i < hfxc_dependency_count(r); i++) {
        const char *d = hfxc_dependency_at(r, i);
        strncat(buf, i ? "|" : "", sizeof buf - strlen(buf) - 1);
        strncat(buf, strncmp(d, tmp, skip - 1) == 0 ? d + skip : d, sizeof buf - strlen(buf) - 1);
    }
    return buf;
}

#define PS "float4 PS() : COLOR0 { return Color; }\ntechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n"

static void root_then_includes_once_each(void) {
    char *root = path_of("main.fx"), *lib = path_of("lib");
    const char *dirs[] = {lib};
    const char *defs[] = {"K=1"};
    hfxc_options opt = {.include_dirs = dirs, .include_dir_count = 1, .defines = defs, .define_count = 1};
    hfxc_result *r = hfxc_compile_file(root, &opt);
    CHECK(hfxc_result_ok(r));
    /* a.fxh twice (guarded), b.fxh from -I lib, which includes c.fxh beside it; K from -D is no file */
    CHECK_STR(deps_text(r), "main.fx|a.fxh|lib/b.fxh|lib/c.fxh");
    CHECK(hfxc_dependency_at(r, 4) == NULL);
    hfxc_result_free(r);
    free(root), free(lib);
}

static void memory_root_is_not_a_file(void) {
    static const char src[] = "#include \"a.fxh\"\nstatic const float4 Color = A;\n" PS;
    char *name = path_of("virtual.fx"); /* includes resolve beside the name, which need not exist */
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), name, NULL);
    CHECK(hfxc_result_ok(r));
    CHECK_STR(deps_text(r), "a.fxh");
    hfxc_result_free(r);
    free(name);
}

static void what_was_read_before_an_error(void) {
    char *root = path_of("broken.fx");
    hfxc_result *r = hfxc_compile_file(root, NULL);
    CHECK(!hfxc_result_ok(r));
    CHECK_STR(deps_text(r), "broken.fx|a.fxh"); /* missing.fxh was never opened */
    hfxc_result_free(r);
    free(root);
    CHECK_INT(hfxc_dependency_count(NULL), 0);
    CHECK(hfxc_dependency_at(NULL, 0) == NULL);
}

int main(void) {
    tmp = test_temp_dir();
    char *lib = path_of("lib");
    mkdir(lib, 0777);
    free(lib);
    write_text("main.fx", "#include \"a.fxh\"\n#include \"b.fxh\"\n#include \"a.fxh\"\n"
                          "static const float4 Color = A * B * K;\n" PS);
    write_text("a.fxh", "#ifndef A_FXH\n#define A_FXH\nfloat4 A = 1;\n#endif\n");
    write_text("lib/b.fxh", "#include \"c.fxh\"\n");
    write_text("lib/c.fxh", "float4 B = 2;\n");
    write_text("broken.fx", "#include \"a.fxh\"\n#include \"missing.fxh\"\n");
    RUN(root_then_includes_once_each);
    RUN(memory_root_is_not_a_file);
    RUN(what_was_read_before_an_error);
    test_remove_dir(tmp);
    free(tmp);
    return test_summary();
}
