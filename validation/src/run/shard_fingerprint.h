// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The fingerprint of a run: everything that decides whether its rows can be put beside another run's — the
// matrix as resolved (scenes with their resolved render settings, patterns, spp, seeds, reference, crop, checks),
// the scene files' content hashes, the renderer's version and the shim's identity. Every run (single or shard)
// stores it in results.json field by field; --merge refuses shards whose fingerprints differ and names the first
// field that does, so a matrix edited between two submissions cannot be averaged into one report.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <stipple/render/input_limits.h>

#include "matrix/matrix.h"

namespace stipple::validation {

struct FingerprintField {
    std::string name;  // e.g. "scene.cornell.width"
    std::string value; // compact JSON text of the value (compared as text)
    bool operator==(const FingerprintField&) const = default;
};

struct Fingerprint {
    std::vector<FingerprintField> fields; // in a fixed order: matrix, scenes (matrix order), renderer, shim
    bool empty() const { return fields.empty(); }
    const FingerprintField* find(const std::string& name) const;
    void add(const std::string& name, const std::string& jsonValue) { fields.push_back({name, jsonValue}); }
};

// What the renderer made of one matrix scene: its resolved settings. `loaded` false: the scene did not load
// (its error is in skipped_scenes), and only its file is known.
struct SceneFingerprint {
    bool loaded = false;
    std::string contentHash; // of the scene file and everything it includes
    int width = 0, height = 0, maxDepth = 0;
    std::string integrator;
    uint32_t referenceSpp = 0;
};

// The fields that follow from the matrix alone ("matrix.*"): scene names, patterns, spp, seeds, reference pattern
// and seed, crop, checks. Threads, cache folder and name are left out: they change no row.
Fingerprint matrixFingerprint(const Matrix& matrix);

// The whole fingerprint: matrixFingerprint, then per scene (matrix order) "scene.<name>.*", then
// "renderer.version" and "shim.identity". `scenes` is indexed like matrix.scenes.
Fingerprint runFingerprint(const Matrix& matrix, const std::vector<SceneFingerprint>& scenes,
                           const std::string& rendererVersion, const std::string& shimIdentity);

// The "fingerprint" member of results.json: a JSON object, one member per field, in order.
std::string fingerprintJson(const Fingerprint& fingerprint, const std::string& indent = "  ");
// Reads the "fingerprint" object of a results.json of at most `maxBytes` bytes; empty when the file has none (older
// versions). Throws std::runtime_error naming the file when it cannot be read or parsed, or is over the limit.
Fingerprint readFingerprint(const std::string& resultsJsonPath, uint64_t maxBytes = render::limits::kMaxYamlFileBytes);
// The same of a results.json's text already read from `path`.
Fingerprint parseFingerprint(const std::string& text, const std::string& path);

struct FingerprintDifference {
    std::string field, a, b; // a missing field reads "(absent)"
};
// The first field, in a's order (then b's extra fields), whose values differ; nothing when they are equal.
std::optional<FingerprintDifference> firstDifference(const Fingerprint& a, const Fingerprint& b);
// Same, over the fields whose names start with `prefix` only.
std::optional<FingerprintDifference> firstDifference(const Fingerprint& a, const Fingerprint& b,
                                                     const std::string& prefix);

// --merge's gate: every shard folder's fingerprint equals the first's, and the first's "matrix.*" fields but the
// checks equal those of the matrix given to --merge (whose checks the merge evaluates). Throws std::runtime_error
// naming the field, both values and both folders (or the matrix file), or the folder whose results.json has no
// fingerprint.
void checkShardFingerprints(const Matrix& matrix, const std::vector<std::string>& dirs);

} // namespace stipple::validation
