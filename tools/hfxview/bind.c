/* bind.c: automatic parameter values (see bind.h). */
#include "bind_internal.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define PI HV_PI

float hv_scene_far(hv_vec3 eye, hv_vec3 at) {
    float d = hv_vec3_length(hv_vec3_sub(eye, at));
    return d > 0.25f ? 4.0f * d : 1.0f;
}

float hv_scene_near(hv_vec3 eye, hv_vec3 at) {
    float d = hv_vec3_length(hv_vec3_sub(eye, at)), n = 0.25f * d;
    if (n > 0.5f * (d - 1.0f)) n = 0.5f * (d - 1.0f); /* half way to the unit sphere's nearest point */
    return n > 0.1f ? n : 0.1f;
}

void hv_scene_from_options(hv_scene *s, const hv_options *o) {
    memset(s, 0, sizeof *s);
    hv_mat4_rotation_y(s->world, o->yaw_degrees * PI / 180.0f);
    hv_mat4_look_at_rh(s->view, o->eye, o->at, o->up);
    s->width = o->width;
    s->height = o->height;
    s->znear = hv_scene_near(o->eye, o->at);
    s->zfar = hv_scene_far(o->eye, o->at);
    hv_mat4_perspective_fov_rh(s->projection, o->fov_degrees * PI / 180.0f, (float)o->width / (float)o->height,
                               s->znear, s->zfar);
    s->eye = o->eye;
    s->at = o->at;
    s->light_position = o->light_position;
    s->light_direction = hv_vec3_normalize(o->light_direction_given ? o->light_direction
                                                                    : hv_vec3_sub(o->at, o->light_position));
    memcpy(s->light_color, o->light_color, sizeof s->light_color);
    s->light_given = o->light_given;
    s->time = HV_HEADLESS_TIME_SECONDS;
    s->elapsed_time = 1.0f / 60.0f;
}

void hv_lower_copy(char *out, size_t cap, const char *in) {
    size_t i = 0;
    for (; in[i] && i + 1 < cap; i++) out[i] = (char)tolower((unsigned char)in[i]);
    out[i] = '\0';
}

static int ends_with(const char *s, const char *suffix) {
    size_t n = strlen(s), k = strlen(suffix);
    return n > k && !strcmp(s + n - k, suffix);
}

/* "g_mWorldViewProj", "matWorld", "WorldITXf", "worldMatrix", "xWorld", "_world", "fxWVP" ->
 * "worldviewproj", "world", "worldit", "world", "world", "world", "wvp": the decorations of the
 * DirectX SDK, NVIDIA and XNA samples, Riemer's XNA tutorials (and the books after them), and
 * engines that mark private members with an underscore. */
static void matrix_stem(char *out, size_t cap, const char *name) {
    while (*name == '_') name++;
    if (!strncmp(name, "g_", 2)) name += 2;
    if (!strncmp(name, "m_", 2)) name += 2;
    if (!strncasecmp(name, "mat", 3) && isupper((unsigned char)name[3])) name += 3; /* matView, MatView */
    else if (!strncmp(name, "fx", 2) && isupper((unsigned char)name[2])) name += 2;
    else if ((name[0] == 'm' || name[0] == 'x') && isupper((unsigned char)name[1])) name++;
    hv_lower_copy(out, cap, name);
    static const char *const suffixes[] = {"matrix", "mat", "xf", "_"};
    for (size_t i = 0; i < sizeof suffixes / sizeof suffixes[0]; i++)
        if (ends_with(out, suffixes[i])) out[strlen(out) - strlen(suffixes[i])] = '\0';
}

enum { M_WORLD, M_VIEW, M_PROJ, M_WORLDVIEW, M_VIEWPROJ, M_WVP };
enum { F_PLAIN, F_INVERSE, F_TRANSPOSE, F_INVERSE_TRANSPOSE };

static const struct { const char *stem; int kind; } matrix_bases[] = {
    {"worldviewprojection", M_WVP}, {"worldviewproj", M_WVP}, {"modelviewprojection", M_WVP}, {"wvp", M_WVP},
    {"mvp", M_WVP}, {"worldview", M_WORLDVIEW}, {"modelview", M_WORLDVIEW}, {"wv", M_WORLDVIEW},
    {"viewprojection", M_VIEWPROJ}, {"viewproj", M_VIEWPROJ}, {"vp", M_VIEWPROJ}, {"world", M_WORLD},
    {"model", M_WORLD}, {"object", M_WORLD}, {"view", M_VIEW}, {"projection", M_PROJ}, {"proj", M_PROJ},
};

