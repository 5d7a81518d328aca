/* The hfxc program, run as a user would ($HFX_BUILD_DIR/compiler/hfxc): both spellings on
 * every seed (the outputs are read back with the .hfxo reader and must be byte-identical),
 * exit codes, the located error of multilights.fx, one-line usage errors, many files in one
 * call, --emit-glsl files, and --annotations / --reflect parsed back with cJSON. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "effect.h"
#include "files.h"
#include "test.h"

#ifdef HFX_HAVE_CJSON
#include <cjson/cJSON.h>
#endif

static char hfxc[4096];
static char *tmp;

typedef struct run_result {
    int status;
    char *out, *err;
} run_result;

/* Runs `hfxc <args>` through the shell, capturing stdout and stderr in files. */
static run_result run(const char *args) {
    /* cmd holds hfxc, args (up to 16384), out, err and the quotes around them */
    char out[1024], err[1024], cmd[sizeof hfxc + 16384 + sizeof out + sizeof err + 16];
    snprintf(out, sizeof out, "%s/stdout.txt", tmp);
    snprintf(err, sizeof err, "%s/stderr.txt", tmp);
    snprintf(cmd, sizeof cmd, "'%s' %s >'%s' 2>'%s'", hfxc, args, out, err);
    int st = system(cmd);
    run_result r = {WIFEXITED(st) ? WEXITSTATUS(st) : -1, test_read_file(out, NULL), test_read_file(err, NULL)};
    if (!r.out) r.out = strdup("");
    if (!r.err) r.err = strdup("");
    return r;
}

static void run_free(run_result *r) {
    free(r->out);
    free(r->err);
}

