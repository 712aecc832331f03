// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The dimension layout a render declares to the shim: an ordered list of named dimensions (arity 1-3, k values
// per pixel sample). Integrators add only what the scene needs, so a scene "asks only for what it uses".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stipple::render {

struct Dimension {
    std::string name; // e.g. "pixel", "lens", "b3.light.pos"
    uint32_t arity = 1;
    uint32_t count = 1; // k values per pixel sample
};

class SampleLayout {
public:
    // Appends a dimension and returns its index (what SampleView reads by).
    int add(const std::string& name, uint32_t arity, uint32_t count = 1);
    int find(const std::string& name) const; // -1 when absent
    const std::vector<Dimension>& dimensions() const { return dims_; }
    size_t size() const { return dims_.size(); }
    // One line per dimension: "<index> <name> <arity>D x<k>".
    std::string describe() const;

private:
    std::vector<Dimension> dims_;
};

} // namespace stipple::render
