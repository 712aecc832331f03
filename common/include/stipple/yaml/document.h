// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// A parsed YAML document in compact form, and the read-only view of its nodes that the loaders use.
//
// yaml-cpp's own node tree costs about 60-70 bytes of memory per byte of input. Here a document is three flat
// arrays: one 16-byte record per node, one 4-byte index per child reference and one arena holding every scalar's
// text once (NUL-terminated). An alias is the index of its anchored node, never a copy, so a "billion laughs"
// input stays as small as its text. The builder (document.cpp) reads yaml-cpp's event stream and rejects while
// building what yaml-cpp would accept but a loader would misread: a duplicate map key, a merge key (<<), a tag
// (!!int, !foo), a second document (---); yaml-cpp does not appear in this header.
#pragma once

#include <stipple/yaml/chunked_array.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace stipple::yaml {

// A position in the text, 0-based; line < 0 when a node has none (a missing key, an empty document).
struct Mark {
    int line = -1;
    int column = -1;
};

// Why a text is not a document; `mark` is where (line < 0 when unknown). The message is yaml-cpp's or ours,
// without a position: StrictYaml puts file:line:column in front.
class DocumentError : public std::runtime_error {
public:
    enum class Kind { Syntax, TooDeep, DuplicateKey, Other };
    DocumentError(Kind kind, Mark mark, const std::string& message)
        : std::runtime_error(message), kind(kind), mark(mark) {}
    Kind kind;
    Mark mark;
};

class Node;

class Document {
public:
    enum class Kind : uint8_t { Null, Scalar, Sequence, Map };

    // Parses `text`, which must hold one document. Throws DocumentError.
    static std::shared_ptr<const Document> parse(std::string_view text);

    // One node: where it starts, and either its scalar text (arena offset, length) or its children (offset into
    // children_, count; a map's children alternate key, value).
    struct Record {
        uint32_t line;
        uint32_t kindAndColumn; // kind in the top 2 bits, then the quoted flag, column (saturated) in the rest
        uint32_t first;
        uint32_t count;
        Kind kind() const { return Kind(kindAndColumn >> 30); }
        bool quoted() const { return (kindAndColumn & kQuotedBit) != 0; }
        uint32_t column() const { return kindAndColumn & kColumnMask; }
    };
    static constexpr uint32_t kQuotedBit = 1u << 29;
    static constexpr uint32_t kColumnMask = kQuotedBit - 1;
    static constexpr uint32_t kNone = UINT32_MAX;

    const Record& record(uint32_t i) const { return nodes_[i]; }
    uint32_t child(uint32_t i) const { return children_[i]; }
    std::string_view text(const Record& r) const { return {arena_.data() + r.first, r.count}; }
    uint32_t root() const { return root_; }

    // Bytes held, for the memory accounting in tests and messages.
    size_t bytes() const { return nodes_.bytes() + children_.bytes() + arena_.capacity(); }

private:
    friend class DocumentBuilder;
    ChunkedArray<Record> nodes_;
    ChunkedArray<uint32_t> children_;
    std::vector<char> arena_;
    uint32_t root_ = kNone;
};

// A read-only view of one node of a Document (which it keeps alive), or an undefined node (a missing key or
// index). The names follow yaml-cpp's Node so the loaders read the same.
class Node {
public:
    Node() = default;
    Node(std::shared_ptr<const Document> doc, uint32_t index) : doc_(std::move(doc)), index_(index) {}

    bool IsDefined() const { return doc_ != nullptr && index_ != Document::kNone; }
    explicit operator bool() const { return IsDefined(); }
    bool operator!() const { return !IsDefined(); }
    bool IsNull() const { return IsDefined() && kind() == Document::Kind::Null; }
    bool IsScalar() const { return IsDefined() && kind() == Document::Kind::Scalar; }
    bool IsSequence() const { return IsDefined() && kind() == Document::Kind::Sequence; }
    bool IsMap() const { return IsDefined() && kind() == Document::Kind::Map; }
    // A scalar written in quotes ('2' or "2"): text, never a number.
    bool IsQuoted() const { return IsScalar() && rec().quoted(); }

    // A scalar's text ("" for anything else). ScalarView's data is NUL-terminated.
    std::string Scalar() const { return std::string(ScalarView()); }
    std::string_view ScalarView() const { return IsScalar() ? doc_->text(rec()) : std::string_view(""); }

    stipple::yaml::Mark Mark() const {
        if (!IsDefined()) return {};
        return {int(rec().line), int(rec().column())};
    }

    // Items of a sequence, key/value pairs of a map, 0 otherwise.
    size_t size() const {
        if (IsSequence()) return rec().count;
        if (IsMap()) return rec().count / 2;
        return 0;
    }
    // A map's value for a scalar key equal to `key`; undefined when absent or not a map.
    Node operator[](std::string_view key) const;
    // A sequence's item; undefined when out of range or not a sequence.
    Node operator[](size_t index) const {
        if (!IsSequence() || index >= rec().count) return {};
        return {doc_, doc_->child(rec().first + uint32_t(index))};
    }

    // What iteration yields: a sequence's item (the Node itself), or a map's pair (first = key, second = value).
    struct Entry;
    class iterator;
    iterator begin() const;
    iterator end() const;

private:
    Document::Kind kind() const { return rec().kind(); }
    const Document::Record& rec() const { return doc_->record(index_); }

    std::shared_ptr<const Document> doc_;
    uint32_t index_ = Document::kNone;
};

struct Node::Entry : Node {
    Node first, second;
};

class Node::iterator {
public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = Entry;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = Entry;

    iterator() = default;
    iterator(std::shared_ptr<const Document> doc, uint32_t first, uint32_t pos, bool map)
        : doc_(std::move(doc)), first_(first), pos_(pos), map_(map) {}

    Entry operator*() const {
        Entry e;
        if (map_) {
            e.first = Node(doc_, doc_->child(first_ + pos_));
            e.second = Node(doc_, doc_->child(first_ + pos_ + 1));
        } else {
            static_cast<Node&>(e) = Node(doc_, doc_->child(first_ + pos_));
        }
        return e;
    }
    struct Arrow {
        Entry e;
        const Entry* operator->() const { return &e; }
    };
    Arrow operator->() const { return Arrow{**this}; }
    iterator& operator++() {
        pos_ += map_ ? 2 : 1;
        return *this;
    }
    iterator operator++(int) {
        iterator t = *this;
        ++*this;
        return t;
    }
    bool operator==(const iterator& o) const { return pos_ == o.pos_; }
    bool operator!=(const iterator& o) const { return pos_ != o.pos_; }

private:
    std::shared_ptr<const Document> doc_;
    uint32_t first_ = 0, pos_ = 0;
    bool map_ = false;
};

inline Node::iterator Node::begin() const {
    if (!IsMap() && !IsSequence()) return {};
    return iterator(doc_, rec().first, 0, IsMap());
}
inline Node::iterator Node::end() const {
    if (!IsMap() && !IsSequence()) return {};
    return iterator(doc_, rec().first, rec().count, IsMap());
}

inline Node Node::operator[](std::string_view key) const {
    if (!IsMap()) return {};
    const Document::Record& r = rec();
    for (uint32_t i = 0; i + 1 < r.count; i += 2) {
        const Document::Record& k = doc_->record(doc_->child(r.first + i));
        if (k.kind() == Document::Kind::Scalar && doc_->text(k) == key) return {doc_, doc_->child(r.first + i + 1)};
    }
    return {};
}

} // namespace stipple::yaml