/* Runs hfxc with printf-formatted arguments and checks its exit status; run_free the result. */
static run_result run_expecting(int status, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static run_result run_expecting(int status, const char *fmt, ...) {
    char args[16384];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(args, sizeof args, fmt, ap);
    va_end(ap);
    run_result r = run(args);
    CHECK_INT(r.status, status);
    return r;
}

/* The same when nothing but the exit status matters. */
#define EXPECT_STATUS(...) do { run_result r_ = run_expecting(__VA_ARGS__); run_free(&r_); } while (0)

static int count_lines(const char *s) {
    int n = 0;
    for (; *s; s++) n += *s == '\n';
    return n;
}

/* One hfxc run and what it must give: the exit status and a check of stdout or stderr. */
typedef enum { SAYS_EXACTLY, SAYS_AMONG_OTHERS, SAYS_ONE_LINE } says;
typedef struct run_case {
    const char *args; /* a printf format: %s is the seed's path (each %s) */
    int status;
    int on_stdout;    /* else stderr */
    says how;
    const char *text; /* the whole text, a part of it, or unused (SAYS_ONE_LINE) */
} run_case;

static void expect_run(const run_case *c, const char *seed) {
    run_result r = run_expecting(c->status, c->args, seed, seed);
    const char *got = c->on_stdout ? r.out : r.err;
    if (c->how == SAYS_EXACTLY) CHECK_STR(got, c->text);
    else if (c->how == SAYS_AMONG_OTHERS) CHECK_CONTAINS(got, c->text);
    else CHECK_INT(count_lines(got), 1);
    run_free(&r);
}

/* Runs every case on the seed file `seed_name`. */
static void expect_runs(const run_case *cases, size_t n, const char *seed_name) {
    char *seed = test_seed_path(seed_name);
    for (size_t i = 0; i < n; i++) expect_run(&cases[i], seed);
    free(seed);
}

#define EXPECT_RUNS(cases, seed_name) expect_runs(cases, sizeof cases / sizeof cases[0], seed_name)

static const char *const good[] = {"tutorial0.fx", "phong.fx", "pointlights.fx", "ambient.fx",
                                   "ambient_textured.fx", "directional.fx", "point.fx", "spot.fx",
                                   "directional_specular.fx", "point_specular.fx", "spot_specular.fx",
                                   "multilights_repaired.fx", "fxcomposer_empty.fx"};

static hfx_fx_effect *read_hfxo(const char *path, size_t *size_out, char **bytes) {
    size_t size = 0;
    char *data = test_read_file(path, &size);
    if (!data) return NULL;
    char err[256];
    hfx_fx_effect *fx = hfx_fx_read_hfxo(data, size, err, sizeof err);
    if (!fx) fprintf(stderr, "%s: %s\n", path, err);
    if (bytes) *bytes = data;
    else free(data);
    if (size_out) *size_out = size;
    return fx;
}

/* Compiles `seed` with `options` followed by $tmp/`name` and the seed, expecting success, and
 * reads the .hfxo back (NULL, a failed check, when it cannot). */
static hfx_fx_effect *compile_to(const char *options, const char *name, const char *seed) {
    char out[1024];
    snprintf(out, sizeof out, "%s/%s", tmp, name);
    EXPECT_STATUS(0, "%s '%s' '%s'", options, out, seed);
    hfx_fx_effect *fx = read_hfxo(out, NULL, NULL);
    CHECK(fx != NULL);
    return fx;
}

static void both_spellings_on_every_seed(void) {
    for (size_t i = 0; i < sizeof good / sizeof *good; i++) {
        char *seed = test_seed_path(good[i]);
        char a[1024], b[1024];
        snprintf(a, sizeof a, "%s/fxc_%s.hfxo", tmp, good[i]);
        snprintf(b, sizeof b, "%s/gnu_%s.hfxo", tmp, good[i]);
        EXPECT_STATUS(0, "/T fx_2_0 --format hfxo /Fo '%s' /nologo '%s'", a, seed);
        run_result r = run_expecting(0, "-o '%s' '%s'", b, seed);
        CHECK_STR(r.out, "");
        run_free(&r);
        size_t sa = 0, sb = 0;
        char *da = NULL, *db = NULL;
        hfx_fx_effect *fa = read_hfxo(a, &sa, &da), *fb = read_hfxo(b, &sb, &db);
        CHECK(fa != NULL && fb != NULL);
        CHECK(sa == sb && da && db && memcmp(da, db, sa) == 0);
        if (fa) {
            CHECK(fa->technique_count >= 1);
            CHECK(fa->program_count >= 1);
            CHECK(fa->programs[0].code[0][0].data != NULL);
        }
        hfx_fx_effect_free(fa);
        hfx_fx_effect_free(fb);
        free(da);
        free(db);
        free(seed);
    }
}

static void multilights_fails_with_its_line(void) {
    char *seed = test_seed_path("multilights.fx");
    char expected[2048], out[1024];
    snprintf(out, sizeof out, "%s/multi.hfxo", tmp);
    run_result r = run_expecting(1, "-o '%s' '%s'", out, seed);
    snprintf(expected, sizeof expected, "%s(204,20): error X3013: 'Phong': no matching 4 parameter function\n", seed);
    CHECK_CONTAINS(r.err, expected);
    CHECK(access(out, F_OK) != 0); /* no output for a failed compile */
    run_free(&r);
    /* The fxc spelling fails the same way. */
    r = run_expecting(1, "/T fx_2_0 /Fo '%s' '%s'", out, seed);
    CHECK_CONTAINS(r.err, expected);
    run_free(&r);
    free(seed);
}

static const run_case BAD_USAGE[] = {
    {"--frobnicate x.fx", 2, 0, SAYS_EXACTLY, "hfxc: error: unknown option '--frobnicate' (hfxc --help for usage)\n"},
    {"/nonexistent/dir/missing.fx", 2, 0, SAYS_ONE_LINE, NULL},
    {"missing_file.fx", 2, 0, SAYS_EXACTLY, "hfxc: error: cannot open 'missing_file.fx': No such file or directory\n"},
    {"--target glsl999 '%s'", 2, 0, SAYS_EXACTLY,
     "hfxc: error: unknown target 'glsl999' (glsl330, glsles300, glsl110, spirv) (hfxc --help for usage)\n"},
    {"", 2, 0, SAYS_EXACTLY, "hfxc: error: no input file (hfxc --help for usage)\n"},
    {"'%s' -o", 2, 0, SAYS_EXACTLY, "hfxc: error: option '-o' needs a value (hfxc --help for usage)\n"},
    {"--dump-ir=bogus '%s'", 2, 0, SAYS_EXACTLY,
     "hfxc: error: unknown pass 'bogus' (hfxc --list-passes) (hfxc --help for usage)\n"},
    {"--list-passes", 0, 1, SAYS_AMONG_OTHERS, "specialise   compile arguments replace the entry's uniform parameters\n"},
    {"--list-passes", 0, 1, SAYS_AMONG_OTHERS, "\npreshade     parameter-only work to preshaders"},
    {"--help", 0, 1, SAYS_AMONG_OTHERS, "usage: hfxc"},
    {"--version", 0, 1, SAYS_AMONG_OTHERS, "hfxc "},
};

static void bad_usage_is_one_line(void) {
    EXPECT_RUNS(BAD_USAGE, "ambient.fx");
}

static void many_files_in_one_call(void) {
    char args[16384], dir[1024];
    snprintf(dir, sizeof dir, "%s/many/", tmp);
    mkdir(dir, 0777);
    size_t n = snprintf(args, sizeof args, "-j 3 -o '%s'", dir);
    for (size_t i = 0; i < sizeof good / sizeof *good; i++) {
        char *seed = test_seed_path(good[i]);
        n += snprintf(args + n, sizeof args - n, " '%s'", seed);
        free(seed);
    }
    char *bad = test_seed_path("multilights.fx");
    snprintf(args + n, sizeof args - n, " '%s'", bad);
    free(bad);
    run_result r = run_expecting(1, "%s", args);
    CHECK_STR(r.out, "13 compiled, 1 failed\n");
    CHECK_CONTAINS(r.err, "error X3013");
    run_free(&r);
    for (size_t i = 0; i < sizeof good / sizeof *good; i++) {
        char path[2048];
        snprintf(path, sizeof path, "%s%.*s.hfxo", dir, (int)(strlen(good[i]) - 3), good[i]);
        hfx_fx_effect *fx = read_hfxo(path, NULL, NULL);
        CHECK(fx != NULL);
        hfx_fx_effect_free(fx);
    }
    char path[2048];
    snprintf(path, sizeof path, "%smultilights.hfxo", dir);
    CHECK(access(path, F_OK) != 0);
}

static void emit_glsl_writes_each_stage(void) {
    char *seed = test_seed_path("multilights_repaired.fx");
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/glsl", tmp);
    EXPECT_STATUS(0, "--emit-glsl '%s' '%s'", dir, seed);
    static const char *const files[] = {"Texturizado.Ambiental", "Texturizado.MultiLuces", "Material.Ambiental",
                                        "Material.MultiLuces"};
    for (int i = 0; i < 4; i++)
        for (int s = 0; s < 2; s++) {
            char path[2048];
            snprintf(path, sizeof path, "%s/multilights_repaired.%s.%s", dir, files[i], s ? "frag" : "vert");
            char *text = test_read_file(path, NULL);
            CHECK(text != NULL);
            if (text) CHECK(strncmp(text, "#version 330", 12) == 0);
            free(text);
        }
    EXPECT_STATUS(0, "--target glsles300 --emit-glsl '%s/es' '%s'", tmp, seed);
    char path[2048];
    snprintf(path, sizeof path, "%s/es/multilights_repaired.Material.Ambiental.frag", tmp);
    char *text = test_read_file(path, NULL);
    CHECK(text && strncmp(text, "#version 300 es", 15) == 0);
    free(text);
    free(seed);
}

/* spot_specular.fx's vertex shader: its world-view-projection product is a preshader, named in
 * a comment; --no-preshaders keeps the product in the shader. */
static void emit_glsl_shows_preshaders(void) {
    char *seed = test_seed_path("spot_specular.fx");
    for (int off = 0; off < 2; off++) {
        EXPECT_STATUS(0, "%s--emit-glsl '%s/pre%d' '%s'", off ? "--no-preshaders " : "", tmp, off, seed);
        char path[2048];
        snprintf(path, sizeof path, "%s/pre%d/spot_specular.Material.P0.vert", tmp, off);
        char *text = test_read_file(path, NULL);
        CHECK(text != NULL);
        if (text && !off) CHECK_CONTAINS(text, "= mul(world, mul(view, projection)), computed on the CPU (a preshader)\n");
        if (text && off) CHECK(strstr(text, "hfx_pre") == NULL && strstr(text, "mat4 mvp = projection * view * world;") != NULL);
        free(text);
    }
    free(seed);
}

static void one_entry_point(void) {
    char *seed = test_seed_path("ambient.fx");
    hfx_fx_effect *fx = compile_to("/T ps_3_0 /E mainPS -o", "entry.hfxo", seed);
    if (fx) {
        CHECK_INT(fx->top_param_count, 4);
        CHECK_INT(fx->technique_count, 1);
        CHECK_STR(fx->techniques[0].name, "mainPS");
        CHECK_INT(fx->pass_count, 1);
        CHECK_STR(fx->passes[0].name, "p0");
        CHECK_INT(fx->program_count, 1);
        CHECK(fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data != NULL);
    }
    hfx_fx_effect_free(fx);
    /* fxc's /T ps_3_0 /E /Fo: the shader's bytecode, version token ps_3_0 first, END last (issue 32) */
    char out[1024];
    snprintf(out, sizeof out, "%s/entry.pso", tmp);
    EXPECT_STATUS(0, "/T ps_3_0 /E mainPS /Fo '%s' '%s'", out, seed);
    size_t size = 0;
    unsigned char *code = (unsigned char *)test_read_file(out, &size);
    CHECK(code != NULL && size >= 8 && size % 4 == 0);
    if (code && size >= 8) {
        CHECK_INT(code[0] | code[1] << 8 | code[2] << 16 | (uint32_t)code[3] << 24, 0xffff0300u);
        CHECK_INT(code[size - 4] | code[size - 3] << 8 | code[size - 2] << 16 | (uint32_t)code[size - 1] << 24, 0x0000ffffu);
    }
    free(code);
    /* /Fc without /Fo: the shader's listing alone, as fxc writes it */
    snprintf(out, sizeof out, "%s/entry.asm", tmp);
    EXPECT_STATUS(0, "/T ps_3_0 /E mainPS /Fc '%s' '%s'", out, seed);
    char *listing = test_read_file(out, &size);
    CHECK(listing && strncmp(listing, "//\n// Generated by hfxc", 23) == 0 && strstr(listing, "\n    ps_3_0\n"));
    free(listing);
    /* /Fc beside -o: the listing and the .hfxo (the effect file hfx's own output keeps) */
    char hfxo[1024];
    snprintf(out, sizeof out, "%s/entry2.asm", tmp);
    snprintf(hfxo, sizeof hfxo, "%s/entry2.hfxo", tmp);
    EXPECT_STATUS(0, "/T ps_3_0 /E mainPS /Fc '%s' -o '%s' '%s'", out, hfxo, seed);
    listing = test_read_file(out, &size);
    CHECK(listing && strstr(listing, "\n    ps_3_0\n"));
    free(listing);
    char *object = test_read_file(hfxo, &size);
    CHECK(object && hfx_fx_is_hfxo(object, size));
    free(object);
    run_result r = run_expecting(1, "-T vs_3_0 -E nope '%s'", seed);
    char expected[2048];
    snprintf(expected, sizeof expected, "%s(1,1): error X3501: 'nope': entrypoint not found\n", seed);
    CHECK_STR(r.err, expected);
    run_free(&r);
    r = run_expecting(2, "/T ps_3_0 '%s'", seed);
    CHECK_STR(r.err, "hfxc: error: profile 'ps_3_0' needs an entry point (/E) (hfxc --help for usage)\n");
    run_free(&r);
    free(seed);
}

static const run_case AST[] = {
    {"--ast '%s'", 0, 1, SAYS_AMONG_OTHERS, "WorldViewProj"},
};

/* phong.fx has two X3206 warnings (float3 = float4): --werror makes them errors. */
static const run_case WARNINGS[] = {
    {"'%s'", 0, 0, SAYS_AMONG_OTHERS, "warning X3206: implicit truncation of vector type"},
    {"--werror '%s'", 1, 0, SAYS_AMONG_OTHERS, "error X3206: implicit truncation of vector type"},
    {"--no-warnings '%s'", 0, 0, SAYS_EXACTLY, ""},
};

static void ast_werror_and_targets(void) {
    EXPECT_RUNS(AST, "fxcomposer_empty.fx");
    EXPECT_RUNS(WARNINGS, "phong.fx");
    /* GLSL 1.10 only: the .hfxo carries that target and no other. */
    char *seed = test_seed_path("phong.fx");
    hfx_fx_effect *fx = compile_to("--no-warnings --target glsl110 -o", "phong110.hfxo", seed);
    if (fx) {
        CHECK_INT(fx->targets, 1u << HFX_TARGET_GLSL110);
        CHECK(fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL110].data != NULL);
        CHECK(fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data == NULL);
    }
    hfx_fx_effect_free(fx);
    free(seed);
}

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* --dump-ir=preshade: the vertex stage's IR after the preshade pass on stderr (the pixel
 * stage's too), headed with the compile's place, which is where it names the entry (line 2,
 * column 54); the same text in the --dump-ir-file file, and stderr then has none of it. The
 * dump's lines are tests/compiler/ir/test_passes.c's, checked there by hand. */
