/* SPDX-License-Identifier: Apache-2.0 */
/* Copyright 2026 The stipple authors */
/*
 * stipple.h — the C ABI of libstipple: deterministic sample streams for Monte Carlo rendering.
 *
 * C99 and C++ compatible. Nothing here owns host memory, throws, aborts or prints.
 *
 * ABI promise (major version STIPPLE_ABI_MAJOR):
 *   - Functions are never removed or changed in signature within a major version; new ones are appended to
 *     the end of stipple_api, whose first field is its own size.
 *   - Structs passed in begin with struct_size; the library accepts any size >= the size of the first
 *     released version and ignores nothing silently (unknown trailing fields must be zero).
 *   - No enum or bool appears in a struct: enumerations are uint32_t with #defined values.
 *
 * Loading:
 *   - dlopen host: dlopen("libstipple.so.1"), dlsym("stipple_get_api"), call it with STIPPLE_ABI_MAJOR.
 *   - linking host: link -lstipple and call the stipple_* functions directly (same semantics).
 *
 * Sample stream semantics:
 *   - A sampler is made from a pattern, N = samples per pixel, a 64-bit seed and optionally the host's
 *     dimension layout: an ordered list of dimensions, each of arity 1, 2 or 3 with a count k >= 1 of values
 *     per pixel sample. Only what is asked for is generated.
 *   - Streams (1.1; no layout needed, dimension_count may be 0): stipple_sampler_stream asks dimension index d
 *     (the host's own call counter, any uint32) with the arity it wants at that call. Stream (d, arity) is one
 *     set of N points of that arity per pixel, randomised independently of every other (d, arity) and of the
 *     declared layout. Asking one index d with two arities gives two independent sets (the 1D value is not
 *     the first axis of the 2D one); each is a full set of the pattern on its own. Keep one arity per index
 *     to keep its stratification across the samples of a pixel.
 *   - Any sample index (1.1): index i is position i mod N of block i / N. Each block of N consecutive indices
 *     is a full, independently randomised set of the pattern; sobol's block b is instead the next Sobol' block
 *     of the same scrambled sequence (blocks 0..2^j-1 together are again a net), and pmj02's blocks continue
 *     the set's sequence for 8 blocks of a power-of-two set (sequences of up to 65536 points: a set of 2^16
 *     points has none past it, a set of 2^14 four blocks), then start a fresh set. 4N samples of an N-sample
 *     sobol or pmj02 sampler have the MSE of a fresh 4N set (0.93-1.03x on the integrand battery, N = 16-1024,
 *     shim/POINTSETS.md; pmj02's are the fresh 4N set's samples up to 4N = 1024). stratified (power-of-two grids) and poisson order a set so that its prefixes are well
 *     spread; sobol and pmj02 are progressive (README: "Any sample count"). The same for fill_pixel (block 0), sample, stream and stream_fill, with or
 *     without STIPPLE_SAMPLER_FLAG_BLUE_NOISE.
 *   - Periods: sobol, lattice and halton blocks continue one sequence with a 32-bit index, so a set of
 *     M = k*N points serves P sample indices from one sequence: P = N * 2^(32 - ceil(log2 M)) for sobol and
 *     lattice, N * floor(2^32 / M) for halton (N = 3: P = 3 * 2^30; arrays of k = 1024 at N = 4096: P = 2^22).
 *     Index i >= P is served from a freshly randomised sequence (its generation i / P), block (i mod P) / N of
 *     it: sample i + P is an independent draw, never a repeat of sample i. P >= 2^32 is never reached.
 *   - Every value is a pure function of (seed, pixel x, pixel y, sample index, dimension, value index):
 *     bitwise the same for any thread count, tile order or call order. A sampler handle is immutable after
 *     creation and may be shared by any number of threads for sampling.
 *   - For one pixel and one dimension, the k*N values (k per pixel sample) form one well-distributed set
 *     of the pattern (one stratification / one Poisson disk set of k*N points). Different dimensions and
 *     pixels get independently randomised sets, so dimensions are not correlated.
 *   - Values lie in [0, 1): never 1.0 and never negative.
 *   - Past the declared layout: fill/sample calls with a dimension index >= dimension_count fail with
 *     STIPPLE_ERROR_OUT_OF_RANGE. A host that needs values past its layout (for example, bounces deeper
 *     than it declared) calls stipple_sampler_sample_independent, which serves independent uniform values
 *     hashed from (seed, pixel, sample index, stream index) — defined, deterministic, never stratified.
 *
 * Errors: every function returns a stipple_status. On failure a message for the calling thread, naming the
 * argument, its value and what was expected, is available from stipple_last_error_message() until the next
 * failing call on that thread.
 */
