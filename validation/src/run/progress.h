// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Progress of a run on stderr: a redrawn bar (work done / total, ETA) on a terminal, plain lines otherwise
// (CI logs, pipes). Work is counted in samples per pixel: a cell at 16 spp is 16, a reference at 2048 spp is 2048,
// so the references a run renders are in its ETA; while one renders (minutes, with no cell finishing) a line
// every kHeartbeatSeconds says how long it has taken so far.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace stipple::validation {

class Progress {
public:
    static constexpr int kHeartbeatSeconds = 20;

    // cells: the cells × seeds to render; totalWork: their spp summed, plus the references' spp.
    Progress(size_t cells, double totalWork);
    ~Progress();
    // One cell × seed of `work` spp finished; `what` describes it (and its figures, shown on plain lines).
    void step(const std::string& what, double work);
    // A message that is not a cell (scene loads, references): its own line in both modes.
    void note(const std::string& message);
    // A long piece of work that is not a cell (a reference render): heartbeat lines until endTask. endTask(false)
    // when it was not done after all (the reference came from the cache): its work leaves the total.
    void beginTask(const std::string& what, double work);
    void endTask(bool rendered);
    void finish();
    // --quiet: from now on steps and notes are not shown, except notes that start with "ERROR".
    static void setQuiet(bool quiet);
    // Time between pause() and resume() (scene loads) is left out of the ETA.
    void pause();
    void resume();

private:
    std::string eta(double extraDone = 0) const;
    double elapsed() const;
    void heartbeat();
    size_t cells_, cellsDone_ = 0;
    double total_, done_ = 0;
    bool tty_;
    bool barShown_ = false;
    std::chrono::steady_clock::time_point start_, pausedAt_;
    std::chrono::steady_clock::duration paused_{};
    bool isPaused_ = false;
    // The task the heartbeat reports on.
    std::mutex mutex_;
    std::condition_variable wake_;
    std::thread heartbeat_;
    std::string task_;
    double taskWork_ = 0;
    std::chrono::steady_clock::time_point taskStart_;
    bool taskRunning_ = false;
};

} // namespace stipple::validation