static void dump_ir_after_a_pass(void) {
    char path[1024], dump[1024];
    snprintf(path, sizeof path, "%s/dump.fx", tmp);
    snprintf(dump, sizeof dump, "%s/dump.txt", tmp);
    write_text(path,
        "float4x4 World, ViewProj; float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, mul(World, ViewProj)); }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); } }\n");
    static const char want[] =
        "dump.fx(2,54)\n"
        "shader vertex VS\n"
        "global uniform float4x4 World\n"
        "global uniform float4x4 ViewProj\n"
        "preshader float4x4 hfx_pre0 = mul(World, ViewProj)\n"
        "function VS : float4\n"
        "  param float4 p\n"
        "  block\n"
        "    return (mul (param p) (private hfx_pre0))\n";
    run_result r = run_expecting(0, "--dump-ir=preshade -o /dev/null '%s'", path);
    CHECK_CONTAINS(r.err, "// after preshade: ");
    CHECK_CONTAINS(r.err, want);
    CHECK(strstr(r.err, "// after fold: ") == NULL);
    run_free(&r);
    r = run_expecting(0, "--dump-ir=preshade --dump-ir-file '%s' -o /dev/null '%s'", dump, path);
    CHECK_STR(r.err, "");
    char *text = test_read_file(dump, NULL);
    CHECK_CONTAINS(text, want);
    free(text);
    run_free(&r);
    r = run_expecting(0, "--dump-ir -o /dev/null '%s'", path); /* every pass: fold's among them */
    CHECK_CONTAINS(r.err, "// after fold: ");
    CHECK_CONTAINS(r.err, "// after uses-again: ");
    run_free(&r);
}

