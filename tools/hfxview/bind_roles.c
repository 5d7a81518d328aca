/* bind_roles.c: parameters recognised by name (see bind.h): the stem of a name after its
 * decorations are stripped, looked up in one table of roles. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bind_internal.h"

void hv_name_stem(char *out, size_t cap, const char *name) {
    int material = 0;
    while (*name == '_') name++;
    if ((name[0] == 'g' || name[0] == 'm') && name[1] == '_') name += 2; /* g_LightDir, m_Color */
    else if (name[0] == 'g' && isupper((unsigned char)name[1])) name++; /* FX Composer's gLamp0Color */
    if (!strncmp(name, "mat", 3) && isupper((unsigned char)name[3])) name += 3, material = 1; /* g_matDiffuse */
    else if (!strncmp(name, "vec", 3) && isupper((unsigned char)name[3])) name += 3; /* vecLightDir, vecEye */
    else if (!strncmp(name, "fx", 2) && isupper((unsigned char)name[2])) name += 2;
    else if (strchr("fvcbimnx", name[0]) && name[0] && isupper((unsigned char)name[1])) name++; /* g_fTime, g_vLightDir */
    size_t n = 0;
    if (material) n = (size_t)snprintf(out, cap, "material");
    for (; *name && n + 1 < cap; name++)
        if (!isdigit((unsigned char)*name) && *name != '_') out[n++] = (char)tolower((unsigned char)*name);
    if (cap) out[n < cap ? n : cap - 1] = '\0';
}

typedef enum {
    R_NONE, R_CAMERA, R_LIGHT_DIR, R_LIGHT_POS, R_LIGHT_COLOR, R_TARGET, R_WHITE, R_GREY, R_SCALAR, R_LIGHT_COUNT,
    R_RADIUS, R_TIME, R_ELAPSED, R_WEIGHTS, R_VIEWPORT_SCALE, R_NEAR, R_FAR,
    R_CAMERA_FORWARD, R_CAMERA_UP, R_WORLD_UP, R_FOG_START, R_FOG_END, R_FIRST_CHANNEL
} role;

static const char *const role_phrases[] = {
    NULL, "name: the camera position", "name: light direction", "name: light position", "name: light colour",
    "name: spot target", "name: white (a material or light colour)", "name: grey ambient", "name: a sensible scalar",
    "name: light count", "name: light radius", "name: the clock (seconds)", "name: the frame time",
    "name: a Gaussian kernel summing to 1", "name: the particles' viewport scale", "name: the camera's near plane",
    "name: the camera's far plane", "name: the camera's forward direction", "name: the camera's up direction",
    "name: the world's up direction (0, 1, 0)", "name: fog start beyond the far plane (no fog)",
    "name: fog end beyond the far plane (no fog)", "name: the first channel (1, 0, 0, 0)",
};

/* Stems (lower case, no digits, no underscores; see hv_name_stem) as the XNA stock effects and
 * samples, the DirectX SDK, FX Composer, engines and the seed tutorials write them. */
