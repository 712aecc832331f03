// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The names the validation tests' matrices use, standing in for the shim's patterns and the renderer's
// integrators (validation's core library, which these tests exercise, does not load either).
#pragma once

#include "matrix/matrix.h"

namespace stipple::validation::test {

inline const MatrixVocabulary kVocabulary{{"independent", "stratified", "poisson", "poisson-seed"},
                                          {"path", "direct", "direct-light", "direct-bsdf", "bdpt"}};

} // namespace stipple::validation::test
