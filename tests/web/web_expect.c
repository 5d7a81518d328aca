/* web_expect: the colours the page's tests (page_test.js) must read back, printed as JSON,
 * from the seed tutorials' equations as tests/seeds/ write them (lighting.h's terms; each
 * equation is quoted above its case from the seed test that derives it).
 *
 * The page's scene for these probes: hfxview's "plane" (y = 0, normal +y, normalised), World
 * the identity, the orbit camera at yaw 0, pitch 60 degrees, distance 3, looking at the origin:
 * eye = (0, 3 sin 60, 3 cos 60). Under the centre pixel of an even-sized canvas (Direct3D 9's
 * pixel centres put pixel (256, 256) of 512 exactly on the axis) lies P = (0, 0, 0), N = (0, 1, 0).
 * A corner pixel sees only the clear colour, XNA's CornflowerBlue (100, 149, 237). */
#include <stdio.h>
#include <string.h>

#include "lighting.h"

static const v3 P = {0, 0, 0}, N = {0, 1, 0};

static v3 eye(void) { return v3_make(0, 3 * sin(SEED_PI / 3), 3 * cos(SEED_PI / 3)); }

static void print_rgba(rgba c) {
    printf("[%.6f, %.6f, %.6f, %.6f]", saturate(c.r), saturate(c.g), saturate(c.b), saturate(c.a));
}

static int first_case = 1;

static void print_params(const char *const *params) {
    printf("[");
    for (int i = 0; params[i]; i += 2) printf("%s[\"%s\", \"%s\"]", i ? ", " : "", params[i], params[i + 1]);
    printf("]");
}

/* One case: the effect, technique, parameters set by name ("name", "values" pairs, NULL
 * ended), an optional solid texture, and the colour under the centre pixel; add_passes: the
 * page's "add passes" box ticked (the application blends passes 2.. ONE, ONE onto the first). */
static void emit_case(const char *file, const char *technique, const char *const *params, const char *texture,
                      const int texel[4], rgba expect, int add_passes) {
    printf("%s\n  {\"file\": \"%s\", \"technique\": \"%s\", \"addPasses\": %s, \"params\": ", first_case ? "" : ",",
           file, technique, add_passes ? "true" : "false");
    first_case = 0;
    print_params(params);
    printf(", \"texture\": ");
    if (texture) printf("[\"%s\", %d, %d, %d, %d]", texture, texel[0], texel[1], texel[2], texel[3]);
    else printf("null");
    printf(", \"expect\": ");
    print_rgba(expect);
    printf("}");
}

static void emit(const char *file, const char *technique, const char *const *params, const char *texture,
                 const int texel[4], rgba expect) {
    emit_case(file, technique, params, texture, texel, expect, 0);
}

static const int TEXEL[4] = {200, 150, 100, 255};

static rgba texel_colour(void) { return rgba_make(200 / 255.0, 150 / 255.0, 100 / 255.0, 1); }

/* ambient.fx: the ambient colour alone (test_ambient: flat_shade). */
static void ambient(void) {
    static const char *const p[] = {"colorMaterialAmbiental", "0.9,0.6,0.3,0.8", NULL};
    emit("ambient.fx", "ModeloAmbiental", p, NULL, NULL, rgba_make(0.9, 0.6, 0.3, 0.8));
}

/* ambient_textured.fx, Texturizado: ambient * tex (test_ambient: textured_shade); a solid
 * texture samples its one colour under any filter. */
static void ambient_textured(void) {
    static const char *const p[] = {"colorMaterialAmbiental", "0.8,0.9,0.7,1", NULL};
    emit("ambient_textured.fx", "Texturizado", p, "texturaModelo", TEXEL, rgba_mul(rgba_make(0.8, 0.9, 0.7, 1), texel_colour()));
}

/* fxcomposer_empty.fx: a white pixel shader (test_fxcomposer_empty). */
static void fxcomposer_empty(void) {
    static const char *const p[] = {NULL};
    emit("fxcomposer_empty.fx", "technique0", p, NULL, NULL, rgba_make(1, 1, 1, 1));
}

/* tutorial0.fx: tex2D of the texture (test_tutorial0: tutorial0_shade). */
static void tutorial0(void) {
    static const char *const p[] = {NULL};
    emit("tutorial0.fx", "Tut0", p, "diffuseTexture", TEXEL, texel_colour());
}

