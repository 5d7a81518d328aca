/* test_spirv_cli.c: `hfxc --target spirv` as a user runs it ($HFX_BUILD_DIR/compiler/hfxc):
 * exit 0 with nothing on stderr for a seed without source warnings, a .hfxo carrying only
 * SPIR-V, and --emit-glsl writing .spv files that spirv-val accepts (when it is installed). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "effect.h"
#include "files.h"
#include "glsl/spirv.h"
#include "test.h"

static char hfxc[4096];
static char *tmp;

static int run(const char *args, char **err) {
    char errf[1024], cmd[16384];
    snprintf(errf, sizeof errf, "%s/stderr.txt", tmp);
    snprintf(cmd, sizeof cmd, "'%s' %s >/dev/null 2>'%s'", hfxc, args, errf);
    int st = system(cmd);
    *err = test_read_file(errf, NULL);
    if (!*err) *err = strdup("");
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void hfxo_carries_spirv(void) {
    char *seed = test_seed_path("ambient_textured.fx"), out[2048], args[8192], *err;
    snprintf(out, sizeof out, "%s/ambient_textured.hfxo", tmp);
    snprintf(args, sizeof args, "--quiet --target spirv -o '%s' '%s'", out, seed);
    CHECK_INT(run(args, &err), 0);
    CHECK_STR(err, ""); /* no "no spirv code was generated" warning, nothing else either */
    free(err);
    size_t size = 0;
    char *data = test_read_file(out, &size), why[256] = "";
    hfx_fx_effect *fx = data ? hfx_fx_read_hfxo(data, size, why, sizeof why) : NULL;
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT(fx->targets, 1u << HFX_TARGET_SPIRV);
        CHECK_INT(fx->program_count, 2);
        for (uint32_t p = 0; p < fx->program_count; p++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++) {
                const hfx_fx_code *c = &fx->programs[p].code[s][HFX_TARGET_SPIRV];
                CHECK(c->data && c->size > 20 && c->size % 4 == 0);
                uint32_t magic = 0;
                if (c->data) memcpy(&magic, c->data, 4);
                CHECK_INT(magic, HFX_SPIRV_MAGIC);
                CHECK(fx->programs[p].code[s][HFX_TARGET_GLSL330].data == NULL);
            }
    }
    hfx_fx_effect_free(fx);
    free(data);
    free(seed);
}

static void emit_writes_valid_spv(void) {
    char *seed = test_seed_path("multilights_repaired.fx"), dir[2048], args[8192], *err;
    snprintf(dir, sizeof dir, "%s/spv", tmp);
    snprintf(args, sizeof args, "--quiet --no-warnings --target spirv --emit-glsl '%s' -o '%s/m.hfxo' '%s'", dir, tmp,
             seed);
    CHECK_INT(run(args, &err), 0);
    CHECK_STR(err, "");
    free(err);
    static const char *const files[] = {"Material.Ambiental.vert", "Material.Ambiental.frag", "Material.MultiLuces.vert",
                                        "Material.MultiLuces.frag", "Texturizado.MultiLuces.frag"};
    int have_val = system("command -v spirv-val >/dev/null 2>&1") == 0;
    if (!have_val) printf("note: spirv-val is not installed: the .spv files are checked by header only\n");
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        char path[4096], cmd[8192];
        snprintf(path, sizeof path, "%s/multilights_repaired.%s.spv", dir, files[i]);
        size_t size = 0;
        char *data = test_read_file(path, &size);
        CHECK(data != NULL);
        uint32_t magic = 0;
        if (data && size >= 4) memcpy(&magic, data, 4);
        CHECK_INT(magic, HFX_SPIRV_MAGIC);
        free(data);
        if (have_val) {
            snprintf(cmd, sizeof cmd, "spirv-val --target-env opengl4.5 '%s'", path);
            CHECK_INT(system(cmd), 0);
        }
    }
    free(seed);
}

int main(void) {
    test_require_seeds();
    if (!hfx_spirv_available()) test_skip("built without glslang: no SPIR-V target");
    const char *build = getenv("HFX_BUILD_DIR");
    if (!build) test_skip("HFX_BUILD_DIR is not set (run through ctest)");
    snprintf(hfxc, sizeof hfxc, "%s/compiler/hfxc", build);
    if (access(hfxc, X_OK) != 0) test_skip("hfxc is not built");
    tmp = test_temp_dir();
    RUN(hfxo_carries_spirv);
    RUN(emit_writes_valid_spv);
    free(tmp);
    return test_summary();
}