static const struct { const char *text; int form; } matrix_forms[] = {
    {"", F_PLAIN}, {"inverse", F_INVERSE}, {"inv", F_INVERSE}, {"i", F_INVERSE}, {"transpose", F_TRANSPOSE},
    {"t", F_TRANSPOSE}, {"inversetranspose", F_INVERSE_TRANSPOSE}, {"invtranspose", F_INVERSE_TRANSPOSE},
    {"invtrans", F_INVERSE_TRANSPOSE}, {"it", F_INVERSE_TRANSPOSE},
};

static void base_matrix(const hv_scene *s, int kind, float out[16]) {
    switch (kind) {
    case M_WORLD: memcpy(out, s->world, 16 * sizeof *out); break;
    case M_VIEW: memcpy(out, s->view, 16 * sizeof *out); break;
    case M_PROJ: memcpy(out, s->projection, 16 * sizeof *out); break;
    case M_WORLDVIEW: hv_mat4_mul(out, s->world, s->view); break;
    case M_VIEWPROJ: hv_mat4_mul(out, s->view, s->projection); break;
    default:
        hv_mat4_mul(out, s->world, s->view);
        hv_mat4_mul(out, out, s->projection);
        break;
    }
}

/* The kind (M_*) and form (F_*) a name or semantic asks for; 0 when it names no scene matrix. */
static int matrix_kind(const char *name, int is_semantic, int *kind, int *form) {
    char stem[128];
    if (is_semantic) hv_lower_copy(stem, sizeof stem, name);
    else matrix_stem(stem, sizeof stem, name);
    for (size_t b = 0; b < sizeof matrix_bases / sizeof matrix_bases[0]; b++) {
        size_t n = strlen(matrix_bases[b].stem);
        if (strncmp(stem, matrix_bases[b].stem, n)) continue;
        for (size_t f = 0; f < sizeof matrix_forms / sizeof matrix_forms[0]; f++) {
            if (strcmp(stem + n, matrix_forms[f].text)) continue;
            *kind = matrix_bases[b].kind;
            *form = matrix_forms[f].form;
            return 1;
        }
    }
    return 0;
}

int hv_scene_matrix(const hv_scene *s, const char *name, int is_semantic, float out[16]) {
    int kind, form;
    if (!matrix_kind(name, is_semantic, &kind, &form)) return 0;
    base_matrix(s, kind, out);
    if (form == F_INVERSE || form == F_INVERSE_TRANSPOSE) hv_mat4_invert(out, out);
    if (form == F_TRANSPOSE || form == F_INVERSE_TRANSPOSE) hv_mat4_transpose(out, out);
    return 1;
}

/* The kind of scene matrix parameter p is, by semantic then name; -1 for none. */
static int param_matrix_kind(hfx_param *p) {
    int kind, form;
    const char *sem = hfx_param_semantic(p);
    if (hfx_param_get_class(p) != HFX_CLASS_MATRIX || hfx_param_elements(p)) return -1;
    if (sem && *sem && matrix_kind(sem, 1, &kind, &form)) return kind;
    return matrix_kind(hfx_param_name(p), 0, &kind, &form) ? kind : -1;
}

/* ---- values already there ---------------------------------------------------------------- */

static size_t param_words(const hfx_param *p) {
    size_t n = hfx_param_rows(p) * hfx_param_columns(p);
    return hfx_param_elements(p) ? n * hfx_param_elements(p) : n;
}

/* True when a numeric parameter holds only zeros: it had no initializer worth keeping. */
int hv_param_is_zero(const hfx_param *p) {
    size_t n = param_words(p);
    if (n == 0 || n > 4096) return 0;
    union { float f[4096]; int i[4096]; } v;
    int is_float = hfx_param_get_type(p) == HFX_TYPE_FLOAT;
    if ((is_float ? hfx_param_get_floats(p, v.f, n) : hfx_param_get_ints(p, v.i, n)) != HFX_OK) return 0;
    for (size_t k = 0; k < n; k++)
        if (is_float ? v.f[k] != 0.0f : v.i[k] != 0) return 0;
    return 1;
}

