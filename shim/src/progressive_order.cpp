// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// progressive_order.cpp — farthest-point and Morton/radical-inverse orders of a stored toroidal set.
#include "progressive_order.h"

#include <algorithm>
#include <numeric>

namespace stipple::detail {

namespace {

float torusDistance2(const float* a, const float* b, uint32_t arity) {
    float sum = 0.0f;
    for (uint32_t c = 0; c < arity; ++c) {
        float d = a[c] - b[c];
        d = d < 0.0f ? -d : d;
        d = d > 0.5f ? 1.0f - d : d;
        sum += d * d;
    }
    return sum;
}

std::vector<uint32_t> farthestPointOrder(const std::vector<float>& points, uint32_t arity) {
    const uint32_t m = static_cast<uint32_t>(points.size() / arity);
    std::vector<uint32_t> order;
    order.reserve(m);
    std::vector<float> nearest(m, 1e30f); // squared distance to the nearest chosen point
    std::vector<bool> chosen(m, false);
    uint32_t next = 0;
    for (uint32_t step = 0; step < m; ++step) {
        order.push_back(next);
        chosen[next] = true;
        const float* c = &points[size_t(next) * arity];
        float best = -1.0f;
        uint32_t bestIndex = 0;
        for (uint32_t i = 0; i < m; ++i) {
            if (chosen[i]) continue;
            nearest[i] = std::min(nearest[i], torusDistance2(&points[size_t(i) * arity], c, arity));
            if (nearest[i] > best) best = nearest[i], bestIndex = i; // ties: the lowest index, deterministic
        }
        next = bestIndex;
    }
    return order;
}

uint32_t spread10(uint32_t v, uint32_t arity) { // bits of v at every arity-th position
    uint32_t out = 0;
    for (uint32_t b = 0; b < 10; ++b) out |= ((v >> b) & 1u) << (b * arity);
    return out;
}

std::vector<uint32_t> mortonRadicalInverseOrder(const std::vector<float>& points, uint32_t arity) {
    const uint32_t m = static_cast<uint32_t>(points.size() / arity);
    std::vector<uint32_t> curve(m);
    std::iota(curve.begin(), curve.end(), 0u);
    std::vector<uint32_t> code(m);
    for (uint32_t i = 0; i < m; ++i) {
        uint32_t z = 0;
        for (uint32_t c = 0; c < arity; ++c)
            z |= spread10(uint32_t(points[size_t(i) * arity + c] * 1024.0f), arity) << c;
        code[i] = z;
    }
    std::stable_sort(curve.begin(), curve.end(), [&](uint32_t a, uint32_t b) { return code[a] < code[b]; });
    std::vector<uint32_t> position(m); // curve positions in radical-inverse order
    std::iota(position.begin(), position.end(), 0u);
    auto reverse = [](uint32_t v) {
        v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
        v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
        v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
        v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
        return (v >> 16) | (v << 16);
    };
    std::sort(position.begin(), position.end(), [&](uint32_t a, uint32_t b) { return reverse(a) < reverse(b); });
    std::vector<uint32_t> order(m);
    for (uint32_t i = 0; i < m; ++i) order[i] = curve[position[i]];
    return order;
}

} // namespace

void orderProgressively(std::vector<float>& points, uint32_t arity) {
    const uint32_t m = static_cast<uint32_t>(points.size() / arity);
    if (m < 2) return;
    const std::vector<uint32_t> order =
        m <= kFarthestPointLimit ? farthestPointOrder(points, arity) : mortonRadicalInverseOrder(points, arity);
    std::vector<float> reordered(points.size());
    for (uint32_t i = 0; i < m; ++i)
        std::copy_n(&points[size_t(order[i]) * arity], arity, &reordered[size_t(i) * arity]);
    points.swap(reordered);
}

} // namespace stipple::detail
