/* hfxview's textures (tools/hfxview/textures.c): the file a texture's annotations name
 * (ResourceName, the SDK's `string name`), read beside the effect; DDS files (uncompressed,
 * DXT1, cube maps, volumes) through DevIL; and default textures that are never black, for 2D,
 * cube and volume samplers. The DDS files are written here byte by byte from the DDS header
 * layout (DDS_HEADER, DDS_PIXELFORMAT in Microsoft's documentation), so every expected
 * colour is a texel the test put there. */
#include "test.h"

#include <stdint.h>
#include <string.h>

#include "files.h"
#include "view_support.h"

static char *hfxview, *tmp;

enum { DDSD_CAPS = 0x1, DDSD_HEIGHT = 0x2, DDSD_WIDTH = 0x4, DDSD_PITCH = 0x8, DDSD_PIXELFORMAT = 0x1000,
       DDSD_LINEARSIZE = 0x80000, DDSD_DEPTH = 0x800000, DDPF_ALPHAPIXELS = 0x1, DDPF_FOURCC = 0x4, DDPF_RGB = 0x40,
       DDSCAPS_COMPLEX = 0x8, DDSCAPS_TEXTURE = 0x1000, DDSCAPS2_CUBEMAP_ALL = 0xFE00, DDSCAPS2_VOLUME = 0x200000 };

static void put32(unsigned char *p, uint32_t v) {
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}

/* The 128-byte header of a w x h (x depth) file: A8R8G8B8 texels, or DXT1 when dxt1. */
static void dds_header(unsigned char h[128], int w, int hgt, int depth, uint32_t caps2, int dxt1) {
    memset(h, 0, 128);
    memcpy(h, "DDS ", 4);
    put32(h + 4, 124);
    put32(h + 8, DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PIXELFORMAT | (dxt1 ? DDSD_LINEARSIZE : DDSD_PITCH) |
                     (depth > 1 ? DDSD_DEPTH : 0));
    put32(h + 12, (uint32_t)hgt);
    put32(h + 16, (uint32_t)w);
    put32(h + 20, dxt1 ? 8u : (uint32_t)w * 4);
    put32(h + 24, (uint32_t)(depth > 1 ? depth : 0));
    put32(h + 76, 32); /* DDS_PIXELFORMAT */
    if (dxt1) {
        put32(h + 80, DDPF_FOURCC);
        memcpy(h + 84, "DXT1", 4);
    } else {
        put32(h + 80, DDPF_RGB | DDPF_ALPHAPIXELS);
        put32(h + 88, 32);
        put32(h + 92, 0x00FF0000u);
        put32(h + 96, 0x0000FF00u);
        put32(h + 100, 0x000000FFu);
        put32(h + 104, 0xFF000000u);
    }
    put32(h + 108, DDSCAPS_TEXTURE | (caps2 ? DDSCAPS_COMPLEX : 0));
    put32(h + 112, caps2);
}

static void write_file(const char *name, const unsigned char *a, size_t na, const unsigned char *b, size_t nb) {
    char *path = view_format("%s/%s", tmp, name);
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (f) {
        fwrite(a, 1, na, f);
        if (nb) fwrite(b, 1, nb, f);
        fclose(f);
    }
    free(path);
}

/* n texels of (r, g, b) as A8R8G8B8 memory: B, G, R, A. */
static void fill_bgra(unsigned char *p, int n, int r, int g, int b) {
    for (int i = 0; i < n; i++, p += 4) p[0] = (unsigned char)b, p[1] = (unsigned char)g, p[2] = (unsigned char)r, p[3] = 255;
}

/* An effect whose pixel shader returns `body`, drawn over the whole image (a quad pushed out). */
static void write_effect(const char *name, const char *decls, const char *body) {
    char *src = view_format("%s\nfloat4 VS(float4 p : POSITION) : POSITION { return float4(p.xy * 8, 0.5, 1); }\n"
                            "float4 PS() : COLOR { return %s; }\n"
                            "technique T { pass P { CullMode = None; VertexShader = compile vs_3_0 VS(); "
                            "PixelShader = compile ps_3_0 PS(); } }\n", decls, body);
    write_file(name, (const unsigned char *)src, strlen(src), NULL, 0);
    free(src);
}

/* Renders tmp/fx with hfxview and checks the centre pixel; *messages gets what it printed. */
static void check_render(const char *fx, int r, int g, int b, char **messages) {
    char *cmd = view_format("cd %s && %s %s --mesh quad --size 16x16 -o %s.png", tmp, hfxview, fx, fx);
    char *out = NULL;
    int rc = view_run(cmd, &out);
    if (rc != 0) fprintf(stderr, "%s: exit %d\n%s\n", cmd, rc, out ? out : "");
    CHECK_INT(rc, 0);
    char *png = view_format("%s/%s.png", tmp, fx);
    view_png img;
    if (rc == 0 && view_png_read(&img, png) == 0) {
        if (!view_pixel_near(&img, 8, 8, r, g, b, 1)) {
            const unsigned char *px = view_png_at(&img, 8, 8);
            fprintf(stderr, "%s: centre pixel %d %d %d, want %d %d %d\n", fx, px[0], px[1], px[2], r, g, b);
            CHECK(0);
        }
        view_png_free(&img);
    } else
        CHECK(0);
    if (messages) *messages = out;
    else free(out);
    free(png);
    free(cmd);
}

#define POINT_SAMPLER(kind, name, tex) \
    "sampler" kind " " name " = sampler_state { Texture = <" tex ">; MinFilter = Point; MagFilter = Point; MipFilter = None; };\n"