/* Sets a float scalar or vector from up to 4 values, padding with the last of `pad`. */
int hv_set_vector(hfx_param *p, const float *v, size_t n, float pad) {
    size_t want = hfx_param_rows(p) * hfx_param_columns(p);
    float buf[16];
    if (hfx_param_get_type(p) != HFX_TYPE_FLOAT || want == 0 || want > 4) return 0;
    for (size_t i = 0; i < want; i++) buf[i] = i < n ? v[i] : pad;
    return hfx_param_set_floats(p, buf, want) == HFX_OK;
}

int hv_set_scalar_default(hfx_param *p, float v) {
    if (!hv_param_is_zero(p)) return 0;
    if (hfx_param_get_type(p) == HFX_TYPE_FLOAT) return hv_set_vector(p, &v, 1, v);
    if (hfx_param_get_type(p) == HFX_TYPE_INT) return hfx_param_set_int(p, (int)v) == HFX_OK;
    if (hfx_param_get_type(p) == HFX_TYPE_BOOL) return hfx_param_set_bool(p, v != 0) == HFX_OK;
    return 0;
}

int hv_set_matrix_param(hfx_param *p, const float m[16]) {
    size_t rows = hfx_param_rows(p), cols = hfx_param_columns(p);
    if (hfx_param_get_class(p) != HFX_CLASS_MATRIX || hfx_param_get_type(p) != HFX_TYPE_FLOAT) return 0;
    if (rows == 4 && cols == 4) return hfx_param_set_matrix(p, m) == HFX_OK;
    float sub[16]; /* float3x3 WorldIT and the like: the upper-left block */
    for (size_t r = 0; r < rows && r < 4; r++)
        for (size_t c = 0; c < cols && c < 4; c++) sub[r * cols + c] = m[r * 4 + c];
    return hfx_param_set_floats(p, sub, rows * cols) == HFX_OK;
}

/* Identity in every element of an all-zero matrix array: a bone palette (Bones[], MatrixPalette)
 * or instance transforms the application would fill; zeros collapse every vertex to a point. */
int hv_set_identity_palette(hfx_param *p) {
    size_t n = hfx_param_elements(p), set = 0;
    float id[16];
    hv_mat4_identity(id);
    if (!n || !hv_param_is_zero(p)) return 0;
    for (size_t k = 0; k < n; k++) set += hv_set_matrix_param(hfx_param_element(p, k), id);
    return set == n;
}

void hv_light_scene(const hv_scene *s, hv_scene *light) {
    *light = *s;
    hv_vec3 d = hv_vec3_normalize(hv_vec3_sub(s->at, s->light_position));
    hv_vec3 up = fabsf(d.y) > 0.99f ? hv_vec3_make(0, 0, 1) : hv_vec3_make(0, 1, 0);
    hv_mat4_look_at_rh(light->view, s->light_position, s->at, up);
    light->znear = hv_scene_near(s->light_position, s->at);
    light->zfar = hv_scene_far(s->light_position, s->at);
    hv_mat4_perspective_fov_rh(light->projection, 60.0f * PI / 180.0f, 1.0f, light->znear, light->zfar);
    light->eye = s->light_position;
}

/* SpriteBatch's projection (XNA, FNA): x 0..width to -1..1, y 0..height to 1..-1, moved half a
 * pixel up and left as on Direct3D 9 (FNA's half-pixel offset), so pixel (0, 0)'s centre is
 * the sprite's texel (0, 0) centre and the rectangle's edges fall between pixel centres. */
static void pixel_projection(const hv_scene *s, float m[16]) {
    memset(m, 0, 16 * sizeof *m);
    m[0] = 2.0f / (float)s->width;
    m[5] = -2.0f / (float)s->height;
    m[10] = -1.0f;
    m[12] = -1.0f - 1.0f / (float)s->width;
    m[13] = 1.0f + 1.0f / (float)s->height;
    m[15] = 1.0f;
}

static int is_pixel_transform(const hfx_param *p) {
    char stem[64];
    hv_name_stem(stem, sizeof stem, hfx_param_name(p));
    return hfx_param_get_class(p) == HFX_CLASS_MATRIX && hfx_param_elements(p) == 0 &&
           (!strcmp(stem, "matrixtransform") || !strcmp(stem, "spritetransform") || !strcmp(stem, "transformmatrix"));
}

/* The size in pixels of what is drawn into: SAS's ViewportPixelSize, DigitalRise's
 * VIEWPORTSIZE, ViewportSize and TargetSize (its filters read SourceSize, the same picture),
 * and engines' ScreenSize, ScreenResolution, RenderTargetSize; a two-component Viewport
 * (UltimaXNA's half-pixel offset). A lower-case name. */
