// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The compact document's builder: yaml-cpp's parser emits events, and each node becomes one record as it
// arrives. Children of the containers still open wait on one scratch stack and move to the document's child
// array when their container ends, so every child reference is written twice at most and memory stays linear
// in the input whatever its nesting. The parser keeps its own depth guard (DeepRecursion); nothing here recurses.
#include <stipple/yaml/document.h>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <istream>
#include <streambuf>
#include <unordered_set>

namespace stipple::yaml {

namespace {

// An istream over text already in memory: the parser reads it in place, no second copy.
struct MemoryBuffer : std::streambuf {
    explicit MemoryBuffer(std::string_view text) {
        char* p = const_cast<char*>(text.data());
        setg(p, p, p + text.size());
    }
};

Mark markOf(const YAML::Mark& m) { return {m.line, m.column}; }

} // namespace

class DocumentBuilder : public YAML::EventHandler {
public:
    explicit DocumentBuilder(Document& doc) : d_(doc) {}

    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}

    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        add(record(mark, Document::Kind::Null, 0, 0), anchor);
    }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        if (anchor == 0 || anchor >= anchors_.size() || anchors_[anchor] == Document::kNone)
            throw DocumentError(DocumentError::Kind::Syntax, markOf(mark), "alias to an unknown anchor");
        place(anchors_[anchor]);
    }
    void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  const std::string& value) override {
        checkTag(mark, tag);
        // yaml-cpp would merge nothing: a map key "<<" would be read as a plain (unknown) key.
        if (tag == "?" && value == "<<" && !open_.empty() && open_.back().map &&
            (scratch_.size() - open_.back().start) % 2 == 0)
            throw DocumentError(DocumentError::Kind::Syntax, markOf(mark), "YAML merge keys (<<) are not supported");
        const size_t offset = d_.arena_.size();
        if (offset + value.size() + 1 > UINT32_MAX)
            throw DocumentError(DocumentError::Kind::Other, markOf(mark), "scalars larger than 4 GiB in total");
        d_.arena_.insert(d_.arena_.end(), value.begin(), value.end());
        d_.arena_.push_back('\0');
        const uint32_t node = record(mark, Document::Kind::Scalar, uint32_t(offset), uint32_t(value.size()));
        if (tag == "!") d_.nodes_[node].kindAndColumn |= Document::kQuotedBit; // yaml-cpp's tag of a quoted scalar
        add(node, anchor);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value) override {
        checkTag(mark, tag);
        open(record(mark, Document::Kind::Sequence, 0, 0), anchor);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value) override {
        checkTag(mark, tag);
        open(record(mark, Document::Kind::Map, 0, 0), anchor);
    }
    void OnMapEnd() override { close(); }

