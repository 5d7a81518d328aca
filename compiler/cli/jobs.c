/* jobs.c: compiling the inputs on a pool of threads. The compiler library keeps no global
 * state, so each thread compiles its own files; the only shared thing is the next-file counter
 * (and the progress line), under one mutex. Outputs: the .hfxo and --emit-glsl files. */
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

static const char *const target_names[HFX_TARGET_COUNT] = {"glsl330", "glsles300", "glsl110", "spirv",
                                                                   "spirv-vk"};

const char *cli_target_name(int target) {
    return target >= 0 && target < HFX_TARGET_COUNT ? target_names[target] : "?";
}

int cli_target_from_name(const char *name) {
    for (int i = 0; i < HFX_TARGET_COUNT; i++)
        if (strcmp(name, target_names[i]) == 0) return i;
    return -1;
}

static char *fmt(const char *f, const char *a, const char *b) {
    size_t n = strlen(f) + strlen(a) + strlen(b) + 1;
    char *s = malloc(n);
    if (s) snprintf(s, n, f, a, b);
    return s;
}

/* "dir/name.fx" -> "name" */
static char *stem(const char *path) {
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    char *s = strdup(base);
    char *dot = s ? strrchr(s, '.') : NULL;
    if (dot && dot != s) *dot = 0;
    return s;
}

static bool is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

char *cli_output_path(const cli_options *o, const char *input) {
    if (!o->output) return NULL;
    size_t n = strlen(o->output);
    bool folder = o->input_count > 1 || (n && o->output[n - 1] == '/') || is_dir(o->output);
    if (!folder) return strdup(o->output);
    char *s = stem(input);
    const char *ext = o->format == CLI_FORMAT_FXC ? "fxo" : "hfxo";
    char *named = s ? fmt("%s.%s", s, ext) : NULL;
    char *path = named ? fmt(o->output[n - 1] == '/' ? "%s%s" : "%s/%s", o->output, named) : NULL;
    free(named);
    free(s);
    return path;
}

/* strerror is not promised to be thread-safe; the workers use this. */
static const char *error_text(int err, char *buf, size_t size) {
    if (strerror_r(err, buf, size) != 0) snprintf(buf, size, "error %d", err);
    return buf;
}

static bool write_file(const char *path, const void *data, size_t size, char **error) {
    FILE *f = fopen(path, "wb");
    bool ok = f && fwrite(data, 1, size, f) == size;
    if (f && fclose(f) != 0) ok = false;
    char why[128];
    if (!ok && !*error) *error = fmt("cannot write '%s': %s", path, error_text(errno, why, sizeof why));
    return ok;
}

/* /Fo: the raw token stream; /Fc: fxc's listing of it. */
static void write_shader(const cli_options *o, cli_job *job, const void *code, size_t size) {
    char *path = o->output && o->format == CLI_FORMAT_FXC ? strdup(o->output) : NULL;
    if (path && !write_file(path, code, size, &job->error)) job->ok = false;
    free(path);
    if (!o->listing) return;
    char *diags = NULL, *text = hfxc_disassemble(code, size, job->input, &diags);
    if (!text || !write_file(o->listing, text, strlen(text), &job->error)) job->ok = false;
    if (!text && !job->error) job->error = fmt("cannot list the shader of '%s'%s", job->input, "");
    free(text);
    free(diags);
}

static void write_hfxo_file(const cli_options *o, cli_job *job, const hfx_fx_effect *fx) {
    char *path = cli_output_path(o, job->input);
    if (!path) return;
    void *data = NULL;
    size_t size = 0;
    if (hfx_fx_write_hfxo(fx, &data, &size) != 0) job->error = fmt("cannot encode '%s'%s", path, "");
    else if (!write_file(path, data, size, &job->error)) job->ok = false;
    if (job->error) job->ok = false;
    free(data);
    free(path);
}

static void write_hfxo(const cli_options *o, cli_job *job, const hfx_fx_effect *fx) {
    cli_write_fxc(o, job, fx); /* /Fo (fxc's format), /Fh, /Fc */
    if (o->format != CLI_FORMAT_FXC) write_hfxo_file(o, job, fx);
}

/* The first target the effect carries code for, in the user's order of preference. */
static int emit_target(const cli_options *o, const hfx_fx_effect *fx) {
    unsigned want = o->targets ? o->targets : fx->targets;
    for (int t = 0; t < HFX_TARGET_COUNT; t++)
        if ((want & fx->targets) & (1u << t)) return t;
    return HFX_TARGET_GLSL330;
}

/* One program's shaders as <effect>.<technique>.<pass><suffix>.vert / .frag. */
static void emit_program(cli_job *job, const char *base, const char *suffix, const hfx_fx_program *prog, int target) {
    static const char *const ext[HFX_STAGE_COUNT] = {"vert", "frag"};
    for (int s = 0; s < HFX_STAGE_COUNT; s++) {
        const hfx_fx_code *c = &prog->code[s][target];
        if (!c->data) continue;
        char path[4096];
        snprintf(path, sizeof path, "%s%s.%s%s", base, suffix, ext[s], target >= HFX_TARGET_SPIRV ? ".spv" : "");
        if (!write_file(path, c->data, c->size, &job->error)) job->ok = false;
    }
}

