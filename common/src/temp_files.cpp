// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include <stipple/render/temp_files.h>

#include <stipple/render/publish_journal.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <cerrno>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <set>
#include <shared_mutex>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

namespace stipple::render {

namespace {

namespace fs = std::filesystem;

constexpr const char* kMarker = ".stipple-tmp-";
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

std::mutex& registryMutex() {
    static std::mutex m;
    return m;
}
std::set<std::string>& registry() {
    static std::set<std::string> r;
    return r;
}
// Shared by every SignalHold; the cleanup thread takes it exclusively before removing anything and keeps it until
// the process ends, so a group of renames completes and no temporary is created after the removal.
std::shared_mutex& holdMutex() {
    static std::shared_mutex m;
    return m;
}

std::string hostName() {
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) != 0 || !buf[0]) return "host";
    std::string h(buf);
    for (char& c : h)
        if (c == '/' || c == '-') c = '_';
    return h;
}

int signalPipe[2] = {-1, -1};

extern "C" void onSignal(int sig) {
    const unsigned char b = static_cast<unsigned char>(sig);
    const int saved = errno;
    [[maybe_unused]] ssize_t n = write(signalPipe[1], &b, 1); // the only async-signal-safe work done here
    errno = saved;
}

std::mutex& childGroupsMutex() {
    static std::mutex m;
    return m;
}
std::vector<int>& childGroups() {
    static std::vector<int> groups;
    return groups;
}

void cleanupThread() {
    unsigned char b = 0;
    while (read(signalPipe[0], &b, 1) < 0 && errno == EINTR) {}
    holdMutex().lock(); // never unlocked: a writer waiting for a SignalHold waits until the process ends
    {
        // Children first: they may still be writing into a temporary folder.
        std::lock_guard lock(childGroupsMutex());
        for (int g : childGroups()) ::kill(-g, SIGKILL);
        for (int g : childGroups()) ::waitpid(g, nullptr, 0); // a zombie leader would keep its pid taken
    }
    {
        std::lock_guard lock(registryMutex());
        // Files are written under a SignalHold, so none appears from here on. Writers that work without one (a
        // child process drawing into a temporary folder) may still add to a folder after remove_all listed it, or
        // bring a removed folder back: remove until two passes ~1 ms apart find nothing, and end right after.
        for (int attempt = 0, clean = 0; attempt < 200; ++attempt) {
            bool left = false;
            for (const std::string& p : registry()) {
                std::error_code ec;
                fs::remove_all(p, ec);
                left = left || fs::exists(p, ec);
            }
            clean = left ? 0 : clean + 1;
            if (clean == 2) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        registry().clear();
    }
    // End as the signal would have: default action, delivered to this thread.
    std::signal(int(b), SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, int(b));
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    raise(int(b));
    _exit(128 + int(b));
}

// host, pid and age of a temporary name; false when the name is not one.
bool parseTempName(const std::string& name, std::string& host, long& pid) {
    const size_t m = name.find(kMarker);
    if (name.empty() || name[0] != '.' || m == std::string::npos) return false;
    const std::string rest = name.substr(m + std::strlen(kMarker)); // host-pid-n[ext]
    const size_t last = rest.rfind('-');
    if (last == std::string::npos || last == 0) return false;
    const size_t prev = rest.rfind('-', last - 1);
    if (prev == std::string::npos || prev == 0) return false;
    host = rest.substr(0, prev);
    const std::string p = rest.substr(prev + 1, last - prev - 1);
    if (p.empty() || p.size() > 10 || p.find_first_not_of("0123456789") != std::string::npos) return false;
    pid = std::stol(p);
    return true;
}

} // namespace

bool isOwnFile(const std::string& path, bool folderToo, std::string& why) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
        why = std::string("cannot stat it: ") + std::strerror(errno);
        return false;
    }
    if (!S_ISREG(st.st_mode) && !(folderToo && S_ISDIR(st.st_mode))) {
        why = S_ISLNK(st.st_mode) ? "a symlink" : S_ISDIR(st.st_mode) ? "a folder" : "not a regular file";
        why += ", which this tool never writes there";
        return false;
    }
    if (st.st_uid != ::geteuid()) {
        why = "owned by uid " + std::to_string(st.st_uid) + ", not by this user (uid " +
              std::to_string(::geteuid()) + ")";
        return false;
    }
    return true;
}

