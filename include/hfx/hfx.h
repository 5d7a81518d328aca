/* hfx.h: the hfx runtime. Load Direct3D 9 effects (.fx or .hfxo) and draw with them on OpenGL
 * or Vulkan, the way XNA's Effect drives Direct3D. Every handle is opaque; every call that can
 * fail returns HFX_OK (0) or an error code, and hfx_device_last_error() says why. No global
 * state: everything hangs off an hfx_device, one per OpenGL context (hfx_device_create_gl) or
 * Vulkan device (hfx_vulkan.h's hfx_device_create_vulkan). The effect, parameter, technique and pass
 * calls here are the same on both; a few are one back end's (hfx_device_sync, the program cache
 * and texture names are OpenGL's; Vulkan applies a pass with hfx_pass_apply_vk, which records
 * into a command buffer). */
#ifndef HFX_HFX_H
#define HFX_HFX_H

#include <stddef.h>

#include "hfx/hfx_export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hfx_device hfx_device;
typedef struct hfx_effect hfx_effect;
typedef struct hfx_param hfx_param;
typedef struct hfx_technique hfx_technique;
typedef struct hfx_pass hfx_pass;
typedef struct hfx_annotation hfx_annotation;
typedef struct hfx_pool hfx_pool;

/* Return codes. */
enum {
    HFX_OK = 0,
    HFX_ERR_NULL = -1,      /* a NULL handle or pointer */
    HFX_ERR_TYPE = -2,      /* wrong type for this parameter */
    HFX_ERR_COUNT = -3,     /* wrong number of values */
    HFX_ERR_NOT_FOUND = -4, /* unknown name or index */
    HFX_ERR_GL = -5,        /* OpenGL refused (compile, link, missing entry point) */
    HFX_ERR_LOAD = -6,      /* the effect did not compile or the file is not valid */
    HFX_ERR_MEMORY = -7,
    HFX_ERR_VULKAN = -8,    /* Vulkan refused (a failed call, a missing feature or format) */
    HFX_ERR_STATE = -9      /* a call out of order: hfx_effect_begin twice, hfx_effect_end without begin */
};

/* What a return code means, in a few words ("a call out of order"); "unknown result" for none. */
HFX_API const char *hfx_result_string(int code);

/* Parameter classes and types: XNA's EffectParameterClass / EffectParameterType (D3DX's). */
typedef enum {
    HFX_CLASS_SCALAR, HFX_CLASS_VECTOR, HFX_CLASS_MATRIX, HFX_CLASS_OBJECT, HFX_CLASS_STRUCT
} hfx_param_class;

typedef enum {
    HFX_TYPE_VOID, HFX_TYPE_BOOL, HFX_TYPE_INT, HFX_TYPE_FLOAT, HFX_TYPE_STRING,
    HFX_TYPE_TEXTURE, HFX_TYPE_TEXTURE1D, HFX_TYPE_TEXTURE2D, HFX_TYPE_TEXTURE3D, HFX_TYPE_TEXTURECUBE,
    HFX_TYPE_SAMPLER, HFX_TYPE_SAMPLER1D, HFX_TYPE_SAMPLER2D, HFX_TYPE_SAMPLER3D, HFX_TYPE_SAMPLERCUBE,
    HFX_TYPE_PIXELSHADER, HFX_TYPE_VERTEXSHADER
} hfx_param_type;

/* Shader languages a compiled effect may carry. */
typedef enum {
    HFX_TARGET_GLSL330, HFX_TARGET_GLSLES300, HFX_TARGET_GLSL110, HFX_TARGET_SPIRV,
    HFX_TARGET_SPIRV_VK, /* SPIR-V for Vulkan: uniforms in blocks, descriptor sets and bindings */
    HFX_TARGET_COUNT
} hfx_target;

typedef void *(*hfx_gl_loader)(const char *name); /* glfwGetProcAddress, OSMesaGetProcAddress... */

