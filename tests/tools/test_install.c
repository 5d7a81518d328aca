/* `cmake --install` into a temporary prefix, then an outside program built against it twice:
 * with `pkg-config --cflags --libs hfx` and with CMake's find_package(hfx) (hfx::hfx). The
 * program compiles an effect with the compiler API, loads it with the runtime on an OSMesa
 * context and prints what it found; the installed hfxc and hfxview must run too. */
#include "test.h"

#include "files.h"
#include "view_support.h"

static char *build, *tmp, *prefix;
static int sanitized;

static const char *program =
    "#include <GL/osmesa.h>\n"
    "#include <hfx/hfx.h>\n"
    "#include <hfx/hfxc.h>\n"
    "#include <stdio.h>\n"
    "#include <string.h>\n"
    "static const char *fx = \"float4x4 WorldViewProj : WorldViewProjection;\\n\"\n"
    "  \"float4 vs(float3 p : POSITION) : POSITION { return mul(float4(p, 1), WorldViewProj); }\\n\"\n"
    "  \"float4 ps() : COLOR { return float4(1, 1, 1, 1); }\\n\"\n"
    "  \"technique t0 { pass p0 { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\\n\";\n"
    "static void *loader(const char *name) { OSMESAproc p = OSMesaGetProcAddress(name); void *q;\n"
    "  memcpy(&q, &p, sizeof q); return q; }\n"
    "int main(void) {\n"
    "  hfxc_result *r = hfxc_compile_memory(fx, strlen(fx), \"outside.fx\", NULL);\n"
    "  printf(\"compile %s\\n\", hfxc_result_ok(r) ? \"ok\" : \"failed\");\n"
    "  hfxc_result_free(r);\n"
    "  static const int attrs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE,\n"
    "    OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};\n"
    "  static unsigned char pixels[8 * 8 * 4];\n"
    "  OSMesaContext ctx = OSMesaCreateContextAttribs(attrs, NULL);\n"
    "  if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 8, 8)) return 3;\n"
    "  hfx_device *dev = hfx_device_create_gl(loader);\n"
    "  char *errors = NULL;\n"
    "  hfx_effect *e = dev ? hfx_effect_load_memory(dev, fx, strlen(fx), \"outside.fx\", NULL, &errors) : NULL;\n"
    "  printf(\"device %s\\n\", dev ? \"ok\" : \"failed\");\n"
    "  if (e) printf(\"effect ok, %zu technique\\n\", hfx_effect_technique_count(e));\n"
    "  else printf(\"effect failed: %s\\n\", errors ? errors : (dev ? hfx_device_last_error(dev) : \"\"));\n"
    "  hfx_free(errors);\n"
    "  hfx_effect_destroy(e);\n"
    "  hfx_device_destroy(dev);\n"
    "  OSMesaDestroyContext(ctx);\n"
    "  return 0;\n"
    "}\n";

static const char *cmake_lists =
    "cmake_minimum_required(VERSION 3.20)\n"
    "project(outside LANGUAGES C)\n"
    "find_package(hfx 0.1 REQUIRED)\n"
    "find_package(PkgConfig REQUIRED)\n"
    "pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)\n"
    "add_executable(outside main.c)\n"
    "target_link_libraries(outside PRIVATE hfx::hfx PkgConfig::OSMESA)\n"
    "hfx_add_effects(shaders white.fx)\n"; /* the installed hfxc, through hfxEffects.cmake */

static const char *white_fx =
    "float4 ps() : COLOR { return float4(1, 1, 1, 1); }\n"
    "technique t0 { pass p0 { PixelShader = compile ps_2_0 ps(); } }\n";

