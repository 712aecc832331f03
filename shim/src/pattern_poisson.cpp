// pattern_poisson.cpp — serving Poisson-disk sets: "poisson" from the cache, "poisson-seed" generated fresh.
//
// A served set is a stored toroidal set moved by a symmetry of the torus (axis permutation and reflections),
// a Cranley-Patterson shift and a permutation of sample order, all hashed from the set key. These maps are
// isometries of the torus, so they keep the set's minimum distance (rho); the shift makes every sample uniformly
// distributed over [0,1)^arity whatever the stored set is.
#include "error.h"
#include "hash.h"
#include "patterns.h"
#include "permutation.h"
#include "pointsets/pointsets.h"

#include <string>
#include <vector>

namespace stipple {

namespace {

constexpr uint8_t kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

struct TorusMap {
    uint32_t orderSeed;
    uint8_t source[3] = {0, 1, 2}; // output axis c reads stored axis source[c]
    bool reflect[3] = {false, false, false};
    float shift[3];

    TorusMap(uint64_t key, uint32_t arity, bool useSymmetry) : orderSeed(static_cast<uint32_t>(hashAt(key, 1) >> 32)) {
        for (uint32_t c = 0; c < 3; ++c) shift[c] = unitFloat(hashAt(key, 3 + c));
        if (!useSymmetry) return;
        const uint64_t symmetry = hashAt(key, 2);
        const uint32_t axisOrder = arity == 3 ? uint32_t(symmetry % 6) : arity == 2 ? uint32_t(symmetry % 2) * 2 : 0;
        for (uint32_t c = 0; c < 3; ++c) {
            source[c] = kAxisOrders[axisOrder][c];
            reflect[c] = (symmetry >> (32 + c)) & 1;
        }
    }

    // s + x or s - x, wrapped into [0,1) without branches (the wrap is a coin flip per value: a branch would be
    // mispredicted half the time). s - x in (-1, 1) plus 1 may round up to 1.0, which the second step maps to 0;
    // s + x in [1, 2) minus 1 is exact.
    void apply(const float* stored, uint32_t arity, float* out) const {
        for (uint32_t c = 0; c < arity; ++c) {
            const float x = stored[source[c]];
            float v = shift[c] + (reflect[c] ? -x : x);
            v += float(v < 0.0f);
            v -= float(v >= 1.0f);
            out[c] = v;
        }
    }
};

void serve(const TorusMap& map, const Dimension& dim, const float* stored, float* out) {
    for (uint32_t p = 0; p < dim.setSize; ++p) {
        const uint32_t q = permuteIndex(p, dim.setSize, map.orderSeed);
        map.apply(stored + size_t(q) * dim.arity, dim.arity, out + size_t(p) * dim.arity);
    }
}

const float* cachedSet(uint64_t key, const Dimension& dim) {
    const PoissonFamily& family = *dim.poisson;
    return family.set(static_cast<uint32_t>(hashAt(key, 0) % family.setCount()));
}

// A fresh set per call: allocating here is part of the cost the study paid.
std::vector<float> freshSeedSet(uint64_t key, const Dimension& dim) {
    std::vector<float> set = pointsets::generatePoissonSeed(int(dim.arity), dim.setSize, hashAt(key, 6));
    if (set.size() != size_t(dim.setSize) * dim.arity)
        throw Error(STIPPLE_ERROR_INTERNAL, "poisson-seed generator returned " + std::to_string(set.size()) +
                                                " floats; expected " + std::to_string(size_t(dim.setSize) * dim.arity));
    return set;
}

} // namespace

void fillPoisson(uint64_t key, const Dimension& dim, float* out) {
    serve(TorusMap(key, dim.arity, true), dim, cachedSet(key, dim), out);
}

void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
    const TorusMap map(key, dim.arity, true);
    const uint32_t q = permuteIndex(p, dim.setSize, map.orderSeed);
    map.apply(cachedSet(key, dim) + size_t(q) * dim.arity, dim.arity, out);
}

void fillPoissonSeed(uint64_t key, const Dimension& dim, float* out) {
    const std::vector<float> set = freshSeedSet(key, dim);
    serve(TorusMap(key, dim.arity, false), dim, set.data(), out);
}

} // namespace stipple