typedef struct hfx_load_options {
    const char *const *defines;      /* "NAME" or "NAME=VALUE", like fxc /D */
    size_t define_count;
    const char *const *include_dirs; /* searched after the including file's folder and the root's */
    size_t include_dir_count;
    hfx_target target;               /* GLSL flavour to use; 0 = GLSL 330 */
    int separate_uniforms;           /* .fx only: 1 = one GLSL uniform per parameter; 0 = float parameters
                                        packed in vec4 registers, sent in one call per Apply (default) */
    int no_self_check;               /* .fx only: 1 = skip glslang's check of the emitted GLSL (faster loads) */
    int no_preshaders;               /* .fx only: 1 = parameter-only work stays in the shaders (by default it
                                        runs on the CPU once per change, as fxc's preshaders) */
    hfx_pool *pool;                  /* NULL, or the pool whose `shared` parameters the effect shares */
} hfx_load_options;

/* Device: one per GL context, which must be current on every call (Vulkan: hfx_vulkan.h). */
HFX_API hfx_device *hfx_device_create_gl(hfx_gl_loader load);            /* loads its own GL function table */
HFX_API void hfx_device_destroy(hfx_device *dev);                        /* effects must be destroyed first */
HFX_API const char *hfx_device_last_error(const hfx_device *dev);        /* message of the last failed call */
/* glViewport, remembered for D3D9's pixel centres (hfx_pos_fixup); hfx_effect_begin also reads it. */
HFX_API void hfx_device_set_viewport(hfx_device *dev, int x, int y, int width, int height);
HFX_API void hfx_device_sync(hfx_device *dev);  /* re-read GL state the application changed behind hfx's back */
/* Keeps linked programs' driver binaries in folder dir (which must exist) and reads them back on
 * later loads, skipping GLSL compilation; NULL turns it off. Entries are checked (driver, hash,
 * CRC) and rebuilt when they do not match. Without GL_ARB_get_program_binary it does nothing. */
HFX_API int hfx_device_set_program_cache(hfx_device *dev, const char *dir);
/* A texture hfx has bound got new mip levels, or its name a new texture: check its levels at the next bind. */
HFX_API void hfx_device_texture_changed(hfx_device *dev, unsigned int texture);
HFX_API void hfx_free(void *p);                                          /* frees strings hfx hands out */

/* Effect pools (D3DX's ID3DXEffectPool): effects loaded with the same hfx_load_options.pool
 * share every top-level parameter declared `shared`, by name: a value set through any of them is
 * seen by all and reaches each program when it next applies. An effect joining takes the pool's
 * value; the same shared name with another type (or struct layout) fails the load with both
 * declarations' positions (X9003). Clones and reloads stay in the pool. */
HFX_API hfx_pool *hfx_pool_create(hfx_device *dev);
HFX_API void hfx_pool_destroy(hfx_pool *pool);                           /* effects still in it carry on unpooled */
HFX_API hfx_device *hfx_pool_device(const hfx_pool *pool);

/* Effects. */
HFX_API hfx_effect *hfx_effect_load(hfx_device *dev, const char *path, const hfx_load_options *opt, char **errors);
HFX_API hfx_effect *hfx_effect_load_memory(hfx_device *dev, const void *data, size_t size, const char *name,
                                   const hfx_load_options *opt, char **errors);
HFX_API hfx_effect *hfx_effect_clone(const hfx_effect *fx);              /* same code, independent values */
HFX_API void hfx_effect_destroy(hfx_effect *fx);
HFX_API hfx_device *hfx_effect_device(const hfx_effect *fx);              /* Effect.GraphicsDevice */
HFX_API const char *hfx_effect_warnings(const hfx_effect *fx);           /* load-time notes (unsupported states) or "" */
/* Begin saves the state the effect's passes change (GL: syncs, then saves the GL state they touch;
 * Vulkan: the render states), End restores it. Begin twice, or End without Begin: HFX_ERR_STATE. */