#ifndef STIPPLE_STIPPLE_H
#define STIPPLE_STIPPLE_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define STIPPLE_API
#elif defined(__GNUC__)
#define STIPPLE_API __attribute__((visibility("default")))
#else
#define STIPPLE_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define STIPPLE_ABI_MAJOR 1
#define STIPPLE_ABI_MINOR 2

/* ---- status codes --------------------------------------------------------------------------------- */
typedef int32_t stipple_status;
#define STIPPLE_OK 0
#define STIPPLE_ERROR_NULL_ARGUMENT 1    /* a required pointer was NULL */
#define STIPPLE_ERROR_INVALID_ARGUMENT 2 /* a value outside its allowed set (unknown pattern, arity 4, ...) */
#define STIPPLE_ERROR_OUT_OF_RANGE 3     /* a count or index too large or zero (N, dimension index, buffer) */
#define STIPPLE_ERROR_STRUCT_SIZE 4      /* struct_size smaller than the first released version */
#define STIPPLE_ERROR_ABI_VERSION 5      /* the host was built for another ABI major version */
#define STIPPLE_ERROR_OUT_OF_MEMORY 6
#define STIPPLE_ERROR_INTERNAL 7 /* a bug: please report the message */

/* ---- patterns --------------------------------------------------------------------------------------- */
#define STIPPLE_PATTERN_INDEPENDENT 0u  /* counter-based hash, no shared RNG state */
#define STIPPLE_PATTERN_STRATIFIED 1u   /* jittered strata; any N (see README for non-square N) */
#define STIPPLE_PATTERN_POISSON 2u      /* amortised Poisson disk sets, toroidal, served with a random torus
                                          * symmetry and shift: 2D/3D dart throwing at rho 0.76 / 0.72, whose
                                          * served spectrum matches fresh dart throwing at that radius (largest
                                          * periodogram value 0.91-1.13x, RAPS peak 0.96-1.03x, N = 16-1024,
                                          * shim/docs/tables/spectra-dart.md; no crystal peaks; its ring stands above
                                          * the study's rho 0.52 dart throwing's); 1D one point per cell (of a
                                          * shifted grid, rho >= 0.2). Not "never worse than stratified": on
                                          * the grown 2D battery (shim/docs/tables/grown.md) 0.78x on gratings, 1.3-2.2x
                                          * on steps and edges at N = 64-256; shim/POINTSETS.md */
#define STIPPLE_PATTERN_POISSON_SEED 3u /* the study's dart throwing (Algorithm 1), generated per set */
#define STIPPLE_PATTERN_SOBOL 4u        /* Owen-scrambled Sobol' (hash-based, nested uniform), padded per dimension */
#define STIPPLE_PATTERN_PMJ02 5u        /* progressive multi-jittered (0,2) sequences; sets <= 65536 points; 3D:
                                          * (x, y) as in 2D, z stratified at every 2^k prefix and inside each
                                          * (x, y) cell of side 2^-r at 2^-(k-2r) (a jittered 3D set at 8^r
                                          * points; the 2^r x 2^r grids of (x, z), (y, z) hold equal counts) */
#define STIPPLE_PATTERN_LATTICE 6u      /* randomly shifted rank-1 lattice sequence, extensible in base 2 */
#define STIPPLE_PATTERN_HALTON 7u       /* scrambled Halton (bases 2, 3, 5 per set), padded per dimension */
#define STIPPLE_PATTERN_COUNT 8u

