/* main.c: hfxc, the command line. Takes fxc's spelling (/T fx_2_0 /Fo out.fxo /Fh /Vn /Fc /D N=V
 * /I dir /E main /nologo: fxc's outputs, in fxc_out.c) and the GNU one (-o, -D, -I, --target, --emit-glsl, --reflect...). Exit 0 on
 * success, 1 when a file fails to compile, 2 on bad usage (one line on stderr saying why). */
#include <errno.h>
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

static const char usage_text[] =
    "usage: hfxc [options] file.fx...\n"
    "Compiles Direct3D 9 effect files (.fx) to .hfxo (GLSL programs + effect data).\n"
    "\n"
    "  -o PATH               the .hfxo to write (one input), or a folder (several, or PATH ending in /)\n"
    "  /Fo PATH              fxc's fx_2_0 effect to write (FNA, MojoShader, D3DX load it), or a folder\n"
    "  --format hfxo|fxc     the format of -o or /Fo, whichever is given\n"
    "  /Fh FILE, /Vn NAME    a C header of the fx_2_0 bytes: const BYTE NAME[] (default g_<input>)\n"
    "  /Fc FILE              the listing of the fx_2_0 written\n"
    "  /Zpr, /Zpc            matrices without row_major / column_major are row- / column-major in it\n"
    "  -D, /D NAME[=VALUE]   define a macro\n"
    "  -I, /I DIR            add an include folder\n"
    "  /T PROFILE            fx_2_0 (default), or vs_3_0, ps_2_0... with /E\n"
    "  /E NAME               compile one entry point with the /T profile\n"
    "  --target T            glsl330, glsles300, glsl110, spirv, spirv-vk (repeat or comma-separate)\n"
    "  --emit-glsl DIR       write each pass's shaders: <effect>.<technique>.<pass>.vert/.frag\n"
    "  --reflect             print the effect and its compiled interface as JSON\n"
    "  --annotations         print parameters, annotations, techniques and states as JSON\n"
    "  --ast                 print the syntax tree and stop\n"
    "  --dump-ir[=PASS]      print each shader's IR after PASS (default: after every pass) on\n"
    "                        stderr, each dump headed `// after PASS: file(line,col)`\n"
    "  --dump-ir-file FILE   write those dumps to FILE instead (alone: after every pass)\n"
    "  --list-passes         print the compiler's passes in the order they run, and stop\n"
    "  --disassemble, /dumpbin  print the listing of effects fxc compiled (fx_2_0 .fxo / .fxb,\n"
    "                        uncompressed XNA .xnb): parameters, techniques, states, shaders\n"
    "  --separate-uniforms   one GLSL uniform per parameter; by default float parameters\n"
    "                        share one vec4 array per program (D3D9 registers, one upload)\n"
    "  --no-preshaders       keep work on parameters alone in the shaders; by default it runs\n"
    "                        on the CPU once per change, as fxc's preshaders (packed registers only)\n"
    "  --no-derived-varyings interpolate every vertex output, even one the pixel shader can\n"
    "                        compute from another output and parameters (by default it does)\n"
    "  --werror, /WX         treat warnings as errors\n"
    "  --no-warnings         drop warnings\n"
    "  --no-self-check       do not check the emitted GLSL with glslang (faster; by default a\n"
    "                        shader glslang rejects is an internal error X9000, never output)\n"
    "  -MD                   also write a Make / Ninja depfile: the effect and every file it includes\n"
    "  -MF FILE, --depfile FILE  the depfile's name (one input; --depfile implies -MD);\n"
    "                        default: the output's name with .d for its extension\n"
    "  -MT TARGET            the depfile rule's target (default: the output path)\n"
    "  -MP                   add an empty rule per include, so deleting one does not break make\n"
    "  -j, --jobs N          compile N files at a time (default: one per core)\n"
    "  --quiet               no progress line and no summary\n"
    "  /Op                 fxc's spelling of --no-preshaders\n"
    "  /nologo, /Od, /O0-/O3, /Gec, /Gfa, /Gfp, /Ges, /Gis, /Gpp, /Zi, /Vi, /Vd, /LD\n"
    "                      accepted for fxc compatibility; change nothing\n"
    "  --help, /?            this text\n"
    "  --version             the version\n";

