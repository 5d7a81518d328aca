/* mesh.h: triangle meshes for hfxview: built-in shapes made in code and Wavefront OBJ files.
 * Every mesh has positions, normals, texture coordinates, tangents and binormals, fits in the
 * unit sphere around the origin, and winds its front faces clockwise as seen from outside in
 * a right-handed world, like XNA's models (the default CullMode culls counter-clockwise). */
#ifndef HFXVIEW_MESH_H
#define HFXVIEW_MESH_H

#include <stddef.h>
#include <stdint.h>

typedef struct hv_vertex {
    float pos[3];
    float normal[3];
    float uv[2];      /* Direct3D convention: v = 0 is the top row of the image */
    float tangent[3]; /* direction of increasing u */
    float binormal[3];/* direction of increasing v */
} hv_vertex;

typedef struct hv_mesh {
    hv_vertex *v;
    size_t vcount, vcap;
    uint32_t *idx;
    size_t icount, icap;
    int oom;          /* an allocation failed while building */
} hv_mesh;

/* The inputs a mesh never has, and the constant each drawing path (GL, --vulkan, the web page)
 * gives them, the same everywhere: a white COLOR0 (an untextured, unlit model looks as its
 * material), no COLOR1, a full weight on the first bone; BLENDWEIGHT0..3 are the rows of the
 * identity, so a per-instance world matrix read from them (XNA's instancing sample's
 * `float4x4 instanceTransform : BLENDWEIGHT`, DigitalRise's three world columns) places the
 * one instance where the mesh is; TEXCOORD1..7 reuse TEXCOORD0, as a
 * single-UV model would. Any other input the mesh lacks reads the runtime's (0, 0, 0, 1),
 * what Direct3D 9 gives an element the vertex declaration lacks (docs/runtime.md). */
typedef struct hv_vertex_constant { const char *semantic; float v[4]; } hv_vertex_constant;
extern const hv_vertex_constant hv_vertex_constants[];
extern const size_t hv_vertex_constant_count;

/* Names hv_mesh_builtin knows, NULL-terminated. */
extern const char *const hv_mesh_names[];

int hv_mesh_builtin(hv_mesh *m, const char *name);                           /* 0, or -1 if unknown */
int hv_mesh_load_obj(hv_mesh *m, const char *path, char *err, size_t errlen); /* 0, or -1 with err */
int hv_mesh_load(hv_mesh *m, const char *spec, char *err, size_t errlen);     /* a built-in name or an .obj path */
int hv_mesh_screen(hv_mesh *m, int width, int height); /* "screen": the image's rectangle in pixels; 0 or -1 */
void hv_mesh_free(hv_mesh *m);

/* Building blocks, shared by the shapes and the OBJ reader. */
uint32_t hv_mesh_add_vertex(hv_mesh *m, const float pos[3], const float normal[3], const float uv[2]);
void hv_mesh_add_triangle(hv_mesh *m, uint32_t a, uint32_t b, uint32_t c);
void hv_mesh_compute_normals(hv_mesh *m);  /* area-weighted, assuming counter-clockwise fronts */
void hv_mesh_finish(hv_mesh *m);           /* tangents, clockwise fronts, fit to the unit sphere */

#endif
