/* fx2.h: effects compiled by Microsoft's fxc (`fxc /T fx_2_0`, magic 0xFEFF0901: FNA's .fxb,
 * DigitalRune's .efb, D3DX's .fxo), read into hfx's effect model (common/effect.h), so the
 * runtime treats a loaded binary as a compiled source. docs/fx2.md describes the layout.
 *
 * fx2_read.c decodes the container (parameters, annotations, samplers, techniques, passes,
 * states, the object tables), fx2_states.c maps states and resources onto hfx's states and
 * builds the passes' programs, fxlvm.c turns fxc's expression programs (FXLVM) into
 * common/eval_code programs, fx2_list.c prints the listing of `hfxc --disassemble`.
 *
 * Errors are located at the byte offset in the file: `name(0,OFFSET): error X9010: message`. */
#ifndef HFX_FX2_H
#define HFX_FX2_H

#include <stddef.h>
#include <stdint.h>

#include "base/diag.h"
#include "effect.h"

enum { X_FX2_BINARY = 9010 }; /* a bad or unsupported fxc binary (hfx's own number) */

enum { /* hfx_fx2_read's flags */
    HFX_FX2_DECODE_ONLY = 1u << 31 /* (above hfxc_options.flags)  no programs: passes with shaders keep program HFX_NONE (listings, counts) */
};

/* 1 when data starts like an fxc effect: fx_2_0's magic, XNA 4's 0xBCF00BCF header before it,
 * or an XNA 4 .xnb file. */
int hfx_fx2_is_binary(const void *data, size_t size);
/* 1 when the file at path starts like one (reads its first bytes only); 0 otherwise or unreadable. */
int hfx_fx2_file_is_binary(const char *path);

/* Reads the binary data (size bytes) named `name` (as messages show it; path, when not NULL,
 * is recorded as the file the compile read). targets: bits (1 << hfx_target); flags:
 * HFX_FX2_DECODE_ONLY, and hfxc_options.flags. Returns the effect (malloc'ed, the caller's) or
 * NULL with errors in diags. Scratch memory comes from arena. */
hfx_fx_effect *hfx_fx2_read(hfx_arena *arena, hfx_diags *diags, const char *name, const char *path,
                            const void *data, size_t size, unsigned targets, unsigned flags);

/* The effect as text, in the manner of fxc's listing (parameters with their types, semantics,
 * annotations and defaults, techniques, passes, states, the expressions); NULL (errors in
 * diags) when the binary does not decode. In the arena. */
char *hfx_fx2_listing(hfx_arena *arena, hfx_diags *diags, const char *name, const void *data, size_t size);

#endif
