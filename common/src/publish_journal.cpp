// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include <stipple/render/publish_journal.h>

#include <stipple/render/temp_files.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace stipple::render {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHeader = "stipple-publish 1\n";
constexpr const char* kJournalExtension = ".publish";

// The journal's entries as plain names; false when the text is not a whole journal of plain names.
bool parseJournal(const std::string& text, std::vector<PendingRename>& out) {
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line + "\n" != kHeader) return false;
    for (;;) {
        if (!std::getline(in, line)) return false;
        if (line == "end") break;
        size_t tempLength = 0, targetLength = 0;
        std::istringstream lengths(line);
        if (!(lengths >> tempLength >> targetLength) || tempLength == 0 || targetLength == 0 ||
            tempLength + targetLength > 8192)
            return false;
        std::string names(tempLength + targetLength, '\0');
        if (!in.read(names.data(), std::streamsize(names.size())) || in.get() != '\n') return false;
        PendingRename r{names.substr(0, tempLength), names.substr(tempLength)};
        for (const std::string* n : {&r.temp, &r.target})
            if (n->find('/') != std::string::npos || n->find('\0') != std::string::npos || *n == "." || *n == "..")
                return false;
        // A temporary of exactly that target (tempPathBeside's naming), nothing else.
        if (!isTempName(r.temp) || r.temp.rfind("." + r.target + ".stipple-tmp-", 0) != 0) return false;
        out.push_back(std::move(r));
    }
    return !out.empty();
}

bool isThere(const fs::path& p) {
    std::error_code ec;
    return fs::exists(fs::symlink_status(p, ec));
}

} // namespace

bool isPublishJournalName(const std::string& name) {
    return isTempName(name) && name.size() > std::strlen(kJournalExtension) &&
           name.compare(name.size() - std::strlen(kJournalExtension), std::string::npos, kJournalExtension) == 0;
}

std::string writePublishJournal(const std::vector<PendingRename>& renames) {
    if (renames.empty()) throw std::invalid_argument("writePublishJournal: nothing to publish");
    const fs::path dir = fs::path(renames.front().target).parent_path();
    std::string text = kHeader;
    for (const PendingRename& r : renames) {
        if (fs::path(r.temp).parent_path() != dir || fs::path(r.target).parent_path() != dir)
            throw std::invalid_argument("writePublishJournal: '" + r.temp + "' and '" + r.target +
                                        "' are not in one folder");
        const std::string temp = fs::path(r.temp).filename().string(), target = fs::path(r.target).filename().string();
        text += std::to_string(temp.size()) + " " + std::to_string(target.size()) + "\n" + temp + target + "\n";
    }
    text += "end\n";
    const std::string journal = tempPathBeside(renames.front().target + kJournalExtension);
    TempPath part(renames.front().target + ".publish-part"); // a plain temporary until renamed
    const int fd = ::open(part.path().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("cannot write '" + part.path() + "': " + std::strerror(errno));
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            throw std::runtime_error("cannot write '" + part.path() + "': " + why);
        }
        done += size_t(n);
    }
    ::fsync(fd); // the journal's content is on disk before its name is
    ::close(fd);
    if (::rename(part.path().c_str(), journal.c_str()) != 0)
        throw std::runtime_error("cannot rename '" + part.path() + "' to '" + journal + "': " + std::strerror(errno));
    part.release();
    return journal;
}

void renameTogether(const std::vector<PendingRename>& renames) {
    SignalHold hold; // SIGINT / SIGTERM wait until every rename is done (or undone)
    const std::string journal = writePublishJournal(renames);
    for (size_t i = 0; i < renames.size(); ++i) {
        std::error_code ec;
        fs::rename(renames[i].temp, renames[i].target, ec);
        if (!ec) continue;
        // The targets before i are new; the rest would be stale partners: remove them with their temporaries.
        for (size_t j = i; j < renames.size(); ++j) {
            std::error_code ignored;
            fs::remove(renames[j].target, ignored);
            fs::remove(renames[j].temp, ignored);
        }
        std::error_code ignored;
        fs::remove(journal, ignored);
        throw std::runtime_error("cannot rename '" + renames[i].temp + "' to '" + renames[i].target +
                                 "': " + ec.message());
    }
    std::error_code ec;
    fs::remove(journal, ec);
}

bool recoverPublishJournal(const std::string& path) {
    // Only a journal this user wrote is obeyed; another user's (planted in a shared folder) is left as it is.
    if (std::string why; !isOwnFile(path, false, why)) {
        warnLeftAlone(path, why);
        return false;
    }
    std::string text;
    if (const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC); fd >= 0) {
        char buf[65536];
        for (ssize_t n; text.size() <= (1u << 20) && (n = ::read(fd, buf, sizeof buf)) != 0;) {
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) break;
            text.append(buf, size_t(n));
        }
        ::close(fd);
    }
    std::vector<PendingRename> renames;
    const fs::path dir = fs::path(path).parent_path();
    bool readable = text.size() <= (1u << 20) && parseJournal(text, renames);
    // Every temporary and target it would rename or remove must be this user's regular file (or absent).
    for (const PendingRename& r : renames)
        for (const std::string* name : {&r.temp, &r.target})
            if (std::string why; isThere(dir / *name) && !isOwnFile((dir / *name).string(), false, why)) {
                warnLeftAlone((dir / *name).string(), why + " (named by the publish journal " + path + ")");
                readable = false;
            }
    if (readable) {
        // Renames run in order, so the temporaries still there form a tail when nothing else interfered.
        std::vector<bool> present;
        for (const PendingRename& r : renames) present.push_back(isThere(dir / r.temp));
        bool tail = true;
        for (size_t i = 1; i < present.size(); ++i) tail &= present[i] || !present[i - 1];
        for (size_t i = 0; i < renames.size(); ++i) {
            if (!present[i]) continue;
            std::error_code ec;
            if (tail) {
                fs::rename(dir / renames[i].temp, dir / renames[i].target, ec);
            } else {
                fs::remove(dir / renames[i].target, ec); // its partners are new: the old file must not stay
                fs::remove(dir / renames[i].temp, ec);
            }
        }
    }
    std::error_code ec;
    fs::remove(path, ec);
    return readable;
}

} // namespace stipple::render
