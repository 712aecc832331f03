// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "report/report_publish.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <unistd.h>
#include <stdio.h>

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

// True when every entry of `dir` is a regular file with one of `extensions` (no folders, no symlinks).
bool onlyFilesEndingIn(const fs::path& dir, const std::vector<std::string>& extensions) {
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string ext = it->path().extension().string();
        if (!fs::is_regular_file(it->symlink_status(ec)) ||
            std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
            return false;
    }
    return !ec;
}

// A report an earlier version wrote (before the marker): exactly a report's files and nothing else.
bool isEarlierReport(const fs::path& dir) {
    static const std::vector<std::string> files = {"index.html", "results.json", "results.csv", "cells.csv"};
    std::error_code ec;
    bool index = false, results = false;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const fs::file_status st = it->symlink_status(ec);
        if (std::find(files.begin(), files.end(), name) != files.end() && fs::is_regular_file(st)) {
            index |= name == "index.html";
            results |= name == "results.json";
        } else if (name == "crops" && fs::is_directory(st)) {
            if (!onlyFilesEndingIn(it->path(), {".png"})) return false;
        } else if (name == "plots" && fs::is_directory(st)) {
            if (!onlyFilesEndingIn(it->path(), {".png", ".svg", ".dat", ".gp", ".log"})) return false;
        } else {
            return false;
        }
    }
    return !ec && index && results;
}

} // namespace

bool isReplaceableReportFolder(const std::string& dir) {
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(dir, ec);
    if (!fs::exists(st)) return true;
    if (!fs::is_directory(st)) return false;
    if (fs::is_empty(dir, ec) && !ec) return true;
    return fs::is_regular_file(fs::symlink_status(fs::path(dir) / kReportMarker, ec)) || isEarlierReport(dir);
}

std::string resolveReportTarget(const std::string& dir) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(dir, ec))) return dir;
    const fs::path real = fs::canonical(dir, ec);
    if (ec || !fs::is_directory(real, ec))
        throw std::runtime_error("-o " + dir + ": a symlink that does not lead to a folder; refusing to replace it");
    return real.string();
}

ReportStaging::ReportStaging(const std::string& target)
    : target_(resolveReportTarget([&] {
          std::string t = fs::path(target).lexically_normal().string();
          if (!t.empty() && t.back() == '/') t.pop_back(); // "report/" would follow a symlink named report
          return t;
      }())),
      temp_(target_) {
    const std::string leaf = fs::path(temp_.path()).filename().string();
    if (target_.empty() || target_ == "." || target_ == ".." || target_ == "/" || target_.ends_with("/..") ||
        target_.ends_with("/.") || leaf.rfind("...", 0) == 0)
        throw std::runtime_error("-o " + target + ": must name a report folder, not the working folder, a parent or /");
    if (!isReplaceableReportFolder(target_))
        throw std::runtime_error("-o " + target + ": exists and is not a report folder (not empty, no " +
                                 kReportMarker + " that stipple-validate writes in each report, and files a "
                                 "report does not have); refusing to replace it");
    std::error_code ec;
    const fs::path parent = fs::absolute(temp_.path()).parent_path();
    fs::create_directories(parent, ec);
    render::sweepStaleTemps(parent.string());
    if (!fs::create_directory(temp_.path(), ec) || ec)
        throw std::runtime_error("-o " + target + ": cannot create a folder beside it (" + temp_.path() +
                                 "): " + (ec ? ec.message() : std::string("it exists")));
    std::ofstream marker(fs::path(temp_.path()) / kReportMarker);
    marker << "a report folder of stipple-validate: the next run with -o here replaces it whole\n";
    if (!marker.flush())
        throw std::runtime_error("-o " + target + ": cannot write in " + temp_.path());
}

void ReportStaging::publish() {
    render::SignalHold hold;
    const std::string& target = target_;
    std::error_code ec;
    // The folder was checked when the run started; whatever was made or filled there since is checked again here,
    // under the hold, just before the exchange. A folder that is no longer a report's keeps its files, and the new
    // report is kept beside it under a name no sweep removes.
    if (!isReplaceableReportFolder(target)) {
        const std::string kept = target + ".unpublished-" + std::to_string(::getpid());
        std::string where = temp_.path();
        if (std::rename(temp_.path().c_str(), kept.c_str()) == 0) {
            temp_.release();
            where = kept;
        }
        throw std::runtime_error("-o " + target + ": changed during the run and is no longer a report folder (files "
                                 "a report does not have); it is left untouched and the new report is in " + where);
    }
    if (fs::exists(target, ec)) {
        // One atomic step: the old report takes the temporary's name, the new one the target's.
        if (renameat2(AT_FDCWD, temp_.path().c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0) {
            if (errno != EINVAL && errno != ENOSYS)
                throw std::runtime_error("cannot swap the report into " + target + ": " + std::strerror(errno));
            // A file system without exchange (NFS): the rename dance, with a moment when the target is absent.
            render::TempPath old(target);
            if (std::rename(target.c_str(), old.path().c_str()) != 0 ||
                std::rename(temp_.path().c_str(), target.c_str()) != 0)
                throw std::runtime_error("cannot move the report to " + target + ": " + std::strerror(errno));
            temp_.release();
            return; // old's destructor removes the previous report
        }
        // temp_ now names the old report: its destructor removes it (and so would a signal).
        return;
    }
    if (std::rename(temp_.path().c_str(), target.c_str()) != 0)
        throw std::runtime_error("cannot move the report to " + target + ": " + std::strerror(errno));
    temp_.release();
}

} // namespace stipple::validation
