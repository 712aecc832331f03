// poisson_avx512.cpp — serving a 1D or 2D poisson set of 2^j points in its layered order (pattern_poisson.cpp,
// serveLayered) with AVX-512, a 16-float block at a time (simd_avx512.h).
//
// In an aligned block of P = 16 / arity positions b..b+P-1 with b >= P, every position lies in b's layer [B, 2B), so
// position b + i reads stored point (b ^ (seed & (B - 1) & ~(P - 1))) + (i ^ (seed & (P - 1))): one contiguous
// stored block, permuted within. The block at 0 holds the small layers: i ^ (seed & (bit_floor(i) - 1)).
#include "batch_isa.h"
#include "simd_avx512.h"

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include <immintrin.h>

#include <bit>

namespace stipple {

namespace {

template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void layered(const PoissonKernelArgs& a, const float* stored, uint32_t points,
                                       uint32_t first, uint32_t count, float* out) {
    constexpr uint32_t P = 16 / Arity;
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512i point = _mm512_srli_epi32(lane, Arity - 1); // lane's point in the block
    // Lane's axis c reads stored axis source[c]; shift and sign per lane.
    __m512i axis = _mm512_setzero_si512();
    __m512 shift = _mm512_set1_ps(a.shift[0]), sign = _mm512_set1_ps(a.sign[0]);
    if constexpr (Arity == 2) {
        axis = _mm512_mask_set1_epi32(_mm512_set1_epi32(int(a.source[0])), 0xaaaa, int(a.source[1]));
        shift = _mm512_mask_mov_ps(shift, 0xaaaa, _mm512_set1_ps(a.shift[1]));
        sign = _mm512_mask_mov_ps(sign, 0xaaaa, _mm512_set1_ps(a.sign[1]));
    }
    const __m512i seed = _mm512_set1_epi32(int(a.orderSeed));
    // Block 0: bit_floor(i) - 1 per point (0 for i < 2).
    const __m512i smallLayers = _mm512_srli_epi32(
        _mm512_srlv_epi32(_mm512_set1_epi32(-1), _mm512_lzcnt_epi32(_mm512_or_si512(point, _mm512_set1_epi32(1)))), 1);
    const __m512i firstPermute =
        _mm512_add_epi32(_mm512_mullo_epi32(_mm512_xor_si512(point, _mm512_and_si512(seed, smallLayers)),
                                            _mm512_set1_epi32(Arity)),
                         axis);
    const __m512i permute = _mm512_add_epi32(
        _mm512_mullo_epi32(_mm512_xor_si512(point, _mm512_set1_epi32(int(a.orderSeed & (P - 1)))),
                           _mm512_set1_epi32(Arity)),
        axis);
    const __mmask16 storedLanes = points >= P ? 0xffff : __mmask16((1u << (points * Arity)) - 1u);
    for (uint32_t base = 0; base < count; base += P) {
        const uint32_t b = first + base;
        __m512 v;
        if (b == 0) {
            v = _mm512_permutexvar_ps(firstPermute, _mm512_maskz_loadu_ps(storedLanes, stored));
        } else {
            const uint32_t block = b ^ (a.orderSeed & (std::bit_floor(b) - 1) & ~(P - 1));
            v = _mm512_permutexvar_ps(permute, _mm512_loadu_ps(stored + size_t(block) * Arity));
        }
        // wrapUnit(shift + sign * v) of pattern_poisson.cpp (sign * v is exact, so a fused multiply-add rounds the
        // same).
        __m512 r = _mm512_fmadd_ps(sign, v, shift);
        r = _mm512_sub_ps(r, _mm512_cvtepi32_ps(_mm512_cvttps_epi32(r)));
        r = _mm512_add_ps(r, _mm512_castsi512_ps(_mm512_and_si512(_mm512_srai_epi32(_mm512_castps_si512(r), 31),
                                                                   _mm512_set1_epi32(0x3f800000))));
        r = _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(r, _mm512_set1_ps(1.0f), _CMP_LT_OQ), r);
        const uint32_t floats = (count - base < P ? count - base : P) * Arity;
        float* o = out + size_t(base) * Arity;
        if (floats == 16)
            _mm512_storeu_ps(o, r);
        else
            _mm512_mask_storeu_ps(o, __mmask16((1u << floats) - 1u), r);
    }
}

} // namespace

bool poissonLayeredAvx512(const PoissonKernelArgs& args, uint32_t arity, const float* stored, uint32_t points,
                          uint32_t first, uint32_t count, float* out) {
    if (arity > 2 || !std::has_single_bit(points) || first % (16 / arity) != 0) return false;
    if (arity == 1)
        layered<1>(args, stored, points, first, count, out);
    else
        layered<2>(args, stored, points, first, count, out);
    return true;
}

} // namespace stipple
#endif
