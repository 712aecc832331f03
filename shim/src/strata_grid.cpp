// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// strata_grid.cpp — choosing the grid of strata and locating the cell of each set point.
#include "strata_grid.h"

#include "progressive_strata.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <mutex>

namespace stipple::detail {

namespace {

// Smallest n with n^degree >= value (exact integer arithmetic; value <= 2^22).
uint32_t ceilRoot(uint64_t value, uint32_t degree) {
    uint64_t n = static_cast<uint64_t>(std::floor(std::pow(double(value), 1.0 / degree)));
    auto power = [degree](uint64_t x) {
        uint64_t p = 1;
        for (uint32_t i = 0; i < degree; ++i) p *= x;
        return p;
    };
    while (n > 1 && power(n - 1) >= value) --n;
    while (power(n) < value) ++n;
    return static_cast<uint32_t>(std::max<uint64_t>(n, 1));
}

// One table per (arity, axis bits), built once and shared (a process holds few shapes: one per arity and M).
std::shared_ptr<const std::vector<uint32_t>> sharedCellTable(uint32_t arity, const uint32_t axisBits[3],
                                                             uint32_t points) {
    static std::mutex mutex;
    static std::map<uint64_t, std::shared_ptr<const std::vector<uint32_t>>> tables;
    const uint64_t key = (uint64_t(arity) << 48) | (uint64_t(axisBits[0]) << 32) | (axisBits[1] << 16) | axisBits[2];
    std::lock_guard<std::mutex> lock(mutex);
    auto& table = tables[key];
    if (!table) {
        auto words = std::make_shared<std::vector<uint32_t>>(size_t(points) * arity);
        for (uint32_t q = 0; q < points; ++q) {
            uint32_t cell[3];
            progressiveCell(q, arity, axisBits, cell);
            for (uint32_t c = 0; c < arity; ++c) (*words)[size_t(q) * arity + c] = cell[c] << (24 - axisBits[c]);
        }
        table = std::move(words);
    }
    return table;
}

} // namespace

StrataGrid StrataGrid::choose(uint32_t arity, uint32_t points) {
    StrataGrid grid;
    grid.arity = arity;
    grid.points = points;
    if (arity == 1) {
        grid.axis[0] = points;
    } else if (arity == 2) {
        uint32_t small = 1;
        for (uint32_t a = 1; uint64_t(a) * a <= points; ++a)
            if (points % a == 0) small = a;
        uint32_t large = points / small;
        if (large <= 2 * small) {
            grid.axis[0] = large;
            grid.axis[1] = small;
        } else {
            uint32_t n = ceilRoot(points, 2);
            grid.axis[0] = n;
            grid.axis[1] = (points + n - 1) / n;
        }
    } else {
        // Most-cubic a <= b <= c with a*b*c = M, minimising c / a.
        uint32_t bestA = 1, bestB = 1, bestC = points;
        for (uint32_t a = 1; uint64_t(a) * a * a <= points; ++a) {
            if (points % a) continue;
            uint32_t rest = points / a;
            for (uint32_t b = a; uint64_t(b) * b <= rest; ++b) {
                if (rest % b) continue;
                uint32_t c = rest / b;
                if (uint64_t(c) * bestA < uint64_t(bestC) * a) bestA = a, bestB = b, bestC = c;
            }
        }
        if (bestC <= 2 * bestA) {
            grid.axis[0] = bestC;
            grid.axis[1] = bestB;
            grid.axis[2] = bestA;
        } else {
            uint32_t n = ceilRoot(points, 3);
            grid.axis[0] = n;
            grid.axis[1] = n;
            grid.axis[2] = static_cast<uint32_t>((uint64_t(points) + uint64_t(n) * n - 1) / (uint64_t(n) * n));
        }
    }
    grid.lineLength = grid.axis[arity - 1];
    grid.lineCount = 1;
    for (uint32_t c = 0; c + 1 < arity; ++c) grid.lineCount *= grid.axis[c];
    grid.emptyCells = grid.lineLength * grid.lineCount - points;
    for (uint32_t c = 0; c < 3; ++c) grid.inverseAxis[c] = 1.0 / grid.axis[c];
    grid.lineDivider = FastDivider(grid.lineLength);
    grid.shortLineDivider = FastDivider(grid.lineLength > 1 ? grid.lineLength - 1 : 1);
    grid.axis0Divider = FastDivider(grid.axis[0]);
    grid.progressive = grid.emptyCells == 0;
    for (uint32_t c = 0; c < arity; ++c) {
        grid.progressive = grid.progressive && (grid.axis[c] & (grid.axis[c] - 1)) == 0;
        grid.axisBits[c] = static_cast<uint32_t>(std::countr_zero(grid.axis[c]));
        grid.pointBits += grid.axisBits[c];
    }
    if (grid.progressive && points <= kCellTableLimit) grid.cellTable = sharedCellTable(arity, grid.axisBits, points);
    return grid;
}

} // namespace stipple::detail