static void write_file(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static int run(const char *cmd, char **out) {
    int rc = view_run(cmd, out);
    if (rc != 0) fprintf(stderr, "$ %s\nexit %d:\n%s\n", cmd, rc, out && *out ? *out : "");
    return rc;
}

static void check_program_output(const char *out) {
    CHECK_CONTAINS(out, "compile ok\n");
    CHECK_CONTAINS(out, "device ok\n");
    CHECK_CONTAINS(out, "effect ok, 1 technique\n");
}

static void installs_the_files(void) {
    char *out = NULL, *cmd = view_format("cmake --install %s --prefix %s", build, prefix);
    CHECK_INT(run(cmd, &out), 0);
    free(out);
    free(cmd);
    const char *files[] = {"include/hfx/hfx.h", "include/hfx/hfxc.h", "lib/libhfx.a", "lib/libhfx_runtime.a",
                           "lib/libhfx_compiler.a", "lib/libhfx_common.a", "lib/pkgconfig/hfx.pc",
                           "lib/cmake/hfx/hfxConfig.cmake", "bin/hfxc", "bin/hfxview", NULL};
    for (int i = 0; files[i]; i++) {
        char *p = view_format("%s/%s", prefix, files[i]);
        FILE *f = fopen(p, "r");
        if (!f) fprintf(stderr, "missing %s\n", p);
        CHECK(f != NULL);
        if (f) fclose(f);
        free(p);
    }
    cmd = view_format("%s/bin/hfxc --version && %s/bin/hfxview --help", prefix, prefix);
    CHECK_INT(run(cmd, &out), 0);
    CHECK_CONTAINS(out, "usage: hfxview");
    free(out);
    free(cmd);
}

static void builds_with_pkg_config(void) {
    char *src = view_format("%s/main.c", tmp);
    write_file(src, program);
    char *out = NULL;
    char *cmd = view_format("cd %s && PKG_CONFIG_PATH=%s/lib/pkgconfig cc %s -o outside_pc main.c "
                            "$(PKG_CONFIG_PATH=%s/lib/pkgconfig pkg-config --cflags --libs hfx osmesa) && "
                            "ASAN_OPTIONS=detect_leaks=0 ./outside_pc",
                            tmp, prefix, sanitized ? "-fsanitize=address,undefined" : "", prefix);
    CHECK_INT(run(cmd, &out), 0);
    check_program_output(out);
    free(out);
    free(cmd);
    /* build scripts find hfxc through the .pc file */
    cmd = view_format("\"$(PKG_CONFIG_PATH=%s/lib/pkgconfig pkg-config --variable=hfxc hfx)\" --version", prefix);
    CHECK_INT(run(cmd, &out), 0);
    CHECK_CONTAINS(out, "hfxc 0.1.0");
    free(out);
    free(cmd);
    free(src);
}

static void builds_with_find_package(void) {
    char *dir = view_format("%s/cmake_project", tmp), *out = NULL;
    char *mk = view_format("mkdir -p %s && cp %s/main.c %s/", dir, tmp, dir);
    run(mk, NULL);
    char *lists = view_format("%s/CMakeLists.txt", dir);
    write_file(lists, cmake_lists);
    char *fx = view_format("%s/white.fx", dir);
    write_file(fx, white_fx);
    free(fx);
    const char *san = sanitized ? "-DCMAKE_C_FLAGS=-fsanitize=address,undefined" : "";
    char *cmd = view_format("cmake -S %s -B %s/build -DCMAKE_PREFIX_PATH=%s %s >/dev/null && "
                            "cmake --build %s/build >/dev/null && ASAN_OPTIONS=detect_leaks=0 %s/build/outside",
                            dir, dir, prefix, san, dir, dir);
    CHECK_INT(run(cmd, &out), 0);
    check_program_output(out);
    char *hfxo = view_format("%s/build/effects/white.hfxo", dir);
    FILE *f = fopen(hfxo, "rb");
    CHECK(f != NULL); /* hfx_add_effects ran the installed hfxc */
    if (f) fclose(f);
    free(hfxo);
    free(out);
    free(cmd);
    free(lists);
    free(mk);
    free(dir);
}

int main(void) {
    const char *b = getenv("HFX_BUILD_DIR");
    if (!b) test_skip("HFX_BUILD_DIR is not set (run through ctest)");
    build = view_format("%s", b);
    if (view_run("command -v cmake && command -v pkg-config && command -v cc", NULL) != 0)
        test_skip("cmake, pkg-config or cc is missing");
    char *hfxview = view_build_path("tools/hfxview/hfxview");
    if (!hfxview) test_skip("hfxview is not built (it needs OSMesa, libpng and stb), so there is nothing whole to install");
    free(hfxview);
    char *grep = view_format("grep -q '^HFX_SANITIZE:BOOL=ON' %s/CMakeCache.txt", build);
    sanitized = view_run(grep, NULL) == 0; /* the libraries carry ASan calls: the program must too */
    free(grep);
    tmp = test_temp_dir();
    prefix = view_format("%s/prefix", tmp);
    RUN(installs_the_files);
    RUN(builds_with_pkg_config);
    RUN(builds_with_find_package);
    char *rm = view_format("rm -rf %s", tmp);
    view_run(rm, NULL);
    free(rm);
    free(prefix);
    free(tmp);
    free(build);
    return test_summary();
}
