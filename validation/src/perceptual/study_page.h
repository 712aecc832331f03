// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The experiment's one page (study_page.html, built in): runs from file:// or from --serve-study, with no network
// and no external resources; its plan (crop ids and sizes, no pattern names) replaces the marker "@PLAN@".
#pragma once

namespace stipple::validation {

extern const char* const kStudyPageTemplate;

} // namespace stipple::validation