/* ---- sampler flags (stipple_sampler_desc.flags) ------------------------------------------------------ */
/* Screen-space blue noise, for STIPPLE_PATTERN_STRATIFIED only (stipple_pattern_get_limits' flags say so per
 * pattern): the pixels of each 64 x 64 tile stratify every stratum among themselves through a lattice map hashed
 * per tile from a family, so the per-pixel error is spread as blue noise over the image while each pixel's set
 * keeps exactly the plain pattern's distribution. Measured low-frequency gain (low-quarter error energy without /
 * with the flag; shim/docs/tables/blue-noise-grown.md, shim_blue_noise_gain --grown, 8 images of 128 x 128 pixels, fixed
 * seeds) at N = 16, 64, 256 on the grown battery (checkerboards 7 x 7 to 24 x 24, gratings cos(2 pi k.x) at every
 * |k| <= 2 sqrt(N), thin stripes, axis and near-axis steps, edges at 16 orientations, opposite bumps across a
 * stratum face): no integrand's 95% interval lies below 1; the least gain per family is 1.36-17 at N = 16, 1.08-13
 * at 64, and at 256 2.0-12 except gratings, whose least of 1604 estimates is 0.71 [0.50, 1.39] (that grating's
 * predicted gain, shim/bench/lattice_search.py: 1.42); median gains 1.6-17. On the standard 2D battery
 * (shim_blue_noise_gain --patterns stratified, 12 images): 200-670x on smooth integrands, 4.7-15x on edges,
 * 1.1-1.7x on the Genz discontinuous family, 1.35-15x on the zone plate. Per-pixel MSE unchanged. Every
 * other pattern refuses the flag at creation with STIPPLE_ERROR_INVALID_ARGUMENT and a message saying why:
 * independent has no strata to share, and a lattice map of the unit square put checkerboard and grating error
 * into the low band (2.2-2.4x the plain pattern's on an 8 x 8 checkerboard); for the others a per-pixel shift of a
 * tile-shared set added low-frequency error on non-periodic integrands. Works for declared layouts and streams, in
 * every block. Unknown bits are rejected. */
#define STIPPLE_SAMPLER_FLAG_BLUE_NOISE 1u

/* ---- limits ----------------------------------------------------------------------------------------- */
#define STIPPLE_MAX_SAMPLES_PER_PIXEL (1u << 20) /* N */
#define STIPPLE_MAX_VALUES_PER_SAMPLE 1024u      /* k of one dimension */
#define STIPPLE_MAX_SET_SIZE (1u << 22)          /* k*N of one dimension */
#define STIPPLE_MAX_DIMENSIONS 4096u
#define STIPPLE_MAX_NAME_LENGTH 63u

typedef struct stipple_sampler_t* stipple_sampler; /* opaque handle */

/* One entry of the host's dimension layout. */
typedef struct stipple_dimension_desc {
    uint32_t struct_size; /* sizeof(stipple_dimension_desc) */
    uint32_t arity;       /* 1, 2 or 3 floats per value */
    uint32_t count;       /* k >= 1 values per pixel sample; 0 is read as 1 */
    uint32_t reserved;    /* must be 0 */
    const char* name;     /* optional (may be NULL), <= STIPPLE_MAX_NAME_LENGTH chars; copied */
} stipple_dimension_desc;

typedef struct stipple_sampler_desc {
    uint32_t struct_size;       /* sizeof(stipple_sampler_desc) */
    uint32_t pattern;           /* STIPPLE_PATTERN_* */
    uint32_t samples_per_pixel; /* N, 1..STIPPLE_MAX_SAMPLES_PER_PIXEL */
    uint32_t dimension_count;   /* 0..STIPPLE_MAX_DIMENSIONS (0 since 1.1: streams only, dimensions unread) */
    uint64_t seed;              /* any value */
    const stipple_dimension_desc* dimensions; /* dimension_count entries, copied */
    uint32_t flags;                           /* STIPPLE_SAMPLER_FLAG_* bits; unknown bits are rejected */
    uint32_t reserved;                        /* must be 0 */
} stipple_sampler_desc;

typedef struct stipple_sampler_info {
    uint32_t struct_size; /* set by the caller to sizeof(stipple_sampler_info) */
    uint32_t pattern;
    uint32_t samples_per_pixel;
    uint32_t dimension_count;
    uint64_t seed;
} stipple_sampler_info;

typedef struct stipple_dimension_info {
    uint32_t struct_size; /* set by the caller to sizeof(stipple_dimension_info) */
    uint32_t arity;
    uint32_t count;            /* k */
    uint32_t floats_per_pixel; /* N * k * arity: the size fill_pixel writes */
    const char* name;          /* owned by the sampler, "" when unnamed; valid until release */
    uint32_t strata[3];        /* stratified: strata per axis for the set of k*N points; others 0 */
    uint32_t reserved;
} stipple_dimension_info;

/* ---- functions (also reachable through stipple_api) -------------------------------------------------- */

/* The message of the calling thread's last failure ("" if none). Valid until that thread's next failure. */
STIPPLE_API const char* stipple_last_error_message(void);

STIPPLE_API stipple_status stipple_get_version(uint32_t* major, uint32_t* minor, uint32_t* patch);

/* "independent", "stratified", "poisson", "poisson-seed", "sobol", "pmj02", "lattice", "halton" <->
 * STIPPLE_PATTERN_*. Names are static strings. */
STIPPLE_API stipple_status stipple_pattern_from_name(const char* name, uint32_t* out_pattern);
STIPPLE_API stipple_status stipple_pattern_name(uint32_t pattern, const char** out_name);