/* directional(_specular).fx, Material (test_directional: directional_shade), the light set so
 * that its mirror direction at the centre is the view direction (R = V: the highlight's peak):
 *   L = normalize(direccionLuz); rd = max(dot(-L, N), 0); color = ambient + difuso * rd
 *   [modIluEsp] R = normalize(2 N rd + L); color += ks max(dot(R, V), 0)^n especular rd; a = 1 */
static void directional(int specular) {
    v3 dir = v3_make(0, -0.866025, 0.5), l = v3_neg(v3_normalize(dir));
    rgba amb = rgba_make(0.1, 0.05, 0.05, 1), dif = rgba_make(0.6, 0.5, 0.3, 1), spec = rgba_make(1, 0.9, 0.8, 1);
    double rd = maxd(v3_dot(l, N), 0), ks = 0.3, n = 12;
    rgba c = rgba_add(amb, rgba_scale(dif, rd));
    if (specular) c = rgba_add(c, rgba_scale(spec, ks * seed_book_specular(N, l, P, eye(), n) * rd));
    c.a = 1;
    static const char *const base[] = {"direccionLuz", "0,-0.866025,0.5", "colorMaterialAmbiental", "0.1,0.05,0.05,1",
                                       "colorMaterialDifuso", "0.6,0.5,0.3,1", NULL};
    static const char *const spec_p[] = {"direccionLuz", "0,-0.866025,0.5", "colorMaterialAmbiental", "0.1,0.05,0.05,1",
                                         "colorMaterialDifuso", "0.6,0.5,0.3,1", "colorMaterialEspecular", "1,0.9,0.8,1",
                                         "modIluEsp", "true", "ks", "0.3", "n", "12", "posicionCamara", "CAMERA", NULL};
    emit(specular ? "directional_specular.fx" : "directional.fx", "Material", specular ? spec_p : base, NULL, NULL, c);
}

/* point_specular.fx, Material, attenuated, modIluEsp (test_point: point_shade), the light where
 * its mirror direction at the centre is the view direction:
 *   R = normalize(2 N rd - L); color += ks max(dot(R, V), 0)^n especular rd, before attenuation */
static void point_specular(void) {
    v3 light = v3_make(0, 1.732051, -1), l = v3_normalize(v3_sub(light, P));
    rgba amb = rgba_make(0.05, 0.1, 0.05, 1), dif = rgba_make(0.4, 0.3, 0.5, 1), esp = rgba_make(0.9, 1, 0.8, 1);
    double rd = maxd(v3_dot(l, N), 0), ks = 0.4, n = 16;
    rgba c = rgba_add(rgba_scale(dif, rd), rgba_scale(esp, ks * seed_book_specular(N, l, P, eye(), n) * rd));
    c = rgba_scale(c, seed_book_attenuation(v3_distance(P, light), 20, 1, 0.1, 0.05));
    c = rgba_add(c, amb);
    c.a = 1;
    static const char *const p[] = {"posicionLuz", "0,1.732051,-1", "colorMaterialAmbiental", "0.05,0.1,0.05,1",
                                    "colorMaterialDifuso", "0.4,0.3,0.5,1", "colorMaterialEspecular", "0.9,1,0.8,1",
                                    "atenuado", "true", "c1", "1", "c2", "0.1", "c3", "0.05", "rango", "20",
                                    "modIluEsp", "true", "ks", "0.4", "n", "16", "posicionCamara", "CAMERA", NULL};
    emit("point_specular.fx", "Material", p, NULL, NULL, c);
}

/* phong.fx (test_phong: phong_shade), camPosition bound to the camera by the page:
 *   L = -normalize(LightDirection); diff = saturate(N.L); R = normalize(2 diff N - L)
 *   I = A Ai + Lc Di tex diff + Si Sc saturate(R.V)^n  (alpha too, clamped by the framebuffer) */
static rgba phong_colour(v3 light_direction, v3 cam) {
    v3 l = v3_neg(v3_normalize(light_direction));
    double diff = saturate(v3_dot(N, l)), spec = seed_tutorial_specular(N, l, v3_normalize(v3_sub(cam, P)), 20);
    rgba c = rgba_scale(rgba_make(0.2, 0.3, 0.4, 1), 0.5);
    c = rgba_add(c, rgba_scale(rgba_mul(rgba_make(1, 0.9, 0.8, 1), texel_colour()), 0.6 * diff));
    return rgba_add(c, rgba_scale(rgba_make(1, 1, 1, 1), 0.2 * spec));
}

