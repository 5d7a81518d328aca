/* cli.h: the parts of the hfxc program (main.c reads the command line, jobs.c compiles the
 * inputs on a pool of threads and writes what they produce, json.c describes effects). */
#ifndef HFX_CLI_H
#define HFX_CLI_H

#include <stdbool.h>
#include <stddef.h>

#include "effect.h"
#include "hfx/hfxc.h"

enum { EXIT_OK = 0, EXIT_COMPILE = 1, EXIT_USAGE = 2 };

typedef struct cli_options {
    const char **inputs; size_t input_count;
    const char **defines; size_t define_count;
    const char **include_dirs; size_t include_dir_count;
    const char *output;      /* -o / /Fo: a file for one input, a folder (ending in / or existing) for many */
    const char *emit_glsl;   /* --emit-glsl DIR */
    const char *entry;       /* /E */
    const char *profile;     /* /T */
    unsigned targets;        /* bits (1 << hfx_target); 0 = the library's default */
    bool disassemble;        /* --disassemble, /dumpbin: listings of fxc's binaries */
    bool reflect, annotations, ast, werror, quiet, no_warnings, pack_uniforms, no_self_check, no_preshaders, no_derived_varyings;
    bool via_d3d9;           /* --via-d3d9 (tests): programs through the D3D9 bytecode back end and back */
    int jobs;                /* 0 = one per core */
    bool depfile;            /* -MD: write a Make / Ninja depfile per input */
    bool depfile_phony;      /* -MP: an empty rule per include, so deleting one does not break make */
    const char *depfile_path;/* -MF / --depfile: its name (one input); default <output minus extension>.d */
    const char *dep_target;  /* -MT: the rule's target; default the output path */
    /* fxc's outputs (fxc_out.c): /Fo writes fxc's fx_2_0, -o hfx's .hfxo, --format says which */
    int format;              /* CLI_FORMAT_* */
    bool format_given;       /* --format said it: /Fo or -o no longer choose */
    const char *header;      /* /Fh: a C header holding the effect's bytes */
    const char *header_name; /* /Vn: its array's name (default g_<input's stem>) */
    const char *listing;     /* /Fc: the effect's listing (fx2_list.c's) */
    int matrix_packing;      /* /Zpr: 1 (row_major), /Zpc: -1 (column_major, fxc's default), 0 unsaid */
    const char *dump_ir;     /* --dump-ir[=PASS]: a pass's name or "all" (hfxc_options.dump_ir) */
    const char *dump_ir_file;/* --dump-ir-file: where the dumps go (default stderr) */
} cli_options;

enum { CLI_FORMAT_HFXO, CLI_FORMAT_FXC };

/* What compiling one input left behind, for main to print in input order. */
typedef struct cli_job {
    const char *input;
    char *diagnostics;       /* fxc-style lines, malloc'ed */
    char *ast;               /* --ast dump, malloc'ed */
    char *ir_dump;           /* --dump-ir text, malloc'ed */
    char *error;             /* an output that could not be written, malloc'ed */
    hfx_fx_effect *effect;   /* kept for --reflect / --annotations */
    bool ok;
} cli_job;

/* Compiles every input on `jobs` threads (progress on stderr when it is a terminal). */
void cli_run_jobs(const cli_options *o, cli_job *jobs, size_t count, bool progress);
/* The JSON document --annotations (reflect = false) or --reflect prints; malloc'ed. */
char *cli_json(const cli_job *jobs, size_t count, bool reflect);
/* Where the .hfxo of `input` goes, or NULL when none is asked for; malloc'ed. */
char *cli_output_path(const cli_options *o, const char *input);
/* depfile.c: after a successful compile, the depfile naming every file r read (-MD). */
bool cli_write_depfile(const cli_options *o, const char *input, const hfxc_result *r, char **error);
/* The rule text: `target: dep...`, Make's escapes, one dependency a line; phony: `dep:` rules. malloc'ed. */
char *cli_depfile_text(const char *target, const char *const *deps, size_t count, bool phony);
/* fxc_out.c: /Fo in fxc's format, /Fh, /Fc for a compiled effect (job->ok false on failure). */
void cli_write_fxc(const cli_options *o, cli_job *job, const hfx_fx_effect *fx);
const char *cli_target_name(int target);
int cli_target_from_name(const char *name); /* -1 when unknown */

#endif
