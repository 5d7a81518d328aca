/* test_program_cache.c: hfx_device_set_program_cache. The first load of an effect compiles its
 * GLSL and leaves one file per program in the folder; a later load (same or another device)
 * compiles nothing and draws the same pixels; every damaged or foreign entry (truncated, a
 * flipped byte in the binary, another driver's string, a binary the driver refuses although
 * its CRC matches) is ignored, rebuilt from the GLSL and written again. Without a folder
 * nothing is written. The colour is worked out by hand: Tint (0.25, 0.5, 0.75) * Scale 0.8 =
 * (0.2, 0.4, 0.6) -> (51, 102, 153). */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "gl_context.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static char dir[] = "/tmp/hfx_program_cache_XXXXXX";

/* Two programs (two techniques with different pixel shaders). */
static const char effect[] =
    "float4 Tint = float4(0.25, 0.5, 0.75, 1);\n"
    "float Scale = 0.8;\n"
    "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
    "float4 Lit() : COLOR0 { return float4(Tint.rgb * Scale, 1); }\n"
    "float4 Flat() : COLOR0 { return Tint; }\n"
    "technique Lit { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Lit(); } }\n"
    "technique Flat { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Flat(); } }\n";

/* The cache entries' paths, sorted; returns how many (at most 8). */
static int entries(char paths[8][512]) {
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL)
        if (strstr(e->d_name, ".hfxbin") && n < 8) snprintf(paths[n++], 512, "%s/%s", dir, e->d_name);
    if (d) closedir(d);
    qsort(paths, (size_t)n, 512, (int (*)(const void *, const void *))strcmp);
    return n;
}

static long file_size(const char *p) {
    FILE *f = fopen(p, "rb");
    if (!f) return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fclose(f);
    return n;
}

static hfx_effect *load(hfx_device *dev) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, effect, sizeof effect - 1, "cache.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    return fx;
}

/* Draws technique Lit over the whole target and checks the centre pixel. */
static void draws_lit(hfx_effect *fx) {
    static const float xy[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    GLuint vbo, vao = tgl_triangles(&g, xy, 6, &vbo);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "Lit"), 0);
    CHECK(pass != NULL);
    hfx_effect_begin(fx);
    if (pass) CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    hfx_effect_end(fx);
    unsigned char px[4];
    test_gl_read(gl, W / 2, H / 2, px);
    CHECK_NEAR(px[0], 51, 1);
    CHECK_NEAR(px[1], 102, 1);
    CHECK_NEAR(px[2], 153, 1);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
}

/* Loads with the cache on a counting device; returns how many shaders GL compiled. */
static unsigned long load_and_draw(void) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    CHECK(dev != NULL);
    if (!dev) return 0;
    CHECK_INT(hfx_device_set_program_cache(dev, dir), HFX_OK);
    tc_reset();
    hfx_effect *fx = load(dev);
    unsigned long compiled = tc_count("glCompileShader");
    CHECK(fx != NULL);
    if (fx) draws_lit(fx);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    return compiled;
}

static void first_load_writes_second_compiles_nothing(void) {
    char p[8][512];
    CHECK_INT(entries(p), 0);
    CHECK_INT(load_and_draw(), 4); /* two programs, two stages each */
    CHECK_INT(entries(p), 2);
    CHECK_INT(load_and_draw(), 0);
    CHECK_INT(entries(p), 2);
}

/* Rewrites an entry through fn, then checks that a load compiles the program again and
 * leaves the entry whole (its original size) for the load after, which compiles nothing. */
static void damaged(const char *what, void (*fn)(unsigned char *d, long *n)) {
    char p[8][512];
    CHECK_INT(entries(p), 2);
    long size = file_size(p[0]);
    FILE *f = fopen(p[0], "rb");
    unsigned char *d = malloc((size_t)size);
    CHECK(f && d && fread(d, 1, (size_t)size, f) == (size_t)size);
    if (f) fclose(f);
    long n = size;
    fn(d, &n);
    f = fopen(p[0], "wb");
    if (f) fwrite(d, 1, (size_t)n, f), fclose(f);
    free(d);
    unsigned long compiled = load_and_draw();
    if (compiled != 2) printf("  %s: %lu shaders compiled, expected 2\n", what, compiled);
    CHECK_INT(compiled, 2);
    CHECK_INT(file_size(p[0]), size);
    CHECK_INT(load_and_draw(), 0);
}