static const struct { const char *stem; role r; float v; } roles[] = {
    {"campos", R_CAMERA, 0}, {"camposition", R_CAMERA, 0}, {"camerapos", R_CAMERA, 0}, {"cameraposition", R_CAMERA, 0},
    {"eyepos", R_CAMERA, 0}, {"eyeposition", R_CAMERA, 0}, {"viewpos", R_CAMERA, 0}, {"viewposition", R_CAMERA, 0},
    {"posicioncamara", R_CAMERA, 0}, {"camaraposicion", R_CAMERA, 0}, {"eye", R_CAMERA, 0}, {"cameraeye", R_CAMERA, 0},
    {"eyepositionworld", R_CAMERA, 0}, {"camerapositionworld", R_CAMERA, 0}, {"worldcameraposition", R_CAMERA, 0},
    {"cameraforward", R_CAMERA_FORWARD, 0}, {"camforward", R_CAMERA_FORWARD, 0}, {"viewforward", R_CAMERA_FORWARD, 0},
    {"cameradirection", R_CAMERA_FORWARD, 0}, {"camdir", R_CAMERA_FORWARD, 0}, {"cameradir", R_CAMERA_FORWARD, 0},
    {"viewdirection", R_CAMERA_FORWARD, 0}, {"viewdir", R_CAMERA_FORWARD, 0}, {"lookdirection", R_CAMERA_FORWARD, 0},
    {"camup", R_CAMERA_UP, 0}, {"cameraup", R_CAMERA_UP, 0}, {"viewup", R_CAMERA_UP, 0}, {"cameraupvector", R_CAMERA_UP, 0},
    {"allowedrotdir", R_WORLD_UP, 0}, {"worldup", R_WORLD_UP, 0}, {"upvector", R_WORLD_UP, 0}, {"up", R_WORLD_UP, 0},
    {"fogstart", R_FOG_START, 0}, {"fognear", R_FOG_START, 0}, {"fogend", R_FOG_END, 0}, {"fogfar", R_FOG_END, 0},
    {"lightdirection", R_LIGHT_DIR, 0}, {"lightdir", R_LIGHT_DIR, 0}, {"direccionluz", R_LIGHT_DIR, 0},
    {"lampdir", R_LIGHT_DIR, 0}, {"dirlight", R_LIGHT_DIR, 0}, {"dirlightdirection", R_LIGHT_DIR, 0},
    {"dirlightdir", R_LIGHT_DIR, 0}, {"sundir", R_LIGHT_DIR, 0}, {"sundirection", R_LIGHT_DIR, 0},
    {"lightvector", R_LIGHT_DIR, 0}, {"lightvec", R_LIGHT_DIR, 0}, {"directionallightdirection", R_LIGHT_DIR, 0},
    {"lightposition", R_LIGHT_POS, 0}, {"lightpos", R_LIGHT_POS, 0}, {"posicionluz", R_LIGHT_POS, 0},
    {"lamppos", R_LIGHT_POS, 0}, {"pointlightposition", R_LIGHT_POS, 0}, {"pointlightpos", R_LIGHT_POS, 0},
    {"lightworldposition", R_LIGHT_POS, 0}, {"spotlightposition", R_LIGHT_POS, 0},
    {"lightcolor", R_LIGHT_COLOR, 0}, {"lightcolour", R_LIGHT_COLOR, 0}, {"colorluz", R_LIGHT_COLOR, 0},
    {"lampcolor", R_LIGHT_COLOR, 0}, {"lightdiffuse", R_LIGHT_COLOR, 0}, {"lightdiffusecolor", R_LIGHT_COLOR, 0},
    {"diffuselightcolor", R_LIGHT_COLOR, 0}, {"diffuselight", R_LIGHT_COLOR, 0}, {"dirlightdiffusecolor", R_LIGHT_COLOR, 0},
    {"suncolor", R_LIGHT_COLOR, 0}, {"directionallightcolor", R_LIGHT_COLOR, 0}, {"pointlightcolor", R_LIGHT_COLOR, 0},
    {"lightintensity", R_LIGHT_COLOR, 1}, {"color", R_WHITE, 0}, {"colour", R_WHITE, 0},
    {"blancoluz", R_TARGET, 0}, {"lighttarget", R_TARGET, 0}, {"spottarget", R_TARGET, 0},
    {"specularlightcolor", R_WHITE, 0}, {"lightspecular", R_WHITE, 0}, {"lightspecularcolor", R_WHITE, 0},
    {"dirlightspecularcolor", R_WHITE, 0}, {"specularlight", R_WHITE, 0},
    {"ambientlightcolor", R_GREY, 0}, {"ambientlight", R_GREY, 0}, {"lightambient", R_GREY, 0},
    {"lightambientcolor", R_GREY, 0}, {"ambient", R_GREY, 0}, {"materialambient", R_GREY, 0},
    {"materialambientcolor", R_GREY, 0},
    {"specularcolor", R_WHITE, 0}, {"ambientcolor", R_WHITE, 0}, {"diffusecolor", R_WHITE, 0},
    {"diffusecolour", R_WHITE, 0}, {"materialdiffuse", R_WHITE, 0}, {"materialdiffusecolor", R_WHITE, 0},
    {"materialcolor", R_WHITE, 0}, {"materialspecular", R_WHITE, 0}, {"materialspecularcolor", R_WHITE, 0},
    {"diffuse", R_WHITE, 0}, {"basecolor", R_WHITE, 0}, {"tint", R_WHITE, 0}, {"tintcolor", R_WHITE, 0},
    {"albedo", R_WHITE, 0}, {"modelcolor", R_WHITE, 0}, {"objectcolor", R_WHITE, 0}, {"surfacecolor", R_WHITE, 0},
    {"specularpower", R_SCALAR, 50}, {"shininess", R_SCALAR, 32}, {"specpower", R_SCALAR, 32},
    {"specularexponent", R_SCALAR, 32}, {"materialpower", R_SCALAR, 32}, {"materialshininess", R_SCALAR, 32},
    {"specularintensity", R_SCALAR, 1}, {"diffuseintensity", R_SCALAR, 1}, {"ambientintensity", R_SCALAR, 0.05f},
    {"intensity", R_SCALAR, 1}, {"environmentmapamount", R_SCALAR, 1}, {"fresnelfactor", R_SCALAR, 1},
    {"alpha", R_SCALAR, 1}, {"opacity", R_SCALAR, 1}, {"bloomintensity", R_SCALAR, 1}, {"baseintensity", R_SCALAR, 1},
    {"bloomsaturation", R_SCALAR, 1}, {"basesaturation", R_SCALAR, 1}, {"saturation", R_SCALAR, 1},
    {"brightness", R_SCALAR, 1}, {"exposure", R_SCALAR, 1}, {"glowintensity", R_SCALAR, 1},
    {"rango", R_SCALAR, 20}, {"lightrange", R_SCALAR, 20}, {"range", R_SCALAR, 20}, {"invlightradius", R_SCALAR, 0.2f},
    {"falloff", R_SCALAR, 0.8f}, {"angulointerno", R_SCALAR, 0.15f}, {"anguloexterno", R_SCALAR, 0.3f},
    {"innerangle", R_SCALAR, 0.15f}, {"outerangle", R_SCALAR, 0.3f},
    {"startsize", R_SCALAR, 0.5f}, {"endsize", R_SCALAR, 0.5f}, {"minsize", R_SCALAR, 0.5f}, {"maxsize", R_SCALAR, 0.5f},
    {"size", R_SCALAR, 0.5f}, {"particlesize", R_SCALAR, 0.5f}, {"billboardsize", R_SCALAR, 0.5f},
    {"duration", R_SCALAR, 2}, {"endvelocity", R_SCALAR, 1}, {"viewportscale", R_VIEWPORT_SCALE, 0},
    {"lightpower", R_SCALAR, 1}, {"ambientpower", R_SCALAR, 0.2f}, {"texelwidth", R_SCALAR, 1.0f / 256},
    {"texelheight", R_SCALAR, 1.0f / 256}, {"texelsize", R_SCALAR, 1.0f / 256},
    {"conedirection", R_LIGHT_DIR, 0}, {"coneangle", R_SCALAR, 0.5f}, {"conedecay", R_SCALAR, 2}, /* spot cones */
    {"scale", R_SCALAR, 1}, {"scalefactor", R_SCALAR, 1}, /* a multiplier: zero would erase what it scales */
    {"shadowmaskchannel", R_FIRST_CHANNEL, 0}, /* DigitalRise: which channel of the shadow mask to read */
    {"iterations", R_SCALAR, 32}, {"numberofsamples", R_SCALAR, 16}, {"numsamples", R_SCALAR, 16}, /* loop counts */
    {"samplecount", R_SCALAR, 16}, {"stepsize", R_SCALAR, 1.0f / 32},
    {"wavelength", R_SCALAR, 1}, {"wavelengths", R_SCALAR, 1}, /* divisors: waves of one unit */
    {"waveheight", R_SCALAR, 0.05f}, {"waveheights", R_SCALAR, 0.05f},
    {"width", R_SCALAR, 1}, {"height", R_SCALAR, 1}, /* a billboard's or quad's size (DigitalRise's _width) */
    {"depth", R_SCALAR, 1}, {"cleardepth", R_SCALAR, 1}, /* a depth to clear to: the far plane, as Clear's 1 */
    {"tween", R_SCALAR, 1}, /* an animation's interpolation factor: its end, the whole effect */
    {"overcast", R_SCALAR, 1.1f}, /* Riemer's XNA tutorials' clouds: pow(noise, xOvercast), his 1.1 */
    {"scenenodetype", R_SCALAR, 1}, /* DigitalRise: 1 a static object (G-buffer depth positive), the one mesh */
    {"activelights", R_LIGHT_COUNT, 0}, {"numlights", R_LIGHT_COUNT, 0}, {"lightcount", R_LIGHT_COUNT, 0},
    {"numberoflights", R_LIGHT_COUNT, 0}, {"lightradius", R_RADIUS, 0},
    {"time", R_TIME, 0}, {"currenttime", R_TIME, 0}, {"totaltime", R_TIME, 0}, {"gametime", R_TIME, 0},
    {"timer", R_TIME, 0}, {"globaltime", R_TIME, 0}, {"elapsedtime", R_ELAPSED, 0}, {"timeelapsed", R_ELAPSED, 0},
    {"sampleweights", R_WEIGHTS, 0}, {"weights", R_WEIGHTS, 0}, {"blurweights", R_WEIGHTS, 0},
    {"gaussianweights", R_WEIGHTS, 0}, {"kernelweights", R_WEIGHTS, 0},
};

