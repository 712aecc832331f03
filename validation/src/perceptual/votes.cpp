// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/votes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace stipple::validation {

namespace fs = std::filesystem;
using nlohmann::json;

bool validObserverId(const std::string& id) {
    if (id.empty() || id.size() > 64) return false;
    return std::all_of(id.begin(), id.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    });
}

namespace {

std::vector<std::string> idList(const json& j, const std::string& where) {
    if (!j.is_array()) throw StudyError(where + ": expected a list of crop ids");
    std::vector<std::string> out;
    for (const auto& v : j) {
        if (!v.is_string()) throw StudyError(where + ": expected crop ids (text)");
        out.push_back(v.get<std::string>());
    }
    return out;
}

std::string quoted(const std::string& s) { return "'" + (s.size() > 40 ? s.substr(0, 40) + "…" : s) + "'"; }

} // namespace

ObserverVotes parseVotes(const std::string& text, const StudyKey& key, const std::string& name) {
    if (text.size() > kMaxVotesBytes)
        throw StudyError(name + ": " + std::to_string(text.size()) + " bytes, more than a votes file's limit of " +
                         std::to_string(kMaxVotesBytes));
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {
        throw StudyError(name + ": not JSON: " + e.what());
    }
    auto field = [&](const json& o, const char* k, const std::string& where) -> const json& {
        if (!o.is_object() || !o.contains(k)) throw StudyError(name + ": " + where + ": missing '" + k + "'");
        return o.at(k);
    };
    if (!j.is_object()) throw StudyError(name + ": expected a JSON object");
    if (field(j, "format", "top") != "stipple-perceptual-votes" || field(j, "version", "top") != 1)
        throw StudyError(name + ": not a stipple votes file (format 'stipple-perceptual-votes', version 1)");
    const json& study = field(j, "study", "top");
    if (!study.is_string() || study.get<std::string>() != key.study)
        throw StudyError(name + ": study: votes for another experiment (" + (study.is_string() ? quoted(study.get<std::string>()) : std::string("?")) +
                         "; this one is '" + key.study + "')");
    ObserverVotes v;
    v.source = name;
    const json& observer = field(j, "observer", "top");
    if (!observer.is_string() || !validObserverId(observer.get<std::string>()))
        throw StudyError(name + ": observer: expected 1-64 letters, digits, - or _");
    v.observer = observer.get<std::string>();
    const json& trials = field(j, "trials", "top");
    if (!trials.is_array() || int(trials.size()) != key.trialCount())
        throw StudyError(name + ": trials: expected " + std::to_string(key.trialCount()) + " trials, got " +
                         (trials.is_array() ? std::to_string(trials.size()) : std::string("no list")));
    int counts[3] = {0, 0, 0};
    for (size_t i = 0; i < trials.size(); ++i) {
        const std::string where = "trials[" + std::to_string(i) + "]";
        const json& t = trials[i];
        TrialVote tv;
        const json& kind = field(t, "kind", where);
        if (kind == "test") tv.kind = TrialKind::Test;
        else if (kind == "repeat") tv.kind = TrialKind::Repeat;
        else if (kind == "control") tv.kind = TrialKind::Control;
        else throw StudyError(name + ": " + where + ".kind: expected test, repeat or control");
        ++counts[int(tv.kind)];
        const json& set = field(t, "set", where);
        if (!set.is_number_integer() || set.get<long long>() < 0 || set.get<long long>() >= (long long)key.sets.size())
            throw StudyError(name + ": " + where + ".set: expected a set index in [0, " +
                             std::to_string(key.sets.size() - 1) + "]");
        tv.set = set.get<int>();
        const StudySet& s = key.sets[size_t(tv.set)];
        std::set<std::string> expected;
        for (const auto& c : s.crops) expected.insert(c.id);
        if (tv.kind == TrialKind::Control) expected.insert(s.control.id);
        tv.shown = idList(field(t, "shown", where), name + ": " + where + ".shown");
        if (std::set<std::string>(tv.shown.begin(), tv.shown.end()) != expected || tv.shown.size() != expected.size())
            throw StudyError(name + ": " + where + ".shown: not the crops of set " + std::to_string(tv.set) +
                             (tv.kind == TrialKind::Control ? " and its control" : ""));
        tv.ranking = idList(field(t, "ranking", where), name + ": " + where + ".ranking");
        const json& nd = field(t, "no_difference", where);
        if (!nd.is_boolean()) throw StudyError(name + ": " + where + ".no_difference: expected true or false");
        if (nd.get<bool>() != tv.ranking.empty())
            throw StudyError(name + ": " + where + ".ranking: empty exactly when no_difference is true");
        if (!tv.ranking.empty() && (std::set<std::string>(tv.ranking.begin(), tv.ranking.end()) != expected ||
                                    tv.ranking.size() != expected.size()))
            throw StudyError(name + ": " + where + ".ranking: not an order of the crops shown");
        const json& ms = field(t, "ms", where);
        if (!ms.is_number() || !(ms.get<double>() >= 0) || !std::isfinite(ms.get<double>()))
            throw StudyError(name + ": " + where + ".ms: expected a time in milliseconds ≥ 0");
        tv.milliseconds = ms.get<double>();
        v.trials.push_back(std::move(tv));
    }
    if (counts[0] != int(key.sets.size()) * key.trials || counts[1] != key.repeats || counts[2] != key.controls)
        throw StudyError(name + ": trials: expected " + std::to_string(key.sets.size() * size_t(key.trials)) +
                         " test, " + std::to_string(key.repeats) + " repeat and " + std::to_string(key.controls) +
                         " control trials");
    return v;
}

std::vector<ObserverVotes> loadVotes(const std::vector<std::string>& paths, const StudyKey& key) {
    std::vector<std::string> files;
    for (const auto& p : paths) {
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            std::vector<std::string> here;
            for (const auto& e : fs::directory_iterator(p))
                if (e.is_regular_file() && e.path().extension() == ".json") here.push_back(e.path().string());
            std::sort(here.begin(), here.end());
            files.insert(files.end(), here.begin(), here.end());
        } else if (fs::is_regular_file(p, ec))
            files.push_back(p);
        else
            throw StudyError(p + ": no such votes file or folder");
    }
    std::vector<ObserverVotes> out;
    std::map<std::string, std::string> seen;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        if (!in) throw StudyError(f + ": cannot read");
        std::string text(kMaxVotesBytes + 1, '\0');
        in.read(text.data(), std::streamsize(text.size()));
        text.resize(size_t(in.gcount()));
        ObserverVotes v = parseVotes(text, key, f);
        if (auto [it, fresh] = seen.emplace(v.observer, f); !fresh)
            throw StudyError(f + ": observer '" + v.observer + "' already voted in " + it->second +
                             " (merge each observer's votes once)");
        out.push_back(std::move(v));
    }
    return out;
}

} // namespace stipple::validation
