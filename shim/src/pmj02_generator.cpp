// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pmj02_generator.cpp — the pmj02 construction of Christensen, Kensler & Kilpatrick (EGSR 2018), section 5.
//
// The sequence grows by doublings. Going from n = 4^q points (one per cell of a 2^q x 2^q grid) to 2n, the new
// point i + n goes into the sub-quadrant of point i's cell diagonally opposite to it; going from 2n to 4n, the
// new points i + 2n and i + 3n fill the two sub-quadrants of the cell that points i and i + n left empty (which
// of the two comes first is a coin flip). Inside its sub-quadrant a new point is placed at random among the
// positions that leave the grown prefix of 2^(k+1) points with one point in every elementary interval of area
// 2^-(k+1): an occupancy bitmap per interval shape (2^a columns x 2^(k+1-a) rows) says which cells are free, and
// a depth-first search over the y digits of a random free x stratum finds a free position (placePoint). If a
// point finds none (a dead end), the level is redrawn from a derived seed, so the output is always a valid
// progressive (0,2) prefix.
//
// The depth coordinate (generatePmj02Depth) is a digital (0,1)-sequence in the point index, z = C t (kDepthMatrix,
// over GF(2)), plus random digits below the sequence's resolution. It is tied to (x, y) through the doublings: a
// point stays in the 2^r-grid cell of its index mod 4^r, so the points of a prefix sharing a cell differ only in
// their high index bits, and C maps those onto distinct z strata of the cell. Why not an orthogonal-array z, one
// point per cell of the 2^q x 2^q grids of (x, z) and (y, z) at every 4^q prefix: nested over every q, such a z is
// a function of (x, y) (its top q digits follow from the 2^q-cell), so the points lie on a surface and the 3D
// error stops falling with N (measured: 93x stratified's MSE on the smooth 3D integrands at N = 4096).
#include "pmj02_generator.h"

#include "error.h"
#include "hash.h"

#include <algorithm>
#include <bit>
#include <string>

namespace stipple::detail {

namespace {

class Random {
public:
    explicit Random(uint64_t key) : key_(key) {}
    uint64_t next() { return hashAt(key_, counter_++); }
    uint32_t below(uint32_t n) { return static_cast<uint32_t>((next() >> 32) * n >> 32); }

private:
    uint64_t key_, counter_ = 0;
};

// Occupancy of the elementary intervals of area 2^-k for every shape a = 0..k (2^a columns, 2^(k-a) rows).
class IntervalOccupancy {
public:
    explicit IntervalOccupancy(uint32_t k) : k_(k), bits_(size_t(k + 1) << k, false) {}

