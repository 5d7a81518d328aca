/* lighting.h: the terms the seeds' lighting equations share, written independently of hfx
 * from the books' formulas, for the tests' reference shaders. `l` is always the unit vector
 * from the surface towards the light. */
#ifndef HFX_SEED_LIGHTING_H
#define HFX_SEED_LIGHTING_H

#include "scene.h"

/* 003 Código 7-7's specular factor at pos with normal n (not renormalised, as the book does):
 *   R = normalize(2 N max(dot(L, N), 0) - L); V = normalize(cam - P); max(dot(R, V), 0)^power */
double seed_book_specular(v3 n, v3 l, v3 pos, v3 cam, double power);
/* 003's distance attenuation: min(1 / (c1 + c2 d + c3 d^2), 1) within range, 0 beyond. */
double seed_book_attenuation(double d, double range, double c1, double c2, double c3);
/* 003's spot cone (the equation after Ilustración 7-25), angles in radians: 1 inside the
 * inner cone, ((cosA - cosF) / (cosT - cosF))^falloff between, 0 outside the outer one. */
double seed_book_spot_cone(double cos_a, double inner, double outer, double falloff);

/* The 000/001 tutorials' specular factor, n and v unit vectors:
 *   R = normalize(2 saturate(dot(N, L)) N - L); saturate(dot(R, V))^power */
double seed_tutorial_specular(v3 n, v3 l, v3 v, double power);

/* The material parameters phong.fx (000) and pointlights.fx (001) share, under the same names. */
typedef struct seed_tutorial_material {
    v3 cam;                                          /* camPosition */
    rgba specular_colour, ambient_colour;            /* SpecularColor, AmbientColor */
    double specular_power, specular_intensity;       /* SpecularPower, SpecularIntensity */
    double ambient_intensity, diffuse_intensity;     /* AmbientIntensity, DiffuseIntensity */
    const seed_texture *tex;                         /* DiffuseTexture */
} seed_tutorial_material;

/* Sets camPosition, SpecularColor... DiffuseTexture, noting failures as seed_set_* do. */
void seed_set_tutorial_material(seed_scene *s, hfx_effect *fx, const seed_tutorial_material *m);

#endif
