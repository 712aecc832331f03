// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// orthant_tree.h — the quadtree (D = 2) and octree (D = 3) of the study's dart throwing.
//
// A bucket region tree over the unit cube: a leaf holds up to kLeafCapacity points, then splits into 2^D
// equal children. The only query dart throwing needs is "is any stored point closer than r to p on the
// torus?", answered by descending into nodes whose box is within r of p (or of a periodic image of p).
// It is written plainly on purpose: it IS the baseline poisson-seed is measured with.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

template <int D>
class OrthantTree {
public:
    using Point = std::array<float, D>;

    OrthantTree() { nodes_.push_back(Node{}); }

    void insert(const Point& p) {
        uint32_t index = uint32_t(points_.size());
        points_.push_back(p);
        insertInto(0, Point{}, 1.0f, index, 0);
    }

    // True if a stored point lies at toroidal distance < r from p (r < 0.5).
    bool anyWithin(const Point& p, float r) const {
        // The ball around p may cross the cube's faces: query each periodic image that reaches the cube.
        constexpr int kImages = D == 2 ? 9 : 27;
        for (int image = 0; image < kImages; ++image) {
            Point q = p;
            bool reaches = true;
            for (int k = 0, code = image; k < D; ++k, code /= 3) {
                int shift = code % 3 - 1;
                q[k] += float(shift);
                if ((shift < 0 && q[k] + r <= 0.0f) || (shift > 0 && q[k] - r >= 1.0f)) reaches = false;
            }
            if (reaches && anyWithinNode(0, Point{}, 1.0f, q, r * r)) return true;
        }
        return false;
    }

    const std::vector<Point>& points() const { return points_; }

private:
    static constexpr int kChildren = 1 << D;
    static constexpr int kLeafCapacity = 8;
    static constexpr int kMaxDepth = 20; // cells of 2^-20: below any radius dart throwing reaches

    struct Node {
        int32_t firstChild = -1; // children are kChildren consecutive nodes; -1 for a leaf
        uint32_t count = 0;      // points in this leaf
        uint32_t bucket = 0;     // index into buckets_ of this leaf's storage
        bool hasBucket = false;
    };

    static int childIndex(const Point& p, const Point& lo, float half) {
        int c = 0;
        for (int k = 0; k < D; ++k) c |= (p[k] >= lo[k] + half ? 1 : 0) << k;
        return c;
    }
    static Point childLo(const Point& lo, float half, int c) {
        Point l = lo;
        for (int k = 0; k < D; ++k)
            if (c >> k & 1) l[k] += half;
        return l;
    }

    void insertInto(uint32_t node, Point lo, float size, uint32_t index, int depth) {
        for (;;) {
            Node& n = nodes_[node];
            if (n.firstChild < 0) {
                if (!n.hasBucket) {
                    n.bucket = uint32_t(buckets_.size());
                    n.hasBucket = true;
                    buckets_.emplace_back();
                }
                if (n.count < kLeafCapacity || depth >= kMaxDepth) {
                    if (n.count < kLeafCapacity) buckets_[n.bucket][n.count++] = index;
                    // At kMaxDepth a full leaf drops nothing in practice: points closer than 2^-20 never
                    // pass the distance test. (Guard only against pathological input.)
                    return;
                }
                split(node, lo, size);
            }
            float half = size * 0.5f;
            int c = childIndex(points_[index], lo, half);
            node = uint32_t(nodes_[node].firstChild + c);
            lo = childLo(lo, half, c);
            size = half;
            ++depth;
        }
    }

    void split(uint32_t node, const Point& lo, float size) {
        int32_t first = int32_t(nodes_.size());
        nodes_.resize(nodes_.size() + kChildren);
        Node& n = nodes_[node];
        n.firstChild = first;
        std::array<uint32_t, kLeafCapacity> old = buckets_[n.bucket];
        uint32_t count = n.count;
        n.count = 0;
        // The parent's bucket is handed to its first child that needs one.
        uint32_t freeBucket = n.bucket;
        n.hasBucket = false;
        float half = size * 0.5f;
        for (uint32_t i = 0; i < count; ++i) {
            Node& child = nodes_[first + childIndex(points_[old[i]], lo, half)];
            if (!child.hasBucket) {
                if (freeBucket != UINT32_MAX) {
                    child.bucket = freeBucket;
                    freeBucket = UINT32_MAX;
                } else {
                    child.bucket = uint32_t(buckets_.size());
                    buckets_.emplace_back();
                }
                child.hasBucket = true;
            }
            buckets_[child.bucket][child.count++] = old[i];
        }
    }

    bool anyWithinNode(uint32_t node, const Point& lo, float size, const Point& q, float r2) const {
        // Squared distance from q to the node's box: skip boxes farther than r.
        float d2 = 0.0f;
        for (int k = 0; k < D; ++k) {
            float d = q[k] < lo[k] ? lo[k] - q[k] : (q[k] > lo[k] + size ? q[k] - lo[k] - size : 0.0f);
            d2 += d * d;
        }
        if (d2 >= r2) return false;
        const Node& n = nodes_[node];
        if (n.firstChild < 0) {
            for (uint32_t i = 0; i < n.count; ++i) {
                const Point& s = points_[buckets_[n.bucket][i]];
                float e2 = 0.0f;
                for (int k = 0; k < D; ++k) e2 += (s[k] - q[k]) * (s[k] - q[k]);
                if (e2 < r2) return true;
            }
            return false;
        }
        float half = size * 0.5f;
        for (int c = 0; c < kChildren; ++c)
            if (anyWithinNode(uint32_t(n.firstChild + c), childLo(lo, half, c), half, q, r2)) return true;
        return false;
    }

    std::vector<Node> nodes_;
    std::vector<std::array<uint32_t, kLeafCapacity>> buckets_;
    std::vector<Point> points_;
};

} // namespace stipple::detail::pointsets
