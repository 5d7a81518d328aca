/* bind_sas.c: parameters that say what they are in annotations, FX Composer's and DXSAS's
 * conventions (see bind.h): `Object = "SpotLight0"` (a light's matrix, position, direction or
 * colour, by the semantic), `Space = "View"` (the vector in camera space), `SasBindAddress =
 * "Sas.Camera.WorldToView"`, `UIWidget = "Color"` (white when left at zero), `UIMin` (taken
 * when zero lies below the range). */
#include <string.h>
#include <strings.h>

#include "bind_internal.h"

/* The annotation named name (case-insensitive), or NULL. */
static hfx_annotation *annotation(hfx_param *p, const char *name) {
    for (size_t i = 0; i < hfx_param_annotation_count(p); i++) {
        hfx_annotation *a = hfx_param_annotation_at(p, i);
        if (!strcasecmp(hfx_annotation_name(a), name)) return a;
    }
    return NULL;
}

static const char *annotation_string(hfx_param *p, const char *name) {
    hfx_annotation *a = annotation(p, name);
    return a ? hfx_annotation_string(a) : NULL;
}

static int starts_with(const char *s, const char *prefix) { return !strncasecmp(s, prefix, strlen(prefix)); }

static int contains(const char *s, const char *part) {
    for (size_t n = strlen(part); *s; s++)
        if (!strncasecmp(s, part, n)) return 1;
    return 0;
}

/* A vector in the space `Space` names: world (the default), view ("View", "Camera", "Eye") or
 * object ("Object", "Model"). w = 1 for points, 0 for directions. */
static hv_vec3 in_space(hfx_param *p, const hv_scene *s, hv_vec3 v, int point) {
    const char *space = annotation_string(p, "Space");
    float m[16];
    if (!space) return v;
    if (starts_with(space, "View") || starts_with(space, "Camera") || starts_with(space, "Eye")) memcpy(m, s->view, sizeof m);
    else if (starts_with(space, "Object") || starts_with(space, "Model")) hv_mat4_invert(m, s->world);
    else return v;
    return point ? hv_mat4_transform_point(m, v, NULL) : hv_mat4_transform_normal(m, v);
}

static int set_xyzw(hfx_param *p, hv_vec3 v, float w) {
    float f[4] = {v.x, v.y, v.z, w};
    return hv_set_vector(p, f, 4, w);
}

/* What a light's parameter asks for, by its semantic or, lacking one, its name. */
typedef enum { L_NONE, L_MATRIX, L_POSITION, L_DIRECTION, L_COLOR, L_AMBIENT } light_part;

static light_part light_part_of(hfx_param *p) {
    const char *sem = hfx_param_semantic(p), *key = sem && *sem ? sem : hfx_param_name(p);
    if (hfx_param_get_class(p) == HFX_CLASS_MATRIX) return L_MATRIX;
    if (contains(key, "Position") || contains(key, "Pos")) return L_POSITION;
    if (contains(key, "Direction") || contains(key, "Dir")) return L_DIRECTION;
    if (contains(key, "Ambient")) return L_AMBIENT;
    if (contains(key, "Diffuse") || contains(key, "Specular") || contains(key, "Color") || contains(key, "Colour"))
        return L_COLOR;
    return L_NONE;
}

/* Object = "SpotLight0", "PointLight0", "DirectionalLight0", "Lamp0"...: the scene light (its
 * position, direction and colour where the effect left zero, or --light was given). */
static const char *bind_light_object(hfx_param *p, const hv_scene *s, int *set) {
    hv_scene light;
    float m[16], grey[4] = {0.2f, 0.2f, 0.2f, 1};
    const char *sem = hfx_param_semantic(p);
    hv_light_scene(s, &light);
    switch (light_part_of(p)) {
    case L_MATRIX:
        if (!sem || !*sem || !hv_scene_matrix(&light, sem, 1, m)) return NULL;
        *set = hv_set_matrix_param(p, m);
        return "annotation Object: the light's matrix";
    case L_POSITION:
        *set = (s->light_given || hv_param_is_zero(p)) && set_xyzw(p, in_space(p, s, s->light_position, 1), 1);
        return "annotation Object: light position";
    case L_DIRECTION:
        *set = (s->light_given || hv_param_is_zero(p)) && set_xyzw(p, in_space(p, s, s->light_direction, 0), 0);
        return "annotation Object: light direction";
    case L_AMBIENT: *set = hv_param_is_zero(p) && hv_set_vector(p, grey, 4, 1); return "annotation Object: ambient light";
    case L_COLOR: {
        float c[4] = {s->light_color[0], s->light_color[1], s->light_color[2], 1};
        *set = (s->light_given || hv_param_is_zero(p)) && hv_set_vector(p, c, 4, 1);
        return "annotation Object: light colour";
    }
    default: return NULL;
    }
}

