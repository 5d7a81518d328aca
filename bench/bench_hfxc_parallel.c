/* bench_hfxc_parallel: hfxc on a folder of 100 generated effects, one file at a time (-j1)
 * against one per core (-jN). Prints both wall times and the speed-up; no assertions.
 * Usage: bench_hfxc_parallel [path/to/hfxc] [file count] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "files.h"
#include "bench.h"

/* An effect in the seeds' style, made different per index so nothing can be shared. */
static void write_effect(const char *dir, int i) {
    char path[1024];
    snprintf(path, sizeof path, "%s/fx%03d.fx", dir, i);
    FILE *f = fopen(path, "w");
    if (!f) return;
    int lights = 2 + i % 7;
    fprintf(f,
            "float4x4 world : World;\nfloat4x4 view : View;\nfloat4x4 projection : Projection;\n"
            "float3 lightPos[%d];\nfloat4 lightColor[%d];\n"
            "float ks < string UIWidget = \"slider\"; float UIMin = 0; float UIMax = %d; float UIStep = 0.05; > = {0.%02dF};\n"
            "float4 ambient < string UIName = \"Ambient %d\"; string UIWidget = \"Color\"; > = {0.05, 0.05, 0.%02d, 1};\n"
            "texture2D tex;\n"
            "sampler texSampler = sampler_state { Texture = <tex>; MinFilter = Linear; MagFilter = Linear; AddressU = Wrap; };\n"
            "struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; float3 n : TEXCOORD1; float3 wp : TEXCOORD2; };\n"
            "VSOut mainVS(float3 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) {\n"
            "    VSOut o;\n"
            "    float4x4 wvp = mul(world, mul(view, projection));\n"
            "    o.pos = mul(float4(p, 1), wvp);\n"
            "    o.uv = uv * %d.0;\n"
            "    o.n = mul(n, (float3x3)world);\n"
            "    o.wp = mul(float4(p, 1), world).xyz;\n"
            "    return o;\n"
            "}\n"
            "float4 mainPS(VSOut i, uniform bool textured) : COLOR {\n"
            "    float4 c = ambient;\n"
            "    float3 n = normalize(i.n);\n"
            "    for (int k = 0; k < %d; k++) {\n"
            "        float3 l = normalize(lightPos[k] - i.wp);\n"
            "        c += lightColor[k] * max(dot(n, l), 0) * (1 + ks * pow(max(dot(reflect(-l, n), float3(0, 0, 1)), 0), %d));\n"
            "    }\n"
            "    if (textured) c *= tex2D(texSampler, i.uv);\n"
            "    return c;\n"
            "}\n"
            "technique Textured { pass P0 { CullMode = CCW; VertexShader = compile vs_3_0 mainVS(); PixelShader = compile ps_3_0 mainPS(true); } }\n"
            "technique Plain { pass P0 { VertexShader = compile vs_3_0 mainVS(); PixelShader = compile ps_3_0 mainPS(false); } }\n",
            lights, lights, 5 + i % 20, i % 100, i, i % 100, 1 + i % 4, lights, 2 + i % 30);
    fclose(f);
}

static double child_cpu(void) {
    struct rusage u;
    getrusage(RUSAGE_CHILDREN, &u);
    return (double)u.ru_utime.tv_sec + (double)u.ru_stime.tv_sec + 1e-6 * (double)(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/* Best wall time of `reps` runs (the machine may be shared); *cpu gets that run's CPU time. */
static double run(const char *hfxc, const char *dir, int jobs, int reps, int *status, double *cpu) {
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' --quiet -j %d -o '%s/out/' '%s'/*.fx", hfxc, jobs, dir, dir);
    double best = 1e9;
    for (int r = 0; r < reps; r++) {
        double c0 = child_cpu(), t0 = now();
        int st = system(cmd);
        double t = now() - t0, c = child_cpu() - c0;
        *status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
        if (t < best) {
            best = t;
            *cpu = c;
        }
    }
    return best;
}

int main(int argc, char **argv) {
    char hfxc[2048];
    if (argc > 1) snprintf(hfxc, sizeof hfxc, "%s", argv[1]);
    else {
        /* bench/bench_hfxc_parallel -> compiler/hfxc in the same build tree */
        char self[1536];
        ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
        self[n > 0 ? n : 0] = 0;
        char *slash = strrchr(self, '/');
        if (slash) *slash = 0;
        snprintf(hfxc, sizeof hfxc, "%s/../compiler/hfxc", self);
    }
    int count = argc > 2 ? atoi(argv[2]) : 100;
    if (access(hfxc, X_OK) != 0) {
        fprintf(stderr, "bench_hfxc_parallel: no hfxc at %s (pass its path)\n", hfxc);
        return 1;
    }
    char *dir = test_temp_dir();
    char out[1100];
    snprintf(out, sizeof out, "%s/out", dir);
    if (mkdir(out, 0777) != 0) {
        fprintf(stderr, "bench_hfxc_parallel: cannot create %s\n", out);
        return 1;
    }
    for (int i = 0; i < count; i++) write_effect(dir, i);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int st1, stn;
    double c1, cn;
    run(hfxc, dir, (int)cores, 1, &st1, &c1); /* warm the file cache */
    double t1 = run(hfxc, dir, 1, 5, &st1, &c1);
    double tn = run(hfxc, dir, (int)cores, 5, &stn, &cn);
    printf("hfxc on %d generated effects (%s), best of 5\n", count, dir);
    printf("  -j1: %.3f s wall, %.3f s CPU (exit %d)\n", t1, c1, st1);
    printf("  -j%ld: %.3f s wall, %.3f s CPU (exit %d)\n", cores, tn, cn, stn);
    printf("  speed-up: %.2fx on %ld cores; %.2f ms CPU per effect\n", tn > 0 ? t1 / tn : 0.0, cores,
           1000.0 * c1 / count);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
    free(dir);
    return st1 || stn;
}
