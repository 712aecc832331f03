// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What a check kind is to the matrix reader, the fingerprint, the evaluation and the report: one CheckKind.
//
// A kind is defined once, in its own source file (claims/*_check.cpp), as a CheckKind: its name, its keys (each with
// how it is read, its default and how the resolved value is spelled), the rules between its keys, its evaluation and
// how the report's sentences state it. claims/check_registry.cpp lists the kinds. The reader and the shard
// fingerprint both walk a kind's key list, so a key read is a key fingerprinted; nothing else names a kind.
#pragma once

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/fields.h"
#include "matrix/matrix_reader.h"

namespace stipple::validation {

// What a kind's evaluation and sentence take and give: the claims' types (claims/checks.h), which a kind's file
// includes. The matrix reader needs only their names.
struct CheckInputs;
struct CheckOutcome;
struct VerdictRow;
enum class CheckStatus;

// Reading one check: the YAML reader and the matrix read so far (its scenes, patterns and spp, which a check's
// values must name).
class CheckReader {
public:
    CheckReader(const MatrixReader& yaml, const Matrix& matrix);

    const MatrixReader& yaml;
    const Matrix& matrix;

    [[noreturn]] void fail(const yaml::Node& node, const std::string& what) const { yaml.fail(node, what); }
    // A scene of the matrix, or "all" when allowAll.
    std::string scene(const yaml::Node& node, bool allowAll) const;
    // One of the matrix's patterns.
    std::string pattern(const yaml::Node& node) const;
    // One of the matrix's spp.
    uint32_t spp(const yaml::Node& node, const std::string& what) const;

private:
    std::set<std::string> sceneNames_; // a linear findScene per check made a matrix of many checks take minutes
};

// One key of a kind. `read` reads the key's value when the check has it; `absent` sets the default when it does
// not (nothing: the parameter's initial value stands); `value` gives the resolved value as the matrix spells it,
// for the fingerprint.
struct CheckKey {
    std::string name;
    bool required = false;
    // false: a label that states no claim (the study's wording); left out of the fingerprint.
    bool fingerprinted = true;
    std::function<void(const CheckReader&, const yaml::Node& value, Check&)> read;
    std::function<void(const CheckReader&, Check&)> absent;
    std::function<Json(const Check&)> value;
};

// The words the report lends a kind for its sentence in the study's answers (study_answers.h renders them).
struct SentenceWords {
    std::function<std::string(const std::string&)> text;          // HTML-escaped text
    std::function<std::string(const std::string&)> pattern;       // a pattern with its colour swatch
    std::function<std::string(const std::string&)> patternLabel;  // the same, named as a reader knows it
    std::function<std::string(CheckStatus)> status;               // "holds", "refuted" or "undecided", marked up
    // "as good as B in 4 of 4 scenes (0.93–1.04×)"; tagged: then whether the statement holds.
    std::function<std::string(const std::vector<const VerdictRow*>&, const std::string& b, bool tagged)> verdicts;
};

struct CheckKind {
    const char* name; // the `type:` of the check
    // In reading order: a key may look at the keys read before it (a region at its scene). `type` is implied.
    std::vector<CheckKey> keys;
    std::function<std::shared_ptr<CheckParams>()> makeParams; // the kind's parameters at their defaults
    // The rules between keys, after all are read (`check` is the check's map, for positions); nullptr: none.
    void (*validate)(const CheckReader&, const yaml::Node& check, Check&) = nullptr;
    // Sets outcome.claim, figures, status (and verdicts for a pairwise comparison).
    void (*evaluate)(const Check&, const CheckInputs&, CheckOutcome& outcome);
    // The claim in the study's answers, as one or more clauses; nullptr: its one-line claim and whether it holds.
    std::string (*sentence)(const CheckOutcome&, const SentenceWords&) = nullptr;
};

// ---- the registry (claims/check_registry.cpp) ---------------------------------------------------------------------------

// The kinds in the order the matrix format documents them.
const std::vector<const CheckKind*>& checkKinds();
// The kind named `name`, or nullptr.
const CheckKind* findCheckKind(const std::string& name);

// Reads one check (a map with `type`) by its kind. Throws MatrixError naming file:line:column.
Check readCheck(const CheckReader& reader, const yaml::Node& node);
// Reads one check from its YAML text against a matrix read already (a claim stated apart from its matrix file,
// as the unit tests state them against synthetic rows); `path` names it in errors.
Check parseCheck(const std::string& text, const std::string& path, const Matrix& matrix,
                 const MatrixVocabulary& vocabulary);
// The check as the fields that define its claim: its type, then every fingerprinted key's resolved value in the
// kind's order (its place in the file is left out: moving a line changes no claim).
Json checkClaimJson(const Check& check);

// ---- building a kind's keys --------------------------------------------------------------------------------------

// The parameters of a check, as the kind's own struct P.
template <class P>
P& paramsOf(Check& c) {
    return static_cast<P&>(*c.params);
}
template <class P>
const P& paramsOf(const Check& c) {
    return static_cast<const P&>(*c.params);
}
template <class P>
std::shared_ptr<CheckParams> makeParams() {
    return std::make_shared<P>();
}

// Where a key's value lives: a member of the kind's parameters or one of Check's shared members.
template <class T>
using KeyRef = std::function<T&(Check&)>;
template <class P, class T>
KeyRef<T> param(T P::*member) {
    return [member](Check& c) -> T& { return paramsOf<P>(c).*member; };
}
template <class T>
KeyRef<T> shared(T Check::*member) {
    return [member](Check& c) -> T& { return c.*member; };
}

// How a key's value is read (the check so far gives the keys read before it), defaulted and spelled.
template <class T>
using KeyRead = std::function<T(const CheckReader&, const yaml::Node&, const Check&)>;
template <class T>
using KeyDefault = std::function<T(const CheckReader&, const Check&)>;
template <class T>
using KeySpell = std::function<Json(const T&)>;

template <class T>
Json spellValue(const T& v) {
    return Json(v);
}

template <class T>
CheckKey makeKey(std::string name, KeyRef<T> ref, std::type_identity_t<KeyRead<T>> read, bool required,
                 std::type_identity_t<KeyDefault<T>> fallback = {},
                 std::type_identity_t<KeySpell<T>> spell = spellValue<T>) {
    CheckKey k;
    k.name = std::move(name);
    k.required = required;
    k.read = [ref, read](const CheckReader& r, const yaml::Node& n, Check& c) { ref(c) = read(r, n, c); };
    if (fallback) k.absent = [ref, fallback](const CheckReader& r, Check& c) { ref(c) = fallback(r, c); };
    k.value = [ref, spell](const Check& c) { return spell(ref(const_cast<Check&>(c))); };
    return k;
}
template <class T>
CheckKey requiredKey(std::string name, KeyRef<T> ref, std::type_identity_t<KeyRead<T>> read,
                     std::type_identity_t<KeySpell<T>> spell = spellValue<T>) {
    return makeKey<T>(std::move(name), std::move(ref), std::move(read), true, {}, std::move(spell));
}
template <class T>
CheckKey optionalKey(std::string name, KeyRef<T> ref, std::type_identity_t<KeyRead<T>> read,
                     std::type_identity_t<KeyDefault<T>> fallback = {},
                     std::type_identity_t<KeySpell<T>> spell = spellValue<T>) {
    return makeKey<T>(std::move(name), std::move(ref), std::move(read), false, std::move(fallback), std::move(spell));
}

// A key whose value is one of a few words: read, defaulted (the parameter's initial value) and spelled from one
// table; the error lists the words.
template <class T>
CheckKey choiceKey(std::string name, KeyRef<T> ref, std::vector<std::pair<std::string, T>> words) {
    std::string list;
    for (size_t i = 0; i < words.size(); ++i)
        list += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i].first;
    const std::string key = name;
    return makeKey<T>(
        std::move(name), std::move(ref),
        [key, words, list](const CheckReader& r, const yaml::Node& n, const Check&) {
            const auto v = r.yaml.get<std::string>(n, key);
            for (const auto& [word, value] : words)
                if (word == v) return value;
            r.fail(n, key + " must be " + list + ", got '" + v + "'");
        },
        false, {},
        [words](const T& v) {
            for (const auto& [word, value] : words)
                if (value == v) return Json(word);
            return Json(nullptr);
        });
}