/* Object = "Camera" (or a camera's name): the camera's matrices and position. */
static const char *bind_camera_object(hfx_param *p, const hv_scene *s, int *set) {
    float m[16];
    const char *sem = hfx_param_semantic(p);
    if (hfx_param_get_class(p) == HFX_CLASS_MATRIX) {
        if (!sem || !*sem || !hv_scene_matrix(s, sem, 1, m)) return NULL;
        return *set = hv_set_matrix_param(p, m), "annotation Object: the camera's matrix";
    }
    if (light_part_of(p) != L_POSITION) return NULL;
    return *set = set_xyzw(p, in_space(p, s, s->eye, 1), 1), "annotation Object: camera position";
}

/* DXSAS addresses: "Sas.Camera.WorldToView", "Sas.Skeleton.MeshToJointToWorld[*]",
 * "Sas.DirectionalLight[0].Direction", "Sas.Time.Now"... */
static const char *bind_sas_address(hfx_param *p, const char *addr, const hv_scene *s, int *set) {
    float m[16];
    if (starts_with(addr, "Sas.")) addr += 4;
    if (starts_with(addr, "Skeleton.")) return *set = hv_set_identity_palette(p), "SasBindAddress: identity bones";
    if (starts_with(addr, "Time.")) {
        const float *t = contains(addr, "Elapsed") || contains(addr, "Last") ? &s->elapsed_time : &s->time;
        return *set = hv_set_vector(p, t, 1, *t), "SasBindAddress: the clock";
    }
    if (starts_with(addr, "Camera.")) {
        addr += 7;
        if (contains(addr, "Position")) return *set = set_xyzw(p, s->eye, 1), "SasBindAddress: camera position";
        const char *which = !strcasecmp(addr, "WorldToView") ? "View" : !strcasecmp(addr, "Projection") ? "Projection" : NULL;
        if (!which || !hv_scene_matrix(s, which, 1, m)) return NULL;
        return *set = hv_set_matrix_param(p, m), "SasBindAddress: the camera's matrix";
    }
    if (contains(addr, "Light")) {
        float grey[4] = {0.2f, 0.2f, 0.2f, 1}, c[4] = {s->light_color[0], s->light_color[1], s->light_color[2], 1};
        if (starts_with(addr, "AmbientLight")) return *set = hv_set_vector(p, grey, 4, 1), "SasBindAddress: ambient light";
        if (contains(addr, "Position")) return *set = set_xyzw(p, s->light_position, 1), "SasBindAddress: light position";
        if (contains(addr, "Direction")) return *set = set_xyzw(p, s->light_direction, 0), "SasBindAddress: light direction";
        if (contains(addr, "Color")) return *set = hv_set_vector(p, c, 4, 1), "SasBindAddress: light colour";
    }
    return NULL;
}

/* UI annotations of a parameter left at zero: a colour widget is white; a range above zero
 * starts at its minimum (FX Composer's sliders would not go to zero either). */
static const char *bind_ui(hfx_param *p, int *set) {
    const char *widget = annotation_string(p, "UIWidget");
    hfx_annotation *min = annotation(p, "UIMin");
    float lo, white[4] = {1, 1, 1, 1};
    if (!hv_param_is_zero(p) || hfx_param_get_type(p) != HFX_TYPE_FLOAT) return NULL;
    if (widget && (!strcasecmp(widget, "Color") || !strcasecmp(widget, "Colour")))
        return *set = hv_set_vector(p, white, 4, 1), "annotation UIWidget Color: white";
    if (min && hfx_annotation_float(min, &lo) == HFX_OK && lo > 0)
        return *set = hv_set_scalar_default(p, lo), "annotation UIMin: the range's minimum";
    return NULL;
}

const char *hv_bind_by_annotation(hfx_param *p, const hv_scene *s, int view_only, int *set) {
    const char *object = annotation_string(p, "Object"), *addr = annotation_string(p, "SasBindAddress");
    *set = 0;
    if (addr && *addr) return bind_sas_address(p, addr, s, set);
    if (object && *object) {
        if (contains(object, "Camera") || contains(object, "Eye")) return bind_camera_object(p, s, set);
        if (contains(object, "Light") || contains(object, "Lamp")) return bind_light_object(p, s, set);
    }
    if (view_only) return NULL;
    return bind_ui(p, set);
}
