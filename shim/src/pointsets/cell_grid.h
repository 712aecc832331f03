// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// cell_grid.h — a uniform grid of G^D cells over the unit torus, built by a counting sort.
//
// Points are copied in cell order (cellStart[c] .. cellStart[c+1]) so a neighbourhood scan reads memory
// sequentially; `order` maps a sorted slot back to the caller's point index.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

template <int D>
struct CellGrid {
    int cellsPerAxis = 1;
    std::vector<uint32_t> cellStart;         // size G^D + 1
    std::vector<uint32_t> order;             // sorted slot -> input index
    std::vector<float> sorted;               // D floats per slot, in cell order
    std::vector<uint32_t> cellOfPoint, fill; // scratch, kept to avoid reallocating on every rebuild

    // Robust to any input (relativeRadius takes caller data): NaN and negatives go to cell 0, >= 1 to the last.
    static int cellOf(float x, int g) {
        float s = x * float(g);
        if (!(s >= 0.0f)) return 0;
        return s < float(g) ? int(s) : g - 1;
    }
    uint32_t cellIndex(const int* c) const {
        uint32_t index = 0;
        for (int k = D - 1; k >= 0; --k) index = index * uint32_t(cellsPerAxis) + uint32_t(c[k]);
        return index;
    }

    void build(const float* points, uint32_t n, int g) {
        cellsPerAxis = g;
        uint32_t cells = 1;
        for (int k = 0; k < D; ++k) cells *= uint32_t(g);
        cellStart.assign(cells + 1, 0);
        cellOfPoint.resize(n);
        for (uint32_t i = 0; i < n; ++i) {
            int c[D];
            for (int k = 0; k < D; ++k) c[k] = cellOf(points[size_t(i) * D + k], g);
            cellOfPoint[i] = cellIndex(c);
            ++cellStart[cellOfPoint[i] + 1];
        }
        for (uint32_t c = 0; c < cells; ++c) cellStart[c + 1] += cellStart[c];
        order.resize(n);
        sorted.resize(size_t(n) * D);
        fill.assign(cellStart.begin(), cellStart.end() - 1);
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t slot = fill[cellOfPoint[i]]++;
            order[slot] = i;
            for (int k = 0; k < D; ++k) sorted[size_t(slot) * D + k] = points[size_t(i) * D + k];
        }
    }
};

} // namespace stipple::detail::pointsets
