/* fxc_out.c: the outputs fxc's switches name for an effect (/T fx_2_0): /Fo writes fxc's fx_2_0
 * container (compiler/effect/fx2_write.c), /Fh a C header of its bytes (fxc's layout: the
 * listing in `#if 0`, then `const BYTE <name>[] = { ... };`, the name /Vn's, by default
 * g_<input's stem>), /Fc the listing (`hfxc --disassemble`'s). Separate from jobs.c so that the
 * single-shader outputs (/T vs_* /E) sit beside these. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "effect/fx2_write.h"

/* A program's D3D9 bytecode when it carries none. A compiled source's programs carry theirs (jobs.c
 * asks for HFXC_D3D9_BYTECODE), as do an fxc binary's; an .hfxo keeps GLSL only. */
static int bytecode_of(void *ctx, const hfx_fx_effect *fx, uint32_t program, int stage, const void **data, size_t *size,
                       char *err, size_t err_size) {
    (void)ctx, (void)fx, (void)program, (void)stage, (void)data, (void)size;
    snprintf(err, err_size, "no Direct3D 9 bytecode for this shader: an .hfxo carries GLSL only "
             "(compile the effect's .fx source with /T fx_2_0 /Fo)");
    return -1;
}

static char *text_printf(const char *f, const char *a) {
    size_t n = strlen(f) + strlen(a) + 1;
    char *s = malloc(n);
    if (s) snprintf(s, n, f, a);
    return s;
}

static bool write_bytes(cli_job *job, const char *path, const void *data, size_t size) {
    FILE *f = fopen(path, "wb");
    bool ok = f && fwrite(data, 1, size, f) == size;
    if (f && fclose(f) != 0) ok = false;
    if (!ok && !job->error) job->error = text_printf("cannot write '%s'", path);
    return ok;
}

/* g_<stem>, every character that is no identifier's made '_'. */
static char *default_name(const char *input) {
    const char *base = strrchr(input, '/');
    base = base ? base + 1 : input;
    size_t n = strcspn(base, ".");
    char *s = malloc(n + 3);
    if (!s) return NULL;
    snprintf(s, n + 3, "g_%.*s", (int)n, base);
    for (char *c = s + 2; *c; c++)
        if (!isalnum((unsigned char)*c)) *c = '_';
    return s;
}

static void write_header(const cli_options *o, cli_job *job, const uint8_t *data, size_t size, const char *listing) {
    FILE *f = fopen(o->header, "w");
    char *name = o->header_name ? strdup(o->header_name) : default_name(job->input);
    bool ok = f && name;
    if (ok) {
        fprintf(f, "#if 0\n%s#endif\n\nconst BYTE %s[] =\n{\n", listing ? listing : "", name);
        for (size_t i = 0; i < size; i++)
            fprintf(f, "%s%4u%s", i % 8 ? "" : "   ", data[i], i + 1 == size ? "\n" : i % 8 == 7 ? ",\n" : ",");
        fputs("};\n", f);
    }
    if (f && fclose(f) != 0) ok = false;
    if (!ok && !job->error) job->error = text_printf("cannot write '%s'", o->header);
    free(name);
}

void cli_write_fxc(const cli_options *o, cli_job *job, const hfx_fx_effect *fx) {
    bool fo = o->output && o->format == CLI_FORMAT_FXC;
    if (!fo && !o->header && !o->listing) return;
    if (o->entry) { /* fxc's /T vs_* | ps_* /E on a compiled effect: jobs.c writes a source's shader */
        job->error = text_printf("'%s': /E picks one function of an effect's source; a compiled effect has none to pick",
                                 job->input);
        job->ok = false;
        return;
    }
    hfx_fx2_write_options opt = {bytecode_of, NULL, o->matrix_packing};
    void *data = NULL;
    size_t size = 0;
    char err[1024];
    if (hfx_fx2_write(fx, job->input, &opt, &data, &size, err, sizeof err) != 0) {
        job->error = text_printf("%s", err);
        job->ok = false;
        return;
    }
    char *listing = NULL, *diags = NULL;
    if (o->header || o->listing) listing = hfxc_disassemble(data, size, job->input, &diags);
    if (fo) {
        char *path = cli_output_path(o, job->input);
        if (!path || !write_bytes(job, path, data, size)) job->ok = false;
        free(path);
    }
    if (o->listing && !(listing && write_bytes(job, o->listing, listing, strlen(listing)))) job->ok = false;
    if (o->header) write_header(o, job, data, size, listing);
    if (job->error) job->ok = false;
    free(listing);
    free(diags);
    free(data);
}
