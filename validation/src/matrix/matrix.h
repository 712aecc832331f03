// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The validation matrix: which scenes, patterns, sample counts and seeds to run, how to make the reference,
// and which claims to check. Parsed from YAML (format in validation/README.md); every error names
// file:line:column and, for unknown names, the name and what is allowed.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace stipple::validation {

class MatrixError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A named rectangle of the image in normalised coordinates ([0, 1], x right, y down), e.g. the soft shadow
// under a box: error, efficiency and crops are reported for it on its own.
struct Region {
    std::string name;
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

// A host renderer run as a program (external_renderer.h): its command template, an argument vector with
// placeholders, and the format of the image it writes at {output}. Empty: stipple-render, in-process.
struct ExternalCommand {
    std::vector<std::string> command;
    std::string format = "exr"; // exr | pfm: the extension of {output}
    std::string where;          // file:line:column of the template in the matrix
    double timeoutSeconds = 0;  // timeout: seconds one image may take before the program is killed; 0: none
    bool empty() const { return command.empty(); }
};

// The library's limit on samples per pixel (STIPPLE_MAX_SAMPLES_PER_PIXEL in stipple.h, which the validation core
// does not include; kept equal by hand): a matrix's spp is checked against it when read.
inline constexpr long long kMaxSamplesPerPixel = 1ll << 20;

struct MatrixScene {
    std::string name;          // used by checks and in the report; default: the file's stem
    std::string file;          // as written in the matrix
    std::string path;          // resolved against the matrix file's folder
    int width = 0, height = 0; // 0: the scene's default
    std::string integrator;    // empty: the scene's
    int maxDepth = -1;         // -1: the scene's
    uint32_t referenceSpp = 0; // 0: the matrix's reference spp (a noisy scene may need more)
    std::vector<Region> regions;
    ExternalCommand renderer; // the scene's, else the matrix's; empty: stipple-render
};

struct ReferenceSettings {
    std::string pattern = "independent";
    uint32_t spp = 1024;
    uint64_t seed = 1000003;
};

struct CropSettings {
    double x = 0.5, y = 0.5; // centre as a fraction of width / height
    int size = 16;           // side in pixels (clamped to the image)
    int scale = 4;           // nearest-neighbour magnification of the PNGs
    uint32_t spp = 0;        // 0: the largest spp of the matrix
};

struct CheckKind; // check_kind.h

// A kind's own parameters: each kind's file derives its struct from this, and only that file reads it.
struct CheckParams {
    virtual ~CheckParams() = default;
};

// A claim of the matrix: its kind (check_kind.h; claims/check_registry.cpp lists them) and what the
// kind's keys read. The keys several kinds share are members here; a kind's own live in `params`.
struct Check {
    const CheckKind* kind = nullptr;
    std::string where; // file:line:column of the check in the matrix
    std::string scene = "all";
    std::string study;             // the study's statement the claim tests; empty: a claim of the library's own
    bool notSeparatedFails = true; // not_separated: fail makes an undecided verdict fail the run
    bool failFails = true;         // fails_run: false makes a FAIL a finding that does not fail the run
    std::shared_ptr<CheckParams> params; // set once, when the check is read
};

// The perceptual experiment (validation/src/perceptual/): test sets of one region's crops, each at the set's spp
// and the first seed, ranked by people; a control adds the set's first pattern at control spp (known: worst).
struct PerceptualSet {
    std::string scene, region;
    std::vector<std::string> patterns; // 2-4, distinct, of the matrix
    uint32_t spp = 0;                  // one of the matrix's
    std::string where;                 // file:line:column in the matrix
};

struct PerceptualPlan {
    std::vector<PerceptualSet> sets; // empty: no experiment
    int trials = 1;                  // showings of each set per observer
    int repeats = 1;                 // set trials shown a second time (consistency)
    int controls = 2;                // control trials
    uint32_t controlSpp = 0;         // 0: the matrix's smallest spp
    double margin = 0.5;             // JOD: a pair within ±margin (90% interval) is equivalent
};

struct Matrix {
    std::string path; // the matrix file as given
    std::string text; // its full text, shown in the report
    std::string name;
    std::vector<MatrixScene> scenes;
    std::vector<std::string> patterns;
    std::vector<uint32_t> spp;   // ascending
    std::vector<uint64_t> seeds; // K ≥ 4
    ReferenceSettings reference;
    std::string cacheDir; // resolved; empty: <report>/../.stipple-cache
    int threads = 0;
    CropSettings crop;
    double baselineTimeFactor = 1.5; // --baseline: a cell's median seconds may grow by this factor
    std::vector<Check> checks;
    PerceptualPlan perceptual;

    const MatrixScene* findScene(const std::string& name) const;
};

// The names a matrix may use, taken from their owners: the shim's patterns (render::patternNames) and the
// renderer's integrator registry (render::integratorNames).
struct MatrixVocabulary {
    std::vector<std::string> patterns, integrators;
};

// Reads and validates a matrix file. Throws MatrixError("file:line:column: what").
Matrix loadMatrix(const std::string& path, const MatrixVocabulary& vocabulary);
// Same, from text; `path` names it in errors and relative paths resolve against its folder.
Matrix parseMatrix(const std::string& text, const std::string& path, const MatrixVocabulary& vocabulary);

} // namespace stipple::validation
