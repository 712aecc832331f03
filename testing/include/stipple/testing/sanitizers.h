// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Whether this test program is built with a sanitizer. GCC defines __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__;
// clang (up to 16) only answers __has_feature. Tests use it to skip what a sanitizer makes meaningless or minutes
// long (memory peaks, a 2^20-point relaxation), never to skip a check.
#pragma once

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define STIPPLE_TESTING_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define STIPPLE_TESTING_SANITIZED 1
#endif
#endif
#ifndef STIPPLE_TESTING_SANITIZED
#define STIPPLE_TESTING_SANITIZED 0
#endif

namespace stipple::testing {
inline constexpr bool kUnderSanitizer = STIPPLE_TESTING_SANITIZED != 0;
} // namespace stipple::testing