/* -D / /D / -DNAME=V and -I / /I reach the preprocessor in both spellings. */
static void defines_and_include_dirs(void) {
    char dir[1024], path[2048], inc[2048], out[2048];
    snprintf(dir, sizeof dir, "%s/inc", tmp);
    mkdir(dir, 0777);
    snprintf(inc, sizeof inc, "%s/common.fxh", dir);
    write_text(inc, "float extra = EXTRA;\n");
    snprintf(path, sizeof path, "%s/defs.fx", tmp);
    write_text(path, "#include \"common.fxh\"\nfloat4 c = float4(COLOR_R, 0, 0, 1);\n");
    snprintf(out, sizeof out, "%s/defs.hfxo", tmp);
    static const char *const spellings[] = {"-I '%s' -D COLOR_R=0.5 -DEXTRA=2 -o '%s' '%s'",
                                            "/I '%s' /D COLOR_R=0.5 /D EXTRA=2 --format hfxo /Fo '%s' '%s'"};
    for (int k = 0; k < 2; k++) {
        remove(out);
        run_result r = run_expecting(0, spellings[k], dir, out, path);
        CHECK_STR(r.err, "");
        run_free(&r);
        hfx_fx_effect *fx = read_hfxo(out, NULL, NULL);
        CHECK(fx != NULL);
        if (!fx) continue;
        CHECK_INT(fx->top_param_count, 2);
        uint32_t e = hfx_fx_param_find(fx, "extra"), c = hfx_fx_param_find(fx, "c");
        CHECK(e != HFX_NONE && c != HFX_NONE);
        if (e != HFX_NONE && c != HFX_NONE) {
            float f[2];
            memcpy(&f[0], &fx->values[fx->params[e].offset], 4);
            memcpy(&f[1], &fx->values[fx->params[c].offset], 4);
            CHECK_NEAR(f[0], 2.0, 0);
            CHECK_NEAR(f[1], 0.5, 0);
        }
        hfx_fx_effect_free(fx);
    }
    /* Without the folder, the include fails with fxc's located X1507. */
    run_result r = run_expecting(1, "-D COLOR_R=1 -D EXTRA=1 '%s'", path);
    CHECK_CONTAINS(r.err, "error X1507");
    run_free(&r);
}