#define PHONG_MATERIAL "LightColor", "1,0.9,0.8,1", "AmbientColor", "0.2,0.3,0.4,1", "AmbientIntensity", "0.5", \
    "DiffuseIntensity", "0.6", "SpecularColor", "1,1,1,1", "SpecularIntensity", "0.2", "SpecularPower", "20"

static void phong(void) {
    static const char *const p[] = {"LightDirection", "0,-0.866025,0.5", PHONG_MATERIAL, NULL};
    emit("phong.fx", "Phong", p, "DiffuseTexture", TEXEL, phong_colour(v3_make(0, -0.866025, 0.5), eye()));
}

/* The page's orbit camera (app.js: a drag of dx, dy pixels turns yaw by -dx / 2 and pitch by
 * dy / 2 degrees) at yaw, pitch degrees and distance 3: (3 cos p sin y, 3 sin p, 3 cos p cos y). */
static v3 orbit_eye(double yaw, double pitch) {
    double y = yaw * SEED_PI / 180, p = pitch * SEED_PI / 180;
    return v3_make(3 * cos(p) * sin(y), 3 * sin(p), 3 * cos(p) * cos(y));
}

/* phong.fx lit from the side (the light has an x component, so turning left and turning right
 * differ), camPosition following the camera; the centre pixel still sees P with N = +y, the
 * highlight moves with V: at the start (yaw 0, pitch 60), after dragging 60 px right and 40 px
 * up (yaw -30, pitch 40), and the mirror view (yaw +30, pitch 40) the drag must not give. */
static void orbit(void) {
    static const char *const p[] = {"LightDirection", "-0.5,-0.8,0.45", PHONG_MATERIAL, NULL};
    v3 light = v3_make(-0.5, -0.8, 0.45);
    printf(",\n \"orbit\": {\"file\": \"phong.fx\", \"technique\": \"Phong\", \"params\": ");
    print_params(p);
    printf(", \"texture\": [\"DiffuseTexture\", %d, %d, %d, %d], \"drag\": [60, -40],\n  \"start\": ", TEXEL[0], TEXEL[1],
           TEXEL[2], TEXEL[3]);
    print_rgba(phong_colour(light, orbit_eye(0, 60)));
    printf(", \"end\": ");
    print_rgba(phong_colour(light, orbit_eye(-30, 40)));
    printf(", \"mirror\": ");
    print_rgba(phong_colour(light, orbit_eye(30, 40)));
    printf("}");
}

/* pointlights.fx (test_pointlights: pointlights_shade), one light of the arrays, set as a prefix
 * (the tutorial's LightPosition.ToArray()), at (0, 0.5, 0) with radius 1: per light
 *   att = (1 - saturate(|Lpos - P| / radius))^2 = (1 - 0.5)^2 = 0.25, diff = N.L = 1
 *   color += A Ai + att Lc Di tex diff + Si Sc saturate(R.V)^n, R = normalize(2 diff N - L) = N */
static void pointlights(void) {
    v3 light = v3_make(0, 0.5, 0), l = v3_normalize(v3_sub(light, P));
    double k = 1 - saturate(v3_length(v3_sub(light, P)) / 1.0), att = k * k, diff = saturate(v3_dot(N, l));
    double spec = seed_tutorial_specular(N, l, v3_normalize(v3_sub(eye(), P)), 20);
    rgba c = rgba_scale(rgba_make(1, 1, 1, 1), 0.1);
    c = rgba_add(c, rgba_scale(rgba_mul(rgba_make(0.9, 0.7, 0.5, 1), texel_colour()), att * 1.0 * diff));
    c = rgba_add(c, rgba_scale(rgba_make(1, 1, 1, 1), 0.2 * spec));
    static const char *const p[] = {"activeLights", "1", "LightPosition", "0,0.5,0", "LightColor", "0.9,0.7,0.5,1",
                                    "LightRadius", "1", "AmbientColor", "1,1,1,1", "AmbientIntensity", "0.1",
                                    "DiffuseIntensity", "1", "SpecularColor", "1,1,1,1", "SpecularIntensity", "0.2",
                                    "SpecularPower", "20", "camPosition", "CAMERA", NULL};
    emit("pointlights.fx", "PointLights", p, "DiffuseTexture", TEXEL, c);
}

