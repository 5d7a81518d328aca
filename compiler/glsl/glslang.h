/* glslang.h: glslang, in-process, behind one module: its process state, and a shader parsed
 * and checked the way a GL driver would (the self-check of every shader hfx emits) or for
 * SPIR-V (spirv.c). Thread safety: glslang reference-counts its process state under its own
 * lock, so every user brackets its work with hfx_glslang_begin / hfx_glslang_end. */
#ifndef HFX_GLSLANG_H
#define HFX_GLSLANG_H

#include <stdbool.h>

#include "effect.h"

bool hfx_glslang_available(void); /* false when hfx was built without glslang */
bool hfx_glslang_begin(void);     /* glslang_initialize_process; false when it failed */
void hfx_glslang_end(void);       /* once per successful begin */

/* Parses src, the GLSL of `target` (330, ES 300, 110) for stage 0 (vertex) or 1 (fragment), as
 * a driver would before linking. 0 when glslang accepts it (or is absent); -1 with its messages
 * in *log (malloc'ed). Between begin and end. */
int hfx_glslang_check(const char *src, int stage, hfx_target target, char **log);

/* Appends "what" + more (+ a newline) to a malloc'ed log; the log as it was when out of memory. */
char *hfx_glslang_append_log(char *log, const char *what, const char *more);

#endif
