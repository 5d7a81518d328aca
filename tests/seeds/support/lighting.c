/* lighting.c: the shared terms of the reference shaders (lighting.h). */
#include "lighting.h"

double seed_book_specular(v3 n, v3 l, v3 pos, v3 cam, double power) {
    v3 refl = v3_normalize(v3_sub(v3_scale(n, 2 * maxd(v3_dot(l, n), 0)), l));
    v3 view = v3_normalize(v3_sub(cam, pos));
    return hlsl_pow(maxd(v3_dot(refl, view), 0), power);
}

double seed_book_attenuation(double d, double range, double c1, double c2, double c3) {
    return d <= range ? mind(1 / (c1 + c2 * d + c3 * d * d), 1) : 0;
}

double seed_book_spot_cone(double cos_a, double inner, double outer, double falloff) {
    double cos_t = cos(inner), cos_f = cos(outer);
    if (cos_a <= cos_f) return 0;
    if (cos_a >= cos_t) return 1;
    return hlsl_pow((cos_a - cos_f) / (cos_t - cos_f), falloff);
}

double seed_tutorial_specular(v3 n, v3 l, v3 v, double power) {
    double diff = saturate(v3_dot(n, l));
    v3 r = v3_normalize(v3_sub(v3_scale(n, 2 * diff), l));
    return hlsl_pow(saturate(v3_dot(r, v)), power);
}

void seed_set_tutorial_material(seed_scene *s, hfx_effect *fx, const seed_tutorial_material *m) {
    seed_set_v3(s, fx, "camPosition", m->cam);
    seed_set_rgba(s, fx, "SpecularColor", m->specular_colour);
    seed_set_float(s, fx, "SpecularPower", m->specular_power);
    seed_set_float(s, fx, "SpecularIntensity", m->specular_intensity);
    seed_set_rgba(s, fx, "AmbientColor", m->ambient_colour);
    seed_set_float(s, fx, "AmbientIntensity", m->ambient_intensity);
    seed_set_float(s, fx, "DiffuseIntensity", m->diffuse_intensity);
    seed_set_texture(s, fx, "DiffuseTexture", m->tex);
}
