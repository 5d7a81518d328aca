/* hfxview's command line: every option parsed into its field, and the exact usage errors. */
#include "test.h"

#include "../../tools/hfxview/options.c"
#include "../../tools/hfxview/vmath.c"

static int parse(hv_options *o, char *err, size_t errlen, const char *const *args) {
    char *argv[64];
    int argc = 0;
    argv[argc++] = "hfxview";
    for (; *args; args++) argv[argc++] = (char *)*args;
    hv_options_defaults(o);
    err[0] = '\0';
    return hv_options_parse(o, argc, argv, err, errlen);
}

static void defaults(void) {
    hv_options o;
    char err[256];
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"fx/phong.fx", NULL}), 0);
    CHECK_STR(o.input, "fx/phong.fx");
    CHECK(o.output == NULL);
    CHECK_STR(o.mesh, "sphere");
    CHECK_INT(o.pass, -1);
    CHECK_INT(o.width, 512);
    CHECK_INT(o.height, 512);
    CHECK_NEAR(o.background[0], 100 / 255.0, 1e-6); /* CornflowerBlue = (100, 149, 237) */
    CHECK_NEAR(o.background[1], 149 / 255.0, 1e-6);
    CHECK_NEAR(o.background[2], 237 / 255.0, 1e-6);
    CHECK_NEAR(o.fov_degrees, 45, 1e-6);
    CHECK_INT(o.blend_add, 0);
}

static void every_option(void) {
    hv_options o;
    char err[256];
    const char *args[] = {"-o", "out.png", "--technique", "Material", "--pass", "1", "--mesh", "teapot",
                          "--size", "320x200", "--texture", "texturaModelo=wood.png", "--set", "rango=20",
                          "--set=spots[0].Color=1,0,0,1", "--camera", "eye=1,2,3,at=4,5,6,up=0,0,1,fov=60",
                          "--light", "position=0,10,0,color=1,0.5,0.25", "--blend-passes", "add",
                          "--background", "0,0,0", "-DMAX=4", "-I", "inc", "--rotate", "30", "--window",
                          "effect.fx", NULL};
    CHECK_INT(parse(&o, err, sizeof err, args), 0);
    CHECK_STR(err, "");
    CHECK_STR(o.output, "out.png");
    CHECK_STR(o.technique, "Material");
    CHECK_INT(o.pass, 1);
    CHECK_STR(o.mesh, "teapot");
    CHECK_INT(o.width, 320);
    CHECK_INT(o.height, 200);
    CHECK_INT(o.texture_count, 1);
    CHECK(!strncmp(o.textures[0].name, "texturaModelo=", 14));
    CHECK_STR(o.textures[0].value, "wood.png");
    CHECK_INT(o.set_count, 2);
    CHECK_STR(o.sets[1].name, "spots[0].Color=1,0,0,1");
    CHECK_STR(o.sets[1].value, "1,0,0,1");
    CHECK_NEAR(o.eye.x, 1, 0);
    CHECK_NEAR(o.eye.z, 3, 0);
    CHECK_NEAR(o.at.y, 5, 0);
    CHECK_NEAR(o.up.z, 1, 0);
    CHECK_NEAR(o.fov_degrees, 60, 0);
    CHECK_NEAR(o.light_position.y, 10, 0);
    CHECK_NEAR(o.light_color[2], 0.25, 0);
    CHECK_INT(o.light_direction_given, 0);
    CHECK_INT(o.blend_add, 1);
    CHECK_NEAR(o.background[2], 0, 0);
    CHECK_NEAR(o.background[3], 1, 0);
    CHECK_INT(o.define_count, 1);
    CHECK_STR(o.defines[0], "MAX=4");
    CHECK_INT(o.include_dir_count, 1);
    CHECK_STR(o.include_dirs[0], "inc");
    CHECK_NEAR(o.yaw_degrees, 30, 0);
    CHECK_INT(o.window, 1);
    CHECK_STR(o.input, "effect.fx");
}

static void floats(void) {
    float v[4];
    CHECK_INT(hv_parse_floats("1,2.5,-3", v, 4), 3);
    CHECK_NEAR(v[1], 2.5, 0);
    CHECK_NEAR(v[2], -3, 0);
    CHECK_INT(hv_parse_floats("1,,2", v, 4), -1);
    CHECK_INT(hv_parse_floats("1,2,3,4,5", v, 4), -1);
    CHECK_INT(hv_parse_floats("x", v, 4), -1);
    CHECK_INT(hv_parse_floats("", v, 4), -1);
    CHECK_INT(hv_parse_floats("1e99", v, 4), -1); /* out of float range */
}

static void usage_errors(void) {
    hv_options o;
    char err[256];
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){NULL}), -1);
    CHECK_STR(err, "no effect file given");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--frobnicate", NULL}), -1);
    CHECK_STR(err, "unknown option: '--frobnicate'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "b.fx", NULL}), -1);
    CHECK_STR(err, "only one effect file, but also got: 'b.fx'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--size", "512", NULL}), -1);
    CHECK_STR(err, "--size takes WIDTHxHEIGHT, not: '512'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--size", "0x10", NULL}), -1);
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--pass", "first", NULL}), -1);
    CHECK_STR(err, "--pass takes 'all', 'each' or a pass number, not: 'first'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--pass", "-2", NULL}), -1);
    CHECK_STR(err, "--pass takes 'all', 'each' or a pass number, not: '-2'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--pass", "each", NULL}), -1);
    CHECK_STR(err, "--pass each writes one picture a pass: it goes with --technique all");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--pass", "each", "--technique", "all", NULL}), 0);
    CHECK_INT(o.pass, HV_PASS_EACH);
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--camera", "eye=1,2", NULL}), -1);
    CHECK_STR(err, "--camera takes eye=x,y,z,at=x,y,z[,up=x,y,z][,fov=deg], not: 'eye=1,2'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--light", "spot=1,2,3", NULL}), -1);
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--texture", "noequals", NULL}), -1);
    CHECK_STR(err, "--texture takes NAME=FILE, not: 'noequals'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--blend-passes", "multiply", NULL}), -1);
    CHECK_STR(err, "--blend-passes takes 'add' or 'none', not: 'multiply'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "-o", NULL}), -1);
    CHECK_STR(err, "missing output file after: '-o'");
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"--help", NULL}), 0); /* no effect needed */
    CHECK_INT(o.help, 1);
}

static void light_direction(void) {
    hv_options o;
    char err[256];
    CHECK_INT(parse(&o, err, sizeof err, (const char *[]){"a.fx", "--light", "dir=0,-1,0", "--pass=all", NULL}), 0);
    CHECK_INT(o.light_direction_given, 1);
    CHECK_NEAR(o.light_direction.y, -1, 0);
    CHECK_INT(o.pass, HV_PASS_ALL);
}

int main(void) {
    RUN(defaults);
    RUN(every_option);
    RUN(floats);
    RUN(usage_errors);
    RUN(light_direction);
    return test_summary();
}