/* A pass's program, or each variant of a pass drawn from shader arrays (.vs<i>.ps<j>). */
static void emit_pass(cli_job *job, const char *base, const hfx_fx_effect *fx, uint32_t pass, int target) {
    if (fx->passes[pass].program != HFX_NONE) emit_program(job, base, "", &fx->programs[fx->passes[pass].program], target);
    for (uint32_t i = 0; i < fx->variant_count; i++) {
        const hfx_fx_variant *v = &fx->variants[i];
        if (v->pass != pass) continue;
        char suffix[64];
        snprintf(suffix, sizeof suffix, ".vs%d.ps%d", v->vs == HFX_NONE ? -1 : (int)v->vs, v->ps == HFX_NONE ? -1 : (int)v->ps);
        emit_program(job, base, suffix, &fx->programs[v->program], target);
    }
}

static void emit_glsl(const cli_options *o, cli_job *job, const hfx_fx_effect *fx) {
    if (!o->emit_glsl) return;
    if (!is_dir(o->emit_glsl) && mkdir(o->emit_glsl, 0777) != 0 && errno != EEXIST) {
        char why[128];
        job->error = fmt("cannot create folder '%s': %s", o->emit_glsl, error_text(errno, why, sizeof why));
        job->ok = false;
        return;
    }
    int target = emit_target(o, fx);
    char *effect = stem(job->input);
    for (uint32_t t = 0; effect && t < fx->technique_count; t++) {
        const hfx_fx_technique *tq = &fx->techniques[t];
        for (uint32_t p = 0; p < tq->pass_count; p++) {
            const hfx_fx_pass *pass = &fx->passes[tq->first_pass + p];
            char tname[32], pname[32], base[4000];
            if (!tq->name[0]) snprintf(tname, sizeof tname, "t%u", t);
            if (!pass->name[0]) snprintf(pname, sizeof pname, "p%u", p);
            snprintf(base, sizeof base, "%s/%s.%s.%s", o->emit_glsl, effect, tq->name[0] ? tq->name : tname,
                     pass->name[0] ? pass->name : pname);
            emit_pass(job, base, fx, tq->first_pass + p, target);
        }
    }
    free(effect);
}

/* A target asked for that the code generator could not produce is worth a line. */
static void warn_missing_targets(const cli_options *o, cli_job *job, const hfx_fx_effect *fx) {
    unsigned missing = fx->program_count ? o->targets & ~fx->targets : 0;
    for (int t = 0; t < HFX_TARGET_COUNT; t++) {
        if (!(missing & (1u << t))) continue;
        char *line = fmt("hfxc: warning: no %s code was generated for '%s'\n", cli_target_name(t), job->input);
        size_t old = job->diagnostics ? strlen(job->diagnostics) : 0;
        char *d = line ? realloc(job->diagnostics, old + strlen(line) + 1) : NULL;
        if (d) {
            memcpy(d + old, line, strlen(line) + 1);
            job->diagnostics = d;
        }
        free(line);
    }
}

/* A compiled .hfxo given as input: read, not compiled (for --reflect, --emit-glsl, copying). */
static bool load_hfxo(cli_job *job) {
    FILE *f = fopen(job->input, "rb");
    unsigned char head[8];
    bool is = f && fread(head, 1, sizeof head, f) == sizeof head && hfx_fx_is_hfxo(head, sizeof head);
    if (!is) {
        if (f) fclose(f);
        return false;
    }
    char *data = NULL;
    size_t size = 0;
    if (fseek(f, 0, SEEK_END) == 0) {
        long n = ftell(f);
        data = n > 0 ? malloc((size_t)n) : NULL;
        if (data && fseek(f, 0, SEEK_SET) == 0 && fread(data, 1, (size_t)n, f) == (size_t)n) size = (size_t)n;
    }
    fclose(f);
    char err[256] = "hfxo: cannot read the file";
    job->effect = size ? hfx_fx_read_hfxo(data, size, err, sizeof err) : NULL;
    free(data);
    job->ok = job->effect != NULL;
    if (!job->ok) job->error = fmt("%s: %s", job->input, err);
    return true;
}