/* c1 and c3 (the seed tutorials' attenuation constants) would lose their digits as stems. */
static const struct { const char *name; float v; } exact_scalars[] = {{"c1", 1}, {"c3", 0.01f}};

/* Endings that say what a name the table lacks is: DigitalRise's PointLightDiffuse and
 * SpotlightDirection a light's, AmbientLightUp the world's up; "SunLight" and "SkyLight" are light
 * colours, "InstanceColor" a colour (white; emission, fog and borders stay black), "Density"
 * and "BumpStrength" weights of 1, "ReflectionTextureSize" a texture's size. A vector ending in
 * Normal (DigitalRise's ReflectionNormal, a mirror plane's) is the world's up, the normal of the
 * ground plane a viewer shows; a Frequency or Length (divisors: waveLength = ClothLength /
 * Frequency) 1, an Amplitude a small 0.05. */
static const struct { const char *ending; role r; float v; } endings[] = {
    {"lightdiffuse", R_LIGHT_COLOR, 0}, {"lightspecular", R_WHITE, 0}, {"lightdirection", R_LIGHT_DIR, 0},
    {"lightposition", R_LIGHT_POS, 0}, {"lightrange", R_SCALAR, 20}, {"up", R_WORLD_UP, 0},
    {"light", R_LIGHT_COLOR, 0}, {"color", R_WHITE, 0}, {"colour", R_WHITE, 0}, {"intensity", R_SCALAR, 1},
    {"strength", R_SCALAR, 1}, {"amount", R_SCALAR, 1}, {"density", R_SCALAR, 1}, {"texturesize", R_SCALAR, 256},
    {"mapsize", R_SCALAR, 256}, {"far", R_FAR, 0}, {"farplane", R_FAR, 0}, {"farclip", R_FAR, 0},
    {"near", R_NEAR, 0}, {"nearplane", R_NEAR, 0}, {"nearclip", R_NEAR, 0},
    {"normal", R_WORLD_UP, 0}, {"frequency", R_SCALAR, 1}, {"length", R_SCALAR, 1}, {"amplitude", R_SCALAR, 0.05f},
};

