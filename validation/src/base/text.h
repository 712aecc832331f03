// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The small text helpers every writer of validation's output shares: printf-style formatting into a string and
// HTML escaping.
#pragma once

#include <cstdio>
#include <string>

namespace stipple::validation {

// printf into a std::string of whatever length the result needs.
template <class... Args>
std::string fmt(const char* format, Args... args) {
    const int n = std::snprintf(nullptr, 0, format, args...);
    if (n <= 0) return {};
    std::string s(size_t(n) + 1, '\0');
    std::snprintf(s.data(), s.size(), format, args...);
    s.resize(size_t(n));
    return s;
}

// Text made safe inside HTML elements and attribute values.
inline std::string html(const std::string& s) {
    std::string o;
    for (char c : s) {
        switch (c) {
        case '<': o += "&lt;"; break;
        case '>': o += "&gt;"; break;
        case '&': o += "&amp;"; break;
        case '"': o += "&quot;"; break;
        default: o += c;
        }
    }
    return o;
}

} // namespace stipple::validation