static int usage_error(const char *fmt, const char *arg) {
    fprintf(stderr, "hfxc: error: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (hfxc --help for usage)\n");
    return EXIT_USAGE;
}

static int push(const char ***list, size_t *count, const char *s) {
    const char **l = realloc(*list, sizeof *l * (*count + 1));
    if (!l) return -1;
    l[(*count)++] = s;
    *list = l;
    return 0;
}

static int add_targets(cli_options *o, const char *spec) {
    char buf[256];
    snprintf(buf, sizeof buf, "%s", spec);
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int target = cli_target_from_name(t);
        if (target < 0) return usage_error("unknown target '%s' (glsl330, glsles300, glsl110, spirv)", t);
        o->targets |= 1u << target;
    }
    return EXIT_OK;
}

/* fxc's switches that change nothing in hfxc: debug information, optimisation levels, flow-control
 * preferences, strictness, partial precision, include details, validation, the legacy compiler. */
static bool fxc_no_op(const char *a) {
    static const char *const same[] = {"/Zi", "/Od", "/Gec", "/Gfp", "/Gfa", "/Ges", "/Gis", "/Gpp", "/Vi", "/Vd", "/LD"};
    for (size_t i = 0; i < sizeof same / sizeof *same; i++)
        if (!strcmp(a, same[i])) return true;
    return a[0] == '/' && a[1] == 'O' && a[2] >= '0' && a[2] <= '3' && !a[3];
}

static bool exists(const char *path) {
    struct stat st;
    return stat(path, &st) == 0;
}

/* An option taking a value: `-o x`, `-ox`, `/Fo x`, `/Fox`, `--target=x`, `--target x`.
 * Returns the value (advancing *i) or NULL when arg is not this option. */
static const char *value_of(const char *arg, const char *name, int argc, char **argv, int *i, bool *missing) {
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0) return NULL;
    if (arg[n] == 0) {
        if (*i + 1 >= argc) {
            *missing = true;
            return NULL;
        }
        return argv[++*i];
    }
    if (strncmp(name, "--", 2) == 0) return arg[n] == '=' ? arg + n + 1 : NULL;
    return arg + n;
}

typedef enum {
    OPT_OUTPUT, OPT_DEFINE, OPT_INCLUDE, OPT_PROFILE, OPT_ENTRY, OPT_TARGET, OPT_EMIT, OPT_JOBS, OPT_DEPFILE, OPT_DEP_TARGET,
    OPT_FXC_OUTPUT, OPT_FORMAT, OPT_HEADER, OPT_HEADER_NAME, OPT_LISTING,
    OPT_DUMP_FILE
} opt_kind;

static const struct {
    const char *name;
    opt_kind kind;
} valued[] = {
    {"--output", OPT_OUTPUT}, {"--target", OPT_TARGET}, {"--emit-glsl", OPT_EMIT}, {"--jobs", OPT_JOBS},
    {"--define", OPT_DEFINE}, {"--include", OPT_INCLUDE}, {"--depfile", OPT_DEPFILE},
    {"-MF", OPT_DEPFILE}, {"-MT", OPT_DEP_TARGET}, {"--dump-ir-file", OPT_DUMP_FILE},
    {"-o", OPT_OUTPUT}, {"-D", OPT_DEFINE}, {"-I", OPT_INCLUDE}, {"-T", OPT_PROFILE}, {"-E", OPT_ENTRY},
    {"-j", OPT_JOBS}, {"-Fo", OPT_FXC_OUTPUT}, {"--format", OPT_FORMAT}, {"/Fh", OPT_HEADER}, {"-Fh", OPT_HEADER},
    {"/Vn", OPT_HEADER_NAME}, {"-Vn", OPT_HEADER_NAME}, {"/Fc", OPT_LISTING}, {"-Fc", OPT_LISTING},
    {"/Fo", OPT_FXC_OUTPUT}, {"/D", OPT_DEFINE}, {"/I", OPT_INCLUDE}, {"/T", OPT_PROFILE}, {"/E", OPT_ENTRY},
};

/* fxc's outputs: /Fo writes fxc's fx_2_0 (-o hfx's .hfxo), /Fh a C header, /Vn its array, /Fc
 * the listing, --format hfxo|fxc the format of whichever output option is given. */