HFX_API int hfx_effect_begin(hfx_effect *fx);
HFX_API int hfx_effect_end(hfx_effect *fx);
/* Compiles the effect again (from path, or the file it was loaded from when path is NULL) and, on
 * success, replaces its code in place: parameters whose name, class, type, rows, columns, elements
 * (and member names, for structs) are unchanged keep their values and textures; the current
 * technique is kept by name. On failure nothing changes and errors (may be NULL; hfx_free) says why.
 * Parameter, technique, pass and annotation handles taken before a successful reload are invalid. */
HFX_API int hfx_effect_reload(hfx_effect *fx, const char *path, const hfx_load_options *opt, char **errors);
/* The files the effect was loaded from: a .fx and every file it included (paths as the compiler
 * opened them), or the .hfxo; from memory, only what it included. *count gets their number. */
HFX_API const char *const *hfx_effect_dependencies(const hfx_effect *fx, size_t *count);
/* Cheap enough for every frame (one stat per dependency, no allocation): when a dependency's
 * modification time or size changed since the last load or check, hfx_effect_reload from the
 * file it was loaded from. Returns 1 reloaded, 0 nothing changed, or hfx_effect_reload's error
 * (the old effect stays; the same files are not tried again until they change again). */
HFX_API int hfx_effect_reload_if_changed(hfx_effect *fx, const hfx_load_options *opt, char **errors);

/* What hfx_effect_bind_scene fills parameters from. Matrices in XNA order (row-major, row
 * vectors, translation in m[12..14]), projection Direct3D style. */
typedef struct hfx_scene {
    float world[16], view[16], projection[16];
    float time, elapsed_time;               /* seconds: Time, ElapsedTime */
    float viewport_width, viewport_height;  /* pixels: ViewportPixelSize */
} hfx_scene;

/* FX Composer / DirectX SAS binding: every float parameter whose semantic (case-insensitive) is
 * World, View, Projection, WorldView, ViewProjection or WorldViewProjection (also WorldViewProj,
 * ViewProj), each plain or with Inverse, Transpose or InverseTranspose after it, takes that
 * matrix (a float3x3 or 4x3 its upper-left block); CameraPosition / ViewPosition / EyePosition
 * the camera (ViewInverse's translation, w = 1); Time, ElapsedTime, ViewportPixelSize (and
 * ViewportSize) the scene's. Each matrix is computed at most once per call, and a parameter
 * whose value is unchanged is not set (Apply then sends nothing). A parameter whose `Object`
 * annotation names something other than a camera ("SpotLight0"), or that has a
 * `SasBindAddress`, is not the scene's and is left alone. Returns how many parameters the
 * effect binds, or an error code. */
HFX_API int hfx_effect_bind_scene(hfx_effect *fx, const hfx_scene *scene);
HFX_API int hfx_scene_semantic_known(const char *semantic); /* 1 when hfx_effect_bind_scene fills this semantic */

/* Parameters: Parameters["name"], Elements[i], StructureMembers["name"]. */
HFX_API hfx_param *hfx_effect_param(hfx_effect *fx, const char *name);
HFX_API hfx_param *hfx_effect_param_by_semantic(hfx_effect *fx, const char *semantic); /* case-insensitive */
HFX_API size_t hfx_effect_param_count(const hfx_effect *fx);
HFX_API hfx_param *hfx_effect_param_at(hfx_effect *fx, size_t i);
HFX_API hfx_param *hfx_param_member(hfx_param *p, const char *name);
HFX_API hfx_param *hfx_param_member_at(hfx_param *p, size_t i);
HFX_API hfx_param *hfx_param_element(hfx_param *p, size_t i);
HFX_API const char *hfx_param_name(const hfx_param *p);
HFX_API const char *hfx_param_semantic(const hfx_param *p);            /* "" when none */
HFX_API hfx_param_class hfx_param_get_class(const hfx_param *p);
HFX_API hfx_param_type hfx_param_get_type(const hfx_param *p);
HFX_API size_t hfx_param_rows(const hfx_param *p);
HFX_API size_t hfx_param_columns(const hfx_param *p);
HFX_API size_t hfx_param_elements(const hfx_param *p);                 /* array length; 0 when not an array */
HFX_API size_t hfx_param_member_count(const hfx_param *p);