STIPPLE_API stipple_status stipple_sampler_create(const stipple_sampler_desc* desc, stipple_sampler* out_sampler);
/* Releasing NULL is a no-op returning STIPPLE_OK. The handle must not be in use by another thread. */
STIPPLE_API stipple_status stipple_sampler_release(stipple_sampler sampler);

STIPPLE_API stipple_status stipple_sampler_get_info(stipple_sampler sampler, stipple_sampler_info* out_info);
STIPPLE_API stipple_status stipple_sampler_get_dimension_info(stipple_sampler sampler, uint32_t dimension,
                                                              stipple_dimension_info* out_info);
/* Index of the first dimension with this name; STIPPLE_ERROR_INVALID_ARGUMENT if none. */
STIPPLE_API stipple_status stipple_sampler_find_dimension(stipple_sampler sampler, const char* name,
                                                          uint32_t* out_dimension);

/* Batch call (the fast path): all N samples of pixel (x, y) for one dimension.
 * Writes N*k*arity floats, sample-major: out[((i * k) + j) * arity + c] for sample i, value j, axis c.
 * out_count is the capacity of out in floats and must be >= N*k*arity. */
STIPPLE_API stipple_status stipple_sampler_fill_pixel(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                      uint32_t dimension, float* out, size_t out_count);

/* Random access: the k values of one pixel sample for one dimension (k*arity floats), equal bitwise to the
 * corresponding part of stipple_sampler_fill_pixel. Since 1.1 any sample_index is served: index i >= N reads
 * block i / N (1.0 returned STIPPLE_ERROR_OUT_OF_RANGE). */
STIPPLE_API stipple_status stipple_sampler_sample(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                  uint32_t sample_index, uint32_t dimension, float* out,
                                                  size_t out_count);

/* Past the layout: out_count independent uniform floats in [0,1) for (pixel, sample index, stream). */
STIPPLE_API stipple_status stipple_sampler_sample_independent(stipple_sampler sampler, uint32_t pixel_x,
                                                              uint32_t pixel_y, uint32_t sample_index, uint32_t stream,
                                                              float* out, size_t out_count);

/* ---- 1.1: streams (no layout needed), any sample index ------------------------------------------------ */

/* One value of stream (dimension, arity) for pixel (x, y), sample sample_index: arity floats (1, 2 or 3).
 * Works on any sampler (with or without a declared layout); out_count >= arity. */
STIPPLE_API stipple_status stipple_sampler_stream(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                  uint32_t sample_index, uint32_t dimension, uint32_t arity, float* out,
                                                  size_t out_count);

/* Batch call of a stream: samples first_sample .. first_sample + sample_count - 1 (sample_count >= 1,
 * first_sample + sample_count <= 2^32), sample-major: out[i * arity + c]. Equal bitwise to sample_count
 * stipple_sampler_stream calls. out_count >= sample_count * arity. */
STIPPLE_API stipple_status stipple_sampler_stream_fill(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                       uint32_t first_sample, uint32_t sample_count, uint32_t dimension,
                                                       uint32_t arity, float* out, size_t out_count);

/* ---- 1.2: sample arrays, pattern listing and limits, flags by name ------------------------------------- */

/* Array streams: k values per sample of one array (pbrt-v3's Get1DArray / Get2DArray), stratified as one set of
 * N*k points per pixel and block, as a declared dimension of count k is: sample i's values are points i*k .. i*k+k-1
 * of block i / N. Array (index, arity, k) is keyed in an index space of its own: array a is never call-order
 * stream a (not even with k = 1), and arrays of different arity or k are independent sets. Any array index
 * (uint32) is served; 1 <= k <= STIPPLE_MAX_VALUES_PER_SAMPLE and k*N within the pattern's max_set_size
 * (stipple_pattern_get_limits), else STIPPLE_ERROR_OUT_OF_RANGE. */

/* The k values of array (array_index, arity, k) for one sample: k*arity floats, out[j * arity + c]. */
STIPPLE_API stipple_status stipple_sampler_array(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                 uint32_t sample_index, uint32_t array_index, uint32_t arity,
                                                 uint32_t k, float* out, size_t out_count);
/* Samples first_sample .. first_sample + sample_count - 1 of one array: sample_count*k*arity floats,
 * out[((i * k) + j) * arity + c], equal bitwise to sample_count stipple_sampler_array calls. */
