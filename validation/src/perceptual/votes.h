// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// One observer's votes file, as the page writes it, checked against the experiment's key: the study id, the
// observer id, the trial counts per kind, every crop id and every ranking. Anything else is refused whole.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "perceptual/study_key.h"

namespace stipple::validation {

enum class TrialKind { Test, Repeat, Control };

struct TrialVote {
    TrialKind kind = TrialKind::Test;
    int set = 0;
    std::vector<std::string> shown;   // crop ids left to right
    std::vector<std::string> ranking; // best first; empty: no visible difference
    double milliseconds = 0;
};

struct ObserverVotes {
    std::string observer;
    std::string source; // the file it came from
    std::vector<TrialVote> trials;
};

// The largest votes file accepted (a finished session is a few kB).
inline constexpr size_t kMaxVotesBytes = 256 * 1024;

// True for an observer id the page and the server accept: 1-64 of [A-Za-z0-9_-] (safe as a file name).
bool validObserverId(const std::string& id);
// Throws StudyError("<name>: <field>: what").
ObserverVotes parseVotes(const std::string& text, const StudyKey& key, const std::string& name);
// Every votes-*.json / *.json of the folders and files given, in name order; a second file of an observer
// already read is an error naming both.
std::vector<ObserverVotes> loadVotes(const std::vector<std::string>& paths, const StudyKey& key);

} // namespace stipple::validation