// ---- keys and values several kinds share (check_keys.cpp) --------------------------------------------------------

// scene: a scene of the matrix or all; not required: all.
CheckKey sceneKey(bool required);
// study: the study's statement the check tests (a label: not fingerprinted).
CheckKey studyKey();
// not_separated: fail | pass, whether an undecided verdict fails the run; `failsByDefault` when absent.
CheckKey notSeparatedKey(bool failsByDefault);
// fails_run: true | false, whether a FAIL fails the run.
CheckKey failsRunKey();
// spp: one of the matrix's; absent: the largest.
template <class P>
CheckKey sppKey(uint32_t P::*member) {
    return optionalKey<uint32_t>(
        "spp", param(member), [](const CheckReader& r, const yaml::Node& n, const Check&) { return r.spp(n, "spp"); },
        [](const CheckReader& r, const Check&) { return r.matrix.spp.back(); });
}
// metric: mse | flip (true: flip).
template <class P>
CheckKey metricKey(bool P::*member) {
    return choiceKey<bool>("metric", param(member), {{"mse", false}, {"flip", true}});
}

// Values: a list (key `key`) of at least two distinct patterns of the matrix (`what` ends the error: ", best
// first"); an equivalence margin [lo < 1 < hi]; a number; a number > 0.
std::vector<std::string> readPatternList(const CheckReader& r, const yaml::Node& node, const std::string& key,
                                         const std::string& what);
std::pair<double, double> readMargin(const CheckReader& r, const yaml::Node& node, const Check&);
double readNumber(const CheckReader& r, const yaml::Node& node, const std::string& what);
double readPositive(const CheckReader& r, const yaml::Node& node, const std::string& what);
// The scenes a check names: every scene of the matrix for "all".
std::vector<const MatrixScene*> scenesOf(const Check& check, const Matrix& matrix);

} // namespace stipple::validation