HFX_API int hfx_param_set_bool(hfx_param *p, int v);
HFX_API int hfx_param_set_int(hfx_param *p, int v);
HFX_API int hfx_param_set_float(hfx_param *p, float v);
HFX_API int hfx_param_set_floats(hfx_param *p, const float *v, size_t count); /* vectors, arrays, matrices as stored */
HFX_API int hfx_param_set_ints(hfx_param *p, const int *v, size_t count);
HFX_API int hfx_param_set_matrix(hfx_param *p, const float m[16]);           /* XNA order: row-major, translation in m[12..14] */
HFX_API int hfx_param_set_matrix_transpose(hfx_param *p, const float m[16]);
HFX_API int hfx_param_set_texture(hfx_param *p, unsigned int gl_texture);    /* target from the parameter's type */
HFX_API int hfx_param_get_bool(const hfx_param *p, int *out);
HFX_API int hfx_param_get_int(const hfx_param *p, int *out);
HFX_API int hfx_param_get_float(const hfx_param *p, float *out);
HFX_API int hfx_param_get_floats(const hfx_param *p, float *out, size_t count);
HFX_API int hfx_param_get_ints(const hfx_param *p, int *out, size_t count);
HFX_API int hfx_param_get_matrix(const hfx_param *p, float out[16]);
/* GL_TEXTURE_2D, _3D or _CUBE_MAP: where the passes bind this texture (a plain `texture` takes
 * its samplers' dimension); 0 when no pass samples it or it is not a texture. */
HFX_API unsigned int hfx_param_texture_target(const hfx_param *p);
HFX_API int hfx_param_get_texture(const hfx_param *p, unsigned int *out);

/* Techniques and passes. */
HFX_API hfx_technique *hfx_effect_technique(hfx_effect *fx, const char *name);
HFX_API hfx_technique *hfx_effect_technique_at(hfx_effect *fx, size_t i);
HFX_API size_t hfx_effect_technique_count(const hfx_effect *fx);
HFX_API void hfx_effect_set_current_technique(hfx_effect *fx, hfx_technique *t);
HFX_API hfx_technique *hfx_effect_current_technique(hfx_effect *fx);
HFX_API const char *hfx_technique_name(const hfx_technique *t);
HFX_API size_t hfx_technique_pass_count(const hfx_technique *t);
HFX_API hfx_pass *hfx_technique_pass(hfx_technique *t, size_t i);
HFX_API hfx_pass *hfx_technique_pass_by_name(hfx_technique *t, const char *name);
HFX_API const char *hfx_pass_name(const hfx_pass *p);
HFX_API int hfx_pass_apply(hfx_pass *p);                                       /* Passes[i].Apply() (GL; Vulkan: hfx_pass_apply_vk) */
HFX_API int hfx_pass_attribute_location(const hfx_pass *p, const char *semantic); /* "POSITION0" -> 0; -1 if unused */

/* Annotations on parameters, techniques and passes. */
HFX_API hfx_annotation *hfx_param_annotation(hfx_param *p, const char *name);
HFX_API hfx_annotation *hfx_technique_annotation(hfx_technique *t, const char *name);
HFX_API hfx_annotation *hfx_pass_annotation(hfx_pass *p, const char *name);
HFX_API size_t hfx_param_annotation_count(const hfx_param *p);
HFX_API hfx_annotation *hfx_param_annotation_at(hfx_param *p, size_t i);
HFX_API const char *hfx_annotation_name(const hfx_annotation *a);
HFX_API hfx_param_type hfx_annotation_type(const hfx_annotation *a);
HFX_API const char *hfx_annotation_string(const hfx_annotation *a);            /* NULL unless a string */
HFX_API int hfx_annotation_float(const hfx_annotation *a, float *out);         /* first component, converted */
HFX_API int hfx_annotation_floats(const hfx_annotation *a, float *out, size_t count);
HFX_API int hfx_annotation_int(const hfx_annotation *a, int *out);

#ifdef __cplusplus
}
#endif
#endif