#ifdef HFX_HAVE_CJSON
static cJSON *json_of(const char *flag, const char *seed_name) {
    char *seed = test_seed_path(seed_name);
    run_result r = run_expecting(0, "%s '%s'", flag, seed);
    cJSON *j = cJSON_Parse(r.out);
    CHECK(j != NULL);
    run_free(&r);
    free(seed);
    return j;
}

static cJSON *named(const cJSON *array, const char *name) {
    const cJSON *it;
    cJSON_ArrayForEach(it, array) {
        const cJSON *n = cJSON_GetObjectItemCaseSensitive(it, "name");
        if (cJSON_IsString(n) && strcmp(n->valuestring, name) == 0) return (cJSON *)it;
    }
    fprintf(stderr, "no '%s' in the JSON\n", name);
    return NULL;
}

static const char *str_of(const cJSON *o, const char *key) {
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsString(v) ? v->valuestring : NULL;
}

static double num_of(const cJSON *o, const char *key) {
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(v) ? v->valuedouble : -12345;
}

static void annotations_json_ambient(void) {
    cJSON *j = json_of("--annotations", "ambient.fx");
    if (!j) return;
    const cJSON *params = cJSON_GetObjectItemCaseSensitive(j, "parameters");
    CHECK_INT(cJSON_GetArraySize(params), 4);
    const cJSON *world = named(params, "world");
    CHECK_STR(str_of(world, "semantic"), "World");
    CHECK_STR(str_of(world, "class"), "matrix");
    CHECK_STR(str_of(world, "type"), "float");
    CHECK_NEAR(num_of(world, "rows"), 4, 0);
    CHECK_NEAR(num_of(world, "columns"), 4, 0);
    const cJSON *c = named(params, "colorMaterialAmbiental");
    CHECK(c != NULL);
    CHECK_STR(str_of(c, "class"), "vector");
    CHECK_NEAR(num_of(c, "rows"), 1, 0);
    CHECK_NEAR(num_of(c, "columns"), 4, 0);
    CHECK_NEAR(num_of(c, "elements"), 0, 0);
    CHECK(cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(c, "semantic")));
    const cJSON *def = cJSON_GetObjectItemCaseSensitive(c, "default");
    CHECK_INT(cJSON_GetArraySize(def), 4);
    static const double want[] = {0.05, 0.05, 0.05, 1};
    for (int i = 0; i < 4; i++) {
        const cJSON *v = cJSON_GetArrayItem(def, i);
        CHECK(cJSON_IsNumber(v));
        if (v) CHECK_NEAR(v->valuedouble, want[i], 0); /* printed as the shortest decimal: exactly 0.05 */
    }
    const cJSON *anns = cJSON_GetObjectItemCaseSensitive(c, "annotations");
    CHECK_INT(cJSON_GetArraySize(anns), 2);
    const cJSON *ui = named(anns, "UIName");
    CHECK_STR(str_of(ui, "type"), "string");
    CHECK_STR(str_of(ui, "value"), "Color Ambiental");
    CHECK_STR(str_of(named(anns, "UIWidget"), "value"), "Color");
    const cJSON *tech = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(j, "techniques"), 0);
    CHECK_STR(str_of(tech, "name"), "ModeloAmbiental");
    const cJSON *pass = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(tech, "passes"), 0);
    CHECK_STR(str_of(pass, "name"), "p0");
    CHECK(cJSON_GetObjectItemCaseSensitive(pass, "program") == NULL); /* only --reflect has it */
    cJSON_Delete(j);
}

