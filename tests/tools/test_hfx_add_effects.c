/* cmake/hfxEffects.cmake's hfx_add_effects in an outside CMake project, built with `cmake
 * --build` under each generator present (Unix Makefiles; Ninja when installed): every effect
 * compiles to a .hfxo with the depfile hfxc -MD writes, a second build with nothing changed runs
 * nothing, and touching an included .fxh rebuilds exactly the effects that include it: an output
 * counts as rebuilt when its modification time (to the nanosecond) moved. The outputs depend on
 * hfxc too (a new compiler recompiles), so the test runs a copy dated 200 s ago. */
#include <fcntl.h>
#include <sys/stat.h>
#include <time.h>

#include "files.h"
#include "test.h"
#include "view_support.h"

static char *tmp, *hfxc;


static void write_file(const char *dir, const char *name, const char *text) {
    char *path = view_format("%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    free(path);
}

static void set_mtime(const char *dir, const char *name, time_t when) {
    char *path = view_format("%s/%s", dir, name);
    struct timespec ts[2] = {{when, 0}, {when, 0}};
    CHECK_INT(utimensat(AT_FDCWD, path, ts, 0), 0);
    free(path);
}

/* a.fx includes common.fxh (its own folder) and light.fxh (the INCLUDE_DIRS folder inc/), which
 * includes nothing; b.fx includes other.fxh; c.fx includes nothing. K comes from DEFINES. */
static void write_project(const char *src) {
    char *lists = view_format(
        "cmake_minimum_required(VERSION 3.20)\n"
        "project(effects_user NONE)\n"
        "include(%s/cmake/hfxEffects.cmake)\n"
        "set(HFX_HFXC_EXECUTABLE %s)\n"
        "hfx_add_effects(shaders a.fx b.fx c.fx OUTPUT_DIR fx DEFINES K=0.5 INCLUDE_DIRS inc TARGETS glsl330)\n"
        "list(LENGTH shaders_OUTPUTS n)\n"
        "message(STATUS \"outputs: ${n}\")\n",
        HFX_SOURCE_DIR, hfxc);
    write_file(src, "CMakeLists.txt", lists);
    free(lists);
    static const char ps[] = "float4 PS() : COLOR0 { return Color; }\n"
                             "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    char *a = view_format("#include \"common.fxh\"\n#include \"light.fxh\"\nstatic const float4 Color = Base * Light;\n%s", ps);
    char *b = view_format("#include \"other.fxh\"\nstatic const float4 Color = Other;\n%s", ps);
    char *c = view_format("float4 Color = K;\n%s", ps);
    write_file(src, "a.fx", a);
    write_file(src, "b.fx", b);
    write_file(src, "c.fx", c);
    write_file(src, "common.fxh", "float4 Base = K;\n");
    write_file(src, "inc/light.fxh", "float4 Light = 1;\n");
    write_file(src, "other.fxh", "float4 Other = K;\n");
    free(a), free(b), free(c);
}

static int build(const char *bin) {
    char *out = NULL, *cmd = view_format("cmake --build %s", bin);
    int rc = view_run(cmd, &out);
    if (rc) fprintf(stderr, "$ %s\nexit %d:\n%s\n", cmd, rc, out ? out : "");
    free(out), free(cmd);
    return rc;
}

static struct timespec mtime_of(const char *dir, const char *name) {
    char *path = view_format("%s/%s", dir, name);
    struct stat st;
    int rc = stat(path, &st);
    free(path);
    CHECK_INT(rc, 0);
    return rc == 0 ? st.st_mtim : (struct timespec){0, 0};
}

/* The outputs' times, to compare after the next build. */
static void snapshot(const char *fx, struct timespec t[3]) {
    const char *outputs[] = {"a.hfxo", "b.hfxo", "c.hfxo"};
    for (int i = 0; i < 3; i++) t[i] = mtime_of(fx, outputs[i]);
}

/* Which of a, b, c were written since the snapshot, as "a.." / ".b." letters. */
static void check_rebuilt(const char *fx, const struct timespec before[3], const char *want) {
    struct timespec now[3];
    snapshot(fx, now);
    char got[4] = "...";
    for (int i = 0; i < 3; i++)
        if (now[i].tv_sec != before[i].tv_sec || now[i].tv_nsec != before[i].tv_nsec) got[i] = (char)('a' + i);
    CHECK_STR(got, want);
}

/* Modified now, a little after the outputs were written (ext4 and tmpfs keep nanoseconds; the
 * pause covers file systems that round to milliseconds). */
static void touch(const char *dir, const char *name) {
    nanosleep(&(struct timespec){0, 20 * 1000 * 1000}, NULL);
    char *path = view_format("%s/%s", dir, name);
    CHECK_INT(utimensat(AT_FDCWD, path, NULL, 0), 0);
    free(path);
}

/* Builds after touching `name` (NULL: nothing) and checks which outputs were written. */
static void rebuild_after(const char *src, const char *bin, const char *fx, const char *name, const char *want) {
    struct timespec before[3];
    snapshot(fx, before);
    if (name) touch(src, name);
    CHECK_INT(build(bin), 0);
    check_rebuilt(fx, before, want);
}

static void check_depfile(const char *src, const char *fx) {
    char *path = view_format("%s/a.hfxo.d", fx);
    char *text = test_read_file(path, NULL);
    char *want = view_format("%s/a.hfxo: %s/a.fx \\\n %s/common.fxh \\\n %s/inc/light.fxh\n", fx, src, src, src);
    CHECK_STR(text, want);
    free(path), free(text), free(want);
}

static void builds_incrementally(const char *generator) {
    char *dir = view_format("%s/%s", tmp, generator[0] == 'N' ? "ninja" : "make");
    char *src = view_format("%s/src", dir), *bin = view_format("%s/build", dir), *fx = view_format("%s/fx", bin);
    char *mk = view_format("mkdir -p %s/inc", src);
    CHECK_INT(view_run(mk, NULL), 0);
    write_project(src);
    char *out = NULL, *cmd = view_format("cmake -S %s -B %s -G '%s'", src, bin, generator);
    CHECK_INT(view_run(cmd, &out), 0);
    CHECK_CONTAINS(out, "outputs: 3");
    CHECK_INT(build(bin), 0);
    check_depfile(src, fx);
    rebuild_after(src, bin, fx, NULL, "..."); /* nothing changed, nothing ran */
    rebuild_after(src, bin, fx, "common.fxh", "a..");
    rebuild_after(src, bin, fx, "inc/light.fxh", "a.."); /* found through INCLUDE_DIRS */
    rebuild_after(src, bin, fx, "other.fxh", ".b.");
    rebuild_after(src, bin, fx, "c.fx", "..c");
    rebuild_after(src, bin, fx, NULL, "...");
    free(out), free(cmd), free(mk), free(fx), free(bin), free(src), free(dir);
}

static void with_makefiles(void) { builds_incrementally("Unix Makefiles"); }

static void with_ninja(void) {
    if (view_run("command -v ninja", NULL) != 0) {
        printf("(ninja is not installed: Ninja generator not tried)\n");
        return;
    }
    builds_incrementally("Ninja");
}

int main(void) {
    if (view_run("command -v cmake && command -v make", NULL) != 0) test_skip("cmake or make is missing");
    char *built = view_build_path("compiler/hfxc");
    if (!built) test_skip("hfxc is not built");
    tmp = test_temp_dir();

    hfxc = view_format("%s/hfxc", tmp);
    char *cp = view_format("cp %s %s", built, hfxc);
    CHECK_INT(view_run(cp, NULL), 0);
    set_mtime(tmp, "hfxc", time(NULL) - 200);
    free(cp), free(built);
    RUN(with_makefiles);
    RUN(with_ninja);
    test_remove_dir(tmp);
    free(tmp), free(hfxc);
    return test_summary();
}
