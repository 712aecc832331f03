// blue_noise.cpp — the void-and-cluster mask, the Z-order Sobol' assignment and the toroidal shift.
#include "blue_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stipple {

namespace {

constexpr uint32_t kSize = 1u << kBlueNoiseMaskLog2, kCells = kSize * kSize;

// Ulichney's void-and-cluster with a toroidal Gaussian filter (sigma 1.5). Energy[i] is the filtered density
// of the ones at i; the tightest cluster is the one with the most energy, the largest void the zero with least.
class VoidAndCluster {
public:
    VoidAndCluster() : kernel_(kCells), energy_(kCells, 0.0), ones_(kCells, false) {
        constexpr double kSigma = 1.5;
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                const double dx = std::min(x, kSize - x), dy = std::min(y, kSize - y);
                kernel_[y * kSize + x] = std::exp(-(dx * dx + dy * dy) / (2 * kSigma * kSigma));
            }
    }

    void set(uint32_t i, bool one) {
        ones_[i] = one;
        const double sign = one ? 1.0 : -1.0;
        const uint32_t ix = i % kSize, iy = i / kSize;
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x)
                energy_[y * kSize + x] += sign * kernel_[((y - iy) & (kSize - 1)) * kSize + ((x - ix) & (kSize - 1))];
    }
    bool one(uint32_t i) const { return ones_[i]; }
    uint32_t tightestCluster() const { return extreme(true); }
    uint32_t largestVoid() const { return extreme(false); }

private:
    uint32_t extreme(bool amongOnes) const {
        uint32_t best = kCells;
        for (uint32_t i = 0; i < kCells; ++i)
            if (ones_[i] == amongOnes &&
                (best == kCells || (amongOnes ? energy_[i] > energy_[best] : energy_[i] < energy_[best])))
                best = i;
        return best;
    }
    std::vector<double> kernel_, energy_;
    std::vector<bool> ones_;
};

std::vector<float> makeMask() {
    // Initial pattern: 10% ones at hashed positions, relaxed until the tightest cluster is the largest void.
    constexpr uint32_t kInitialOnes = kCells / 10;
    constexpr uint64_t kMaskKey = 0xb1e5ee0dc0ffee08ull;
    VoidAndCluster prototype;
    for (uint32_t placed = 0, counter = 0; placed < kInitialOnes; ++counter) {
        const uint32_t i = static_cast<uint32_t>(hashAt(kMaskKey, counter) % kCells);
        if (!prototype.one(i)) prototype.set(i, true), ++placed;
    }
    for (uint32_t pass = 0; pass < kCells; ++pass) {
        const uint32_t cluster = prototype.tightestCluster();
        prototype.set(cluster, false);
        const uint32_t hole = prototype.largestVoid();
        prototype.set(hole, true);
        if (hole == cluster) break;
    }
    std::vector<uint32_t> rank(kCells);
    // Phase 1: remove the tightest clusters of the prototype, ranks kInitialOnes - 1 down to 0.
    VoidAndCluster pattern = prototype;
    for (uint32_t r = kInitialOnes; r-- > 0;) {
        const uint32_t cluster = pattern.tightestCluster();
        pattern.set(cluster, false);
        rank[cluster] = r;
    }
    // Phases 2 and 3: fill the largest voids of the prototype, ranks kInitialOnes .. kCells - 1 (past half, the
    // tightest cluster of zeros is the zero with the least energy of ones: the same rule).
    for (uint32_t r = kInitialOnes; r < kCells; ++r) {
        const uint32_t hole = prototype.largestVoid();
        prototype.set(hole, true);
        rank[hole] = r;
    }
    std::vector<float> mask(kCells);
    for (uint32_t i = 0; i < kCells; ++i) mask[i] = (float(rank[i]) + 0.5f) / float(kCells);
    return mask;
}

// The 24 permutations of {0, 1, 2, 3}.
constexpr uint8_t kPermutations4[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1}, {1, 0, 2, 3}, {1, 0, 3, 2},
    {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 0, 2}, {1, 3, 2, 0}, {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 1, 0, 3}, {2, 1, 3, 0},
    {2, 3, 0, 1}, {2, 3, 1, 0}, {3, 0, 1, 2}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 1, 2, 0}, {3, 2, 0, 1}, {3, 2, 1, 0}};

} // namespace

const float* blueNoiseMask() {
    static const std::vector<float> mask = makeMask();
    return mask.data();
}