static void annotations_json_spot_specular(void) {
    cJSON *j = json_of("--annotations", "spot_specular.fx");
    if (!j) return;
    const cJSON *params = cJSON_GetObjectItemCaseSensitive(j, "parameters");
    CHECK_INT(cJSON_GetArraySize(params), 22);
    const cJSON *ks = named(params, "ks");
    CHECK_STR(str_of(ks, "class"), "scalar");
    const cJSON *def = cJSON_GetObjectItemCaseSensitive(ks, "default");
    CHECK_INT(cJSON_GetArraySize(def), 1);
    CHECK_NEAR(cJSON_GetArrayItem(def, 0)->valuedouble, 0.05, 0);
    const cJSON *anns = cJSON_GetObjectItemCaseSensitive(ks, "annotations");
    CHECK_INT(cJSON_GetArraySize(anns), 5);
    CHECK_STR(str_of(named(anns, "UIWidget"), "value"), "slider");
    const cJSON *mn = named(anns, "UIMin"), *mx = named(anns, "UIMax"), *st = named(anns, "UIStep");
    CHECK_STR(str_of(mn, "type"), "float");
    CHECK_STR(str_of(mn, "class"), "scalar");
    CHECK_NEAR(num_of(mn, "value"), 0, 0);
    CHECK_NEAR(num_of(mx, "value"), 10, 0);
    CHECK_NEAR(num_of(st, "value"), 0.05, 0);
    CHECK_STR(str_of(named(anns, "UIName"), "value"), "Coeficiente de reflexi\xc3\xb3n especular");
    const cJSON *at = named(params, "atenuado");
    CHECK_STR(str_of(at, "type"), "bool");
    CHECK(cJSON_IsFalse(cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(at, "default"), 0)));
    /* The sampler: texture and states by name. */
    const cJSON *s = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(j, "samplers"), 0);
    CHECK_STR(str_of(s, "name"), "modeloTexturaMuestra");
    CHECK_STR(str_of(s, "texture"), "texturaModelo");
    const cJSON *states = cJSON_GetObjectItemCaseSensitive(s, "states");
    CHECK_INT(cJSON_GetArraySize(states), 5);
    CHECK_STR(str_of(named(states, "MinFilter"), "value"), "Linear");
    CHECK_NEAR(num_of(named(states, "AddressU"), "number"), 1, 0);
    const cJSON *techs = cJSON_GetObjectItemCaseSensitive(j, "techniques");
    CHECK_INT(cJSON_GetArraySize(techs), 2);
    CHECK(named(techs, "Material") != NULL);
    cJSON_Delete(j);
}

/* A .hfxo describes itself exactly as its source does. */
static void hfxo_input_reflects_like_source(void) {
    char *seed = test_seed_path("spot_specular.fx");
    char out[1024];
    snprintf(out, sizeof out, "%s/self.hfxo", tmp);
    run_result a = run_expecting(0, "--no-warnings --reflect -o '%s' '%s'", out, seed);
    run_result b = run_expecting(0, "--reflect '%s'", out);
    cJSON *ja = cJSON_Parse(a.out), *jb = cJSON_Parse(b.out);
    CHECK(ja && jb);
    if (ja && jb) {
        /* Everything but the "file" key is the same. */
        cJSON_DeleteItemFromObjectCaseSensitive(ja, "file");
        cJSON_DeleteItemFromObjectCaseSensitive(jb, "file");
        CHECK(cJSON_Compare(ja, jb, 1));
    }
    cJSON_Delete(ja);
    cJSON_Delete(jb);
    run_free(&a);
    run_free(&b);
    /* A damaged one is refused with the reader's message. */
    char *data = NULL;
    size_t size = 0;
    data = test_read_file(out, &size);
    CHECK(data && size > 100);
    if (data) {
        data[100] ^= 1;
        FILE *f = fopen(out, "wb");
        if (f) {
            fwrite(data, 1, size, f);
            fclose(f);
        }
    }
    free(data);
    run_result c = run_expecting(1, "--reflect '%s'", out);
    CHECK_CONTAINS(c.err, "hfxo: checksum mismatch (the file is corrupted)");
    run_free(&c);
    free(seed);
}

static void reflect_json_interface(void) {
    cJSON *j = json_of("--reflect", "tutorial0.fx");
    if (!j) return;
    const cJSON *params = cJSON_GetObjectItemCaseSensitive(j, "parameters");
    CHECK_STR(str_of(named(params, "World"), "glsl_name"), "World");
    const cJSON *tech = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(j, "techniques"), 0);
    const cJSON *pass = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(tech, "passes"), 0);
    const cJSON *prog = cJSON_GetObjectItemCaseSensitive(pass, "program");
    CHECK(cJSON_IsObject(prog));
    const cJSON *attrs = cJSON_GetObjectItemCaseSensitive(prog, "attributes");
    CHECK_INT(cJSON_GetArraySize(attrs), 2);
    const cJSON *it;
    int found = 0;
    cJSON_ArrayForEach(it, attrs) {
        const char *sem = str_of(it, "semantic");
        /* The NVIDIA aliasing convention: POSITION 0, TEXCOORD0 8. */
        if (sem && !strcmp(sem, "POSITION0")) {
            CHECK_NEAR(num_of(it, "location"), 0, 0);
            found++;
        }
        if (sem && !strcmp(sem, "TEXCOORD0")) {
            CHECK_NEAR(num_of(it, "location"), 8, 0);
            found++;
        }
    }
    CHECK_INT(found, 2);
    const cJSON *samplers = cJSON_GetObjectItemCaseSensitive(prog, "samplers");
    CHECK_INT(cJSON_GetArraySize(samplers), 1);
    CHECK_STR(str_of(cJSON_GetArrayItem(samplers, 0), "sampler"), "diffuseSampler");
    CHECK_NEAR(num_of(cJSON_GetArrayItem(samplers, 0), "unit"), 0, 0);
    /* The position goes through World, View and Projection in turn: one preshader holds their
     * product (registers 0..3, nothing else packed), so the GLSL reads no parameter itself. */
    const cJSON *uniforms = cJSON_GetObjectItemCaseSensitive(prog, "uniforms");
    CHECK_INT(cJSON_GetArraySize(uniforms), 0);
    const cJSON *pre = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(prog, "preshaders"), 0);
    CHECK_NEAR(num_of(pre, "register"), 0, 0);
    CHECK_NEAR(num_of(pre, "rows"), 4, 0);
    CHECK_NEAR(num_of(pre, "cols"), 4, 0);
    const cJSON *reads = cJSON_GetObjectItemCaseSensitive(pre, "parameters");
    CHECK_INT(cJSON_GetArraySize(reads), 3);
    CHECK_STR(cJSON_GetArrayItem(reads, 0)->valuestring, "World");
    CHECK_STR(cJSON_GetArrayItem(reads, 1)->valuestring, "View");
    CHECK_STR(cJSON_GetArrayItem(reads, 2)->valuestring, "Projection");
    cJSON_Delete(j);
}
#endif

