// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// An EXR and its PNG are published together or not at all, even when the process is killed between the two
// renames. The states a SIGKILL can leave are built exactly: a child process writes the new pair to temporaries
// and the journal with the real code, does some of the renames and ends without cleaning up (as SIGKILL would);
// the next sweep of the folder must leave the new pair (or, when something removed a temporary, no mismatched
// pair), and no temporary or journal.
#define BOOST_TEST_MODULE publish_journal
#include <boost/test/unit_test.hpp>

#include <stipple/render/publish_journal.h>
#include <stipple/render/temp_files.h>
#include <stipple/testing/scratch_folder.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace stipple::render;
namespace fs = std::filesystem;

namespace {

struct Folder {
    fs::path dir;
    explicit Folder(const std::string& name) {
        dir = stipple::testing::scratchRoot() / "publish" / name;
        fs::remove_all(dir);
        fs::create_directories(dir);
        write("img.exr", "old exr");
        write("img.png", "old png");
    }
    ~Folder() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    void write(const std::string& name, const std::string& text) const { std::ofstream(dir / name) << text; }
    std::string read(const std::string& name) const {
        std::ifstream in(dir / name);
        if (!in) return "(missing)";
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    std::string listing() const {
        std::set<std::string> names;
        for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
        std::string s;
        for (const auto& n : names) s += n + " ";
        return s;
    }
    std::string exr() const { return (dir / "img.exr").string(); }
    std::string png() const { return (dir / "img.png").string(); }
    // The new pair written to temporaries beside the old one, as the renderer stages it; the renames to publish it.
    std::vector<PendingRename> stageNewPair() const {
        const std::vector<PendingRename> renames{{tempPathBeside(exr()), exr()}, {tempPathBeside(png()), png()}};
        std::ofstream(renames[0].temp) << "new exr";
        std::ofstream(renames[1].temp) << "new png";
        return renames;
    }
};

// Runs `interrupted` in a child that writes the new pair to temporaries and then ends with _exit: no
// destructor, no cleanup, as after SIGKILL. Its pid is gone when this returns.
void inDeadChild(const Folder& f, const std::function<void(const std::vector<PendingRename>&)>& interrupted) {
    const pid_t pid = fork();
    BOOST_REQUIRE(pid >= 0);
    if (pid == 0) {
        interrupted(f.stageNewPair());
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    BOOST_REQUIRE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

} // namespace

BOOST_AUTO_TEST_CASE(killed_between_the_renames_is_rolled_forward) {
    Folder f("between");
    inDeadChild(f, [](const std::vector<PendingRename>& r) {
        writePublishJournal(r);
        fs::rename(r[0].temp, r[0].target); // the EXR is new, the PNG still old
    });
    BOOST_TEST(f.read("img.exr") == "new exr");
    BOOST_TEST(f.read("img.png") == "old png");
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("img.exr") == "new exr");
    BOOST_TEST(f.read("img.png") == "new png");
    BOOST_TEST(f.listing() == "img.exr img.png ", f.listing());
}

BOOST_AUTO_TEST_CASE(killed_before_the_renames_is_rolled_forward) {
    Folder f("before");
    inDeadChild(f, [](const std::vector<PendingRename>& r) { writePublishJournal(r); });
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("img.exr") == "new exr");
    BOOST_TEST(f.read("img.png") == "new png");
    BOOST_TEST(f.listing().find("stipple-tmp") == std::string::npos, f.listing());
}

BOOST_AUTO_TEST_CASE(killed_after_the_renames_leaves_the_new_pair) {
    Folder f("after");
    inDeadChild(f, [](const std::vector<PendingRename>& r) {
        writePublishJournal(r);
        for (const auto& x : r) fs::rename(x.temp, x.target);
    });
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("img.exr") == "new exr");
    BOOST_TEST(f.read("img.png") == "new png");
    BOOST_TEST(f.listing().find("stipple-tmp") == std::string::npos, f.listing());
}

BOOST_AUTO_TEST_CASE(killed_before_the_journal_keeps_the_old_pair) {
    Folder f("nojournal");
    inDeadChild(f, [](const std::vector<PendingRename>&) {});
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("img.exr") == "old exr");
    BOOST_TEST(f.read("img.png") == "old png");
    BOOST_TEST(f.listing().find("stipple-tmp") == std::string::npos, f.listing());
}

BOOST_AUTO_TEST_CASE(a_lost_temporary_leaves_no_mismatched_pair) {
    // The PNG's temporary disappeared (not by a rename: the EXR's is still there), so the renames cannot be
    // finished: rolled back, and the old EXR goes too rather than stay beside a PNG that may be new.
    Folder g("lost");
    inDeadChild(g, [](const std::vector<PendingRename>& r) {
        writePublishJournal(r);
        fs::remove(r[1].temp);
    });
    sweepStaleTemps(g.dir.string());
    BOOST_TEST(g.read("img.exr") == "(missing)");
    BOOST_TEST(g.read("img.png") == "old png");
    BOOST_TEST(g.listing().find("stipple-tmp") == std::string::npos, g.listing());
}

BOOST_AUTO_TEST_CASE(a_live_process_journal_is_left_alone) {
    Folder f("live");
    const std::vector<PendingRename> r = f.stageNewPair();
    const std::string journal = writePublishJournal(r);
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(fs::exists(journal));
    BOOST_TEST(f.read("img.png") == "old png");
    fs::remove(journal);
}

