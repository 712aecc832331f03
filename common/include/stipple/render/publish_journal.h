// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Publishing several temporaries together, recoverably: before the first rename a journal naming every
// temporary and its target is written (to a temporary, then renamed into place, so it exists whole or not at
// all); the renames follow in order; the journal is removed last. A process killed in between (SIGKILL, which no
// handler sees) leaves the journal, and the next sweep of the folder (sweepStaleTemps) finishes the job:
// forward when the temporaries still there are the tail of the list (the renames done so far are a prefix), else
// back (the remaining temporaries and their targets' old files removed). Either way no reader afterwards sees
// a new file beside an old partner.
//
// The journal is a temporary like the others, `.<first target>.publish.stipple-tmp-<host>-<pid>-<n>.publish`:
//   stipple-publish 1
//   <length of temporary> <length of target>      (one such pair of lines per rename, in order)
//   <temporary><target>
//   end
// Both names are plain file names in the journal's folder; a journal naming anything else is ignored and removed.
// Recovery obeys only a journal owned by the effective user, and only when every temporary and target it names
// is that user's regular file (or absent); anything else is left alone and named in a warning.
#pragma once

#include <string>
#include <vector>

namespace stipple::render {

// One temporary and the target it becomes, both in the same folder.
struct PendingRename {
    std::string temp;
    std::string target;
};

// Renames every temporary onto its target, as above, with SIGINT / SIGTERM held off meanwhile. On a failed
// rename the ones done stay, the targets not yet replaced are removed (no stale partner), the other temporaries
// and the journal too, and std::runtime_error names the failure.
void renameTogether(const std::vector<PendingRename>& renames);

// Writes the journal for `renames` (whole, by rename) and returns its path. renameTogether's first step; public
// so tests can build the state a SIGKILL leaves.
std::string writePublishJournal(const std::vector<PendingRename>& renames);

// True when `name` (no folder) is a journal's name.
bool isPublishJournalName(const std::string& name);

// Finishes or undoes the publication the journal at `path` describes (its process is gone), then removes the
// journal. Returns false when the journal was unreadable or named files outside its folder (removed unused).
bool recoverPublishJournal(const std::string& path);

} // namespace stipple::render
