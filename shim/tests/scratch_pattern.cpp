// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// scratch_pattern.cpp — the scratch build's extra pattern (STIPPLE_TEST_SCRATCH_PATTERN, shim/CMakeLists.txt): a
// pattern added the way shim/README's recipe says, one file and one registry row, which every pattern test must
// then pick up with no change of its own. Not part of the library.
//
// "scratch": a randomly shifted Kronecker sequence (Roberts' R_d: point j is frac(u + (j + 1) * a) per axis, a the
// powers of the inverse of the generalised golden ratio of the arity), in 32-bit fixed point; each block of N
// sample indices and each (pixel, dimension) gets a shift u of its own, so every point is uniform on the cube.
#include "batch_kernel.h"
#include "owen_scrambling.h"
#include "pattern_registry.h"

#include <atomic>

namespace stipple::detail {

namespace {

// How often the library used the pattern (a set prepared or computed): the tests' fixture checks at exit that
// every scratch test reached it.
std::atomic<uint64_t> scratchUses{0};

struct ScratchKernel {
    struct Set {
        uint32_t shift[3];
        uint32_t step[3];
    };
    static Set set(const SetKey& key, const Dimension& dim) {
        scratchUses.fetch_add(1, std::memory_order_relaxed);
        // 2^32 / phi_d^k for d = 1, 2, 3 (phi_1 the golden ratio, phi_2 the plastic number, phi_3 the root of
        // x^4 = x + 1).
        static constexpr uint32_t kSteps[3][3] = {{2654435769u, 0u, 0u},
                                                  {3242174889u, 2447445413u, 0u},
                                                  {3518319154u, 2882110344u, 2360945575u}};
        const uint64_t h0 = hashAt(key.key, 0), h1 = hashAt(key.key, 1);
        const uint32_t* steps = kSteps[dim.arity - 1];
        return Set{{static_cast<uint32_t>(h0), static_cast<uint32_t>(h0 >> 32), static_cast<uint32_t>(h1)},
                   {steps[0], steps[1], steps[2]}};
    }
    template <uint32_t Arity>
    [[gnu::always_inline]] static void point(const Set& s, uint32_t p, float* out) {
        for (uint32_t c = 0; c < Arity; ++c) out[c] = fixedToUnitFloat(s.shift[c] + (p + 1) * s.step[c]);
    }
};

} // namespace

uint64_t scratchPatternUses() { return scratchUses.load(); }

extern const PatternOps kScratchPattern;
constinit const PatternOps kScratchPattern{
    .name = STIPPLE_TEST_SCRATCH_PATTERN,
    .domain = static_cast<HashDomain>(0x5c7a7c40c0ffee0eull), // test-only: not in hash.h's list, used by no other
    .blockKeying = BlockKeying::EveryBlock,
    .prepare = [](Dimension&) { scratchUses.fetch_add(1, std::memory_order_relaxed); },
    .point = kernelPoint<ScratchKernel>,
    .fill = kernelFills<ScratchKernel>(),
};

} // namespace stipple::detail
