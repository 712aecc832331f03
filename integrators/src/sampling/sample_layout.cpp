// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "sampling/sample_layout.h"

#include <stdexcept>

namespace stipple::render {

int SampleLayout::add(const std::string& name, uint32_t arity, uint32_t count) {
    if (find(name) >= 0) throw std::logic_error("dimension '" + name + "' declared twice");
    if (arity < 1 || arity > 3) throw std::logic_error("dimension '" + name + "' has arity outside 1..3");
    dims_.push_back({name, arity, count < 1 ? 1u : count});
    return int(dims_.size()) - 1;
}

int SampleLayout::find(const std::string& name) const {
    for (size_t i = 0; i < dims_.size(); ++i)
        if (dims_[i].name == name) return int(i);
    return -1;
}

std::string SampleLayout::describe() const {
    std::string out;
    for (size_t i = 0; i < dims_.size(); ++i) {
        const Dimension& d = dims_[i];
        out +=
            std::to_string(i) + " " + d.name + " " + std::to_string(d.arity) + "D x" + std::to_string(d.count) + "\n";
    }
    return out;
}

} // namespace stipple::render