static int ends_in(const char *s, const char *ending) {
    size_t n = strlen(s), k = strlen(ending);
    return n >= k && !strcmp(s + n - k, ending);
}

static role role_by_ending(const char *stem, float *v) {
    if (strstr(stem, "emissive") || strstr(stem, "fog") || strstr(stem, "border") || strstr(stem, "clear")) return R_NONE;
    for (size_t i = 0; i < sizeof endings / sizeof *endings; i++)
        if (ends_in(stem, endings[i].ending)) return *v = endings[i].v, endings[i].r;
    return R_NONE;
}

static role role_of(const char *name, float *v) {
    char stem[128];
    for (size_t i = 0; i < sizeof exact_scalars / sizeof *exact_scalars; i++)
        if (!strcmp(name, exact_scalars[i].name)) return *v = exact_scalars[i].v, R_SCALAR;
    hv_name_stem(stem, sizeof stem, name);
    for (size_t i = 0; i < sizeof roles / sizeof *roles; i++)
        if (!strcmp(stem, roles[i].stem)) return *v = roles[i].v, roles[i].r;
    return role_by_ending(stem, v);
}

enum { ARRAY_LIGHTS = 3 }; /* how many lights light arrays get */

/* Light k of an array: the scene light, then others turned 120 degrees about y, closer in. */
static hv_vec3 array_light_position(const hv_scene *s, size_t k) {
    hv_vec3 p = hv_vec3_scale(hv_vec3_normalize(s->light_position), 2.5f);
    float m[16];
    hv_mat4_rotation_y(m, (float)k * 2.0f * HV_PI / 3.0f);
    return hv_mat4_transform_point(m, p, NULL);
}

