// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// batch_isa.cpp — the run-time pick of the batch kernels' ISA (see batch_isa.h).
#include "batch_isa.h"

#include <atomic>

namespace stipple::detail {

namespace {

BatchIsa detect() {
#if defined(STIPPLE_BATCH_ISA_CLONES)
    __builtin_cpu_init(); // needed before __builtin_cpu_supports during static initialisation
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512cd") &&
        __builtin_cpu_supports("avx512vbmi") &&
        __builtin_cpu_supports("gfni"))
        return BatchIsa::Avx512;
    if (__builtin_cpu_supports("avx2")) return BatchIsa::Avx2;
#endif
    return BatchIsa::Baseline;
}

std::atomic<BatchIsa>& current() {
    static std::atomic<BatchIsa> isa{widestBatchIsa()};
    return isa;
}

} // namespace

BatchIsa widestBatchIsa() {
    static const BatchIsa widest = detect();
    return widest;
}

BatchIsa batchIsa() { return current().load(std::memory_order_relaxed); }

void forceBatchIsa(BatchIsa isa) {
    current().store(static_cast<uint32_t>(isa) < static_cast<uint32_t>(widestBatchIsa()) ? isa : widestBatchIsa(),
                    std::memory_order_relaxed);
}

} // namespace stipple::detail