static int set_fxc_option(cli_options *o, opt_kind kind, const char *v) {
    switch (kind) {
    case OPT_FXC_OUTPUT:
        o->output = v;
        if (!o->format_given) o->format = CLI_FORMAT_FXC;
        break;
    case OPT_FORMAT:
        if (strcmp(v, "hfxo") && strcmp(v, "fxc")) return usage_error("unknown format '%s' (hfxo or fxc)", v);
        o->format = strcmp(v, "fxc") ? CLI_FORMAT_HFXO : CLI_FORMAT_FXC;
        o->format_given = true;
        break;
    case OPT_HEADER: o->header = v; break;
    case OPT_HEADER_NAME: o->header_name = v; break;
    default: o->listing = v; break;
    }
    return EXIT_OK;
}

static int set_valued(cli_options *o, opt_kind kind, const char *v) {
    switch (kind) {
    case OPT_OUTPUT: o->output = v; break;
    case OPT_FXC_OUTPUT: case OPT_FORMAT: case OPT_HEADER: case OPT_HEADER_NAME: case OPT_LISTING:
        return set_fxc_option(o, kind, v);
    case OPT_DEFINE: if (push(&o->defines, &o->define_count, v)) return EXIT_USAGE; break;
    case OPT_INCLUDE: if (push(&o->include_dirs, &o->include_dir_count, v)) return EXIT_USAGE; break;
    case OPT_PROFILE: o->profile = v; break;
    case OPT_ENTRY: o->entry = v; break;
    case OPT_TARGET: return add_targets(o, v);
    case OPT_EMIT: o->emit_glsl = v; break;
    case OPT_DEPFILE: o->depfile = true, o->depfile_path = v; break;
    case OPT_DEP_TARGET: o->dep_target = v; break;
    case OPT_DUMP_FILE: o->dump_ir_file = v; break;
    case OPT_JOBS: {
        char *end;
        long n = strtol(v, &end, 10);
        if (*end || n < 1 || n > 1024) return usage_error("bad job count '%s'", v);
        o->jobs = (int)n;
        break;
    }
    }
    return EXIT_OK;
}

/* --list-passes: the pass table, one `name  why` a line. */
static void list_passes(void) {
    const char *why, *name;
    for (size_t i = 0; (name = hfxc_pass_name(i, &why)) != NULL; i++) printf("%-12s %s\n", name, why);
}

/* --dump-ir (after every pass) or --dump-ir=PASS, PASS one of the table's names. */
static int dump_ir(cli_options *o, const char *a) {
    const char *want = a[9] == '=' ? a + 10 : "all", *name;
    for (size_t i = 0; strcmp(want, "all") != 0; i++) {
        if (!(name = hfxc_pass_name(i, NULL))) return usage_error("unknown pass '%s' (hfxc --list-passes)", want);
        if (!strcmp(name, want)) break;
    }
    o->dump_ir = want;
    return EXIT_OK;
}

static int flag(cli_options *o, const char *a, bool *handled) {
    *handled = true;
    if (!strncmp(a, "--dump-ir", 9) && (!a[9] || a[9] == '=')) return dump_ir(o, a);
    if (!strcmp(a, "--reflect")) o->reflect = true;
    else if (!strcmp(a, "--annotations")) o->annotations = true;
    else if (!strcmp(a, "--ast")) o->ast = true;
    else if (!strcmp(a, "--disassemble") || !strcmp(a, "/dumpbin") || !strcmp(a, "-dumpbin")) o->disassemble = true;
    else if (!strcmp(a, "--werror") || !strcmp(a, "/WX") || !strcmp(a, "-WX")) o->werror = true;
    else if (!strcmp(a, "--no-warnings")) o->no_warnings = true;
    else if (!strcmp(a, "--no-self-check")) o->no_self_check = true;
    else if (!strcmp(a, "--no-preshaders")) o->no_preshaders = true;
    else if (!strcmp(a, "--no-derived-varyings")) o->no_derived_varyings = true;
    else if (!strcmp(a, "--via-d3d9")) o->via_d3d9 = true;
    else if (!strcmp(a, "--pack-uniforms")) o->pack_uniforms = true; /* the default; kept for scripts */
    else if (!strcmp(a, "--separate-uniforms")) o->pack_uniforms = false;
    else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) o->quiet = true;
    else if (!strcmp(a, "-MD") || !strcmp(a, "-MMD")) o->depfile = true; /* no system headers to leave out */
    else if (!strcmp(a, "-MP")) o->depfile_phony = true;
    else if (!strcmp(a, "/nologo") || !strcmp(a, "-nologo")) {
    } else if (!strcmp(a, "/Zpr") || !strcmp(a, "-Zpr") || !strcmp(a, "/Zpc") || !strcmp(a, "-Zpc")) {
        o->matrix_packing = a[3] == 'r' ? 1 : -1;
    } else if (!strcmp(a, "/Op")) {
        o->no_preshaders = true; /* fxc's "disable preshaders" */
    } else if (fxc_no_op(a)) {
        /* fxc's debug, optimisation and strictness switches change nothing here. */
    } else *handled = false;
    return EXIT_OK;
}

