/* SPDX-License-Identifier: Apache-2.0 */
/* Copyright 2026 The stipple authors */
/* header_c99.c — the public header must compile as strict C99 (-std=c99 -pedantic -Wall -Wextra -Werror) and,
 * compiled as C++ (-x c++), as strict C++20. Also checks the sizes the ABI promises on LP64. */
#include <stipple/stipple.h>

#ifdef __cplusplus
#define STIPPLE_STATIC_ASSERT(c, m) static_assert(c, #m)
#else
#define STIPPLE_STATIC_ASSERT(c, m) typedef char m[(c) ? 1 : -1]
#endif

STIPPLE_STATIC_ASSERT(sizeof(stipple_dimension_desc) == 24, dimension_desc_is_24_bytes);
STIPPLE_STATIC_ASSERT(sizeof(stipple_sampler_desc) == 40, sampler_desc_is_40_bytes);
STIPPLE_STATIC_ASSERT(sizeof(stipple_sampler_info) == 24, sampler_info_is_24_bytes);
STIPPLE_STATIC_ASSERT(sizeof(stipple_dimension_info) == 40, dimension_info_is_40_bytes);
STIPPLE_STATIC_ASSERT(offsetof(stipple_api, last_error_message) == 16, api_table_header_is_16_bytes);

int stipple_header_c99_check(void);
int stipple_header_c99_check(void) {
    stipple_get_api_fn entry = &stipple_get_api;
    const stipple_api* api = 0;
    return entry(STIPPLE_ABI_MAJOR, &api) == STIPPLE_OK ? (int)api->struct_size : -1;
}
