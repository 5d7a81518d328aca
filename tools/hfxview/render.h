/* render.h: drawing an effect's passes over a mesh, the way an XNA Draw method does: set the
 * device's default states, then for each pass Apply() and DrawIndexedPrimitives. */
#ifndef HFXVIEW_RENDER_H
#define HFXVIEW_RENDER_H

#include "gl.h"
#include "hfx/hfx.h"
#include "image.h"
#include "mesh.h"

typedef struct hv_gpu_mesh {
    unsigned int vao, vbo, ibo;
    int index_count;
} hv_gpu_mesh;

int hv_gpu_mesh_upload(const hv_gl *gl, hv_gpu_mesh *g, const hv_mesh *m); /* 0, or -1 */
void hv_gpu_mesh_release(const hv_gl *gl, hv_gpu_mesh *g);

/* Binds the mesh's attributes to the locations the pass's vertex shader wants, by semantic
 * (POSITION0, NORMAL0, TEXCOORD0, TANGENT0, BINORMAL0); inputs the mesh lacks get
 * hv_vertex_constants (mesh.h), TEXCOORD1..7 the first set. Call after hfx_pass_apply. */
void hv_bind_attributes(const hv_gl *gl, const hv_gpu_mesh *g, const hfx_pass *pass);

/* DrawIndexedPrimitives: binds the attributes for the applied pass and draws the triangles. */
void hv_draw_mesh(const hv_gl *gl, const hv_gpu_mesh *g, const hfx_pass *pass);

/* XNA's device defaults: depth test LessEqual with writes, CullCounterClockwiseFace, opaque. */
void hv_set_default_states(const hv_gl *gl);
void hv_clear(const hv_gl *gl, int width, int height, const float rgba[4]);

/* Draws pass `pass` (-1: all in order) of technique t between one hfx_effect_begin / end, so
 * render states carry from pass to pass as in D3D9. blend_add: the application switches to
 * additive blending without depth writes before the second pass. Returns HFX_OK or the first
 * hfx error; *failed_pass says which. */
int hv_draw_technique(const hv_gl *gl, const hv_gpu_mesh *g, hfx_effect *fx, hfx_technique *t, int pass,
                      int blend_add, size_t *failed_pass);

/* The current colour buffer as an image, top row first (rows flipped for the default
 * framebuffer; a bound framebuffer object holds D3D9's row order already). 0, or -1 on
 * allocation failure. */
int hv_read_image(const hv_gl *gl, int width, int height, hv_image *out);

/* A mipmapped RGBA8 2D texture (or each face of a cube map) from an image; 0 on failure. */
unsigned int hv_texture_2d(const hv_gl *gl, const hv_image *img);
unsigned int hv_texture_cube(const hv_gl *gl, const hv_image *img); /* 6 faces, or one image on each */
unsigned int hv_texture_3d(const hv_gl *gl, const hv_image *img);   /* the image's slices */

#endif