static void compile_one(const cli_options *o, cli_job *job, hfxc_session *session) {
    if (!o->ast && load_hfxo(job)) {
        if (job->ok) {
            write_hfxo(o, job, job->effect);
            emit_glsl(o, job, job->effect);
        }
        if (!o->reflect && !o->annotations) {
            hfx_fx_effect_free(job->effect);
            job->effect = NULL;
        }
        return;
    }
    hfxc_options opt;
    memset(&opt, 0, sizeof opt);
    opt.defines = o->defines;
    opt.define_count = o->define_count;
    opt.include_dirs = o->include_dirs;
    opt.include_dir_count = o->include_dir_count;
    opt.targets = o->targets;
    opt.entry = o->entry;
    opt.profile = o->profile;
    opt.session = session;
    opt.dump_ir = o->dump_ir;
    opt.flags = (o->werror ? HFXC_WERROR : 0) | (o->no_warnings ? HFXC_NO_WARNINGS : 0) | (o->ast ? HFXC_PARSE_ONLY : 0) |
                (o->pack_uniforms ? HFXC_PACK_UNIFORMS : 0) | (o->no_self_check ? HFXC_NO_SELF_CHECK : 0) |
                (o->no_preshaders ? HFXC_NO_PRESHADERS : 0) |
                (o->no_derived_varyings ? HFXC_NO_DERIVED_VARYINGS : 0) | (o->via_d3d9 ? HFXC_VIA_D3D9 : 0);
    if (!o->entry && ((o->output && o->format == CLI_FORMAT_FXC) || o->header || o->listing))
        opt.flags |= HFXC_D3D9_BYTECODE; /* fx_2_0's writer needs every pass's shaders as Direct3D 9 bytecode */
    hfxc_result *r = hfxc_compile_file(job->input, &opt);
    if (!r) {
        job->error = fmt("out of memory compiling '%s'%s", job->input, "");
        return;
    }
    job->diagnostics = hfxc_diagnostics_text(r);
    job->ok = hfxc_result_ok(r) != 0;
    if (o->dump_ir) job->ir_dump = hfxc_result_ir_dump(r);
    if (o->ast) {
        job->ast = hfxc_result_ast_dump(r);
    } else if (job->ok) {
        job->effect = hfxc_result_take_effect(r);
        if (!job->effect) {
            job->ok = false;
            job->error = fmt("'%s': the compiler produced no effect%s", job->input, "");
        } else {
            warn_missing_targets(o, job, job->effect);
            size_t size = 0;
            const void *code = hfxc_result_bytecode(r, &size);
            /* fxc /T vs_* | ps_* /E: /Fo the shader as fxc writes it, /Fc its listing; -o the .hfxo
             * beside them (/Fc alone writes only the listing) */
            if (code && o->entry && !o->header) {
                write_shader(o, job, code, size);
                if (o->format != CLI_FORMAT_FXC && (o->output || !o->listing)) write_hfxo_file(o, job, job->effect);
            } else write_hfxo(o, job, job->effect);
            emit_glsl(o, job, job->effect);
            if (job->ok && o->depfile && !cli_write_depfile(o, job->input, r, &job->error)) job->ok = false;
        }
    }
    hfxc_result_free(r);
    if (!o->reflect && !o->annotations) {
        hfx_fx_effect_free(job->effect);
        job->effect = NULL;
    }
}

typedef struct pool {
    const cli_options *o;
    cli_job *jobs;
    size_t count, next, done;
    bool progress;
    pthread_mutex_t lock;
} pool;

/* Each worker has its own session: the headers it has cut into tokens serve its next files. */
static void *worker(void *arg) {
    pool *p = arg;
    hfxc_session *session = hfxc_session_new(); /* NULL is fine: compiles without one */
    for (;;) {
        pthread_mutex_lock(&p->lock);
        size_t i = p->next < p->count ? p->next++ : p->count;
        pthread_mutex_unlock(&p->lock);
        if (i == p->count) break;
        compile_one(p->o, &p->jobs[i], session);
        pthread_mutex_lock(&p->lock);
        p->done++;
        if (p->progress) {
            fprintf(stderr, "\r[%zu/%zu] %s\033[K", p->done, p->count, p->jobs[i].input);
            fflush(stderr);
        }
        pthread_mutex_unlock(&p->lock);
    }
    hfxc_session_free(session);
    return NULL;
}

void cli_run_jobs(const cli_options *o, cli_job *jobs, size_t count, bool progress) {
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    size_t threads = o->jobs > 0 ? (size_t)o->jobs : cores > 0 ? (size_t)cores : 1;
    if (threads > count) threads = count;
    pool p = {.o = o, .jobs = jobs, .count = count, .progress = progress};
    pthread_mutex_init(&p.lock, NULL);
    pthread_t *ids = threads > 1 ? calloc(threads, sizeof *ids) : NULL;
    size_t started = 0;
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, 16u << 20); /* deeply nested input recurses in the checker */
    for (size_t t = 0; ids && t < threads; t++)
        if (pthread_create(&ids[started], &attr, worker, &p) == 0) started++;
    pthread_attr_destroy(&attr);
    if (!started) worker(&p); /* one job, one core, or no threads: this thread does the work */
    for (size_t t = 0; t < started; t++) pthread_join(ids[t], NULL);
    free(ids);
    pthread_mutex_destroy(&p.lock);
    if (progress) fprintf(stderr, "\r\033[K");
}