/* point.fx, Material, attenuated (test_point: point_shade):
 *   L = normalize(posicionLuz - P); rd = max(dot(L, N), 0); color = difuso rd
 *   color *= d <= rango ? min(1 / (c1 + c2 d + c3 d^2), 1) : 0; color += ambient; a = 1 */
static void point(void) {
    v3 light = v3_make(1, 2, 0.5), l = v3_normalize(v3_sub(light, P));
    rgba amb = rgba_make(0.05, 0.1, 0.05, 1), dif = rgba_make(0.7, 0.6, 0.9, 1);
    rgba c = rgba_scale(dif, maxd(v3_dot(l, N), 0));
    c = rgba_scale(c, seed_book_attenuation(v3_distance(P, light), 20, 0.5, 0.1, 0.02));
    c = rgba_add(c, amb);
    c.a = 1;
    static const char *const p[] = {"posicionLuz", "1,2,0.5", "colorMaterialAmbiental", "0.05,0.1,0.05,1",
                                    "colorMaterialDifuso", "0.7,0.6,0.9,1", "atenuado", "true", "c1", "0.5", "c2", "0.1",
                                    "c3", "0.02", "rango", "20", NULL};
    emit("point.fx", "Material", p, NULL, NULL, c);
}

/* spot(_specular).fx, Material, the book's values (test_spot: spot_shade, book_values):
 *   S = normalize(posicionLuz - blancoLuz); L = normalize(posicionLuz - P); rd = max(dot(L, N), 0)
 *   color = difuso rd [+ especular ks spec rd]; color *= cone(max(dot(S, L), 0)) * attenuation;
 *   color += ambient; a = 1.  At the origin under the light the cone factor is 1. */
static rgba spot_colour(int specular, double ks) {
    v3 light = v3_make(0, 10, 0), target = v3_make(0, 0, 0);
    v3 s = v3_normalize(v3_sub(light, target)), l = v3_normalize(v3_sub(light, P));
    double rd = maxd(v3_dot(l, N), 0);
    rgba c = rgba_scale(rgba_make(0.24, 0.34, 0.39, 1), rd);
    if (specular) c = rgba_add(c, rgba_scale(rgba_make(1, 1, 1, 1), ks * seed_book_specular(N, l, P, eye(), 5) * rd));
    c = rgba_scale(c, seed_book_spot_cone(maxd(v3_dot(s, l), 0), 0.01, 0.1, 0.8));
    c = rgba_scale(c, seed_book_attenuation(v3_distance(P, light), 20, 1, 0, 0.001));
    c = rgba_add(c, rgba_make(0.07, 0.07, 0.07, 1));
    c.a = 1;
    return c;
}

#define SPOT_PARAMS "posicionLuz", "0,10,0", "blancoLuz", "0,0,0", "anguloInterno", "0.01", "anguloExterno", "0.1", \
    "falloff", "0.8", "atenuado", "true", "c1", "1", "c2", "0", "c3", "0.001", "rango", "20", \
    "colorMaterialAmbiental", "0.07,0.07,0.07,1", "colorMaterialDifuso", "0.24,0.34,0.39,1"

static void spot(void) {
    static const char *const p[] = {SPOT_PARAMS, NULL};
    emit("spot.fx", "Material", p, NULL, NULL, spot_colour(0, 0));
    static const char *const ps[] = {SPOT_PARAMS, "colorMaterialEspecular", "1,1,1,1", "modIluEsp", "true", "ks", "0.05",
                                     "n", "5", "posicionCamara", "CAMERA", NULL};
    emit("spot_specular.fx", "Material", ps, NULL, NULL, spot_colour(1, 0.05));
}