static const float array_light_colors[ARRAY_LIGHTS][4] = {{1.0f, 0.85f, 0.7f, 1}, {0.6f, 0.8f, 1.0f, 1}, {0.7f, 1.0f, 0.7f, 1}};

/* Sample k of a blur kernel in the order XNA's bloom sample fills SampleWeights: the centre,
 * then a pair at each distance (k = 1, 2 at one sample, 3, 4 at two...). */
static float kernel_weight(size_t k) {
    float d = (float)((k + 1) / 2);
    return expf(-0.5f * d * d);
}

/* A Gaussian kernel of one sample's deviation in that order, summing to 1 over the whole array:
 * with offsets left at zero a copy of the input, and a technique that reads only the first few
 * entries (DigitalRise's Logarithmic3..9 over a 23-entry array, combined in log space) still
 * gets nearly all the weight (0.88 in the first 3) where equal weights gave it 3 / 23. */
static int set_weights(hfx_param *p) {
    size_t n = hfx_param_elements(p), set = 0;
    float sum = 0;
    for (size_t k = 0; k < n; k++) sum += kernel_weight(k);
    for (size_t k = 0; k < n; k++) set += hv_set_scalar_default(hfx_param_element(p, k), kernel_weight(k) / sum);
    return set > 0;
}

static int bind_array(hfx_param *p, role r, const hv_scene *s) {
    size_t n = hfx_param_elements(p), set = 0;
    if (r == R_WEIGHTS) return set_weights(p);
    for (size_t k = 0; k < n && k < ARRAY_LIGHTS; k++) {
        hfx_param *e = hfx_param_element(p, k);
        hv_vec3 pos = array_light_position(s, k);
        float v[4] = {pos.x, pos.y, pos.z, 1}, radius = 5.0f;
        if (r == R_LIGHT_POS) set += hv_set_vector(e, v, 3, 1);
        else if (r == R_LIGHT_COLOR) set += hv_set_vector(e, array_light_colors[k], 4, 1);
        else if (r == R_RADIUS) set += hv_set_vector(e, &radius, 1, radius);
        else if (r == R_LIGHT_DIR) {
            hv_vec3 d = hv_vec3_normalize(hv_vec3_sub(s->at, pos));
            float dv[4] = {d.x, d.y, d.z, 0};
            set += hv_set_vector(e, dv, 3, 0);
        } else if (r == R_WHITE || r == R_GREY) {
            float c = r == R_WHITE ? 1.0f : 0.2f, cv[4] = {c, c, c, 1};
            set += hv_param_is_zero(e) && hv_set_vector(e, cv, 4, 1);
        }
    }
    return set > 0;
}

static int is_light_role(role r) {
    return r == R_LIGHT_DIR || r == R_LIGHT_POS || r == R_LIGHT_COLOR || r == R_TARGET;
}

/* What follows the camera and the clock every frame, whatever the effect or the user set. */
static int follows_view(role r) {
    return r == R_CAMERA || r == R_TIME || r == R_ELAPSED || r == R_CAMERA_FORWARD || r == R_CAMERA_UP;
}

static int set_xyz(hfx_param *p, hv_vec3 a, float w) {
    float v[4] = {a.x, a.y, a.z, w};
    return hv_set_vector(p, v, 4, w);
}

