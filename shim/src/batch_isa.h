// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// batch_isa.h — which vector ISA the batch kernels run with.
//
// The batch calls (fill_pixel, stream_fill) of the cheap patterns are loops of integer hashing that the compiler
// vectorises. On x86-64 such a kernel is compiled three times — for the baseline ISA, for AVX2 and for AVX-512
// (F, DQ, VL, BW: 64-bit lane multiplies) — and the widest one this CPU runs is picked at run time. Integer
// arithmetic only, so every variant gives the same bits; the per-point paths (sample, stream) stay scalar.
#pragma once

#include <cstdint>

namespace stipple::detail {

enum class BatchIsa : uint32_t { Baseline = 0, Avx2 = 1, Avx512 = 2 };
inline constexpr uint32_t kBatchIsaCount = 3;

// The variant the batch kernels use: the widest the CPU supports unless lowered by forceBatchIsa. Detected once;
// a sampler takes its pattern's kernels for it when it is created (pattern_registry.h).
BatchIsa batchIsa();
// The widest variant this CPU (and this build) supports.
BatchIsa widestBatchIsa();
// For tests and benchmarks: samplers created from now on use `isa` (clamped to widestBatchIsa()).
void forceBatchIsa(BatchIsa isa);

} // namespace stipple::detail

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define STIPPLE_BATCH_ISA_CLONES 1
#define STIPPLE_TARGET_AVX2 gnu::target("avx2")
#define STIPPLE_TARGET_AVX512 gnu::target("avx512f,avx512dq,avx512vl,avx512bw,avx512cd,avx512vbmi,gfni")
#endif