/* multilights_repaired.fx, Material, both passes with the page's "add passes" (test_multilights:
 * multilights_shade, its equations restated here):
 *   pass 1 = colorMaterialAmbiental; pass 2 = sum over the lights switched on of
 *   Phong(L, P, N, Lc, M) = rd (Lc M) [+ ks max(dot(R, V), 0)^n (Lc Esp) M rd when habiEspec],
 *     rd = max(dot(L, N), 0), R = normalize(2 N rd - L), V = normalize(cam - P), M = colorMaterialDifuso;
 *   directional: L = -normalize(Direccion); point: L = normalize(Posicion - P), times the
 *   distance attenuation when Atenuar; spot: L as a point's, times the cone of
 *   cos A = dot(normalize(Posicion - Blanco), L) [times the attenuation when Atenuar];
 *   alpha 1; the framebuffer holds saturate(saturate(pass 1) + saturate(pass 2)). */
typedef struct ml_light { int kind, on, attenuate; v3 pos, dir, target; rgba colour; double inner, outer, falloff, range, c1, c2, c3; } ml_light;
enum { ML_DIR, ML_POINT, ML_SPOT, ML_LIGHTS = 6 };

static const rgba ML_DIFFUSE = {0.24, 0.34, 0.39, 1}, ML_AMBIENT = {0.07, 0.07, 0.07, 1};
static const double ML_KS = 0.6, ML_N = 10;

static rgba ml_phong(v3 l, v3 cam, rgba lc) {
    double rd = maxd(v3_dot(l, N), 0);
    rgba c = rgba_scale(rgba_mul(lc, ML_DIFFUSE), rd);
    rgba spec = rgba_scale(lc, ML_KS * seed_book_specular(N, l, P, cam, ML_N)); /* colorMaterialEspecular white */
    return rgba_add(c, rgba_scale(rgba_mul(spec, ML_DIFFUSE), rd));
}

static rgba ml_light_colour(const ml_light *k, v3 cam) {
    if (!k->on) return rgba_make(0, 0, 0, 0);
    if (k->kind == ML_DIR) return ml_phong(v3_neg(v3_normalize(k->dir)), cam, k->colour);
    v3 l = v3_normalize(v3_sub(k->pos, P));
    double f = k->attenuate ? seed_book_attenuation(v3_distance(P, k->pos), k->range, k->c1, k->c2, k->c3) : 1;
    if (k->kind == ML_SPOT)
        f *= seed_book_spot_cone(maxd(v3_dot(v3_normalize(v3_sub(k->pos, k->target)), l), 0), k->inner, k->outer, k->falloff);
    return rgba_scale(ml_phong(l, cam, k->colour), f);
}

static rgba ml_colour(const ml_light *lights) {
    rgba sum = rgba_make(0, 0, 0, 0);
    for (int i = 0; i < ML_LIGHTS; i++) sum = rgba_add(sum, ml_light_colour(&lights[i], eye()));
    rgba c = rgba_add(ML_AMBIENT, rgba_make(saturate(sum.r), saturate(sum.g), saturate(sum.b), 1));
    return rgba_make(saturate(c.r), saturate(c.g), saturate(c.b), saturate(c.a));
}

/* direccionales[0], puntuales[0] (attenuated) and spots[0] (in its cone's falloff) on; every
 * element 1 set too but off, spots[1] fully inside its cone for the panel step. */
static const ml_light ML[ML_LIGHTS] = {
    {.kind = ML_DIR, .on = 1, .dir = {0.5, -1, 0.2}, .colour = {0.8, 0.7, 0.6, 1}},
    {.kind = ML_DIR, .on = 0, .dir = {-1, -0.7, -0.4}, .colour = {0.3, 0.5, 0.9, 1}},
    {.kind = ML_POINT, .on = 1, .attenuate = 1, .pos = {-1, 0.6, -1}, .colour = {0.9, 0.4, 0.2, 1},
     .range = 5, .c1 = 1, .c2 = 0.5, .c3 = 0.2},
    {.kind = ML_POINT, .on = 0, .attenuate = 1, .pos = {1.2, 0.5, 0.8}, .colour = {0.5, 0.9, 0.5, 1},
     .range = 1.6, .c1 = 1, .c2 = 0.5, .c3 = 1.5},
    {.kind = ML_SPOT, .on = 1, .pos = {0, 3, 0}, .target = {0.4, 0, 0.3}, .colour = {1, 1, 0.8, 1},
     .inner = 0.1, .outer = 0.3, .falloff = 1.2, .range = 10, .c1 = 1},
    {.kind = ML_SPOT, .on = 0, .attenuate = 1, .pos = {-0.8, 1.5, 1}, .target = {0.3, 0, -0.2}, .colour = {0.6, 0.6, 1, 1},
     .inner = 0.2, .outer = 0.5, .falloff = 0.8, .range = 5, .c1 = 1, .c2 = 0.1, .c3 = 0.1},
};