static int bind_role(hfx_param *p, role r, float v, const hv_scene *s) {
    float vec[4] = {0, 0, 0, 1};
    int forced = follows_view(r) || (s->light_given && is_light_role(r));
    if (r == R_NONE || (!forced && !hv_param_is_zero(p))) return 0;
    if (hfx_param_elements(p)) return bind_array(p, r, s);
    switch (r) {
    case R_CAMERA: return set_xyz(p, s->eye, 1);
    case R_LIGHT_DIR: return set_xyz(p, s->light_direction, 0);
    case R_LIGHT_POS: return set_xyz(p, s->light_position, 1);
    case R_LIGHT_COLOR:
        if (hfx_param_get_class(p) == HFX_CLASS_SCALAR) return hv_set_scalar_default(p, 1); /* lightIntensity */
        memcpy(vec, s->light_color, 3 * sizeof *vec);
        return hv_set_vector(p, vec, 4, 1);
    case R_TARGET: return set_xyz(p, s->at, 1);
    case R_WHITE: vec[0] = vec[1] = vec[2] = 1; return hv_set_vector(p, vec, 4, 1);
    case R_GREY: vec[0] = vec[1] = vec[2] = 0.2f; return hv_set_vector(p, vec, 4, 1);
    case R_SCALAR: return hv_set_scalar_default(p, v);
    case R_LIGHT_COUNT: return hv_set_scalar_default(p, ARRAY_LIGHTS);
    case R_RADIUS: return hv_set_scalar_default(p, 5.0f);
    case R_CAMERA_FORWARD: return set_xyz(p, hv_vec3_normalize(hv_vec3_sub(s->at, s->eye)), 0);
    case R_CAMERA_UP: return set_xyz(p, hv_vec3_make(s->view[1], s->view[5], s->view[9]), 0); /* the view's y axis */
    case R_WORLD_UP: return set_xyz(p, hv_vec3_make(0, 1, 0), 0);
    case R_FIRST_CHANNEL: vec[0] = 1, vec[3] = 0; return hv_set_vector(p, vec, 4, 0);
    case R_FOG_START: return hv_set_scalar_default(p, s->zfar);
    case R_FOG_END: return hv_set_scalar_default(p, 2.0f * s->zfar);
    case R_NEAR: return hv_set_scalar_default(p, s->znear);
    case R_FAR: return hv_set_scalar_default(p, s->zfar);
    case R_TIME: return hv_set_vector(p, &s->time, 1, s->time) || hfx_param_set_int(p, (int)s->time) == HFX_OK;
    case R_ELAPSED: return hv_set_vector(p, &s->elapsed_time, 1, s->elapsed_time);
    case R_VIEWPORT_SCALE: vec[0] = 0.5f * (float)s->height / (float)s->width, vec[1] = -0.5f; return hv_set_vector(p, vec, 2, 0);
    default: return 0;
    }
}

/* ---- structs of lights (multilights: LuzDireccional, LuzPuntual, LuzSpot) ------------------ */

static hfx_param *member_named(hfx_param *p, const char *const *names) {
    for (size_t i = 0; i < hfx_param_member_count(p); i++) {
        hfx_param *m = hfx_param_member_at(p, i);
        char low[64];
        hv_lower_copy(low, sizeof low, hfx_param_name(m));
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
    if (!m || !hv_param_is_zero(m)) return 0;
    if (hfx_param_get_type(m) == HFX_TYPE_FLOAT) return hv_set_vector(m, v, n, v[n - 1]);
    return hv_set_scalar_default(m, v[0]);
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

/* ---- the entry -------------------------------------------------------------------------- */

const char *hv_bind_by_name(hfx_param *p, const hv_scene *s, int view_only, int *set) {
    hfx_param_class k = hfx_param_get_class(p);
    float v = 0;
    *set = 0;
    if (k == HFX_CLASS_STRUCT) {
        if (view_only) return NULL;
        *set = bind_struct(p, s);
        return *set ? "name: members of a light struct" : NULL;
    }
    if (k != HFX_CLASS_SCALAR && k != HFX_CLASS_VECTOR) return NULL;
    role r = role_of(hfx_param_name(p), &v); /* sets v: before it is passed */
    const char *sem = hfx_param_semantic(p);
    if (r == R_NONE && sem && *sem) r = role_of(sem, &v); /* FX Composer's DIFFUSE, SPECULARPOWER... */
    if (r == R_NONE) return NULL;
    if (view_only && !follows_view(r)) return NULL;
    *set = bind_role(p, r, v, s);
    return role_phrases[r];
}