void warnLeftAlone(const std::string& path, const std::string& why) {
    std::cerr << "warning: left " << path << " alone: " << why << "\n";
}

std::string tempPathBeside(const std::string& target) {
    static std::atomic<unsigned> counter{0};
    static const std::string host = hostName();
    fs::path t(target);
    std::string name = t.filename().string();
    if (name.empty()) name = "output";
    return (t.parent_path() / ("." + name + kMarker + host + "-" + std::to_string(getpid()) + "-" +
                               std::to_string(counter++) + t.extension().string()))
        .string();
}

bool isTempName(const std::string& name) {
    std::string host;
    long pid = 0;
    return parseTempName(name, host, pid);
}

void registerChildGroup(int pgid) {
    std::lock_guard lock(childGroupsMutex());
    childGroups().push_back(pgid);
}

void unregisterChildGroup(int pgid) {
    std::lock_guard lock(childGroupsMutex());
    std::erase(childGroups(), pgid);
}

void installTempCleanupOnSignals() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (pipe2(signalPipe, O_CLOEXEC) != 0) return;
        std::thread(cleanupThread).detach();
        struct sigaction sa {};
        sa.sa_handler = onSignal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        for (int s : kSignals) sigaction(s, &sa, nullptr);
    });
}

size_t sweepStaleTemps(const std::string& dir) {
    static const std::string host = hostName();
    std::error_code ec;
    const std::time_t now = std::time(nullptr);
    std::vector<fs::path> stale;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        std::string h;
        long pid = 0;
        if (!parseTempName(name, h, pid)) continue;
        bool gone;
        if (h == host) {
            gone = pid != getpid() && kill(pid_t(pid), 0) != 0 && errno == ESRCH;
        } else {
            struct stat st {};
            gone = lstat(it->path().c_str(), &st) == 0 && now - st.st_mtime > 24 * 3600;
        }
        if (!gone) continue;
        // Never act on what another user (or a symlink) put there under one of our names.
        if (std::string why; !isOwnFile(it->path().string(), !isPublishJournalName(name), why)) {
            warnLeftAlone(it->path().string(), why);
            continue;
        }
        stale.push_back(it->path());
    }
    // A dead process's publish journal first: it renames (or removes) temporaries the plain sweep would remove.
    size_t removed = 0;
    for (const fs::path& p : stale)
        if (isPublishJournalName(p.filename().string())) {
            recoverPublishJournal(p.string());
            ++removed;
        }
    for (const fs::path& p : stale) {
        std::error_code rec;
        if (!isPublishJournalName(p.filename().string()) && fs::remove_all(p, rec) > 0 && !rec) ++removed;
    }
    return removed;
}

std::string fullDiskNote(const std::string& path) {
    std::error_code ec;
    fs::path dir = fs::absolute(path, ec);
    while (!dir.empty() && !fs::is_directory(dir, ec) && dir != dir.parent_path()) dir = dir.parent_path();
    struct statvfs st {};
    if (dir.empty() || ::statvfs(dir.c_str(), &st) != 0) return {};
    const unsigned long long free = (unsigned long long)st.f_bavail * st.f_frsize;
    if (free >= (1ull << 20)) return {};
    return " (no space left on device? " + std::to_string(free) + " bytes free on the file system of " +
           dir.string() + ")";
}

TempPath::TempPath(const std::string& target) : path_(tempPathBeside(target)) {
    std::lock_guard lock(registryMutex());
    registry().insert(path_);
}

TempPath::~TempPath() {
    std::lock_guard lock(registryMutex());
    if (!released_) {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    registry().erase(path_);
}

void TempPath::release() {
    std::lock_guard lock(registryMutex());
    released_ = true;
    registry().erase(path_);
}

SignalHold::SignalHold() { holdMutex().lock_shared(); }

SignalHold::~SignalHold() { holdMutex().unlock_shared(); }

} // namespace stipple::render
