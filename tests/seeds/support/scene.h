/* scene.h: the seed acceptance harness. An OSMesa context with an hfx device, meshes whose
 * position, normal and texcoord under any pixel are known (a ray through the pixel's sample
 * point hits the same triangles the rasterizer covers, and its barycentrics are the
 * perspective-correct weights), XNA-style cameras, and probes that compare a rendered pixel
 * with the colour an independent C version of the seed's equations gives there.
 *
 * Application state is XNA's defaults: depth test on (LessEqual), counter-clockwise faces
 * culled (XNA's CullCounterClockwise: front faces are clockwise on screen; hfx keeps D3D's
 * clip space, so in GL terms GL_CW front faces and GL_BACK culled), no blending. Meshes are
 * wound as XNA's are: clockwise seen from the side their normals point to. */
#ifndef HFX_SEED_SCENE_H
#define HFX_SEED_SCENE_H

#include "gl_context.h"
#include "hfx/hfx.h"
#include "seedmath.h"
#include "test.h"

#define SEED_TOLERANCE 2.0 /* in 1/255 steps */

typedef struct seed_scene seed_scene;

typedef struct seed_vertex { float pos[3], normal[3], uv[2]; } seed_vertex;

typedef struct seed_mesh {
    seed_vertex *v; /* triangle list, object space */
    int count;
    v3 centre;      /* a bounding sphere, object space, for probes to skip meshes a ray misses */
    double radius;
    unsigned vao, vbo;
    void *gpu;      /* Vulkan: the vertex buffer */
} seed_mesh;

/* A mesh placed in the world, as the effect's World parameter places it. */
typedef struct seed_object {
    const seed_mesh *mesh;
    float world[16];
} seed_object;

/* What the vertex shader outputs and the rasterizer interpolates at one pixel, in world space:
 * position (P * World), normal (n * upper 3x3 of World, interpolated, not renormalised), uv. */
typedef struct seed_surface {
    v3 pos, normal;
    double u, v;
    int front; /* 1 when the triangle faces the camera */
} seed_surface;

typedef rgba (*seed_shade_fn)(const seed_surface *s, const void *user);

/* A texture as the test built it, for the reference sampler. */
typedef struct seed_texture {
    int width, height;
    const unsigned char *texels; /* RGBA8, row 0 first (v = 0), as handed to glTexImage2D */
    unsigned gl;
    void *gpu;                   /* Vulkan: the image */
} seed_texture;

typedef enum { SEED_CLAMP, SEED_WRAP } seed_address;
typedef enum { SEED_BLEND_NONE, SEED_BLEND_ADD_AFTER_FIRST } seed_blend;

/* Context, GL functions, device. NULL only when OSMesa refuses (the device may be NULL:
 * seed_device says so and tests fail). */
seed_scene *seed_scene_create(int width, int height);
seed_scene *seed_scene_create_version(int width, int height, int major, int minor); /* another core GL */
void seed_scene_destroy(seed_scene *s);
hfx_device *seed_device(seed_scene *s);
int seed_width(const seed_scene *s);
int seed_height(const seed_scene *s);
void *seed_gl(seed_scene *s, const char *name); /* a GL entry point, for tests that set state */
/* Restores the XNA default application state (depth LessEqual, cull CCW, no blend) and clears. */
void seed_clear(seed_scene *s, rgba colour);
void seed_set_culling(seed_scene *s, int on);     /* the application's CullCounterClockwise, or none */

/* Problems met by the harness calls below (missing parameter, failed apply...), printed as
 * they happen; CHECK_SCENE fails the current test if any, and resets the count. */
int seed_take_errors(seed_scene *s);
#define CHECK_SCENE(s) CHECK_INT(seed_take_errors(s), 0)

/* Cameras. view and proj are XNA matrices; the probes unproject through them. */
void seed_camera(seed_scene *s, const float view[16], const float proj[16]);
const float *seed_view(const seed_scene *s);
const float *seed_projection(const seed_scene *s);
/* Orthographic, from (0, 10, 0) down onto the y = 0 plane, screen up = -z: the image covers
 * x in [-half, half] left to right and z in [-half, half] top to bottom. */
void seed_camera_top(seed_scene *s, double half);
/* Whether pixels sample where Direct3D 9 does (pixel centres on integer coordinates: the
 * half-pixel offset every XNA game sees) or where GL does (+0.5). Default: Direct3D 9. */
void seed_use_d3d9_pixel_centres(seed_scene *s, int on);

/* Meshes. */
/* A quad: corner o has texcoord (u0, v0); o + eu has (u1, v0); o + ev has (u0, v1). */
seed_mesh *seed_mesh_quad(seed_scene *s, v3 o, v3 eu, v3 ev, v3 normal, double u0, double v0, double u1, double v1);
/* The y = 0 plane from -half to half, normal +y, uv (0,0) at (-half, 0, -half) and (1,1) at (half, 0, half). */
seed_mesh *seed_mesh_floor(seed_scene *s, double half);
/* A UV sphere around the origin: u = longitude / 2pi, v = colatitude / pi. */
seed_mesh *seed_mesh_sphere(seed_scene *s, double radius, int slices, int stacks);
void seed_mesh_free(seed_scene *s, seed_mesh *m);
seed_object seed_object_at(const seed_mesh *m, const float world[16]); /* world NULL = identity */

/* Effects. */
hfx_effect *seed_load(seed_scene *s, const char *seed_file);  /* from the seed corpus; prints errors */
/* From now on seed_load compiles with hfxc, writes a .hfxo in memory and loads that (probes
 * are then recorded as "<file> via .hfxo"): the path of an application that ships .hfxo. */