static int is_viewport_size(const char *lower, const hfx_param *p) {
    static const char *const names[] = {"viewportpixelsize", "viewportsize", "targetsize", "sourcesize", "screensize",
                                        "screenresolution", "resolution", "rendertargetsize"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++)
        if (!strcmp(lower, names[i])) return 1;
    return !strcmp(lower, "viewport") && hfx_param_rows(p) * hfx_param_columns(p) == 2;
}

/* Half the viewport's size, as effects that map pixels with (p - half) / half take it: MomoXna's
 * gViewHalfDim : VIEWPORT_HALF_DIMENSION, a ViewportHalfSize, HalfScreenSize. */
static int is_half_viewport(hfx_param *p) {
    char stem[64];
    const char *sem = hfx_param_semantic(p);
    hfx_param_class k = hfx_param_get_class(p);
    if ((k != HFX_CLASS_SCALAR && k != HFX_CLASS_VECTOR) || hfx_param_rows(p) * hfx_param_columns(p) != 2) return 0;
    for (int i = 0; i < 2; i++) {
        hv_name_stem(stem, sizeof stem, i ? hfx_param_name(p) : sem ? sem : "");
        if (strstr(stem, "half") && (strstr(stem, "view") || strstr(stem, "screen"))) return 1;
    }
    return 0;
}

/* DigitalRise's post-processing: a viewport or target size (by name or VIEWPORTSIZE) and no
 * matrix but a projection (read to rebuild depth), so the vertex shader maps pixels itself. */
static int is_viewport_size_param(hfx_param *p) {
    char low[64];
    const char *sem = hfx_param_semantic(p);
    hv_lower_copy(low, sizeof low, hfx_param_name(p));
    /* Not ScreenResolution and its kin: XNA's post-processing samples read them in pixel
     * shaders drawn by SpriteBatch's own vertex shader, so their passes take clip space. */
    return !strcmp(low, "viewportsize") || !strcmp(low, "viewportpixelsize") || !strcmp(low, "targetsize") ||
           (sem && (!strcasecmp(sem, "ViewportSize") || !strcasecmp(sem, "ViewportPixelSize"))) || is_half_viewport(p);
}

/* What the whole effect says about its matrices. iex: it declares IEX's TransMatrix (see
 * iex_matrix). pixel_projection: it has a projection and no matrix that carries a view (View,
 * WorldView, ViewProjection, WorldViewProjection, by name or semantic), so its projection
 * cannot look at a mesh from a camera: it maps pixels, as UltimaXNA's isometric world's
 * ProjectionMatrix (an orthographic projection over the window) and SpriteBatch's do. */
typedef struct { int iex, pixel_projection; } effect_facts;

static effect_facts facts_of(hfx_effect *fx) {
    effect_facts f = {hfx_effect_param(fx, "TransMatrix") != NULL, 0};
    int projection = 0, view = 0;
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        int kind = param_matrix_kind(hfx_effect_param_at(fx, i));
        projection |= kind == M_PROJ;
        view |= kind == M_VIEW || kind == M_WORLDVIEW || kind == M_VIEWPROJ || kind == M_WVP;
    }
    f.pixel_projection = !f.iex && projection && !view;
    return f;
}

int hv_effect_wants_pixels(hfx_effect *fx) {
    int viewport = 0, matrices = 0;
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        if (is_pixel_transform(p)) return 1;
        viewport |= is_viewport_size_param(p);
        matrices |= hfx_param_get_class(p) == HFX_CLASS_MATRIX && param_matrix_kind(p) != M_PROJ; /* a projection alone places nothing */
    }
    return (viewport && !matrices) || facts_of(fx).pixel_projection;
}

/* ---- the whole effect -------------------------------------------------------------------- */

/* "LightViewProj", "gLightWVP", "ShadowViewProjection": the light's matrices. */
static int light_matrix(const hv_scene *s, const char *name, float m[16]) {
    char stem[128];
    hv_name_stem(stem, sizeof stem, name);
    const char *rest = !strncmp(stem, "light", 5) ? stem + 5 : !strncmp(stem, "shadow", 6) ? stem + 6 : NULL;
    if (!rest || !*rest) return 0;
    hv_scene light;
    hv_light_scene(s, &light);
    return hv_scene_matrix(&light, rest, 1, m);
}

