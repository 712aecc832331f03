// avx512_intrinsics.h — <immintrin.h> for the hand-written AVX-512 kernels' own files (simd_avx512.h).
//
// GCC 12's AVX-512 headers start some intrinsics from _mm512_undefined_*(), which -W(maybe-)uninitialized reports
// once inlined (GCC bug 105593, fixed in GCC 13). The warnings are silenced for the rest of the including file, so
// only the kernel files include this.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#include <immintrin.h>