BOOST_AUTO_TEST_CASE(a_journal_naming_other_folders_is_not_followed) {
    Folder f("evil");
    f.write("secret", "keep");
    inDeadChild(f, [&](const std::vector<PendingRename>&) {
        // A journal that would rename a file from outside the folder over one of its own.
        const std::string journal = tempPathBeside(f.exr() + ".publish");
        const std::string temp = "../" + f.dir.filename().string() + "/secret", target = "img.exr";
        std::ofstream(journal) << "stipple-publish 1\n"
                               << temp.size() << " " << target.size() << "\n"
                               << temp << target << "\nend\n";
    });
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("secret") == "keep");
    BOOST_TEST(f.read("img.exr") == "old exr");
    BOOST_TEST(f.listing().find("stipple-tmp") == std::string::npos, f.listing());
}

BOOST_AUTO_TEST_CASE(rename_together_publishes_both_and_leaves_no_journal) {
    Folder f("normal");
    const std::vector<PendingRename> r = f.stageNewPair();
    renameTogether(r);
    BOOST_TEST(f.read("img.exr") == "new exr");
    BOOST_TEST(f.read("img.png") == "new png");
    BOOST_TEST(f.listing().find("stipple-tmp") == std::string::npos, f.listing());
}

// ---- journals and temporaries that are not this user's own are never obeyed -------------------------------------

namespace {

constexpr uid_t kNobody = 65534;

// Another user's files can only be made by root; elsewhere the ownership cases are skipped, saying so.
bool canActAsAnotherUser() {
    if (geteuid() == 0) return true;
    BOOST_TEST_MESSAGE("skipped: needs root to create files owned by another user (uid " << kNobody << ")");
    return false;
}

void chownToNobody(const std::string& path) { BOOST_REQUIRE(lchown(path.c_str(), kNobody, kNobody) == 0); }

// A journal as a dead process of another user would leave it: it would replace `target` with `text`.
std::string plantJournal(const Folder& f, const std::string& target, const std::string& text, std::string& temp) {
    std::string journal;
    const pid_t pid = fork();
    BOOST_REQUIRE(pid >= 0);
    if (pid == 0) {
        const std::string t = tempPathBeside((f.dir / target).string());
        std::ofstream(t) << text;
        const std::string j = writePublishJournal({{t, (f.dir / target).string()}});
        std::ofstream(f.dir / "planted") << t << "\n" << j << "\n";
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    std::ifstream in(f.dir / "planted");
    std::getline(in, temp);
    std::getline(in, journal);
    fs::remove(f.dir / "planted");
    return journal;
}

} // namespace

BOOST_AUTO_TEST_CASE(another_users_journal_is_left_alone) {
    if (!canActAsAnotherUser()) return;
    Folder f("foreign-journal");
    f.write("notes.txt", "mine");
    std::string temp;
    const std::string journal = plantJournal(f, "notes.txt", "theirs", temp);
    chownToNobody(temp);
    chownToNobody(journal);
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("notes.txt") == "mine");
    BOOST_TEST(fs::exists(journal));
    BOOST_TEST(fs::exists(temp));
}

BOOST_AUTO_TEST_CASE(an_own_journal_naming_another_users_target_leaves_it) {
    if (!canActAsAnotherUser()) return;
    Folder f("foreign-target");
    f.write("data.csv", "theirs");
    chownToNobody((f.dir / "data.csv").string());
    std::string temp;
    plantJournal(f, "data.csv", "replaced", temp);
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(f.read("data.csv") == "theirs");
    BOOST_TEST(f.listing().find("stipple-tmp") == std::string::npos, f.listing()); // our own stale files went
}

BOOST_AUTO_TEST_CASE(another_users_stale_temporary_is_left_alone) {
    if (!canActAsAnotherUser()) return;
    Folder f("foreign-temp");
    std::string temp;
    const std::string journal = plantJournal(f, "img.exr", "x", temp);
    fs::remove(journal);
    chownToNobody(temp);
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(fs::exists(temp));
}

BOOST_AUTO_TEST_CASE(a_symlink_with_a_temporary_name_is_left_alone) {
    Folder f("symlink-temp");
    f.write("precious", "keep");
    std::string temp;
    const std::string journal = plantJournal(f, "img.exr", "x", temp);
    fs::remove(journal);
    fs::remove(temp);
    fs::create_symlink(f.dir / "precious", temp); // a dead process's temporary name, pointing at a file
    sweepStaleTemps(f.dir.string());
    BOOST_TEST(fs::is_symlink(temp));
    BOOST_TEST(f.read("precious") == "keep");
}

// SIGTERM while threads keep creating, writing and removing temporaries (as the renderer's writers do, each file
// under a SignalHold): the process must end by the signal and leave no temporary. Twenty rounds, the signal at a
// different moment of the writes each time.
BOOST_AUTO_TEST_CASE(sigterm_while_threads_write_temporaries_leaves_none) {
    Folder f("sigterm-writers");
    for (int round = 0; round < 20; ++round) {
        const pid_t pid = fork();
        BOOST_REQUIRE(pid >= 0);
        if (pid == 0) {
            installTempCleanupOnSignals();
            for (int w = 0; w < 3; ++w)
                std::thread([&f, w] {
                    for (;;) {
                        TempPath temp((f.dir / ("out-" + std::to_string(w) + ".txt")).string());
                        SignalHold hold;
                        std::ofstream(temp.path()) << std::string(4096, 'x');
                    }
                }).detach();
            std::this_thread::sleep_for(std::chrono::microseconds(2000 + 450 * round));
            kill(getpid(), SIGTERM);
            for (;;) pause();
        }
        int status = 0;
        waitpid(pid, &status, 0);
        BOOST_TEST_REQUIRE((WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM),
                           "round " << round << ": the child did not end by SIGTERM (status " << status << ")");
        for (const auto& e : fs::directory_iterator(f.dir))
            BOOST_TEST(!isTempName(e.path().filename().string()),
                       "round " << round << ": left " << e.path().filename().string());
    }
}