static void truncate_half(unsigned char *d, long *n) { (void)d; *n /= 2; }
static void flip_binary_byte(unsigned char *d, long *n) { d[*n - 7] ^= 0x40; }
static void other_driver(unsigned char *d, long *n) { (void)n; d[32] ^= 0x20; } /* first letter of the vendor */
static void flip_key(unsigned char *d, long *n) { (void)n; d[8] ^= 1; }

/* A binary the driver cannot take, with a CRC that matches it: the driver's refusal decides. */
static void garbage_with_good_crc(unsigned char *d, long *n) {
    uint32_t driver_len = d[28] | (uint32_t)d[29] << 8 | (uint32_t)d[30] << 16 | (uint32_t)d[31] << 24;
    unsigned char *bin = d + 32 + driver_len;
    long len = *n - 32 - (long)driver_len;
    for (long i = 0; i < len; i++) bin[i] = (unsigned char)(i * 7 + 3);
    uint32_t crc = (uint32_t)crc32(0L, bin, (uInt)len);
    for (int i = 0; i < 4; i++) d[24 + i] = (unsigned char)(crc >> (8 * i));
}

static void damaged_entries_are_rebuilt(void) {
    damaged("truncated", truncate_half);
    damaged("flipped binary byte", flip_binary_byte);
    damaged("other driver", other_driver);
    damaged("key", flip_key);
    damaged("refused binary", garbage_with_good_crc);
}

/* A cached .fx load (compiled without the self-check, built from the cache alone) still hands
 * back the compile's warnings, as any load does. */
static void cached_loads_keep_warnings(void) {
    static const char warns[] =
        "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
        "float4 PS() : COLOR0 { float2 t = float4(0.2, 0.4, 0.6, 1); return float4(t, 0, 1); }\n"
        "technique T { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    for (int round = 0; round < 2; round++) {
        hfx_device *dev = hfx_device_create_gl(tc_loader);
        CHECK_INT(hfx_device_set_program_cache(dev, dir), HFX_OK);
        tc_reset();
        char *errors = NULL;
        hfx_effect *fx = hfx_effect_load_memory(dev, warns, sizeof warns - 1, "warns.fx", NULL, &errors);
        CHECK(fx != NULL);
        CHECK_INT(tc_count("glCompileShader"), round == 0 ? 2 : 0);
        CHECK_STR(errors ? errors : "", "warns.fx(2,35): warning X3206: implicit truncation of vector type\n");
        hfx_free(errors);
        hfx_effect_destroy(fx);
        hfx_device_destroy(dev);
    }
}

static void off_writes_nothing(void) {
    char empty[] = "/tmp/hfx_program_cache_off_XXXXXX";
    CHECK(mkdtemp(empty) != NULL);
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    CHECK_INT(hfx_device_set_program_cache(dev, empty), HFX_OK);
    CHECK_INT(hfx_device_set_program_cache(dev, NULL), HFX_OK);
    hfx_effect *fx = load(dev);
    CHECK(fx != NULL);
    hfx_effect_destroy(fx);
    DIR *d = opendir(empty);
    int files = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) files += e->d_name[0] != '.';
    if (d) closedir(d);
    CHECK_INT(files, 0);
    remove(empty);
    /* a folder that does not exist: loads work, nothing is written */
    CHECK_INT(hfx_device_set_program_cache(dev, "/nonexistent/hfx/cache"), HFX_OK);
    fx = load(dev);
    CHECK(fx != NULL);
    if (fx) draws_lit(fx);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    CHECK_INT(hfx_device_set_program_cache(NULL, dir), HFX_ERR_NULL);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    if (!mkdtemp(dir)) test_skip("mkdtemp failed");
    RUN(first_load_writes_second_compiles_nothing);
    RUN(damaged_entries_are_rebuilt);
    RUN(cached_loads_keep_warnings);
    RUN(off_writes_nothing);
    char p[8][512];
    for (int i = entries(p); i-- > 0;) remove(p[i]);
    remove(dir);
    test_gl_destroy(gl);
    return test_summary();
}
