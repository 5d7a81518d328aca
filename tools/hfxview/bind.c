/* bind.c: automatic parameter values (see bind.h). */
#include "bind.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846f

void hv_scene_from_options(hv_scene *s, const hv_options *o) {
    memset(s, 0, sizeof *s);
    hv_mat4_rotation_y(s->world, o->yaw_degrees * PI / 180.0f);
    hv_mat4_look_at_rh(s->view, o->eye, o->at, o->up);
    s->width = o->width;
    s->height = o->height;
    hv_mat4_perspective_fov_rh(s->projection, o->fov_degrees * PI / 180.0f, (float)o->width / (float)o->height, 0.1f,
                               100.0f);
    s->eye = o->eye;
    s->at = o->at;
    s->light_position = o->light_position;
    s->light_direction = hv_vec3_normalize(o->light_direction_given ? o->light_direction
                                                                    : hv_vec3_sub(o->at, o->light_position));
    memcpy(s->light_color, o->light_color, sizeof s->light_color);
    s->light_given = o->light_given;
}

static void lower_copy(char *out, size_t cap, const char *in) {
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
    if (!strncmp(name, "mat", 3) && isupper((unsigned char)name[3])) name += 3;
    else if (!strncmp(name, "fx", 2) && isupper((unsigned char)name[2])) name += 2;
    else if ((name[0] == 'm' || name[0] == 'x') && isupper((unsigned char)name[1])) name++;
    lower_copy(out, cap, name);
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

int hv_scene_matrix(const hv_scene *s, const char *name, int is_semantic, float out[16]) {
    char stem[128];
    if (is_semantic) lower_copy(stem, sizeof stem, name);
    else matrix_stem(stem, sizeof stem, name);
    for (size_t b = 0; b < sizeof matrix_bases / sizeof matrix_bases[0]; b++) {
        size_t n = strlen(matrix_bases[b].stem);
        if (strncmp(stem, matrix_bases[b].stem, n)) continue;
        for (size_t f = 0; f < sizeof matrix_forms / sizeof matrix_forms[0]; f++) {
            if (strcmp(stem + n, matrix_forms[f].text)) continue;
            int form = matrix_forms[f].form;
            base_matrix(s, matrix_bases[b].kind, out);
            if (form == F_INVERSE || form == F_INVERSE_TRANSPOSE) hv_mat4_invert(out, out);
            if (form == F_TRANSPOSE || form == F_INVERSE_TRANSPOSE) hv_mat4_transpose(out, out);
            return 1;
        }
    }
    return 0;
}

/* ---- values already there ---------------------------------------------------------------- */

static size_t param_words(const hfx_param *p) {
    size_t n = hfx_param_rows(p) * hfx_param_columns(p);
    return hfx_param_elements(p) ? n * hfx_param_elements(p) : n;
}

/* True when a numeric parameter holds only zeros: it had no initializer worth keeping. */
static int param_is_zero(const hfx_param *p) {
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
static int set_vector(hfx_param *p, const float *v, size_t n, float pad) {
    size_t want = hfx_param_rows(p) * hfx_param_columns(p);
    float buf[16];
    if (hfx_param_get_type(p) != HFX_TYPE_FLOAT || want == 0 || want > 4) return 0;
    for (size_t i = 0; i < want; i++) buf[i] = i < n ? v[i] : pad;
    return hfx_param_set_floats(p, buf, want) == HFX_OK;
}

static int set_scalar_default(hfx_param *p, float v) {
    if (!param_is_zero(p)) return 0;
    if (hfx_param_get_type(p) == HFX_TYPE_FLOAT) return set_vector(p, &v, 1, v);
    if (hfx_param_get_type(p) == HFX_TYPE_INT) return hfx_param_set_int(p, (int)v) == HFX_OK;
    if (hfx_param_get_type(p) == HFX_TYPE_BOOL) return hfx_param_set_bool(p, v != 0) == HFX_OK;
    return 0;
}

static int set_matrix_param(hfx_param *p, const float m[16]) {
    size_t rows = hfx_param_rows(p), cols = hfx_param_columns(p);
    if (hfx_param_get_class(p) != HFX_CLASS_MATRIX || hfx_param_get_type(p) != HFX_TYPE_FLOAT) return 0;
    if (rows == 4 && cols == 4) return hfx_param_set_matrix(p, m) == HFX_OK;
    float sub[16]; /* float3x3 WorldIT and the like: the upper-left block */
    for (size_t r = 0; r < rows && r < 4; r++)
        for (size_t c = 0; c < cols && c < 4; c++) sub[r * cols + c] = m[r * 4 + c];
    return hfx_param_set_floats(p, sub, rows * cols) == HFX_OK;
}

/* ---- lights and materials ---------------------------------------------------------------- */

typedef enum {
    R_NONE, R_CAMERA, R_LIGHT_DIR, R_LIGHT_POS, R_LIGHT_COLOR, R_TARGET, R_WHITE, R_SCALAR, R_LIGHT_COUNT, R_RADIUS
} role;

/* Lower-case names, as the seed tutorials, XNA samples and FX Composer write them. */
static const struct { const char *name; role r; float v; } named_roles[] = {
    {"campos", R_CAMERA, 0}, {"camposition", R_CAMERA, 0}, {"camerapos", R_CAMERA, 0}, {"cameraposition", R_CAMERA, 0},
    {"eyepos", R_CAMERA, 0}, {"eyeposition", R_CAMERA, 0}, {"viewpos", R_CAMERA, 0}, {"viewposition", R_CAMERA, 0},
    {"posicioncamara", R_CAMERA, 0}, {"camaraposicion", R_CAMERA, 0},
    {"lightdirection", R_LIGHT_DIR, 0}, {"lightdir", R_LIGHT_DIR, 0}, {"direccionluz", R_LIGHT_DIR, 0},
    {"lamp0dir", R_LIGHT_DIR, 0}, {"dirlight", R_LIGHT_DIR, 0},
    {"lightposition", R_LIGHT_POS, 0}, {"lightpos", R_LIGHT_POS, 0}, {"posicionluz", R_LIGHT_POS, 0},
    {"lamp0pos", R_LIGHT_POS, 0}, {"pointlightposition", R_LIGHT_POS, 0},
    {"lightcolor", R_LIGHT_COLOR, 0}, {"lightcolour", R_LIGHT_COLOR, 0}, {"colorluz", R_LIGHT_COLOR, 0},
    {"lamp0color", R_LIGHT_COLOR, 0}, {"lightdiffuse", R_LIGHT_COLOR, 0},
    {"blancoluz", R_TARGET, 0}, {"lighttarget", R_TARGET, 0}, {"spottarget", R_TARGET, 0},
    {"specularcolor", R_WHITE, 0}, {"ambientcolor", R_WHITE, 0}, {"diffusecolor", R_WHITE, 0},
    {"specularpower", R_SCALAR, 50}, {"shininess", R_SCALAR, 32}, {"specpower", R_SCALAR, 32},
    {"specularintensity", R_SCALAR, 1}, {"diffuseintensity", R_SCALAR, 1}, {"ambientintensity", R_SCALAR, 0.05f},
    {"c1", R_SCALAR, 1}, {"c3", R_SCALAR, 0.01f}, {"rango", R_SCALAR, 20}, {"lightrange", R_SCALAR, 20},
    {"falloff", R_SCALAR, 0.8f}, {"angulointerno", R_SCALAR, 0.15f}, {"anguloexterno", R_SCALAR, 0.3f},
    {"innerangle", R_SCALAR, 0.15f}, {"outerangle", R_SCALAR, 0.3f},
    {"activelights", R_LIGHT_COUNT, 0}, {"numlights", R_LIGHT_COUNT, 0}, {"lightcount", R_LIGHT_COUNT, 0},
    {"lightradius", R_RADIUS, 0},
};

enum { ARRAY_LIGHTS = 3 }; /* how many lights light arrays get */

static role role_of(const char *name, float *v) {
    char low[128];
    lower_copy(low, sizeof low, name);
    for (size_t i = 0; i < sizeof named_roles / sizeof named_roles[0]; i++)
        if (!strcmp(low, named_roles[i].name)) {
            *v = named_roles[i].v;
            return named_roles[i].r;
        }
    return R_NONE;
}

/* Light k of an array: the scene light, then others turned 120 degrees about y, closer in. */
static hv_vec3 array_light_position(const hv_scene *s, size_t k) {
    hv_vec3 p = hv_vec3_scale(hv_vec3_normalize(s->light_position), 2.5f);
    float m[16];
    hv_mat4_rotation_y(m, (float)k * 2.0f * PI / 3.0f);
    return hv_mat4_transform_point(m, p, NULL);
}

static const float array_light_colors[ARRAY_LIGHTS][4] = {{1.0f, 0.85f, 0.7f, 1}, {0.6f, 0.8f, 1.0f, 1}, {0.7f, 1.0f, 0.7f, 1}};

static int bind_array(hfx_param *p, role r, const hv_scene *s) {
    size_t n = hfx_param_elements(p), set = 0;
    for (size_t k = 0; k < n && k < ARRAY_LIGHTS; k++) {
        hfx_param *e = hfx_param_element(p, k);
        hv_vec3 pos = array_light_position(s, k);
        float v[4] = {pos.x, pos.y, pos.z, 1}, radius = 5.0f;
        if (r == R_LIGHT_POS) set += set_vector(e, v, 3, 1);
        else if (r == R_LIGHT_COLOR) set += set_vector(e, array_light_colors[k], 4, 1);
        else if (r == R_RADIUS) set += set_vector(e, &radius, 1, radius);
        else if (r == R_LIGHT_DIR) {
            hv_vec3 d = hv_vec3_normalize(hv_vec3_sub(s->at, pos));
            float dv[4] = {d.x, d.y, d.z, 0};
            set += set_vector(e, dv, 3, 0);
        }
    }
    return set > 0;
}

static int is_light_role(role r) {
    return r == R_LIGHT_DIR || r == R_LIGHT_POS || r == R_LIGHT_COLOR || r == R_TARGET;
}

static int bind_role(hfx_param *p, role r, float v, const hv_scene *s) {
    float vec[4] = {0, 0, 0, 1};
    int forced = r == R_CAMERA || (s->light_given && is_light_role(r));
    if (r == R_NONE || (!forced && !param_is_zero(p))) return 0;
    if (hfx_param_elements(p)) return bind_array(p, r, s);
    switch (r) {
    case R_CAMERA: vec[0] = s->eye.x; vec[1] = s->eye.y; vec[2] = s->eye.z; return set_vector(p, vec, 4, 1);
    case R_LIGHT_DIR:
        vec[0] = s->light_direction.x; vec[1] = s->light_direction.y; vec[2] = s->light_direction.z; vec[3] = 0;
        return set_vector(p, vec, 4, 0);
    case R_LIGHT_POS:
        vec[0] = s->light_position.x; vec[1] = s->light_position.y; vec[2] = s->light_position.z;
        return set_vector(p, vec, 4, 1);
    case R_LIGHT_COLOR: memcpy(vec, s->light_color, 3 * sizeof *vec); return set_vector(p, vec, 4, 1);
    case R_TARGET: vec[0] = s->at.x; vec[1] = s->at.y; vec[2] = s->at.z; return set_vector(p, vec, 4, 1);
    case R_WHITE: vec[0] = vec[1] = vec[2] = 1; return set_vector(p, vec, 4, 1);
    case R_SCALAR: return set_scalar_default(p, v);
    case R_LIGHT_COUNT: return set_scalar_default(p, ARRAY_LIGHTS);
    case R_RADIUS: return set_scalar_default(p, 5.0f);
    default: return 0;
    }
}

/* ---- structs of lights (multilights: LuzDireccional, LuzPuntual, LuzSpot) ------------------ */

static hfx_param *member_named(hfx_param *p, const char *const *names) {
    for (size_t i = 0; i < hfx_param_member_count(p); i++) {
        hfx_param *m = hfx_param_member_at(p, i);
        char low[64];
        lower_copy(low, sizeof low, hfx_param_name(m));
        for (size_t k = 0; names[k]; k++)
            if (!strcmp(low, names[k])) return m;
    }
    return NULL;
}

static const char *const m_direction[] = {"direccion", "direction", "dir", NULL};
static const char *const m_position[] = {"posicion", "position", "pos", NULL};
static const char *const m_target[] = {"blanco", "target", NULL};
static const char *const m_color[] = {"color", "colour", "diffuse", NULL};
static const char *const m_range[] = {"rango", "range", "radius", NULL};
static const char *const m_c1[] = {"c1", NULL}, *const m_c3[] = {"c3", NULL};
static const char *const m_inner[] = {"angulointerno", "innerangle", "inner", NULL};
static const char *const m_outer[] = {"anguloexterno", "outerangle", "outer", NULL};
static const char *const m_falloff[] = {"falloff", NULL};
static const char *const m_enabled[] = {"encender", "enabled", "enable", "on", NULL};

static int set_member(hfx_param *s, const char *const *names, const float *v, size_t n) {
    hfx_param *m = member_named(s, names);
    if (!m || !param_is_zero(m)) return 0;
    if (hfx_param_get_type(m) == HFX_TYPE_FLOAT) return set_vector(m, v, n, v[n - 1]);
    return set_scalar_default(m, v[0]);
}

/* One light struct: its kind shows in its members (a target: spot; a position: point). */
static int bind_light_struct(hfx_param *l, const hv_scene *s) {
    hfx_param *pos = member_named(l, m_position), *dir = member_named(l, m_direction);
    int spot = member_named(l, m_target) != NULL;
    if (!pos && !dir) return 0;
    static const float dir_color[4] = {0.6f, 0.6f, 0.6f, 1}, point_color[4] = {1.0f, 0.6f, 0.3f, 1},
                       spot_color[4] = {0.4f, 0.6f, 1.0f, 1}, one = 1, range = 20, c3 = 0.01f, inner = 0.15f,
                       outer = 0.3f, falloff = 0.8f;
    hv_vec3 p = spot ? s->light_position : hv_vec3_make(-2.0f, 1.5f, 2.0f);
    float pv[3] = {p.x, p.y, p.z}, tv[3] = {s->at.x, s->at.y, s->at.z};
    float dv[3] = {s->light_direction.x, s->light_direction.y, s->light_direction.z};
    int n = 0;
    n += set_member(l, m_direction, dv, 3);
    n += set_member(l, m_position, pv, 3);
    n += set_member(l, m_target, tv, 3);
    n += set_member(l, m_color, pos ? (spot ? spot_color : point_color) : dir_color, 4);
    n += set_member(l, m_range, &range, 1);
    n += set_member(l, m_c1, &one, 1);
    n += set_member(l, m_c3, &c3, 1);
    n += set_member(l, m_inner, &inner, 1);
    n += set_member(l, m_outer, &outer, 1);
    n += set_member(l, m_falloff, &falloff, 1);
    n += set_member(l, m_enabled, &one, 1);
    return n > 0;
}

static int bind_struct(hfx_param *p, const hv_scene *s) {
    if (!hfx_param_elements(p)) return bind_light_struct(p, s);
    hfx_param *first = hfx_param_element(p, 0); /* one light of each kind is enough to see */
    return first ? bind_light_struct(first, s) : 0;
}

/* ---- the whole effect -------------------------------------------------------------------- */

/* SAS's ViewportPixelSize; DigitalRise's VIEWPORTSIZE semantic and ViewportSize name. */
static int is_viewport_size(const char *lower) {
    return !strcmp(lower, "viewportpixelsize") || !strcmp(lower, "viewportsize");
}

static int set_viewport_size(hfx_param *p, const hv_scene *s) {
    float wh[2] = {(float)s->width, (float)s->height};
    return set_vector(p, wh, 2, 0);
}

/* What follows the camera and the viewport: matrices by semantic or name, the viewport size by
 * name, the camera position. The count set (0 or 1), or -1 when p is none of those. */
static int bind_view_one(hfx_param *p, const hv_scene *s) {
    float m[16], v = 0;
    const char *sem = hfx_param_semantic(p);
    hfx_param_class k = hfx_param_get_class(p);
    if (sem && *sem && hfx_scene_semantic_known(sem)) return 0; /* hfx_effect_bind_scene's, set already */
    if (k == HFX_CLASS_MATRIX && hfx_param_elements(p) == 0) {
        if (sem && *sem && hv_scene_matrix(s, sem, 1, m)) return set_matrix_param(p, m); /* "WVP", "ViewI"... */
        return hv_scene_matrix(s, hfx_param_name(p), 0, m) && set_matrix_param(p, m);
    }
    if (k != HFX_CLASS_SCALAR && k != HFX_CLASS_VECTOR) return -1;
    /* the runtime binds the semantics (hfx_effect_bind_scene); DigitalRise's post-processing
     * declares its viewport size by name only */
    char low_name[64];
    lower_copy(low_name, sizeof low_name, hfx_param_name(p));
    if (is_viewport_size(low_name)) return set_viewport_size(p, s);
    return role_of(hfx_param_name(p), &v) == R_CAMERA ? bind_role(p, R_CAMERA, v, s) : -1;
}

static int bind_one(hfx_param *p, const hv_scene *s) {
    int n = bind_view_one(p, s);
    float v = 0;
    if (n >= 0) return n;
    hfx_param_class k = hfx_param_get_class(p);
    if (k == HFX_CLASS_STRUCT) return bind_struct(p, s);
    if (k != HFX_CLASS_SCALAR && k != HFX_CLASS_VECTOR) return 0;
    role r = role_of(hfx_param_name(p), &v); /* sets v: before it is passed */
    return bind_role(p, r, v, s);
}

/* The standard SAS semantics go through the runtime (hfx_effect_bind_scene); the rest of this
 * file guesses from names, for tutorials' effects that carry no semantics. */
static int bind_semantics(hfx_effect *fx, const hv_scene *s) {
    hfx_scene scene;
    memset(&scene, 0, sizeof scene);
    memcpy(scene.world, s->world, sizeof scene.world);
    memcpy(scene.view, s->view, sizeof scene.view);
    memcpy(scene.projection, s->projection, sizeof scene.projection);
    scene.viewport_width = (float)s->width;
    scene.viewport_height = (float)s->height;
    int n = hfx_effect_bind_scene(fx, &scene);
    return n > 0 ? n : 0;
}

int hv_bind_scene(hfx_effect *fx, const hv_scene *s) {
    int n = bind_semantics(fx, s);
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) n += bind_one(hfx_effect_param_at(fx, i), s);
    return n;
}

int hv_bind_view(hfx_effect *fx, const hv_scene *s) {
    int n = bind_semantics(fx, s);
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        int k = bind_view_one(hfx_effect_param_at(fx, i), s);
        n += k > 0 ? k : 0;
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
