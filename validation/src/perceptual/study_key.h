// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// An experiment folder's key (key.json): which crop id is which pattern, per test set, with the set's mean FLIP
// and RMS from the run. The page never loads it; the analysis and the vote checks do.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace stipple::validation {

// A bad key or votes file: the message names the file and the field.
class StudyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct StudyCrop {
    std::string id, pattern;
    uint32_t spp = 0;
    int width = 0, height = 0;
    double flip = 0, flipHalfWidth = 0; // mean LDR-FLIP over the run's seeds, region only, ± 95%
    double rms = 0;                     // RMS over the region, root of the mean MSE over the seeds
};

struct StudySet {
    std::string name, scene, region;
    uint32_t spp = 0;
    std::vector<StudyCrop> crops; // in the matrix's pattern order of the set
    StudyCrop control;            // crops[0]'s pattern at the control's spp: the known worst
};

struct StudyKey {
    std::string study; // id of this experiment: votes for another are refused
    std::string matrix;
    int trials = 1, repeats = 1, controls = 2;
    uint32_t controlSpp = 0;
    double margin = 0.5;
    std::vector<StudySet> sets;

    // Trials a finished observer's votes hold.
    int trialCount() const { return int(sets.size()) * trials + repeats + controls; }
};

inline constexpr const char* kStudyKeyFile = "key.json";
inline constexpr const char* kStudyVotesDir = "votes";

std::string studyKeyJson(const StudyKey& key);
// The page's plan: crop ids and sizes, no pattern names.
std::string studyPlanJson(const StudyKey& key);
StudyKey parseStudyKey(const std::string& text, const std::string& name);
StudyKey loadStudyKey(const std::string& folder);

} // namespace stipple::validation