#define ML_DIR_P(i, d, c, on) "direccionales[" #i "].Direccion", d, "direccionales[" #i "].Color", c, \
    "direccionales[" #i "].Encender", on
#define ML_REACH_P(a, i, r, c1, c2, c3, att, on) a "[" #i "].Rango", r, a "[" #i "].C1", c1, a "[" #i "].C2", c2, \
    a "[" #i "].C3", c3, a "[" #i "].Atenuar", att, a "[" #i "].Encender", on
#define ML_POINT_P(i, p, c) "puntuales[" #i "].Posicion", p, "puntuales[" #i "].Color", c
#define ML_SPOT_P(i, p, t, c, in, out, f) "spots[" #i "].Posicion", p, "spots[" #i "].Blanco", t, "spots[" #i "].Color", c, \
    "spots[" #i "].AnguloInterno", in, "spots[" #i "].AnguloExterno", out, "spots[" #i "].Falloff", f

/* The same values as ML, as the page sets them (every member of elements 0 and 1). */
static const char *const ML_PARAMS[] = {
    ML_DIR_P(0, "0.5,-1,0.2", "0.8,0.7,0.6,1", "1"), ML_DIR_P(1, "-1,-0.7,-0.4", "0.3,0.5,0.9,1", "0"),
    ML_POINT_P(0, "-1,0.6,-1", "0.9,0.4,0.2,1"), ML_REACH_P("puntuales", 0, "5", "1", "0.5", "0.2", "1", "1"),
    ML_POINT_P(1, "1.2,0.5,0.8", "0.5,0.9,0.5,1"), ML_REACH_P("puntuales", 1, "1.6", "1", "0.5", "1.5", "1", "0"),
    ML_SPOT_P(0, "0,3,0", "0.4,0,0.3", "1,1,0.8,1", "0.1", "0.3", "1.2"), ML_REACH_P("spots", 0, "10", "1", "0", "0", "0", "1"),
    ML_SPOT_P(1, "-0.8,1.5,1", "0.3,0,-0.2", "0.6,0.6,1,1", "0.2", "0.5", "0.8"),
    ML_REACH_P("spots", 1, "5", "1", "0.1", "0.1", "1", "0"),
    "habiEspec", "true", "ks", "0.6", "n", "10", "posicionCamara", "CAMERA", NULL};

static void multilights(void) {
    emit_case("multilights_repaired.fx", "Material", ML_PARAMS, NULL, NULL, ml_colour(ML), 1);
}

/* Then, in the panel: puntuales[0] switched off and spots[1] on (element 1 of an array). */
static void multilights_panel(void) {
    ml_light l[ML_LIGHTS];
    memcpy(l, ML, sizeof l);
    l[2].on = 0, l[5].on = 1;
    printf(",\n \"panel\": {\"file\": \"multilights_repaired.fx\", \"set\": [[\"puntuales[0].Encender\", \"0\"], "
           "[\"spots[1].Encender\", \"1\"]], \"expect\": ");
    print_rgba(ml_colour(l));
    printf("}");
}

int main(void) {
    v3 e = eye();
    printf("{\"camera\": {\"yaw\": 0, \"pitch\": 60, \"distance\": 3, \"eye\": \"%.6f,%.6f,%.6f\"},\n", e.x, e.y, e.z);
    printf(" \"clear\": ");
    print_rgba(rgba_make(100 / 255.0, 149 / 255.0, 237 / 255.0, 1));
    printf(",\n \"cases\": [");
    ambient();
    ambient_textured();
    fxcomposer_empty();
    tutorial0();
    directional(0);
    directional(1);
    point();
    point_specular();
    phong();
    pointlights();
    spot();
    multilights();
    /* The slider: spot_specular.fx's ks moved from 0.05 to 0.8 in the panel (no channel saturates). */
    printf("],\n \"slider\": {\"file\": \"spot_specular.fx\", \"param\": \"ks\", \"value\": 0.8, \"expect\": ");
    print_rgba(spot_colour(1, 0.8));
    printf("}");
    multilights_panel();
    orbit();
    printf("}\n");
    return 0;
}
