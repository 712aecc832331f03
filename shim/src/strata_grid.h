// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// strata_grid.h — the grid of strata of one stratified set of M points in 1, 2 or 3 dimensions.
//
// Rule (documented in shim/README.md):
//  - 1D: M strata.
//  - 2D/3D, exact: the most-square (most-cubic) factorisation of M into per-axis counts, used when the largest
//    count is at most twice the smallest. Axis 0 (x) gets the largest count, the last axis the smallest.
//  - 2D/3D, padded (primes and other awkward M): n = ceil(M^(1/d)) strata on every axis but the last, and
//    L = ceil(M / n^(d-1)) on the last, so the grid has G >= M cells and s = G - M < n^(d-1) cells stay empty.
//    The grid is read as n^(d-1) "lines" of L cells along the last axis. s distinct lines, chosen by a hashed
//    permutation of the lines, each leave out one cell, at positions (t + offset) mod L spread evenly along the
//    last axis. Every cell is thus left out with the same probability s/G, so every sample is uniformly
//    distributed; each used cell holds exactly one sample; no cell of the grid is ever used twice.
#pragma once

#include "fast_divider.h"
#include "permutation.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace stipple::detail {

struct StrataGrid {
    uint32_t arity = 1;
    uint32_t points = 1;          // M
    uint32_t axis[3] = {1, 1, 1}; // strata per axis
    uint32_t lineLength = 1;      // L = axis[arity - 1]
    uint32_t lineCount = 1;       // product of the other axes
    uint32_t emptyCells = 0;      // s = cells - M (0 for an exact factorisation)
    double inverseAxis[3] = {1, 1, 1};
    FastDivider lineDivider, shortLineDivider, axis0Divider; // by L, L - 1 (padded only), axis[0]
    // Progressive grids (exact, every axis a power of two, so M = 2^pointBits): set points are read in the
    // interleaved bit-reversed order of their cells (see pattern_stratified.cpp); axisBits[c] = log2(axis[c]).
    bool progressive = false;
    uint32_t axisBits[3] = {0, 0, 0};
    uint32_t pointBits = 0;
    // Progressive grids with M <= kCellTableLimit: for each q, arity words cell[c] << (24 - axisBits[c]) (the cell's
    // top bits of a 24-bit value), shared by every grid of the same shape. Larger grids compute cells on the fly.
    static constexpr uint32_t kCellTableLimit = 1u << 16;
    std::shared_ptr<const std::vector<uint32_t>> cellTable;

    static StrataGrid choose(uint32_t arity, uint32_t points);
    bool padded() const { return emptyCells != 0; }

    // The cell of set point q (0 <= q < M), given the set's line permutation seed and empty-cell offset.
    // Set points are ordered line by line in permuted line order; the first s lines are the ones with a hole.
    void cellOf(uint32_t q, uint32_t lineSeed, uint32_t holeOffset, uint32_t cell[3]) const {
        uint32_t line, position;
        linesOf(&q, 1, lineSeed, holeOffset, &line, &position);
        splitLine(line, position, cell);
    }

    // cellOf for the set points q[0, n), as each one's line and position along it: a padded grid's line
    // permutation is walked for all of them at once (permuteIndices), for the batch paths.
    [[gnu::always_inline]] void linesOf(const uint32_t* q, uint32_t n, uint32_t lineSeed, uint32_t holeOffset,
                                        uint32_t* line, uint32_t* position) const {
        if (emptyCells == 0) {
            for (uint32_t k = 0; k < n; ++k) {
                line[k] = lineDivider.divide(q[k]);
                position[k] = q[k] - line[k] * lineLength;
            }
            return;
        }
        const uint32_t shortLength = lineLength - 1;
        const uint64_t inShortLines = uint64_t(emptyCells) * shortLength;
        for (uint32_t k = 0; k < n; ++k) {
            if (q[k] < inShortLines) {
                const uint32_t t = shortLineDivider.divide(q[k]);
                const uint32_t hole = (t + holeOffset) % lineLength; // t < s and holeOffset < L: no overflow
                position[k] = q[k] - t * shortLength;
                position[k] += position[k] >= hole ? 1 : 0;
                line[k] = t;
            } else {
                const uint32_t rest = static_cast<uint32_t>(q[k] - inShortLines);
                const uint32_t lines = lineDivider.divide(rest);
                line[k] = emptyCells + lines;
                position[k] = rest - lines * lineLength;
            }
        }
        permuteIndices(line, n, lineCount, lineSeed);
    }

    // A cell's coordinates from its line and its position along the line (the last axis).
    [[gnu::always_inline]] void splitLine(uint32_t line, uint32_t position, uint32_t cell[3]) const {
        cell[arity - 1] = position;
        if (arity == 2) {
            cell[0] = line;
        } else if (arity == 3) {
            cell[1] = axis0Divider.divide(line);
            cell[0] = line - cell[1] * axis[0];
        }
    }
};

} // namespace stipple::detail
