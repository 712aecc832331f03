// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// ctest-labels: unit
// lattice_halton_test.cpp — what the lattice and halton constructions promise, exactly (no alpha).
//
// lattice: the 2^j first samples of a stream (any seed, pixel, stream) are a rank-1 lattice of 2^j points shifted
// by one vector: point differences are multiples of z / 2^j mod 1 (z = 1, 364981, 245389), and blocks past N
// continue the sequence (4N samples of an N sampler are the lattice of 4N points). Every 1D projection of 2^j
// samples has one point in each interval of length 2^-j.
// halton: axis a of the first b_a^k samples of a set (b = 2, 3, 5) has one point in each interval of length
// b_a^-k, at N = b^k and across blocks (the first B blocks are the first B * N points of the sequence).
#define BOOST_TEST_MODULE lattice_halton
#include <boost/test/unit_test.hpp>

#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace {

// A streams-only sampler through the kit (stipple.hpp): s is its handle for the C calls under test.
struct Owned {
    stipple::Sampler sampler;
    stipple_sampler s = nullptr;
};

void create(Owned& o, const char* pattern, uint32_t n, uint64_t seed) {
    const stipple::Status status = stipple::Sampler::create(o.sampler, pattern, n, seed);
    BOOST_REQUIRE_MESSAGE(status.ok(), status.message());
    o.s = o.sampler.handle();
}

std::vector<float> stream(const Owned& o, uint32_t px, uint32_t py, uint32_t first, uint32_t count, uint32_t d,
                          uint32_t arity) {
    std::vector<float> v(size_t(count) * arity);
    BOOST_REQUIRE_EQUAL(stipple_sampler_stream_fill(o.s, px, py, first, count, d, arity, v.data(), v.size()),
                        STIPPLE_OK);
    return v;
}

// Floats of the shim are multiples of 2^-24: exact as 32-bit fractions.
uint32_t toFixed(float v) { return static_cast<uint32_t>(double(v) * 4294967296.0); }

// True when the values' axis c has one point in each of `cells` equal intervals.
bool onePerInterval(const std::vector<float>& v, uint32_t arity, uint32_t c, uint32_t cells) {
    std::set<uint32_t> seen;
    for (size_t i = c; i < v.size(); i += arity) seen.insert(static_cast<uint32_t>(double(v[i]) * cells));
    return seen.size() == cells && v.size() / arity == cells;
}

constexpr uint32_t kLatticeVector[3] = {1u, 364981u, 245389u};

// The 2^j points are {k z / 2^j + shift}: each point minus the first is k z / 2^j for one k in [0, 2^j), up to the
// 8 bits the float drops (values keep 24 bits of the 32-bit fixed point).
bool isShiftedLattice(const std::vector<float>& v, uint32_t arity, uint32_t log2Points) {
    const uint32_t points = 1u << log2Points;
    std::set<uint32_t> ks;
    for (uint32_t i = 0; i < points; ++i) {
        // k from axis 0 (z = 1): the difference's top log2Points bits, rounded through the dropped bits
        const uint32_t d0 = toFixed(v[i * arity]) - toFixed(v[0]);
        const uint32_t k = static_cast<uint32_t>((uint64_t(d0) + (1u << 31 >> log2Points)) >> (32 - log2Points)) &
                           (points - 1);
        for (uint32_t c = 0; c < arity; ++c) {
            const uint32_t expected = uint32_t((uint64_t(kLatticeVector[c]) * k % points) << (32 - log2Points));
            const uint32_t actual = toFixed(v[i * arity + c]) - toFixed(v[c]);
            const int32_t error = static_cast<int32_t>(actual - expected);
            if (error < -256 || error > 256) return false;
        }
        ks.insert(k);
    }
    return ks.size() == points;
}

} // namespace

BOOST_AUTO_TEST_CASE(lattice_prefixes_are_shifted_lattices_and_blocks_continue_the_sequence) {
    for (uint32_t arity = 1; arity <= 3; ++arity)
        for (uint64_t seed : {1ull, 0xfeedull, ~0ull}) {
            Owned o;
            create(o, "lattice", 64, seed);
            for (uint32_t px : {0u, 7u, 4000u}) {
                const std::vector<float> all = stream(o, px, 3, 0, 256, 5, arity); // 4 blocks of 64
                for (uint32_t j = 0; j <= 8; ++j) {
                    const std::vector<float> prefix(all.begin(), all.begin() + (size_t(arity) << j));
                    BOOST_CHECK_MESSAGE(isShiftedLattice(prefix, arity, j),
                                        "lattice arity " << arity << " seed " << seed << " pixel " << px
                                                         << ": the first 2^" << j << " samples");
                    for (uint32_t c = 0; c < arity; ++c)
                        BOOST_CHECK_MESSAGE(onePerInterval(prefix, arity, c, 1u << j),
                                            "lattice axis " << c << " of 2^" << j << " samples");
                }
            }
        }
}

BOOST_AUTO_TEST_CASE(halton_axes_are_stratified_in_their_bases_across_blocks) {
    const uint32_t bases[3] = {2, 3, 5};
    for (uint64_t seed : {3ull, 0xabcdull}) {
        for (uint32_t c = 0; c < 3; ++c) {
            const uint32_t b = bases[c];
            for (uint32_t n = b; n <= 729; n *= b) {
                Owned o;
                create(o, "halton", n, seed);
                const std::vector<float> v = stream(o, 11, 2, 0, n * b, 4, 3); // b blocks: the first b * n points
                const std::vector<float> first(v.begin(), v.begin() + size_t(n) * 3);
                BOOST_CHECK_MESSAGE(onePerInterval(first, 3, c, n), "halton axis " << c << " N " << n);
                BOOST_CHECK_MESSAGE(onePerInterval(v, 3, c, n * b), "halton axis " << c << " " << b << " blocks of "
                                                                                   << n);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(dimensions_of_a_pixel_get_different_sets) {
    for (const char* pattern : {"lattice", "halton"}) {
        Owned o;
        create(o, pattern, 16, 9);
        const std::vector<float> a = stream(o, 1, 1, 0, 16, 0, 2), b = stream(o, 1, 1, 0, 16, 1, 2);
        uint32_t same = 0;
        for (size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
        BOOST_CHECK_MESSAGE(same < 4, std::string(pattern) << ": streams 0 and 1 share " << same << " values");
    }
}