STIPPLE_API stipple_status stipple_sampler_array_fill(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                      uint32_t first_sample, uint32_t sample_count,
                                                      uint32_t array_index, uint32_t arity, uint32_t k, float* out,
                                                      size_t out_count);

/* Stream indices STIPPLE_STREAM_RESERVED_FIRST .. 0xffffffff are reserved for the streams stipple.hpp uses itself
 * (the film position within the pixel: 0xffffffff). A host's own call counters stay below. */
#define STIPPLE_STREAM_RESERVED_FIRST 0xffffff00u

/* Pattern listing: ids 0 .. count-1 (stipple_pattern_name gives each one's name). */
STIPPLE_API stipple_status stipple_pattern_count(uint32_t* out_count);

/* What a pattern serves, to check sizes before creating a sampler or asking an array. */
typedef struct stipple_pattern_limits {
    uint32_t struct_size;           /* set by the caller to sizeof(stipple_pattern_limits) */
    uint32_t max_samples_per_pixel; /* the largest N */
    uint32_t max_set_size;          /* the largest k*N of one dimension or array */
    uint32_t max_values_per_sample; /* the largest k */
    uint32_t max_dimensions;        /* the largest dimension_count */
    uint32_t flags;                 /* STIPPLE_SAMPLER_FLAG_* bits the pattern accepts */
} stipple_pattern_limits;
STIPPLE_API stipple_status stipple_pattern_get_limits(uint32_t pattern, stipple_pattern_limits* out_limits);

/* "<pattern>" or "<pattern>+blue-noise" -> pattern id and STIPPLE_SAMPLER_FLAG_* bits (the tools' spelling).
 * stipple_pattern_from_name accepts the bare names only. */
STIPPLE_API stipple_status stipple_pattern_parse(const char* name, uint32_t* out_pattern, uint32_t* out_flags);

/* ---- the dlopen entry point --------------------------------------------------------------------------- */
typedef struct stipple_api {
    uint32_t struct_size; /* sizeof the table this library provides; grows with minor versions */
    uint32_t abi_major;
    uint32_t abi_minor;
    uint32_t reserved;
    const char* (*last_error_message)(void);
    stipple_status (*get_version)(uint32_t*, uint32_t*, uint32_t*);
    stipple_status (*pattern_from_name)(const char*, uint32_t*);
    stipple_status (*pattern_name)(uint32_t, const char**);
    stipple_status (*sampler_create)(const stipple_sampler_desc*, stipple_sampler*);
    stipple_status (*sampler_release)(stipple_sampler);
    stipple_status (*sampler_get_info)(stipple_sampler, stipple_sampler_info*);
    stipple_status (*sampler_get_dimension_info)(stipple_sampler, uint32_t, stipple_dimension_info*);
    stipple_status (*sampler_find_dimension)(stipple_sampler, const char*, uint32_t*);
    stipple_status (*sampler_fill_pixel)(stipple_sampler, uint32_t, uint32_t, uint32_t, float*, size_t);
    stipple_status (*sampler_sample)(stipple_sampler, uint32_t, uint32_t, uint32_t, uint32_t, float*, size_t);
    stipple_status (*sampler_sample_independent)(stipple_sampler, uint32_t, uint32_t, uint32_t, uint32_t, float*,
                                                 size_t);
    /* 1.1 (present when struct_size >= offsetof(stipple_api, sampler_stream_fill) + sizeof(void*)) */
    stipple_status (*sampler_stream)(stipple_sampler, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t, float*, size_t);
    stipple_status (*sampler_stream_fill)(stipple_sampler, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t,
                                          float*, size_t);
    /* 1.2 (present when struct_size >= offsetof(stipple_api, pattern_parse) + sizeof(void*)) */
    stipple_status (*sampler_array)(stipple_sampler, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t, float*,
                                    size_t);
    stipple_status (*sampler_array_fill)(stipple_sampler, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t, uint32_t,
                                         uint32_t, float*, size_t);
    stipple_status (*pattern_count)(uint32_t*);
    stipple_status (*pattern_get_limits)(uint32_t, stipple_pattern_limits*);
    stipple_status (*pattern_parse)(const char*, uint32_t*, uint32_t*);
} stipple_api;

/* Returns the function table for ABI major version abi_major, or STIPPLE_ERROR_ABI_VERSION (with a
 * message) when this library does not implement it. The table is static: never freed. */
STIPPLE_API stipple_status stipple_get_api(uint32_t abi_major, const stipple_api** out_api);
typedef stipple_status (*stipple_get_api_fn)(uint32_t abi_major, const stipple_api** out_api);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* STIPPLE_STIPPLE_H */