private:
    // A container still being filled: its record, where its children start on the scratch stack, and (for a
    // big map) the set of its scalar keys so far.
    // Scalar keys by their text, held as node indices: the arena may move while the map grows.
    struct KeyHash {
        const Document* d;
        size_t operator()(uint32_t n) const { return std::hash<std::string_view>()(d->text(d->record(n))); }
    };
    struct KeyEqual {
        const Document* d;
        bool operator()(uint32_t a, uint32_t b) const { return d->text(d->record(a)) == d->text(d->record(b)); }
    };
    using KeySet = std::unordered_set<uint32_t, KeyHash, KeyEqual>;
    struct Open {
        uint32_t node;
        size_t start;
        bool map;
        std::unique_ptr<KeySet> keys;
    };
    static constexpr size_t kLinearKeyScan = 16; // below this many keys a scan beats a hash set

    // "?" (plain) and "!" (quoted) are yaml-cpp's non-specific tags; any other is an explicit tag, which the
    // loaders would ignore (!!str 5 read as a number): refused.
    static void checkTag(const YAML::Mark& mark, const std::string& tag) {
        if (!tag.empty() && tag != "?" && tag != "!")
            throw DocumentError(DocumentError::Kind::Syntax, markOf(mark),
                                "YAML tags ('" + tag + "') are not supported");
    }

    uint32_t record(const YAML::Mark& mark, Document::Kind kind, uint32_t first, uint32_t count) {
        if (d_.nodes_.size() >= Document::kNone - 1)
            throw DocumentError(DocumentError::Kind::Other, markOf(mark), "more than 4 G nodes");
        const uint32_t column = std::min<uint32_t>(uint32_t(std::max(mark.column, 0)), Document::kColumnMask);
        d_.nodes_.push_back({uint32_t(std::max(mark.line, 0)), (uint32_t(kind) << 30) | column, first, count});
        return uint32_t(d_.nodes_.size() - 1);
    }
    void remember(uint32_t node, YAML::anchor_t anchor) {
        if (anchor == 0) return;
        if (anchor >= anchors_.size()) anchors_.resize(anchor + 1, Document::kNone);
        anchors_[anchor] = node;
    }
    void add(uint32_t node, YAML::anchor_t anchor) {
        remember(node, anchor);
        place(node);
    }
    void open(uint32_t node, YAML::anchor_t anchor) {
        remember(node, anchor);
        place(node);
        open_.push_back({node, scratch_.size(), d_.nodes_[node].kind() == Document::Kind::Map, nullptr});
    }
    void close() {
        Open& o = open_.back();
        Document::Record& r = d_.nodes_[o.node];
        r.first = uint32_t(d_.children_.size());
        r.count = uint32_t(scratch_.size() - o.start);
        for (size_t i = o.start; i < scratch_.size(); ++i) d_.children_.push_back(scratch_[i]);
        scratch_.truncate(o.start);
        open_.pop_back();
    }
    // A finished node (or an alias's target) becomes the root or the next child of the innermost container.
    void place(uint32_t node) {
        if (open_.empty()) {
            if (d_.root_ == Document::kNone) d_.root_ = node;
            return;
        }
        Open& o = open_.back();
        if (o.map && (scratch_.size() - o.start) % 2 == 0) checkKey(o, node);
        scratch_.push_back(node);
    }
    // yaml-cpp keeps both entries of a repeated key and lookups find the first: a repeat is an error here.
    void checkKey(Open& o, uint32_t key) {
        const Document::Record& k = d_.nodes_[key];
        if (k.kind() != Document::Kind::Scalar) return;
        const std::string_view name = d_.text(k);
        const size_t keys = (scratch_.size() - o.start) / 2;
        bool repeated = false;
        if (keys < kLinearKeyScan) {
            for (size_t i = o.start; i < scratch_.size(); i += 2) {
                const Document::Record& other = d_.nodes_[scratch_[i]];
                repeated |= other.kind() == Document::Kind::Scalar && d_.text(other) == name;
            }
        } else {
            if (!o.keys) {
                o.keys = std::make_unique<KeySet>(2 * keys, KeyHash{&d_}, KeyEqual{&d_});
                for (size_t i = o.start; i < scratch_.size(); i += 2)
                    if (d_.nodes_[scratch_[i]].kind() == Document::Kind::Scalar) o.keys->insert(scratch_[i]);
            }
            repeated = !o.keys->insert(key).second;
        }
        if (repeated)
            throw DocumentError(DocumentError::Kind::DuplicateKey, Mark{int(k.line), int(k.column())},
                                "duplicate key '" + std::string(name) + "'");
    }

    Document& d_;
    ChunkedArray<uint32_t> scratch_;
    std::vector<Open> open_;
    std::vector<uint32_t> anchors_; // yaml-cpp's anchor id -> node
};

std::shared_ptr<const Document> Document::parse(std::string_view text) {
    auto doc = std::make_shared<Document>();
    // Scalars never take more than the text plus one NUL each (escapes only shrink): reserved once, the arena
    // never moves; the pages not written stay unmapped.
    doc->arena_.reserve(text.size() + text.size() / 2 + 64);
    try {
        MemoryBuffer buffer(text);
        std::istream in(&buffer);
        YAML::Parser parser(in);
        DocumentBuilder builder(*doc);
        parser.HandleNextDocument(builder);
        // A second document ("---") would be ignored by a loader that reads the first: refused.
        struct SecondDocument : YAML::EventHandler {
            void OnDocumentStart(const YAML::Mark& mark) override {
                throw DocumentError(DocumentError::Kind::Syntax, markOf(mark),
                                    "a second YAML document ('---'); a file holds one");
            }
            void OnDocumentEnd() override {}
            void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
            void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
            void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
            void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                                 YAML::EmitterStyle::value) override {}
            void OnSequenceEnd() override {}
            void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
            void OnMapEnd() override {}
        } second;
        parser.HandleNextDocument(second);
    } catch (const YAML::DeepRecursion& e) {
        throw DocumentError(DocumentError::Kind::TooDeep, markOf(e.mark), e.msg);
    } catch (const YAML::ParserException& e) {
        throw DocumentError(DocumentError::Kind::Syntax, markOf(e.mark), e.msg);
    } catch (const YAML::Exception& e) {
        throw DocumentError(DocumentError::Kind::Other, Mark{}, e.msg);
    }
    return doc;
}

} // namespace stipple::yaml
