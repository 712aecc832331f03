// A report folder is all-or-nothing: it is written into a temporary folder beside the target and swapped in
// whole (renameat2 RENAME_EXCHANGE, then the old one is removed), so a reader sees the old report or the new one,
// never a mix, and the folder holds only the current run's files. An interrupted run leaves the old report and a
// temporary folder that the signal handler or the next run removes.
#pragma once

#include <string>

#include <stipple/render/temp_files.h>

namespace stipple::validation {

class ReportStaging {
public:
    // Throws std::runtime_error when `target` exists but is not a report folder (an empty folder, or one with
    // index.html or results.json at its top), or when the temporary folder cannot be created beside it.
    explicit ReportStaging(const std::string& target);
    // The folder to write the report into.
    const std::string& dir() const { return temp_.path(); }
    // Swaps the finished report into place.
    void publish();

private:
    std::string target_;
    render::TempPath temp_;
};

// True when `dir` may be replaced by a report: missing, empty, or holding index.html or results.json.
bool isReplaceableReportFolder(const std::string& dir);

} // namespace stipple::validation