/* IEX, the Japanese teaching engine (its effects write "float4x4 TransMatrix; // world" and
 * "float4x4 Projection; // World * View * Projection"), names the world TransMatrix and sets
 * the whole transform into Projection, keeping the plain one as matProjection: an effect
 * that declares TransMatrix follows it. */
static int iex_matrix(const hv_scene *s, const char *name, int iex, float m[16]) {
    hv_scene light;
    if (!iex) return 0;
    if (!strcmp(name, "TransMatrix")) return hv_scene_matrix(s, "World", 1, m);
    if (!strcmp(name, "Projection")) return hv_scene_matrix(s, "WorldViewProjection", 1, m);
    if (!strcmp(name, "ShadowProjection")) { /* the light's View * Projection (the shader multiplies TransMatrix first) */
        hv_light_scene(s, &light);
        return hv_scene_matrix(&light, "ViewProjection", 1, m);
    }
    return 0;
}

/* Matrices: by semantic, then name, SpriteBatch's, the light's; any other one, and every
 * matrix array, the identity when the effect left it at zero. */
static const char *bind_matrix(hfx_param *p, const hv_scene *s, int view_only, const effect_facts *f, int *set) {
    float m[16];
    const char *sem = hfx_param_semantic(p), *name = hfx_param_name(p);
    if (f->pixel_projection && param_matrix_kind(p) == M_PROJ) {
        pixel_projection(s, m);
        return *set = hv_set_matrix_param(p, m), "name: a projection with no view: pixels, as SpriteBatch's";
    }
    if (iex_matrix(s, name, f->iex, m)) return *set = hv_set_matrix_param(p, m), "name: IEX's matrices (TransMatrix the world, Projection the whole transform)";
    if (hfx_param_elements(p)) {
        if (view_only) return NULL;
        *set = hv_set_identity_palette(p);
        return *set ? "identity in every element (a bone or instance palette)" : NULL;
    }
    if (sem && *sem && hv_scene_matrix(s, sem, 1, m)) return *set = hv_set_matrix_param(p, m), "semantic: the scene's matrix";
    if (hv_scene_matrix(s, name, 0, m)) return *set = hv_set_matrix_param(p, m), "name: the scene's matrix";
    if (is_pixel_transform(p)) {
        pixel_projection(s, m);
        return *set = hv_set_matrix_param(p, m), "name: SpriteBatch's pixel projection";
    }
    if (light_matrix(s, name, m)) return *set = hv_set_matrix_param(p, m), "name: the light's matrix";
    if (view_only || !hv_param_is_zero(p)) return NULL;
    hv_mat4_identity(m);
    *set = hv_set_matrix_param(p, m);
    return "identity (no convention names it)";
}

static const char *bind_one(hfx_param *p, const hv_scene *s, int view_only, const effect_facts *f, int *set) {
    const char *sem = hfx_param_semantic(p), *how;
    char low[64];
    *set = 0;
    if (sem && *sem && hfx_scene_semantic_known(sem) && !hfx_param_annotation(p, "Object") &&
        !hfx_param_annotation(p, "SasBindAddress"))
        return "SAS semantic";
    if ((how = hv_bind_by_annotation(p, s, view_only, set))) return how;
    hfx_param_class k = hfx_param_get_class(p);
    if (k == HFX_CLASS_MATRIX && hfx_param_get_type(p) == HFX_TYPE_FLOAT) return bind_matrix(p, s, view_only, f, set);
    hv_lower_copy(low, sizeof low, hfx_param_name(p));
    if (is_half_viewport(p)) {
        float half[2] = {0.5f * (float)s->width, 0.5f * (float)s->height};
        return *set = hv_set_vector(p, half, 2, 0), "name: half the viewport size";
    }
    if ((k == HFX_CLASS_SCALAR || k == HFX_CLASS_VECTOR) && is_viewport_size(low, p)) {
        float wh[2] = {(float)s->width, (float)s->height};
        return *set = hv_set_vector(p, wh, 2, 0), "name: the viewport size";
    }
    return hv_bind_by_name(p, s, view_only, set);
}

/* The standard SAS semantics go through the runtime (hfx_effect_bind_scene). */
static int bind_semantics(hfx_effect *fx, const hv_scene *s) {
    hfx_scene scene;
    memset(&scene, 0, sizeof scene);
    memcpy(scene.world, s->world, sizeof scene.world);
    memcpy(scene.view, s->view, sizeof scene.view);
    memcpy(scene.projection, s->projection, sizeof scene.projection);
    scene.viewport_width = (float)s->width;
    scene.viewport_height = (float)s->height;
    scene.time = s->time;
    scene.elapsed_time = s->elapsed_time;
    int n = hfx_effect_bind_scene(fx, &scene);
    return n > 0 ? n : 0;
}

