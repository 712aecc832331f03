// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pointsets.h — Poisson-disk point-set generators of the shim (internal C++, never exported).
//
// All sets live on the unit torus [0,1)^dim, dim in 1..3, stored interleaved (x0,y0,x1,y1,...).
// Every function is a pure function of its arguments: no global state, no exceptions for valid input.
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

// Largest n served (the C ABI's STIPPLE_MAX_SET_SIZE). Larger n, like dim outside 1..3 or n = 0, is invalid
// input: the generators return an empty vector rather than attempt gigabytes of grid.
inline constexpr uint32_t kMaxPoints = 1u << 22;

// Exactly n points in [0,1)^dim (dim 1..3), interleaved, toroidal domain. Deterministic in seed.
// High quality (see shim/POINTSETS.md): rho >= 0.855 in 2D (0.835 in 3D), every 1D projection stratified (one
// point per 1/n) and the lowest Fourier modes cancelled, from a jittered start and relaxation; order shuffled.
std::vector<float> generatePoisson(int dim, uint32_t n, uint64_t seed);

// 1D sets (cell_set_1d.cpp): one point in each cell [c/n, (c+1)/n), at the centre of one of the cell's m sub-cells
// (m = cellSubdivision1D(n): the largest divisor of n with n * m <= 2^23, m = n for 8 <= n <= 2896, or 1 if that is
// below 8, the equidistant lattice), the sub-cell index stepping by q = cellStep1D(n, setIndex) modulo n from
// cell to cell. From 64 points on q / n ~ 0.809 in every set; below, each n mixes up to three steps over a
// family's 32 sets (set setIndex mod 32), every one q = 0 or q / n >= 1/2, so that two neighbours stay at least
// half a cell apart under the serving's common rotation (pattern_poisson.cpp relies on this layout). Order
// shuffled. generatePoisson(1, n, seed) is set 0.
uint32_t cellSubdivision1D(uint32_t n);
uint32_t cellStep1D(uint32_t n, uint32_t setIndex);
std::vector<float> generateCellSet1D(uint32_t n, uint32_t setIndex, uint64_t seed);

// 2D and 3D sets aligned with the domain (cell_lattice.cpp): a grid of cells(0) x cells(1) [x cells(2)] = n cells,
// one point per cell at the offset frac(A c) for an integer-over-grid matrix A chosen so that the set keeps
// rho >= cellLatticeRhoFloor(dim) under every common within-cell shift (how pattern_poisson.cpp serves it). Points
// in cell order (cell index x-fastest). Empty points if no grid with sides at most 2.5:1 and 16 cells a side
// qualifies, or n > 2^16 (the search's cost grows with n); then the toroidal generatePoisson set is served.
// Deterministic in seed.
struct CellLattice {
    std::vector<float> points;
    uint32_t cells[3] = {0, 0, 0};
    double rho = 0.0;    // the worst case over within-cell shifts (before the face margin: at most 0.003 less)
    uint32_t shared = 0; // cells that share each offset value along the worst axis (1: all n different)
};
CellLattice generateCellLattice(int dim, uint32_t n, uint64_t seed);
double cellLatticeRhoFloor(int dim);

// The study's Algorithm 1: dart throwing with r0 = N^(-1/dim), r <- 0.75 r after TRY_LIMIT = 100
// consecutive failures, neighbour search in an ordered set (1D), quadtree (2D) or octree (3D).
// Points in the order they were accepted.
std::vector<float> generatePoissonSeed(int dim, uint32_t n, uint64_t seed);

// Analysis, in the static library stipple_analysis (relative_radius.cpp), not in libstipple.so:
//
// rho = d_min / d_max on the unit torus, d_max the densest packing distance of n points
// (1/n in 1D, hexagonal sqrt(2/(sqrt(3) n)) in 2D, FCC (sqrt(2)/n)^(1/3) in 3D).
// For n = 1 the only neighbour is the point's own periodic image at distance 1.
double relativeRadius(int dim, const float* points, uint32_t n);

// Mean over points of (nearest-neighbour distance / d_max), toroidal: the "average" figure of the
// literature (dart throwing ~0.805 in 2D).
double meanNearestNeighbourRadius(int dim, const float* points, uint32_t n);

// d_max of n points in dim dimensions (see relativeRadius).
double maxPackingDistance(int dim, uint32_t n);

} // namespace stipple::detail::pointsets
