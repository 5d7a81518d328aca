/* fx2_write.h: hfx's effect model (common/effect.h) written as fxc's fx_2_0 effect (`fxc /T
 * fx_2_0`'s container, docs/fx2.md), which FNA, MonoGame's MojoShader path, D3DX9 and hfx's own
 * reader load: fx2_write.c lays out the container, fxlvm_write.c turns state expressions and
 * shader array indices into fxc's expression programs (FXLVM). */
#ifndef HFX_FX2_WRITE_H
#define HFX_FX2_WRITE_H

#include <stddef.h>
#include <stdint.h>

#include "effect.h"

/* Where the writer takes a stage's Direct3D 9 bytecode when the program carries none
 * (hfx_fx_program.d3d9 empty): the D3D9 back end, or a test's stand-in. Sets *data, *size
 * (size 0: the stage has no shader) and returns 0, or returns -1 with a message in err. */
typedef int (*hfx_fx2_bytecode_fn)(void *ctx, const hfx_fx_effect *fx, uint32_t program, int stage,
                                   const void **data, size_t *size, char *err, size_t err_size);

typedef struct hfx_fx2_write_options {
    hfx_fx2_bytecode_fn bytecode; /* NULL: programs without bytecode write NULL shaders */
    void *ctx;
    int matrix_packing;           /* fxc's /Zpr: 1, matrices declared without row_major / column_major are
                                   * row-major (their class in the file); 0 or -1 (/Zpc): column-major */
} hfx_fx2_write_options;

/* fx as an fx_2_0 effect: *out (malloc'ed, the caller's), *size bytes; 0. On failure -1 and
 * `name(line,col): error X9011: message` lines (the states' positions) in err. */
int hfx_fx2_write(const hfx_fx_effect *fx, const char *name, const hfx_fx2_write_options *opt, void **out,
                  size_t *size, char *err, size_t err_size);

enum { X_FX2_WRITE = 9011 }; /* something of the effect fx_2_0 cannot hold (hfx's own number) */

/* fxlvm_write.c: the common/eval_code program code[0..words) over fx's parameters as an FXLVM
 * program (malloc'ed words, *out_words of them); NULL with the reason in err. */
uint32_t *hfx_fxlvm_write(const hfx_fx_effect *fx, const uint32_t *code, uint32_t words, uint32_t *out_words, char *err,
                          size_t err_size);

#endif