    bool isFree(uint32_t x, uint32_t y) const {
        for (uint32_t a = 0; a <= k_; ++a)
            if (bits_[cell(a, x, y)]) return false;
        return true;
    }
    // The cell of shape a (2^a columns) holding x, in the row given by the top k - a digits of y (yPrefix).
    bool isFreeIn(uint32_t a, uint32_t x, uint32_t yPrefix) const {
        const uint32_t column = a == 0 ? 0 : x >> (32 - a);
        return !bits_[(size_t(a) << k_) + (size_t(column) << (k_ - a)) + yPrefix];
    }
    void occupy(uint32_t x, uint32_t y) {
        for (uint32_t a = 0; a <= k_; ++a) bits_[cell(a, x, y)] = true;
    }

private:
    size_t cell(uint32_t a, uint32_t x, uint32_t y) const {
        const uint32_t column = a == 0 ? 0 : x >> (32 - a);
        const uint32_t row = a == k_ ? 0 : y >> (32 - (k_ - a));
        return (size_t(a) << k_) + (size_t(column) << (k_ - a)) + row;
    }
    uint32_t k_;
    std::vector<bool> bits_;
};

// A fixed-point coordinate inside stratum s of 2^k strata, with random bits below.
inline uint32_t inStratum(uint32_t s, uint32_t k, uint64_t bits) {
    if (k == 0) return static_cast<uint32_t>(bits >> 32);
    return (s << (32 - k)) | (static_cast<uint32_t>(bits >> 32) >> k);
}

// Places one point in the sub-quadrant whose finest x strata start at x0 (and y strata at y0), each spanning
// `span` strata of 2^k, so the prefix stays a net of area 2^-k. False if no position exists. After Pharr
// ("Efficient Generation of Points that Satisfy Two-Dimensional Elementary Intervals", JCGT 8(1), 2019): for a
// chosen x stratum, the y digits are chosen top-down; fixing t digits of y fixes the cell of shape a = k - t, so
// a depth-first search with a random branch order meets every constraint as early as it can be checked.
bool placePoint(IntervalOccupancy& occupancy, uint32_t k, uint32_t x0, uint32_t y0, uint32_t span, Random& random,
                FixedPoint2& out) {
    const uint32_t fixedDigits = k - static_cast<uint32_t>(std::countr_zero(span)); // y digits the sub-quadrant fixes
    const uint32_t start = random.below(span);
    for (uint32_t i = 0; i < span; ++i) {
        const uint32_t x = inStratum(x0 + (start + i) % span, k, random.next());
        if (!occupancy.isFreeIn(k, x, 0)) continue; // the x stratum itself (shape 2^k x 1)
        // Depth-first over y digits fixedDigits..k-1; prefixes of the sub-quadrant's fixed digits are checked first.
        const uint32_t yTop = y0 >> (k - fixedDigits);
        bool blocked = false;
        for (uint32_t t = 1; t <= fixedDigits && !blocked; ++t)
            blocked = !occupancy.isFreeIn(k - t, x, yTop >> (fixedDigits - t));
        if (blocked) continue;
        uint32_t stack[33];
        uint32_t flips[33];
        uint32_t depth = fixedDigits;
        uint32_t prefix = yTop;
        if (depth == k) {
            out = {x, inStratum(prefix, k, random.next())};
            occupancy.occupy(out.x, out.y);
            return true;
        }
        flips[depth] = random.next() & 1u;
        stack[depth] = 0;
        while (true) {
            if (stack[depth] == 2) { // both children tried
                if (depth == fixedDigits) break;
                --depth;
                prefix >>= 1;
                ++stack[depth];
                continue;
            }
            const uint32_t child = (prefix << 1) | (stack[depth] ^ flips[depth]);
            if (occupancy.isFreeIn(k - depth - 1, x, child)) {
                if (depth + 1 == k) {
                    out = {x, inStratum(child, k, random.next())};
                    occupancy.occupy(out.x, out.y);
                    return true;
                }
                prefix = child;
                ++depth;
                stack[depth] = 0;
                flips[depth] = random.next() & 1u;
            } else {
                ++stack[depth];
            }
        }
    }
    return false;
}

// Grows points[0, 2^k) to points[0, 2^(k+1)). Returns false on a dead end (the caller redraws the level).
bool extend(std::vector<FixedPoint2>& points, uint32_t k, Random& random) {
    const uint32_t n = 1u << k, next = k + 1;
    IntervalOccupancy occupancy(next);
    for (uint32_t i = 0; i < n; ++i) occupancy.occupy(points[i].x, points[i].y);
    if (k % 2 == 0) {
        // n = 4^q: cells of a 2^q grid hold one point each; the new point takes the diagonally opposite sub-quadrant.
        const uint32_t q = k / 2, sub = q + 1;    // sub-quadrants: a 2^(q+1) grid
        const uint32_t span = 1u << (next - sub); // finest strata (2^next) per sub-quadrant side
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t sx = (points[i].x >> (32 - sub)) ^ 1u, sy = (points[i].y >> (32 - sub)) ^ 1u;
            if (!placePoint(occupancy, next, sx * span, sy * span, span, random, points[n + i])) return false;
        }
    } else {
        // n = 2 * 4^q: each cell of the 2^q grid holds points i and i + n/2 in diagonal sub-quadrants; points i + n
        // and i + 3n/2 take the two sub-quadrants left.
        const uint32_t half = n / 2, q = (k - 1) / 2, sub = q + 1;
        const uint32_t span = 1u << (next - sub);
        for (uint32_t i = 0; i < half; ++i) {
            const uint32_t ax = points[i].x >> (32 - sub), ay = points[i].y >> (32 - sub);
            const bool swapFirst = random.next() & 1u;
            // The two empty sub-quadrants of the cell: (ax ^ 1, ay) and (ax, ay ^ 1).
            const uint32_t firstX = swapFirst ? ax : ax ^ 1u, firstY = swapFirst ? ay ^ 1u : ay;
            const uint32_t secondX = swapFirst ? ax ^ 1u : ax, secondY = swapFirst ? ay : ay ^ 1u;
            if (!placePoint(occupancy, next, firstX * span, firstY * span, span, random, points[n + i])) return false;
            if (!placePoint(occupancy, next, secondX * span, secondY * span, span, random, points[n + half + i]))
                return false;
        }
    }
    return true;
}

constexpr uint64_t kDepthStream = 0xde97b5eedull;

// Column l: the top 16 digits of z that bit l of the point index flips. Upper triangular with a unit diagonal (column l
// sets digit l + 1 and none below), so z is a (0,1)-sequence. A prefix of 2^k points puts the 2^(k-2r) points that
// differ only in index bits 2r .. k-1 in each (x, y) cell of side 2^-r (the doublings above keep a point in the cell of
// its index mod 4^r). For every even s = 2r and every j, the columns s .. s+j-1 restricted to digits 1 .. j are
// invertible, so those points are stratified in z at 2^-(k-2r): the prefix has one point in every box of 2^-r x 2^-r x
// 2^-(k-2r), for every r with 2r <= k (at 32 points: 4 x 4 x 2, 2 x 2 x 8 and 1 x 1 x 32 boxes of the unit cube, beside
// the (x, y) net's rectangles). A weaker rank (digits 1 .. r only, enough for the cubes of side 2^-r) left the 8 points
// of each (x, y) quadrant of a 32-point prefix in 2 of its 4 z quarters, and 1.85-2.07x stratified's MSE on the slanted
// plane x + y + z < 1.2 at N = 32. Among the matrices with this rank (a seeded greedy search over columns), this one
// was chosen by the worst MSE ratio to jittered 3D sets on slanted planes (4 offsets x 4 orientations, N = 16 .. 2048,
// in a simulation), then by the worst ratio to stratified over the battery's 3D integrands (shim_battery, 400 sets;
// confirmed with 2000).
constexpr uint32_t kDepthMatrix[16] = {0x80000000, 0x40000000, 0xe0000000, 0x70000000, 0xa8000000, 0xcc000000,
                                       0x8a000000, 0xff000000, 0xc1800000, 0x9f400000, 0xf5a00000, 0xbb500000,
                                       0xd8b80000, 0xac0c0000, 0xf8ca0000, 0xb3b10000};

} // namespace

