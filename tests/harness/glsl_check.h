/* glsl_check.h: glslang (its C interface) as the judge of the GLSL hfx emits. */
#ifndef HFX_TEST_GLSL_CHECK_H
#define HFX_TEST_GLSL_CHECK_H

/* stage: 0 vertex, 1 fragment. The source carries its own #version. Returns 1 when glslang
 * accepts it; *log (malloc'ed, may be NULL) gets glslang's messages either way. */
int test_glsl_compile(const char *src, int stage, char **log);
/* Compiles and links a vertex + fragment pair (interfaces must match). */
int test_glsl_link(const char *vs, const char *fs, char **log);

#endif
