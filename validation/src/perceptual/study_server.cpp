// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/study_server.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <httplib.h>

#include "report/report_publish.h"
#include "perceptual/study_key.h"
#include "perceptual/votes.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Writes `text` to votes/<observer>.json unless that file exists: written and synced under a temporary name,
// then link(2)ed to the final name, which fails (EEXIST) rather than replace anything.
// Returns "" or the reason it was not stored.
std::string storeVotes(const fs::path& votesDir, const std::string& observer, const std::string& text) {
    static std::atomic<unsigned> counter{0};
    const fs::path final = votesDir / (observer + ".json");
    const fs::path tmp =
        votesDir / (".incoming-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".partial");
    const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) return "cannot create a file in " + votesDir.string() + ": " + std::strerror(errno);
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string why = std::strerror(errno);
            close(fd);
            unlink(tmp.c_str());
            return "cannot write the votes: " + why;
        }
        done += size_t(n);
    }
    const bool synced = fsync(fd) == 0;
    close(fd);
    if (!synced) {
        unlink(tmp.c_str());
        return "cannot sync the votes to disk";
    }
    const int linked = link(tmp.c_str(), final.c_str());
    const int linkErrno = errno;
    unlink(tmp.c_str());
    if (linked != 0)
        return linkErrno == EEXIST ? "observer '" + observer + "' has already voted; this submission was not stored"
                                   : std::string("cannot store the votes: ") + std::strerror(linkErrno);
    if (const int dfd = open(votesDir.c_str(), O_RDONLY | O_DIRECTORY); dfd >= 0) {
        fsync(dfd);
        close(dfd);
    }
    return "";
}

} // namespace

int serveStudy(const std::string& folder, int port) {
    StudyKey key;
    try {
        key = loadStudyKey(folder);
    } catch (const StudyError& e) {
        std::cerr << "stipple-validate: --serve-study: " << e.what() << "\n";
        return 3;
    }
    // A report folder is replaced whole by the next run: votes collected inside it would go with it.
    const fs::path parent = fs::absolute(folder).lexically_normal().parent_path();
    if (fs::exists(parent / kReportMarker) || fs::exists(fs::path(folder).parent_path() / kReportMarker)) {
        std::cerr << "stipple-validate: --serve-study: " << folder
                  << " is inside a report folder, which the next run replaces whole (votes included): copy it out "
                     "first (cp -r "
                  << folder << " my-study)\n";
        return 3;
    }
    const fs::path votesDir = fs::path(folder) / kStudyVotesDir;
    std::error_code ec;
    fs::create_directories(votesDir, ec);
    if (ec) {
        std::cerr << "stipple-validate: --serve-study: cannot create " << votesDir.string() << ": " << ec.message() << "\n";
        return 3;
    }
    httplib::Server server;
    server.set_payload_max_length(kMaxVotesBytes);
    server.set_read_timeout(10, 0);
    const fs::path root(folder);
    server.Get("/", [&](const httplib::Request&, httplib::Response& res) {
        res.set_content(readFile(root / "index.html"), "text/html; charset=utf-8");
    });
    server.Get("/index.html", [&](const httplib::Request&, httplib::Response& res) {
        res.set_content(readFile(root / "index.html"), "text/html; charset=utf-8");
    });
    // Crop ids only (hex): no other file, and no path, can be asked for.
    server.Get(R"(/crops/([0-9a-f]{12})\.png)", [&](const httplib::Request& req, httplib::Response& res) {
        const fs::path png = root / "crops" / (std::string(req.matches[1]) + ".png");
        if (!fs::is_regular_file(png)) {
            res.status = 404;
            res.set_content("no such crop\n", "text/plain");
            return;
        }
        res.set_content(readFile(png), "image/png");
    });
    server.Post("/votes", [&](const httplib::Request& req, httplib::Response& res) {
        ObserverVotes votes;
        try {
            votes = parseVotes(req.body, key, "votes");
        } catch (const StudyError& e) {
            res.status = 400;
            res.set_content(std::string(e.what()) + "\n", "text/plain");
            std::cerr << "stipple-validate: refused votes from " << req.remote_addr << ": " << e.what() << "\n";
            return;
        }
        const std::string why = storeVotes(votesDir, votes.observer, req.body);
        if (!why.empty()) {
            res.status = why.find("already voted") != std::string::npos ? 409 : 500;
            res.set_content(why + "\n", "text/plain");
            std::cerr << "stipple-validate: " << why << "\n";
            return;
        }
        res.set_content("stored\n", "text/plain");
        std::cout << "votes of " << votes.observer << " stored in " << (votesDir / (votes.observer + ".json")).string()
                  << std::endl;
    });
    server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (res.body.empty())
            res.set_content(res.status == 413 ? "request body too large\n" : "not found\n", "text/plain");
    });
    const int bound = port == 0 ? server.bind_to_any_port("127.0.0.1") : (server.bind_to_port("127.0.0.1", port) ? port : -1);
    if (bound < 0) {
        std::cerr << "stipple-validate: --serve-study: cannot listen on 127.0.0.1:" << port << "\n";
        return 3;
    }
    std::cout << "serving " << folder << " at http://127.0.0.1:" << bound << "/ (votes in " << votesDir.string()
              << "; Ctrl-C stops)" << std::endl;
    return server.listen_after_bind() ? 0 : 3;
}

} // namespace stipple::validation