void seed_use_hfxo(seed_scene *s, int on);
/* The shader target seed_load compiles for and loads; default HFX_TARGET_GLSL330. */
void seed_use_target(seed_scene *s, hfx_target target);
/* The shader target the scene draws with. */
hfx_target seed_target(const seed_scene *s);
/* Setters by name that note (and print) any failure: unknown name, wrong type or count. */
void seed_set_matrix(seed_scene *s, hfx_effect *fx, const char *name, const float m[16]);
void seed_set_float(seed_scene *s, hfx_effect *fx, const char *name, double v);
void seed_set_int(seed_scene *s, hfx_effect *fx, const char *name, int v);
void seed_set_bool(seed_scene *s, hfx_effect *fx, const char *name, int v);
void seed_set_v3(seed_scene *s, hfx_effect *fx, const char *name, v3 v);
void seed_set_rgba(seed_scene *s, hfx_effect *fx, const char *name, rgba c);
void seed_set_texture(seed_scene *s, hfx_effect *fx, const char *name, const seed_texture *t);
/* The same on a parameter handle (an element or a member). */
void seed_param_float(seed_scene *s, hfx_param *p, const char *what, double v);
void seed_param_int(seed_scene *s, hfx_param *p, const char *what, int v);
void seed_param_v3(seed_scene *s, hfx_param *p, const char *what, v3 v);
void seed_param_rgba(seed_scene *s, hfx_param *p, const char *what, rgba c);
/* params[index].member, noting a failure when either does not exist. */
hfx_param *seed_member(seed_scene *s, hfx_effect *fx, const char *array, size_t index, const char *member);
/* World, View, Projection under the given names (the seeds spell them World or world). */
void seed_set_transforms(seed_scene *s, hfx_effect *fx, const char *world, const char *view,
                         const char *projection, const float world_m[16]);
/* Draws the mesh with every pass of the technique (NULL: the current one), binding the
 * mesh's attributes where each pass wants POSITION0, NORMAL0, TEXCOORD0. Returns the number
 * of passes drawn. */
int seed_draw(seed_scene *s, hfx_effect *fx, const char *technique, const seed_mesh *m, seed_blend blend);

/* Textures: RGBA8, one level (GL_TEXTURE_MAX_LEVEL 0, like an XNA Texture2D without mipmaps). */
seed_texture seed_texture_make(seed_scene *s, int width, int height, const unsigned char *texels);
void seed_texture_free(seed_scene *s, seed_texture *t);
/* A 4 x 4 pattern whose neighbouring texels (across the wrap too) differ by at most 40 steps,
 * so a half-pixel shift moves no probe by more than a step, while texels 0 and 3 differ. */
void seed_smooth_texels(unsigned char texels[4 * 4 * 4]);
/* The bilinear filter of D3D9 LINEAR / GL_LINEAR at (u, v), level 0, texels as unorm8. */
rgba seed_texture_sample(const seed_texture *t, double u, double v, seed_address address);

/* Probes. Pixel (x, y) counts from the top left of the image. */
/* The first object the pixel's ray hits, or -1; *out gets the surface there. */
int seed_pick(seed_scene *s, const seed_object *objects, int n, int x, int y, seed_surface *out);
/* The same at a point (dx, dy) pixels away from pixel (x, y)'s sample point. */
int seed_pick_offset(seed_scene *s, const seed_object *objects, int n, int x, int y, double dx, double dy,
                     seed_surface *out);
/* The object under pixel (x, y) when a tenth of a pixel around the sample point sees the same
 * one; -2 when not (a silhouette or an edge passes right by the sample point), else as seed_pick. */
int seed_pick_certain(seed_scene *s, const seed_object *objects, int n, int x, int y, seed_surface *out);
/* Compares the pixel with an expected colour (clamped to [0,1] as the framebuffer does),
 * prints both and the difference, records the difference under `file`, returns it in 1/255
 * steps (the largest over the four channels). */
double seed_expect(seed_scene *s, const char *file, const char *label, int x, int y, rgba expected);
/* Picks the object under the pixel, shades it with the reference and compares (as
 * seed_expect). On a failure, notes whether the other pixel-centre convention's sample point
 * would have matched. Returns the difference, or 999 when the ray misses the object (a test
 * design error). */
double seed_probe(seed_scene *s, const char *file, const char *label, const seed_object *obj, int x, int y,
                  seed_shade_fn shade, const void *user);
/* The pixel as read back, in [0,1]. */
rgba seed_pixel(seed_scene *s, int x, int y);
/* The pixel whose sample point lies nearest to the world point (for choosing probes). */
void seed_pixel_of(const seed_scene *s, v3 world, int *x, int *y);
/* Writes the image to $HFX_BUILD_DIR/seed-images/<name>.png (or /tmp) for a look at failures. */
void seed_save_png(seed_scene *s, const char *name);

/* Prints "seed-acceptance: <file> probes N max D/255" for every file probed. */
void seed_report(const seed_scene *s);

#define CHECK_PROBE(expr) do { double d_ = (expr); if (!(d_ >= 0 && d_ <= SEED_TOLERANCE)) { \
    fprintf(stderr, "%s:%d: probe off by %.2f/255 (tolerance %.0f): %s\n", __FILE__, __LINE__, d_, \
            SEED_TOLERANCE, #expr); test_current_failed_ = 1; test_checks_failed_++; } } while (0)

#endif