static int bind_all(hfx_effect *fx, const hv_scene *s, int view_only, const char **how, size_t count) {
    bind_semantics(fx, s);
    int n = 0, set;
    effect_facts f = facts_of(fx);
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        const char *h = bind_one(hfx_effect_param_at(fx, i), s, view_only, &f, &set);
        n += h != NULL;
        if (i < count) how[i] = h;
    }
    return n;
}

int hv_bind_scene_report(hfx_effect *fx, const hv_scene *s, const char **how, size_t count) {
    return bind_all(fx, s, 0, how, count);
}

int hv_bind_scene(hfx_effect *fx, const hv_scene *s) { return bind_all(fx, s, 0, NULL, 0); }

int hv_bind_view(hfx_effect *fx, const hv_scene *s) { return bind_all(fx, s, 1, NULL, 0); }

static int is_numeric(const hfx_param *p) {
    hfx_param_type t = hfx_param_get_type(p);
    hfx_param_class k = hfx_param_get_class(p);
    return (t == HFX_TYPE_FLOAT || t == HFX_TYPE_INT || t == HFX_TYPE_BOOL) && k != HFX_CLASS_OBJECT;
}

size_t hv_unbound_list(hfx_effect *fx, const char *const *how, char *out, size_t cap) {
    size_t n = 0, used = 0;
    if (cap) out[0] = '\0';
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        if (how[i] || !is_numeric(p)) continue;
        int w = snprintf(out + used, cap > used ? cap - used : 0, "%s%s%s", n ? ", " : "", hfx_param_name(p),
                         hv_param_is_zero(p) ? " = 0" : "");
        if (w > 0) used = used + (size_t)w < cap ? used + (size_t)w : cap;
        n++;
    }
    return n;
}

/* ---- --set --------------------------------------------------------------------------------- */

hfx_param *hv_find_param(hfx_effect *fx, const char *path) {
    char name[256];
    size_t n = strcspn(path, "[.");
    if (n == 0 || n >= sizeof name) return NULL;
    memcpy(name, path, n);
    name[n] = '\0';
    hfx_param *p = hfx_effect_param(fx, name);
    path += n;
    while (p && *path) {
        if (*path == '[') {
            char *end;
            unsigned long i = strtoul(path + 1, &end, 10);
            if (end == path + 1 || *end != ']') return NULL;
            p = hfx_param_element(p, (size_t)i);
            path = end + 1;
        } else if (*path == '.') {
            n = strcspn(path + 1, "[.");
            if (n == 0 || n >= sizeof name) return NULL;
            memcpy(name, path + 1, n);
            name[n] = '\0';
            p = hfx_param_member(p, name);
            path += 1 + n;
        } else {
            return NULL;
        }
    }
    return p;
}

int hv_set_param(hfx_effect *fx, const char *name, const char *values, char *err, size_t errlen) {
    hfx_param *p = hv_find_param(fx, name);
    if (!p) {
        snprintf(err, errlen, "--set: the effect has no parameter '%s'", name);
        return -1;
    }
    hfx_param_type t = hfx_param_get_type(p);
    float f[256];
    int n;
    if (!strcmp(values, "true") || !strcmp(values, "false")) {
        f[0] = values[0] == 't';
        n = 1;
    } else {
        n = hv_parse_floats(values, f, 256);
    }
    if (n <= 0) {
        snprintf(err, errlen, "--set %s: '%s' is not a list of numbers", name, values);
        return -1;
    }
    int rc;
    if (t == HFX_TYPE_FLOAT) {
        rc = hfx_param_set_floats(p, f, (size_t)n);
    } else if (t == HFX_TYPE_INT || t == HFX_TYPE_BOOL) {
        int iv[256];
        for (int i = 0; i < n; i++) iv[i] = t == HFX_TYPE_BOOL ? f[i] != 0 : (int)lroundf(f[i]);
        rc = hfx_param_set_ints(p, iv, (size_t)n);
    } else {
        snprintf(err, errlen, "--set %s: not a numeric parameter (use --texture for textures)", name);
        return -1;
    }
    if (rc != HFX_OK) {
        snprintf(err, errlen, "--set %s=%s: %d values do not fit this parameter", name, values, n);
        return -1;
    }
    return 0;
}
