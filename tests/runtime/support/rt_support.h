/* rt_support.h: helpers for the runtime tests: effects built by hand (hfx_fx_effect values with
 * hand-written GLSL 330), a counting GL loader, and the GL calls the tests make themselves. */
#ifndef HFX_TEST_RT_SUPPORT_H
#define HFX_TEST_RT_SUPPORT_H

#include <GL/glcorearb.h>

#include "gl_fns.h"

#include "effect.h"
#include "hfx/hfx.h"
#include "states.h"

/* Building an effect. Top-level parameters must be added before any child. */
hfx_fx_effect *tb_new(void);
uint32_t tb_param(hfx_fx_effect *fx, const char *name, const char *glsl, hfx_param_class k, hfx_param_type t,
                  uint32_t rows, uint32_t cols, uint32_t elements, uint32_t parent, uint32_t offset, uint32_t words);
void tb_children(hfx_fx_effect *fx, uint32_t parent, uint32_t first, uint32_t count);
void tb_top_count(hfx_fx_effect *fx, uint32_t n);
void tb_set_float(hfx_fx_effect *fx, uint32_t word, float v);
uint32_t tb_annotation_f(hfx_fx_effect *fx, const char *name, const float *v, uint32_t n);
uint32_t tb_annotation_i(hfx_fx_effect *fx, const char *name, hfx_param_type t, int32_t v);
uint32_t tb_annotation_s(hfx_fx_effect *fx, const char *name, const char *s);
uint32_t tb_program(hfx_fx_effect *fx, const char *vs, const char *fs);
void tb_attribute(hfx_fx_effect *fx, uint32_t prog, const char *semantic, const char *glsl, int32_t location);
void tb_uses(hfx_fx_effect *fx, uint32_t prog, uint32_t param);
void tb_sampler_use(hfx_fx_effect *fx, uint32_t prog, const char *glsl, uint32_t sampler, int32_t unit);
uint32_t tb_sampler(hfx_fx_effect *fx, uint32_t param, uint32_t texture_param, hfx_fx_dim dim);
uint32_t tb_state_i(hfx_fx_effect *fx, const char *name, uint32_t index, int32_t v);          /* appends */
uint32_t tb_state_e(hfx_fx_effect *fx, const char *name, uint32_t index, const char *value);  /* by value name */
uint32_t tb_state_f(hfx_fx_effect *fx, const char *name, uint32_t index, const float *f, uint32_t n);
uint32_t tb_state_p(hfx_fx_effect *fx, const char *name, uint32_t index, uint32_t param);
void tb_sampler_states(hfx_fx_effect *fx, uint32_t sampler, uint32_t first, uint32_t count);
uint32_t tb_technique(hfx_fx_effect *fx, const char *name);
/* A pass of the last technique with states [first_state, first_state + state_count). */
uint32_t tb_pass(hfx_fx_effect *fx, const char *name, uint32_t program, uint32_t first_state, uint32_t state_count);

/* Counting loader: wraps every entry point of runtime/gl.h. */
void *tc_loader(const char *name);
unsigned long tc_calls(void);
unsigned long tc_count(const char *gl_name);
void tc_reset(void);

/* GL the tests call directly: the harness's table. */
typedef test_gl_fns tgl;
void tgl_load(tgl *g);

/* A vertex array with one float2 attribute at location 0 holding the given triangle list. */
GLuint tgl_triangles(tgl *g, const float *xy, int vertices, GLuint *buffer);

/* The GLSL 330 programs most tests use: a pass-through position and a colour uniform. */
extern const char *const tb_vs_pos;      /* layout(location = 0) in vec2 POSITION0 */
extern const char *const tb_fs_color;    /* uniform vec4 Color; */

#endif
