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

// "poisson": exactly n points in [0,1)^dim (dim 1..3), interleaved, toroidal domain, in random order.
// Deterministic in seed. 2D and 3D (poisson.cpp): dart throwing at the fixed radius poissonRadius(dim) d_max until
// n points are accepted (near-maximal Poisson-disk sets: rho >= poissonRadius(dim) except where a tiny torus
// cannot hold n such disks). 1D: generateCellSet1D.
std::vector<float> generatePoisson(int dim, uint32_t n, uint64_t seed);
// The minimum distance over d_max the generator keeps: 0.2 (1D), 0.76 (2D), 0.72 (3D).
double poissonRadius(int dim);

// 1D sets (cell_set_1d.cpp): one point in each cell [c/n, (c+1)/n), at least n 2^-23 cells inside it, its offset
// a reflecting random walk of steps uniform on [-0.8, 0.8] (every offset uniform, neighbours at least 0.2 cells
// apart, the last cell's step to the first included). Order shuffled.
std::vector<float> generateCellSet1D(uint32_t n, uint64_t seed);

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