/* Parses argv into o. Returns -1 to go on, or an exit code (help, version, usage error). */
static int parse_args(int argc, char **argv, cli_options *o) {
    bool only_files = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        /* A path such as /work/x.fx looks like an fxc switch: an existing file wins. */
        bool option = !only_files && (a[0] == '-' || a[0] == '/') && a[1] && !(a[0] == '/' && exists(a));
        if (!option) {
            if (push(&o->inputs, &o->input_count, a)) return EXIT_USAGE;
            continue;
        }
        if (!strcmp(a, "--")) { only_files = true; continue; }
        if (!strcmp(a, "--help") || !strcmp(a, "-h") || !strcmp(a, "/?") || !strcmp(a, "-?")) {
            fputs(usage_text, stdout);
            return EXIT_OK;
        }
        if (!strcmp(a, "--version")) {
            printf("%s\n", hfxc_version());
            return EXIT_OK;
        }
        if (!strcmp(a, "--list-passes")) {
            list_passes();
            return EXIT_OK;
        }
        bool handled;
        int rc = flag(o, a, &handled);
        if (rc != EXIT_OK) return rc;
        if (handled) continue;
        for (size_t k = 0; k < sizeof valued / sizeof *valued && !handled; k++) {
            bool missing = false;
            const char *v = value_of(a, valued[k].name, argc, argv, &i, &missing);
            if (missing) return usage_error("option '%s' needs a value", a);
            if (!v) continue;
            handled = true;
            rc = set_valued(o, valued[k].kind, v);
            if (rc != EXIT_OK) return rc;
        }
        if (!handled) return usage_error(a[0] == '/' ? "no such file or option '%s'" : "unknown option '%s'", a);
    }
    return -1;
}

static int check_inputs(const cli_options *o) {
    if (o->input_count == 0) return usage_error("%s", "no input file");
    for (size_t i = 0; i < o->input_count; i++) {
        FILE *f = fopen(o->inputs[i], "rb");
        if (!f) {
            fprintf(stderr, "hfxc: error: cannot open '%s': %s\n", o->inputs[i], strerror(errno));
            return EXIT_USAGE;
        }
        fclose(f);
    }
    size_t n = o->output ? strlen(o->output) : 0;
    bool folder = n && (o->output[n - 1] == '/' || o->input_count > 1);
    struct stat st;
    if (folder && stat(o->output, &st) != 0 && mkdir(o->output, 0777) != 0) {
        fprintf(stderr, "hfxc: error: cannot create folder '%s': %s\n", o->output, strerror(errno));
        return EXIT_USAGE;
    }
    if (o->depfile_path && o->input_count > 1)
        return usage_error("%s", "-MF / --depfile names one depfile: give one input, or -MD alone for one per output");
    if (o->profile && strcmp(o->profile, "fx_2_0") != 0 && !o->entry)
        return usage_error("profile '%s' needs an entry point (/E)", o->profile);
    return EXIT_OK;
}

