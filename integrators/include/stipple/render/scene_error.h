// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The error a scene file that cannot be loaded raises: scene loading throws it, every caller catches it.
#pragma once

#include <stdexcept>

namespace stipple::render {

// A scene file that cannot be loaded: the message names file:line:column, the key and what was expected.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace stipple::render