/* Whether the 4 bytes b occur in data[0..size). */
static int has_bytes(const char *data, size_t size, const uint8_t b[4]) {
    for (size_t i = 0; i + 4 <= size; i++)
        if (memcmp(data + i, b, 4) == 0) return 1;
    return 0;
}

/* fxc's outputs: /Fo writes fx_2_0 (its bytes: tests/compiler/effect/test_fx2_write.c's tiny
 * effect, worked out by hand), /Fh a C header of them named by /Vn, /Fc the listing; -o keeps
 * writing .hfxo; an effect's shaders go in as the D3D9 back end's bytecode; an .hfxo's cannot. */
static void fxc_outputs(void) {
    char src[1024], fxo[1024], h[1024], lst[1024];
    snprintf(src, sizeof src, "%s/tiny.fx", tmp);
    write_text(src, "float Ref = 0.5;\ntechnique T { pass P { CullMode = None; } }\n");
    snprintf(fxo, sizeof fxo, "%s/tiny.fxo", tmp);
    snprintf(h, sizeof h, "%s/tiny.h", tmp);
    snprintf(lst, sizeof lst, "%s/tiny.lst", tmp);
    run_result r = run_expecting(0, "/T fx_2_0 /nologo /Fo '%s' /Fh '%s' /Vn g_tiny /Fc '%s' '%s'", fxo, h, lst, src);
    CHECK_STR(r.err, "");
    run_free(&r);
    size_t size = 0;
    char *bin = test_read_file(fxo, &size), *header = test_read_file(h, NULL), *listing = test_read_file(lst, NULL);
    CHECK_INT(size, 45 * 4);
    CHECK(bin && (uint8_t)bin[0] == 0x01 && (uint8_t)bin[1] == 0x09 && (uint8_t)bin[2] == 0xff && (uint8_t)bin[3] == 0xfe);
    static const char head[] = "#if 0\n//\n// FX Version: fx_2_0\n";
    CHECK(header && strncmp(header, head, sizeof head - 1) == 0);
    CHECK_CONTAINS(header, "#endif\n\nconst BYTE g_tiny[] =\n{\n      1,   9, 255, 254,  92,   0,   0,   0,\n");
    CHECK_CONTAINS(header, ",\n      0,   0,   0,   0\n};\n"); /* 180 bytes: the last line holds 4 (no resources) */
    CHECK(listing != NULL);
    if (listing) CHECK_CONTAINS(listing, "float Ref = 0.5;\n");
    if (listing) CHECK_CONTAINS(listing, "    pass P\n    {\n        CullMode = None;\n    }\n");
    if (listing && header) CHECK(strstr(header, listing) != NULL);
    free(bin), free(header), free(listing);
    /* the same file read back by hfxc: the fxc binary is an input like any */
    hfx_fx_effect *fx = compile_to("-o", "back.hfxo", fxo);
    if (fx) {
        CHECK_INT(fx->top_param_count, 1);
        CHECK_INT(fx->states[fx->passes[0].first_state].i, 1);
    }
    hfx_fx_effect_free(fx);
    /* shaders: the D3D9 back end writes each pass's (ambient.fx: vs_3_0 / ps_3_0) into the file */
    char *seed = test_seed_path("ambient.fx");
    if (!seed) return;
    r = run_expecting(0, "/T fx_2_0 /Fo '%s' '%s'", fxo, seed);
    CHECK_STR(r.err, "");
    run_free(&r);
    fx = compile_to("-o", "ambient_back.hfxo", fxo); /* read back through fx_2_0's reader */
    if (fx) {
        CHECK_INT(fx->technique_count, 1);
        CHECK(fx->program_count >= 1 && fx->programs[0].code[0][0].data && fx->programs[0].code[1][0].data);
    }
    hfx_fx_effect_free(fx);
    /* and for Vulkan and GL 4.6: both stages of every program are SPIR-V modules (magic word
     * 0x07230203), the GLSL 330 they were made from dropped as for a compiled source */
    fx = compile_to("--target spirv,spirv-vk -o", "ambient_spirv.hfxo", fxo);
    for (uint32_t i = 0; fx && i < fx->program_count; i++)
        for (int s = 0; s < HFX_STAGE_COUNT; s++) {
            CHECK(fx->programs[i].code[s][HFX_TARGET_GLSL330].data == NULL);
            for (int t = HFX_TARGET_SPIRV; t <= HFX_TARGET_SPIRV_VK; t++) {
                const hfx_fx_code *c = &fx->programs[i].code[s][t];
                uint32_t magic = 0;
                if (c->data && c->size >= 20) memcpy(&magic, c->data, 4);
                CHECK_INT(magic, 0x07230203);
            }
        }
    CHECK(fx && fx->program_count >= 1);
    hfx_fx_effect_free(fx);
    size_t fxo_size = 0;
    char *bytes = test_read_file(fxo, &fxo_size);
    /* vs_3_0's version token (0xFFFE0300) and ps_3_0's (0xFFFF0300), little-endian, in the resources */
    static const uint8_t vs30[4] = {0x00, 0x03, 0xfe, 0xff}, ps30[4] = {0x00, 0x03, 0xff, 0xff};
    CHECK(bytes && has_bytes(bytes, fxo_size, vs30) && has_bytes(bytes, fxo_size, ps30));
    free(bytes);
    /* an .hfxo keeps GLSL only: its shaders cannot become fx_2_0, said plainly */
    char hfxo[1024];
    snprintf(hfxo, sizeof hfxo, "%s/ambient_back.hfxo", tmp);
    r = run_expecting(1, "/T fx_2_0 /Fo '%s' '%s'", fxo, hfxo);
    CHECK_CONTAINS(r.err, "error X9011: vertex shader: no Direct3D 9 bytecode for this shader: an .hfxo carries GLSL only");
    run_free(&r);
    free(seed);
}

