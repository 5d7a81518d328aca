/* hfxc.h: the hfx compiler library. Compiles Direct3D 9 effect files (.fx, fx_2_0) to GLSL
 * (and SPIR-V) plus everything the runtime needs. It never prints and never exits: every
 * message comes back in the result, as `file(line,col): error X####: message`. */
#ifndef HFX_HFXC_H
#define HFX_HFXC_H

#include <stddef.h>

#include "hfx/hfx_export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hfxc_result hfxc_result;
/* What compiles may share: the headers already cut into tokens (a header is read again every
 * time, and cut again when its text changed). Optional; one session serves one thread at a
 * time; free it after the compiles (their results do not depend on it). */
typedef struct hfxc_session hfxc_session;
struct hfx_fx_effect; /* common/effect.h: the compiled effect as plain data */

typedef enum { HFXC_ERROR, HFXC_WARNING, HFXC_NOTE } hfxc_severity;

typedef struct hfxc_diag {
    hfxc_severity severity;
    const char *file;      /* as the user named it */
    unsigned line, col;    /* 1-based; col counts bytes of the line */
    unsigned code;         /* fxc's number: 3000 for X3000 */
    const char *message;
} hfxc_diag;

enum { /* hfxc_options.flags */
    HFXC_WERROR = 1u << 0,      /* warnings are errors */
    HFXC_NO_WARNINGS = 1u << 1, /* drop warnings */
    HFXC_CARET = 1u << 2,       /* formatted text adds the source line and a caret */
    HFXC_PARSE_ONLY = 1u << 3,  /* stop after the AST */
    HFXC_PACK_UNIFORMS = 1u << 4, /* float parameters share one vec4 array per program (D3D9 registers): one upload for many changes */
    HFXC_NO_SELF_CHECK = 1u << 5, /* skip glslang's check of every emitted shader (faster; a bug of hfx reaches the driver) */
    HFXC_TEST_BREAK_GLSL = 1u << 6, /* for hfx's own tests: the code generator spoils every shader, so the self-check must fail */
    HFXC_NO_PRESHADERS = 1u << 7, /* keep parameter-only work in the shaders (preshaders need HFXC_PACK_UNIFORMS) */
    HFXC_NO_DERIVED_VARYINGS = 1u << 8, /* interpolate every vertex output, even one the pixel shader could compute from another */
    HFXC_VIA_D3D9 = 1u << 9,    /* for tests: every program goes source -> D3D9 bytecode (each pass's profile) -> hfx's reader -> GLSL */
    HFXC_D3D9_BYTECODE = 1u << 10 /* every program also carries its Direct3D 9 bytecode (each pass's profile), for fx_2_0's writer */
};

/* Limits on untrusted input. A source file (the root or an #include) of more than
 * HFXC_MAX_SOURCE_BYTES is refused with error X9002 at its first line (or at the #include); a
 * compile may use HFXC_MEMORY_FLOOR bytes plus HFXC_MEMORY_PER_BYTE for each byte of source it
 * reads, past which it stops with error X9001 (so memory grows at most linearly with input). */
enum { HFXC_MAX_SOURCE_BYTES = 8 << 20, HFXC_MEMORY_FLOOR = 32 << 20, HFXC_MEMORY_PER_BYTE = 40 };

typedef struct hfxc_options {
    const char *const *defines;      /* "NAME" or "NAME=VALUE" */
    size_t define_count;
    const char *const *include_dirs;
    size_t include_dir_count;
    unsigned targets;                /* bit (1 << hfx_target); 0 = GLSL 330 and GLSL ES 300 */
    unsigned flags;
    const char *entry;               /* with a shader profile: compile one entry point, like fxc /E */
    const char *profile;             /* "fx_2_0" (default), or "vs_3_0", "ps_2_0"... for /T */
    hfxc_session *session;           /* NULL, or shared by compiles one after another */
    const char *dump_ir;             /* a pass's name (hfxc_pass_name), or "all": the IR of every stage
                                      * after it, for hfxc_result_ir_dump; NULL: none */
} hfxc_options;

HFX_API hfxc_session *hfxc_session_new(void);                                           /* NULL when out of memory */
HFX_API void hfxc_session_free(hfxc_session *s);

HFX_API hfxc_result *hfxc_compile_file(const char *path, const hfxc_options *opt);      /* opt may be NULL */
HFX_API hfxc_result *hfxc_compile_memory(const char *src, size_t size, const char *name, const hfxc_options *opt);
HFX_API void hfxc_result_free(hfxc_result *r);
HFX_API int hfxc_result_ok(const hfxc_result *r);                        /* 1 when there is no error */
HFX_API size_t hfxc_diag_count(const hfxc_result *r);
HFX_API const hfxc_diag *hfxc_diag_at(const hfxc_result *r, size_t i);
HFX_API char *hfxc_diagnostics_text(const hfxc_result *r);               /* all messages, one a line; free() it */
HFX_API const struct hfx_fx_effect *hfxc_result_effect(const hfxc_result *r); /* NULL when compilation failed */
HFX_API struct hfx_fx_effect *hfxc_result_take_effect(hfxc_result *r);   /* caller owns it now */
/* With a vs_* / ps_* profile and an entry (fxc /T /E): the shader's D3D9 bytecode (little-endian
 * words as fxc writes them, *size bytes, living as long as r); NULL otherwise. */
HFX_API const void *hfxc_result_bytecode(const hfxc_result *r, size_t *size);
/* The effect as fxc's fx_2_0 container (fxc /T fx_2_0 /Fo; compile with HFXC_D3D9_BYTECODE),
 * matrices without a packing keyword row-major when row_major (/Zpr): malloc'ed, *size bytes;
 * NULL with the messages in *errors (free() it; errors may be NULL) when there is none to write. */
HFX_API void *hfxc_result_fx2(const hfxc_result *r, int row_major, size_t *size, char **errors);
HFX_API char *hfxc_result_ast_dump(const hfxc_result *r);                /* readable AST; free() it */
/* With hfxc_options.dump_ir: each stage's IR after that pass, in the order the passes ran, each
 * dump opened by `// after PASS: file(line,col)` (where its compile is); free() it. */
HFX_API char *hfxc_result_ir_dump(const hfxc_result *r);
/* The compiler's passes in the order they run (i from 0; NULL past the last); *why (may be
 * NULL) gets one line on what the pass does. */
HFX_API const char *hfxc_pass_name(size_t i, const char **why);
/* The files the compile read: the root (unless compiled from memory), then every #include'd file
 * in the order first opened, each once, by the path it was opened with (an include folder or the
 * including file's folder joined to the name, with the case found on disk). Also after errors:
 * what was read up to them. Strings live as long as the result. */
HFX_API size_t hfxc_dependency_count(const hfxc_result *r);
HFX_API const char *hfxc_dependency_at(const hfxc_result *r, size_t i);
/* `hfxc --disassemble` (fxc's /dumpbin): the listing of an effect fxc compiled (fx_2_0, or an
 * uncompressed XNA .xnb holding one): parameters, techniques, passes, states, each shader's
 * assembly. NULL when it does not decode; *diagnostics (may be NULL; free() it) says why. */
HFX_API char *hfxc_disassemble(const void *data, size_t size, const char *name, char **diagnostics);
HFX_API const char *hfxc_version(void);

#ifdef __cplusplus
}
#endif
#endif
