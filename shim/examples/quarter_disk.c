/* SPDX-License-Identifier: Apache-2.0 */
/* Copyright 2026 The stipple authors */
/*
 * quarter_disk.c — a plain C99 host of libstipple: estimates the quarter disk area pi/4 with every pattern.
 *
 * Loads the library with dlopen (path from argv[1], else <directory of this executable>/../lib/libstipple.so.1)
 * and uses only the function table from stipple_get_api. For N = 16..4096 it estimates pi/4 = P(x^2 + y^2 < 1)
 * in each of 256 pixels (256 independent estimates) and prints the RMS error per pattern and N.
 *
 * Exit status 0 only if stratified beats independent at every N >= 64 by a one-sided F-test on the mean squared
 * errors (F = MSE_independent / MSE_stratified with (256, 256) degrees of freedom), alpha = 0.01 Sidak-corrected
 * over the 4 tested N. The critical F uses ln F ~ Normal(0, 2/256 + 2/256), accurate to a few percent at 256 dof;
 * theory (RMS ~ N^-0.5 vs N^-0.75) predicts ratios of 10 and more, far above the critical value (about 1.42).
 */
#define _POSIX_C_SOURCE 200809L /* readlink, dlopen */

#include <stipple/stipple.h>

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define PIXELS_X 16
#define PIXELS_Y 16
#define PIXELS (PIXELS_X * PIXELS_Y)

static const stipple_api* api;

static int check(stipple_status status, const char* what) {
    if (status == STIPPLE_OK) return 1;
    fprintf(stderr, "quarter_disk: %s failed with status %d: %s\n", what, (int)status, api->last_error_message());
    return 0;
}

/* Mean squared error of the pi/4 estimate over PIXELS pixels; -1 on error. */
static double meanSquaredError(uint32_t pattern, uint32_t n, float* buffer) {
    const double exact = 0.78539816339744830962;
    stipple_dimension_desc dimension;
    stipple_sampler_desc desc;
    stipple_sampler sampler = NULL;
    double sum = 0.0;
    uint32_t px, py, i;

    memset(&dimension, 0, sizeof dimension);
    dimension.struct_size = sizeof dimension;
    dimension.arity = 2;
    dimension.count = 1;
    dimension.name = "point";
    memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.pattern = pattern;
    desc.samples_per_pixel = n;
    desc.dimension_count = 1;
    desc.seed = 20261121u;
    desc.dimensions = &dimension;
    if (!check(api->sampler_create(&desc, &sampler), "sampler_create")) return -1.0;

    for (py = 0; py < PIXELS_Y; ++py) {
        for (px = 0; px < PIXELS_X; ++px) {
            uint32_t inside = 0;
            double error;
            if (!check(api->sampler_fill_pixel(sampler, px, py, 0, buffer, 2u * n), "sampler_fill_pixel")) {
                api->sampler_release(sampler);
                return -1.0;
            }
            for (i = 0; i < n; ++i) {
                const double x = buffer[2 * i], y = buffer[2 * i + 1];
                inside += x * x + y * y < 1.0;
            }
            error = (double)inside / n - exact;
            sum += error * error;
        }
    }
    api->sampler_release(sampler);
    return sum / PIXELS;
}

static void* openLibrary(const char* argument) {
    char path[4096];
    ssize_t length;
    char* slash;
    if (argument) return dlopen(argument, RTLD_NOW | RTLD_LOCAL);
    length = readlink("/proc/self/exe", path, sizeof path - 1);
    if (length <= 0) return NULL;
    path[length] = '\0';
    slash = strrchr(path, '/');
    if (!slash) return NULL;
    *slash = '\0';
    if (strlen(path) + sizeof "/../lib/libstipple.so.1" > sizeof path) return NULL;
    strcat(path, "/../lib/libstipple.so.1");
    return dlopen(path, RTLD_NOW | RTLD_LOCAL);
}

int main(int argc, char** argv) {
    static const uint32_t counts[] = {16, 64, 256, 1024, 4096};
    const size_t countCount = sizeof counts / sizeof counts[0];
    double mse[STIPPLE_PATTERN_COUNT][5];
    /* Sidak: alpha' = 1 - (1 - 0.01)^(1/4) = 0.002510; z(1 - alpha') = 2.807. */
    const double criticalF = exp(2.807 * sqrt(2.0 / PIXELS + 2.0 / PIXELS));
    stipple_get_api_fn getApi;
    void* library;
    float* buffer;
    uint32_t pattern;
    size_t c;
    int passed = 1;

    library = openLibrary(argc > 1 ? argv[1] : NULL);
    if (!library) {
        fprintf(stderr, "quarter_disk: cannot load libstipple: %s\n", dlerror());
        return 2;
    }
    *(void**)(&getApi) = dlsym(library, "stipple_get_api");
    if (!getApi) {
        fprintf(stderr, "quarter_disk: no stipple_get_api in the library: %s\n", dlerror());
        return 2;
    }
    if (getApi(STIPPLE_ABI_MAJOR, &api) != STIPPLE_OK || api->struct_size < sizeof(stipple_api)) {
        fprintf(stderr, "quarter_disk: the library does not provide ABI %d with a complete table\n", STIPPLE_ABI_MAJOR);
        return 2;
    }
    buffer = malloc(sizeof(float) * 2 * 4096);
    if (!buffer) return 2;

    printf("RMS error of the pi/4 estimate over %d pixels (seed 20261121)\n", PIXELS);
    printf("%-14s", "pattern");
    for (c = 0; c < countCount; ++c) {
        char label[16];
        sprintf(label, "N=%u", (unsigned)counts[c]);
        printf(" %16s", label);
    }
    printf("\n");
    for (pattern = 0; pattern < STIPPLE_PATTERN_COUNT; ++pattern) {
        const char* name = "?";
        api->pattern_name(pattern, &name);
        printf("%-14s", name);
        for (c = 0; c < countCount; ++c) {
            mse[pattern][c] = meanSquaredError(pattern, counts[c], buffer);
            if (mse[pattern][c] < 0.0) {
                free(buffer);
                return 2;
            }
            printf(" %16.3e", sqrt(mse[pattern][c]));
            fflush(stdout);
        }
        printf("\n");
    }

    printf("F-test stratified < independent (critical F = %.3f, alpha 0.01 Sidak over 4 N):\n", criticalF);
    for (c = 1; c < countCount; ++c) {
        const double f = mse[STIPPLE_PATTERN_INDEPENDENT][c] / mse[STIPPLE_PATTERN_STRATIFIED][c];
        const int ok = f > criticalF;
        printf("  N=%-5u F = MSE_independent / MSE_stratified = %8.2f  %s\n", (unsigned)counts[c], f,
               ok ? "pass" : "FAIL");
        passed = passed && ok;
    }
    free(buffer);
    /* The library stays loaded until exit: the function table is static and valid as long as it is. */
    return passed ? 0 : 1;
}
