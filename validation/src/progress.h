// Progress of a run on stderr: a redrawn bar (cells done / total, ETA) on a terminal, plain lines otherwise
// (CI logs, pipes).
#pragma once

#include <chrono>
#include <string>

namespace stipple::validation {

class Progress {
public:
    explicit Progress(size_t total);
    // One cell × seed finished; `what` describes it (and its figures, shown on plain lines).
    void step(const std::string& what);
    // A message that is not a cell (reference renders, scene loads): its own line in both modes.
    void note(const std::string& message);
    void finish();
    // --quiet: from now on steps and notes are not shown, except notes that start with "ERROR".
    static void setQuiet(bool quiet);
    // Time between pause() and resume() (reference renders, scene loads) is left out of the ETA.
    void pause();
    void resume();

private:
    std::string eta() const;
    size_t total_, done_ = 0;
    bool tty_;
    bool barShown_ = false;
    std::chrono::steady_clock::time_point start_, pausedAt_;
    std::chrono::steady_clock::duration paused_{};
    bool isPaused_ = false;
};

} // namespace stipple::validation
