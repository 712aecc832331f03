// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// check_registry.cpp — the check kinds, in the order the matrix format documents them: the one place a kind is
// listed. Each is defined in its own *_check.cpp.
#include "matrix/check_kind.h"

namespace stipple::validation {

extern const CheckKind kOrderingCheck;
extern const CheckKind kSlopeCheck;
extern const CheckKind kTimeRatioCheck;
extern const CheckKind kTimeCeilingCheck;
extern const CheckKind kEqualTimeCheck;
extern const CheckKind kEqualSppCheck;
extern const CheckKind kCompareCheck;

const std::vector<const CheckKind*>& checkKinds() {
    static const std::vector<const CheckKind*> kinds = {
        &kOrderingCheck, &kSlopeCheck, &kTimeRatioCheck, &kTimeCeilingCheck, &kEqualTimeCheck, &kEqualSppCheck,
        &kCompareCheck,
    };
    return kinds;
}

const CheckKind* findCheckKind(const std::string& name) {
    for (const CheckKind* k : checkKinds())
        if (name == k->name) return k;
    return nullptr;
}

} // namespace stipple::validation
