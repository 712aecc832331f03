/* SPDX-License-Identifier: Apache-2.0 */
/* Copyright 2026 The stipple authors */
/* consumer.c — links the installed libstipple directly and draws one stratified pixel. */
#include <stipple/stipple.h>

#include <stdio.h>
#include <string.h>

int main(void) {
    stipple_dimension_desc dim;
    stipple_sampler_desc desc;
    stipple_sampler sampler = NULL;
    float out[32];
    int i;
    memset(&dim, 0, sizeof dim);
    dim.struct_size = sizeof dim;
    dim.arity = 2;
    memset(&desc, 0, sizeof desc);
    desc.struct_size = sizeof desc;
    desc.pattern = STIPPLE_PATTERN_STRATIFIED;
    desc.samples_per_pixel = 16;
    desc.dimension_count = 1;
    desc.dimensions = &dim;
    if (stipple_sampler_create(&desc, &sampler) != STIPPLE_OK ||
        stipple_sampler_fill_pixel(sampler, 0, 0, 0, out, 32) != STIPPLE_OK) {
        fprintf(stderr, "consumer: %s\n", stipple_last_error_message());
        return 1;
    }
    for (i = 0; i < 32; ++i)
        if (!(out[i] >= 0.0f && out[i] < 1.0f)) return 1;
    stipple_sampler_release(sampler);
    printf("consumer: 16 stratified samples drawn through the installed libstipple\n");
    return 0;
}
