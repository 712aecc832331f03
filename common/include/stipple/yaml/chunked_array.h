// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// An append-only array in fixed-size chunks: growing it never copies what is stored and never holds two copies
// at once, so its peak memory is its size plus one chunk (a std::vector's doubling peaks at three times its size
// while it moves). Used for a parsed document's node records and child lists.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace stipple::yaml {

template <typename T, unsigned kChunkBits = 12>
class ChunkedArray {
public:
    static constexpr size_t kChunk = size_t(1) << kChunkBits;

    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T& operator[](size_t i) { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
    const T& operator[](size_t i) const { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
    T& back() { return (*this)[size_ - 1]; }

    void push_back(const T& value) {
        if ((size_ >> kChunkBits) == chunks_.size()) chunks_.push_back(std::make_unique<T[]>(kChunk));
        (*this)[size_++] = value;
    }
    // Drops the elements from `n` on and frees the chunks no longer used.
    void truncate(size_t n) {
        if (n >= size_) return;
        size_ = n;
        chunks_.resize((n + kChunk - 1) >> kChunkBits);
    }
    size_t bytes() const { return chunks_.size() * kChunk * sizeof(T) + chunks_.capacity() * sizeof(void*); }

private:
    std::vector<std::unique_ptr<T[]>> chunks_;
    size_t size_ = 0;
};

} // namespace stipple::yaml
