// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple-validate --serve-study FOLDER: the experiment served on 127.0.0.1 only (cpp-httplib), each finished
// observer's votes checked (size, schema, study and crop ids: votes.h) and written to votes/<observer>.json
// atomically (a temporary file linked into place: a second submission of the same observer fails and never
// overwrites the first). Only index.html and crops/<id>.png are served. Nothing is held in memory between
// requests: a killed server loses at most the observer still voting (whose page offers the votes file).
#pragma once

#include <string>

namespace stipple::validation {

// Port 0: any free port. Prints "serving <folder> at http://127.0.0.1:<port>/" on stdout once listening.
// Returns the exit status (0 after a stop; 3 when the folder is not an experiment or the port is taken).
int serveStudy(const std::string& folder, int port);

} // namespace stipple::validation
