// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// A report folder is all-or-nothing: it is written into a temporary folder beside the target and swapped in
// whole (renameat2 RENAME_EXCHANGE, then the old one is removed), so a reader sees the old report or the new one,
// never a mix, and the folder holds only the current run's files. An interrupted run leaves the old report and a
// temporary folder that the signal handler or the next run removes.
//
// Only a folder stipple-validate made is ever replaced: every report holds the marker file kReportMarker (or,
// written by an earlier version, exactly a report's files), and any other folder (a website with an index.html,
// a home folder) is refused whole and left untouched. A target
// that is a symlink to a report folder is resolved: the report is published into the folder it points to, and
// the link stays.
#pragma once

#include <string>

#include <stipple/render/temp_files.h>

namespace stipple::validation {

// The file every report folder holds: what makes a folder one stipple-validate may replace.
inline constexpr const char* kReportMarker = ".stipple-report";

class ReportStaging {
public:
    // Throws std::runtime_error when `target` exists but is not a report folder (see isReplaceableReportFolder),
    // is a symlink to anything else, or when the temporary folder cannot be created beside it.
    explicit ReportStaging(const std::string& target);
    // The folder to write the report into.
    const std::string& dir() const { return temp_.path(); }
    // Swaps the finished report into place, after checking again (signals held) that the target is still a
    // folder it may replace. Throws std::runtime_error otherwise, leaving the target untouched and the new report
    // in <target>.unpublished-<pid>.
    void publish();

private:
    std::string target_;
    render::TempPath temp_;
};

// True when `dir` may be replaced by a report: missing, an empty folder, a folder holding kReportMarker as a
// regular file, or one an earlier version wrote (exactly a report's files: index.html, results.json, the CSVs,
// crops/ of PNGs, plots/ of gnuplot's files). Not followed if `dir` is a symlink: resolve it first.
bool isReplaceableReportFolder(const std::string& dir);

// `dir` itself, or, when it is a symlink, the folder it resolves to (absolute). Throws std::runtime_error for a
// symlink that does not resolve to a folder.
std::string resolveReportTarget(const std::string& dir);

} // namespace stipple::validation