SobolSet zOrderSobolSet(uint64_t dimensionKey, uint64_t pixelKey, uint32_t pixelX, uint32_t pixelY,
                        uint32_t log2Length) {
    SobolSet set;
    // T levels of Morton digits leave room in the 32-bit index for the pixel's 2^m points (T <= 8: 256^2 tiles).
    const uint32_t levels = std::min<uint32_t>(8, (32 - std::min<uint32_t>(log2Length, 32)) / 2);
    const uint64_t tileKey = hashCombine(dimensionKey, (uint64_t(pixelY >> levels) << 32) | (pixelX >> levels));
    const uint64_t h0 = hashAt(tileKey, 0), h1 = hashAt(tileKey, 1);
    set.scramble[0] = static_cast<uint32_t>(h0 >> 32);
    set.scramble[1] = static_cast<uint32_t>(h1);
    set.scramble[2] = static_cast<uint32_t>(h1 >> 32);
    set.indexSeed = static_cast<uint32_t>(hashAt(pixelKey, 0));
    uint32_t morton = 0, prefix = 1; // prefix: the digits above, with a leading 1 marking their count
    for (uint32_t level = levels; level-- > 0;) {
        const uint32_t digit = ((pixelX >> level) & 1u) | (((pixelY >> level) & 1u) << 1);
        const uint32_t permutation = static_cast<uint32_t>(hashAt(tileKey, 2 + uint64_t(prefix)) % 24);
        morton = (morton << 2) | kPermutations4[permutation][digit];
        prefix = (prefix << 2) | digit;
    }
    set.blockBase = morton;
    set.blockStride = levels == 0 ? 1u : 1u << (2 * levels);
    return set;
}

uint32_t CrossPixelStrata::subcell(uint64_t stratum) const {
    // The pixel's finest Morton digit (which pixel of its 2 x 2 quad) picks the coarsest split of the stratum, so
    // a quad fills the four quarters, a 4 x 4 block the sixteen sixteenths, and so on.
    const uint64_t key = hashCombine(tileKey, stratum);
    uint32_t subcell = 0, prefix = 1;
    for (uint32_t level = 0; level < kCrossPixelLevels; ++level) {
        const uint32_t digit = ((pixelX >> level) & 1u) | (((pixelY >> level) & 1u) << 1);
        subcell = (subcell << 2) | kPermutations4[hashAt(key, prefix) % 24][digit];
        prefix = (prefix << 2) | digit;
    }
    return subcell;
}

void CrossPixelStrata::place(uint64_t stratum, uint32_t arity, uint32_t* jitter) const {
    constexpr uint32_t T = kCrossPixelLevels;
    const uint32_t s = subcell(stratum);
    if (arity == 1) {
        jitter[0] = (s << (32 - 2 * T)) | (jitter[0] >> (2 * T));
        return;
    }
    uint32_t sx = 0, sy = 0;
    for (uint32_t l = 0; l < T; ++l) {
        sx |= ((s >> (2 * l)) & 1u) << l;
        sy |= ((s >> (2 * l + 1)) & 1u) << l;
    }
    jitter[0] = (sx << (32 - T)) | (jitter[0] >> T);
    jitter[1] = (sy << (32 - T)) | (jitter[1] >> T);
}

void blueNoiseShift(uint64_t tileKey, uint32_t pixelX, uint32_t pixelY, uint32_t arity, float* shift) {
    const float* mask = blueNoiseMask();
    for (uint32_t c = 0; c < arity; ++c) {
        // Each axis reads the mask at its own hashed toroidal offset, and adds its own hashed offset.
        const uint64_t h = hashAt(tileKey, 100 + c);
        const uint32_t x = (pixelX + uint32_t(h)) & (kSize - 1), y = (pixelY + uint32_t(h >> 8)) & (kSize - 1);
        float v = mask[y * kSize + x] + unitFloat(hashAt(tileKey, 200 + c));
        v -= float(v >= 1.0f);
        shift[c] = v;
    }
}

void applyToroidalShift(const float* shift, uint32_t arity, size_t count, float* values) {
    for (size_t i = 0; i < count; ++i)
        for (uint32_t c = 0; c < arity; ++c) {
            float v = values[i * arity + c] + shift[c];
            v -= float(v >= 1.0f); // x + s < 2; a sum rounded up to exactly 1.0 becomes 0
            values[i * arity + c] = v;
        }
}

} // namespace stipple