/* fxc's switches that change nothing give the same bytes; /Op is --no-preshaders. */
static void fxc_switches(void) {
    char *seed = test_seed_path("phong.fx");
    if (!seed) return;
    char a[1024], b[1024];
    snprintf(a, sizeof a, "%s/plain.fxo", tmp);
    snprintf(b, sizeof b, "%s/switches.fxo", tmp);
    EXPECT_STATUS(0, "/T fx_2_0 /Fo '%s' '%s'", a, seed);
    EXPECT_STATUS(0, "/T fx_2_0 /nologo /Zi /Od /O3 /Gec /Gfa /Gfp /Ges /Gis /Gpp /Vi /Vd /LD /Fo '%s' '%s'", b, seed);
    size_t sa = 0, sb = 0;
    char *da = test_read_file(a, &sa), *db = test_read_file(b, &sb);
    CHECK(da && db && sa == sb && sa > 0 && memcmp(da, db, sa) == 0);
    free(da), free(db);
    snprintf(a, sizeof a, "%s/nopre.hfxo", tmp);
    snprintf(b, sizeof b, "%s/op.hfxo", tmp);
    EXPECT_STATUS(0, "--no-preshaders -o '%s' '%s'", a, seed);
    EXPECT_STATUS(0, "/Op -o '%s' '%s'", b, seed);
    da = test_read_file(a, &sa), db = test_read_file(b, &sb);
    CHECK(da && db && sa == sb && memcmp(da, db, sa) == 0);
    free(da), free(db);
    snprintf(b, sizeof b, "%s/pre.hfxo", tmp);
    EXPECT_STATUS(0, "-o '%s' '%s'", b, seed);
    db = test_read_file(b, &sb);
    da = test_read_file(a, &sa);
    CHECK(da && db && (sa != sb || memcmp(da, db, sa) != 0)); /* phong.fx has preshaders: /Op changes the file */
    free(da), free(db);
    free(seed);
}

int main(void) {
    test_require_seeds();
    const char *build = getenv("HFX_BUILD_DIR");
    if (!build) test_skip("HFX_BUILD_DIR is not set (run through ctest)");
    snprintf(hfxc, sizeof hfxc, "%s/compiler/hfxc", build);
    if (access(hfxc, X_OK) != 0) test_skip("hfxc is not built");
    tmp = test_temp_dir();
    RUN(both_spellings_on_every_seed);
    RUN(multilights_fails_with_its_line);
    RUN(bad_usage_is_one_line);
    RUN(many_files_in_one_call);
    RUN(emit_glsl_writes_each_stage);
    RUN(emit_glsl_shows_preshaders);
    RUN(one_entry_point);
    RUN(fxc_outputs);
    RUN(fxc_switches);
    RUN(defines_and_include_dirs);
    RUN(ast_werror_and_targets);
    RUN(dump_ir_after_a_pass);
#ifdef HFX_HAVE_CJSON
    RUN(annotations_json_ambient);
    RUN(annotations_json_spot_specular);
    RUN(reflect_json_interface);
    RUN(hfxo_input_reflects_like_source);
#endif
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmp);
    free(tmp);
    return test_summary();
}