static void print_results(const cli_options *o, cli_job *jobs, size_t n, size_t *failed, FILE *dumps) {
    *failed = 0;
    for (size_t i = 0; i < n; i++) {
        if (jobs[i].ir_dump) fputs(jobs[i].ir_dump, dumps);
        if (jobs[i].diagnostics && jobs[i].diagnostics[0]) fputs(jobs[i].diagnostics, stderr);
        if (jobs[i].error) fprintf(stderr, "hfxc: error: %s\n", jobs[i].error);
        if (jobs[i].ast) fputs(jobs[i].ast, stdout);
        if (!jobs[i].ok) (*failed)++;
    }
    if ((o->reflect || o->annotations) && !o->ast) {
        char *json = cli_json(jobs, n, o->reflect);
        if (json) {
            puts(json);
            free(json);
        }
    }
    if (n > 1 && !o->quiet) printf("%zu compiled, %zu failed\n", n - *failed, *failed);
}

/* Each compile frees its arena at the end; glibc would hand the top of the heap back to the
 * kernel every time and fault it in again for the next file (a third of the process's time
 * went to the kernel over the corpus). Keeping freed memory is the program's choice, not the
 * library's. */
static void keep_freed_memory(void) {
#ifdef M_TRIM_THRESHOLD
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
#endif
}

/* --disassemble: each input's listing on stdout (or in the -o file for one input). */
static int disassemble(const cli_options *o) {
    int rc = EXIT_OK;
    for (size_t i = 0; i < o->input_count; i++) {
        FILE *f = fopen(o->inputs[i], "rb");
        long n = -1;
        if (f && fseek(f, 0, SEEK_END) == 0) n = ftell(f);
        char *data = n >= 0 ? malloc((size_t)n + 1) : NULL;
        if (!data || fseek(f, 0, SEEK_SET) != 0 || fread(data, 1, (size_t)n, f) != (size_t)n) {
            fprintf(stderr, "hfxc: error: cannot read '%s'\n", o->inputs[i]);
            free(data);
            if (f) fclose(f);
            rc = EXIT_COMPILE;
            continue;
        }
        fclose(f);
        char *diags = NULL, *text = hfxc_disassemble(data, (size_t)n, o->inputs[i], &diags);
        if (diags) fputs(diags, stderr);
        FILE *out = o->output && o->input_count == 1 ? fopen(o->output, "w") : stdout;
        if (text && out) fputs(text, out);
        if (out && out != stdout) fclose(out);
        if (!text || !out) rc = EXIT_COMPILE;
        free(text);
        free(diags);
        free(data);
    }
    return rc;
}

int main(int argc, char **argv) {
    keep_freed_memory();
    cli_options o;
    memset(&o, 0, sizeof o);
    o.pack_uniforms = true; /* what the runtime does when it compiles a .fx itself */
    int rc = parse_args(argc, argv, &o);
    if (o.dump_ir_file && !o.dump_ir) o.dump_ir = "all"; /* a file for the dumps asks for them */
    if (rc < 0) rc = check_inputs(&o);
    else goto done;
    if (rc != EXIT_OK) goto done;
    if (o.disassemble) {
        rc = disassemble(&o);
        goto done;
    }
    cli_job *jobs = calloc(o.input_count, sizeof *jobs);
    if (!jobs) {
        rc = EXIT_USAGE;
        goto done;
    }
    for (size_t i = 0; i < o.input_count; i++) jobs[i].input = o.inputs[i];
    cli_run_jobs(&o, jobs, o.input_count, !o.quiet && o.input_count > 1 && isatty(STDERR_FILENO));
    size_t failed;
    FILE *dumps = o.dump_ir_file ? fopen(o.dump_ir_file, "w") : stderr;
    if (!dumps) fprintf(stderr, "hfxc: error: cannot write '%s': %s\n", o.dump_ir_file, strerror(errno));
    print_results(&o, jobs, o.input_count, &failed, dumps ? dumps : stderr);
    rc = failed || !dumps ? EXIT_COMPILE : EXIT_OK;
    if (dumps && dumps != stderr && fclose(dumps) != 0) rc = EXIT_COMPILE;
    for (size_t i = 0; i < o.input_count; i++) {
        free(jobs[i].ir_dump);
        free(jobs[i].diagnostics);
        free(jobs[i].ast);
        free(jobs[i].error);
        hfx_fx_effect_free(jobs[i].effect);
    }
    free(jobs);
done:
    free(o.inputs);
    free(o.defines);
    free(o.include_dirs);
    return rc;
}