/* 2x2 A8R8G8B8: row 0 (v = 0) red, green; row 1 blue, white. ResourceName, FX Composer's. */
static void uncompressed_2d_by_resource_name(void) {
    unsigned char h[128], texels[16];
    dds_header(h, 2, 2, 1, 0, 0);
    fill_bgra(texels, 1, 255, 0, 0);
    fill_bgra(texels + 4, 1, 0, 255, 0);
    fill_bgra(texels + 8, 1, 0, 0, 255);
    fill_bgra(texels + 12, 1, 255, 255, 255);
    write_file("rgb.dds", h, sizeof h, texels, sizeof texels);
    const char *decls = "texture T < string ResourceName = \"rgb.dds\"; string ResourceType = \"2D\"; >;\n" POINT_SAMPLER("2D", "s", "T");
    write_effect("row0.fx", decls, "tex2D(s, float2(0.75, 0.25))");
    check_render("row0.fx", 0, 255, 0, NULL);
    write_effect("row1.fx", decls, "tex2D(s, float2(0.25, 0.75))");
    check_render("row1.fx", 0, 0, 255, NULL);
}

/* One DXT1 block: color0 = 0x07E0 (565 green) > color1 = 0x0000, every index 0: all green.
 * (Green, as DevIL 1.7.8 expands 565 red 0xF800 to (255, 0, 7).) The DirectX SDK's
 * `string name = "..."` spelling. */
static void dxt1_by_sdk_name(void) {
    unsigned char h[128], block[8] = {0xE0, 0x07, 0x00, 0x00, 0, 0, 0, 0};
    dds_header(h, 4, 4, 1, 0, 1);
    write_file("red.dds", h, sizeof h, block, sizeof block);
    write_effect("dxt1.fx", "texture T < string name = \"red.dds\"; >;\n" POINT_SAMPLER("2D", "s", "T"),
                 "tex2D(s, float2(0.5, 0.5))");
    check_render("dxt1.fx", 0, 255, 0, NULL);
}

/* A 1x1 cube map, faces +X, -X, +Y, -Y, +Z, -Z in that order in the file. */
static void cube_map_faces(void) {
    static const int colours[6][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {255, 0, 255}, {0, 255, 255}};
    unsigned char h[128], texels[24];
    dds_header(h, 1, 1, 1, DDSCAPS2_CUBEMAP_ALL, 0);
    for (int f = 0; f < 6; f++) fill_bgra(texels + 4 * f, 1, colours[f][0], colours[f][1], colours[f][2]);
    write_file("cube.dds", h, sizeof h, texels, sizeof texels);
    const char *decls = "textureCUBE C < string ResourceName = \"cube.dds\"; string ResourceType = \"Cube\"; >;\n" POINT_SAMPLER("CUBE", "s", "C");
    write_effect("posx.fx", decls, "texCUBE(s, float3(1, 0, 0))");
    check_render("posx.fx", 255, 0, 0, NULL);
    write_effect("negz.fx", decls, "texCUBE(s, float3(0, 0, -1))");
    check_render("negz.fx", 0, 255, 255, NULL);
}

/* A 2x2x2 volume: slice 0 (w = 0.25) orange, slice 1 (w = 0.75) teal. (DevIL 1.7.8 reads
 * only the first slice of a 1x1 volume.) */
static void volume_slices(void) {
    unsigned char h[128], texels[32];
    dds_header(h, 2, 2, 2, DDSCAPS2_VOLUME, 0);
    fill_bgra(texels, 4, 255, 128, 0);
    fill_bgra(texels + 16, 4, 0, 128, 128);
    write_file("vol.dds", h, sizeof h, texels, sizeof texels);
    const char *decls = "texture3D V < string ResourceName = \"vol.dds\"; string ResourceType = \"3D\"; >;\n" POINT_SAMPLER("3D", "s", "V");
    write_effect("slice0.fx", decls, "tex3D(s, float3(0.5, 0.5, 0.25))");
    check_render("slice0.fx", 255, 128, 0, NULL);
    write_effect("slice1.fx", decls, "tex3D(s, float3(0.5, 0.5, 0.75))");
    check_render("slice1.fx", 0, 128, 128, NULL);
}

/* No file, or a missing one: the default checker's first cell, light grey (235), for 2D, cube
 * (a plain `texture` sampled as a cube) and volume; a missing file is a note, not a failure. */
static void defaults_are_never_black(void) {
    write_effect("def3d.fx", "texture3D V;\n" POINT_SAMPLER("3D", "s", "V"), "tex3D(s, float3(0.01, 0.01, 0.01))");
    check_render("def3d.fx", 235, 235, 235, NULL);
    write_effect("defcube.fx", "texture C;\n" POINT_SAMPLER("CUBE", "s", "C"), "texCUBE(s, float3(1, -0.99, -0.99))");
    check_render("defcube.fx", 235, 235, 235, NULL);
    char *messages = NULL;
    write_effect("missing.fx", "texture T < string ResourceName = \"nowhere.dds\"; >;\n" POINT_SAMPLER("2D", "s", "T"),
                 "tex2D(s, float2(0.01, 0.01))");
    check_render("missing.fx", 235, 235, 235, &messages);
    CHECK(messages && strstr(messages, "hfxview: note: T names 'nowhere.dds', not found; using the default texture"));
    free(messages);
}

int main(void) {
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (!hfxview) test_skip("hfxview is not built (it needs OSMesa, libpng and stb)");
    tmp = test_temp_dir();
    RUN(uncompressed_2d_by_resource_name);
    RUN(dxt1_by_sdk_name);
    RUN(cube_map_faces);
    RUN(volume_slices);
    RUN(defaults_are_never_black);
    char *rm = view_format("rm -rf %s", tmp);
    if (!getenv("KEEP_TMP")) view_run(rm, NULL);
    free(rm);
    free(tmp);
    free(hfxview);
    return test_summary();
}
