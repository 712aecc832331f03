// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// batch_kernel.h — a pattern's batch kernel written once; the template compiles it per BatchIsa and per arity.
//
// A pattern whose batch path is a loop the compiler vectorises writes it as a kernel type:
//
//     struct MyKernel {
//         using Set = ...;                                             // what one set's points are computed from
//         static Set set(const SetKey& key, const Dimension& dim);    // its randomisation, once per call
//         template <uint32_t Arity>
//         [[gnu::always_inline]] static void point(const Set& s, uint32_t p, float* out);
//     };
//
// and its PatternOps reads `.point = kernelPoint<MyKernel>, .fill = kernelFills<MyKernel>()`. The batch loop over
// point<Arity> is compiled once per (ISA, arity): the baseline, AVX2 and AVX-512 clones of batch_isa.h, each a
// function of its own with the target attribute, so the compiler vectorises the same source for each; point()
// is always inlined into them, which is why every variant gives the per-point function's bits. The arity is
// switched once per call, outside the loop.
#pragma once

#include "batch_isa.h"
#include "pattern_registry.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace stipple::detail {

// Points [first, first + count) of a set through Kernel::point<Arity>, compiled for the ISA of the specialisation.
template <BatchIsa Isa>
struct KernelClone {
    template <typename Kernel, uint32_t Arity>
    static void run(const typename Kernel::Set& s, uint32_t first, uint32_t count, float* out) {
        for (uint32_t i = 0; i < count; ++i) Kernel::template point<Arity>(s, first + i, out + size_t(i) * Arity);
    }
};
#if defined(STIPPLE_BATCH_ISA_CLONES)
template <>
struct KernelClone<BatchIsa::Avx2> {
    template <typename Kernel, uint32_t Arity>
    [[STIPPLE_TARGET_AVX2]] static void run(const typename Kernel::Set& s, uint32_t first, uint32_t count, float* out) {
        for (uint32_t i = 0; i < count; ++i) Kernel::template point<Arity>(s, first + i, out + size_t(i) * Arity);
    }
};
template <>
struct KernelClone<BatchIsa::Avx512> {
    template <typename Kernel, uint32_t Arity>
    [[STIPPLE_TARGET_AVX512]] static void run(const typename Kernel::Set& s, uint32_t first, uint32_t count,
                                              float* out) {
        for (uint32_t i = 0; i < count; ++i) Kernel::template point<Arity>(s, first + i, out + size_t(i) * Arity);
    }
};
#endif

// PatternOps::fill's function for one ISA: the set once, then the loop for the dimension's arity.
template <typename Kernel, BatchIsa Isa>
void kernelFill(const SetKey& key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const typename Kernel::Set s = Kernel::set(key, dim);
    switch (dim.arity) {
    case 1: return KernelClone<Isa>::template run<Kernel, 1>(s, first, count, out);
    case 2: return KernelClone<Isa>::template run<Kernel, 2>(s, first, count, out);
    default: return KernelClone<Isa>::template run<Kernel, 3>(s, first, count, out);
    }
}

// PatternOps::point: point p alone, the same inlined point<Arity> as the batch loop's.
template <typename Kernel>
void kernelPoint(const SetKey& key, const Dimension& dim, uint32_t p, float* out) {
    const typename Kernel::Set s = Kernel::set(key, dim);
    switch (dim.arity) {
    case 1: return Kernel::template point<1>(s, p, out);
    case 2: return Kernel::template point<2>(s, p, out);
    default: return Kernel::template point<3>(s, p, out);
    }
}

// PatternOps::fill: the kernel's variant per BatchIsa, in BatchIsa order.
template <typename Kernel>
constexpr std::array<PatternFill, kBatchIsaCount> kernelFills() {
    return {kernelFill<Kernel, BatchIsa::Baseline>, kernelFill<Kernel, BatchIsa::Avx2>,
            kernelFill<Kernel, BatchIsa::Avx512>};
}

} // namespace stipple::detail
