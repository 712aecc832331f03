// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The perceptual experiment in the report: people's verdict per pair beside the study table, and the study's
// Figure 8 redone (a gnuplot plot per test set: JOD with 95% intervals) beside mean FLIP and RMS of the same crops.
#pragma once

#include <string>

#include "report/report_inputs.h"
#include "perceptual/study_analysis.h"

namespace stipple::validation {

// The report's block (empty without a 'perceptual' section): from in.studyDir's votes when given, else a pointer
// to the experiment folder. Plots go to <in.reportDir>/plots.
std::string perceptualStudyHtml(const ReportInputs& in);

// A first-screen perceptual cell ("<td ...>...</td>") with people's verdict on (A = p, B = q) added where
// in.studyDir's votes have a set of that scene and region holding both patterns; else the cell unchanged.
std::string withPeopleVerdict(const std::string& cell, const ReportInputs& in, const std::string& scene,
                              const std::string& region, const std::string& p, const std::string& q);

// The verdict table and Figure 8 with plots under `plotsDir` (linked as `plotsHref`/...). Returns the HTML.
std::string studyFigureHtml(const StudyKey& key, const StudyAnalysis& a, const std::string& plotsDir,
                            const std::string& plotsHref);

// --analyse-study FOLDER [VOTES...]: analyses FOLDER's votes (and the files or folders given), prints the
// analysis and writes FOLDER/analysis/ (index.html, analysis.json, analysis.txt, plots). Returns the exit status.
int analyseStudyCommand(const std::string& folder, const std::vector<std::string>& extraVotes);

} // namespace stipple::validation