bool isElementaryNet(const FixedPoint2* points, uint32_t k) {
    IntervalOccupancy occupancy(k);
    for (uint32_t i = 0; i < (1u << k); ++i) {
        if (!occupancy.isFree(points[i].x, points[i].y)) return false;
        occupancy.occupy(points[i].x, points[i].y);
    }
    return true;
}

std::vector<FixedPoint2> generatePmj02(uint32_t log2Length, uint64_t seed) {
    std::vector<FixedPoint2> points(size_t(1) << log2Length);
    Random first(hashCombine(seed, 0));
    points[0] = {static_cast<uint32_t>(first.next() >> 32), static_cast<uint32_t>(first.next() >> 32)};
    constexpr uint32_t kAttemptsPerLevel = 64;
    for (uint32_t k = 0; k < log2Length; ++k) {
        bool done = false;
        for (uint32_t attempt = 0; attempt < kAttemptsPerLevel && !done; ++attempt) {
            Random random(hashCombine(seed, (uint64_t(k + 1) << 32) | attempt));
            done = extend(points, k, random);
        }
        if (!done)
            throw Error(STIPPLE_ERROR_INTERNAL, "pmj02: no valid extension from 2^" + std::to_string(k) +
                                                    " points in " + std::to_string(kAttemptsPerLevel) + " attempts");
    }
    return points;
}

std::vector<uint32_t> generatePmj02Depth(const std::vector<FixedPoint2>& points, uint64_t seed) {
    const size_t n = points.size();
    if (n > (size_t(1) << std::size(kDepthMatrix)))
        throw Error(STIPPLE_ERROR_INTERNAL, "pmj02 depth: more points than the depth matrix has columns");
    // C t leaves the digits of a prefix of 2^k points past digit k at 0 (C is upper triangular): each point at the
    // bottom of its stratum. A nested uniform (Owen) scramble of the matrix's 16 digits, one hashed flip per digit
    // and prefix, makes every point uniform inside its stratum, independently, for every prefix, and keeps every
    // stratification above (it permutes the z strata of every level inside their parents). The digits below are
    // random. Neither depends on the sequence's length, so sequences generated from one seed at different lengths
    // share their z wherever they share their points (Pmj02Family relies on it).
    constexpr uint32_t kDigits = std::size(kDepthMatrix);
    const uint64_t flips = hashCombine(seed, kDepthStream + 1);
    std::vector<uint32_t> z(n);
    Random random(hashCombine(seed, kDepthStream));
    for (uint32_t t = 0; t < n; ++t) {
        uint32_t digits = 0;
        for (uint32_t bits = t, l = 0; bits != 0; bits >>= 1, ++l)
            if (bits & 1u) digits ^= kDepthMatrix[l];
        uint32_t scrambled = digits;
        for (uint32_t j = 0; j < kDigits; ++j) { // digit j + 1, flipped by a hash of digits 1 .. j
            const uint32_t prefix = j == 0 ? 0u : digits >> (32 - j);
            scrambled ^= static_cast<uint32_t>(hashAt(flips, (uint64_t(j) << 32) | prefix) & 1u) << (31 - j);
        }
        z[t] = scrambled | static_cast<uint32_t>(random.next() >> 32) >> kDigits;
    }
    return z;
}

} // namespace stipple::detail
