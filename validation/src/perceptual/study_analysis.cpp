// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/study_analysis.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <nlohmann/json.hpp>
#include <stipple/statistics/student_t.h>

#include "metrics/statistics.h"
#include "base/text.h"
#include "perceptual/thurstone.h"

namespace stipple::validation {

namespace {

// Position of each crop id in a ranking, or -1.
int positionOf(const std::vector<std::string>& ranking, const std::string& id) {
    auto it = std::find(ranking.begin(), ranking.end(), id);
    return it == ranking.end() ? -1 : int(it - ranking.begin());
}

// +1: a before b, −1: after, 0: no visible difference.
int order(const TrialVote& t, const std::string& a, const std::string& b) {
    if (t.ranking.empty()) return 0;
    return positionOf(t.ranking, a) < positionOf(t.ranking, b) ? 1 : -1;
}

// The interval est ± t(n−1) · se of a bootstrap over n observers: se the replicates' standard deviation times
// √(n / (n − 1)) (the bootstrap's plug-in variance is short by that factor), Student's t for the few observers.
// The plain percentile interval covered 88% at 12 observers in the coverage test; this one holds its rate there.
struct BootstrapInterval {
    double lo, hi;
};
BootstrapInterval bootstrapInterval(double estimate, const std::vector<double>& replicates, size_t observers,
                                    double confidence) {
    if (observers < 2 || replicates.size() < 2) return {-INFINITY, INFINITY};
    const double se = std::sqrt(sampleVariance(replicates) * double(observers) / double(observers - 1));
    const double t = statistics::studentTQuantile(0.5 + 0.5 * confidence, double(observers - 1));
    return {estimate - t * se, estimate + t * se};
}

// Kendall's tau between two score lists (higher better), ties counted as neither.
double kendall(const std::vector<double>& x, const std::vector<double>& y, int* concordant = nullptr,
               int* pairs = nullptr) {
    int c = 0, d = 0, n = 0;
    for (size_t i = 0; i < x.size(); ++i)
        for (size_t j = i + 1; j < x.size(); ++j) {
            if (x[i] == x[j]) continue; // people did not order this pair (e.g. no observer kept)
            const double s = (x[i] - x[j]) * (y[i] - y[j]);
            c += s > 0;
            d += s < 0;
            ++n;
        }
    if (concordant) *concordant += c;
    if (pairs) *pairs += n;
    return n ? double(c - d) / n : NAN;
}

} // namespace

const char* pairVerdictName(PairVerdictKind v) {
    switch (v) {
    case PairVerdictKind::PreferredA:
    case PairVerdictKind::PreferredB: return "PREFERRED";
    case PairVerdictKind::NotSeparated: return "NOT SEPARATED";
    case PairVerdictKind::Equivalent: return "EQUIVALENT";
    }
    return "?";
}

ObserverScreen screenObserver(const ObserverVotes& votes, const StudyKey& key) {
    ObserverScreen s;
    s.observer = votes.observer;
    s.source = votes.source;
    std::vector<double> seconds;
    double agree = 0;
    int repeatedPairs = 0;
    for (const auto& t : votes.trials) {
        seconds.push_back(t.milliseconds / 1000);
        const StudySet& set = key.sets[size_t(t.set)];
        if (t.kind == TrialKind::Control) {
            ++s.controls;
            s.controlsPassed += !t.ranking.empty() && t.ranking.back() == set.control.id;
        } else if (t.kind == TrialKind::Repeat) {
            const auto first = std::find_if(votes.trials.begin(), votes.trials.end(), [&](const TrialVote& u) {
                return u.kind == TrialKind::Test && u.set == t.set;
            });
            if (first == votes.trials.end()) continue;
            for (size_t i = 0; i < set.crops.size(); ++i)
                for (size_t j = i + 1; j < set.crops.size(); ++j) {
                    const int a = order(*first, set.crops[i].id, set.crops[j].id);
                    const int b = order(t, set.crops[i].id, set.crops[j].id);
                    agree += a == b ? 1.0 : (a == 0 || b == 0) ? 0.5 : 0.0;
                    ++repeatedPairs;
                }
        }
    }
    s.consistency = repeatedPairs ? agree / repeatedPairs : NAN;
    s.medianSeconds = median(seconds);
    if (s.controlsPassed < s.controls) {
        s.excluded = true;
        s.reason = fmt("control failed in %d of %d trials", s.controls - s.controlsPassed, s.controls);
    } else if (repeatedPairs >= kMinRepeatedPairs && s.consistency < kMinConsistency) {
        s.excluded = true;
        s.reason = fmt("every repeated pair reversed (%d pairs)", repeatedPairs);
    }
    return s;
}

std::vector<std::vector<double>> observerWins(const ObserverVotes& votes, const StudyKey& key, size_t set) {
    const StudySet& s = key.sets[set];
    const size_t n = s.crops.size();
    std::vector<std::vector<double>> w(n, std::vector<double>(n, 0));
    for (const auto& t : votes.trials) {
        if (t.kind != TrialKind::Test || size_t(t.set) != set) continue;
        for (size_t i = 0; i < n; ++i)
            for (size_t j = i + 1; j < n; ++j) {
                const int o = order(t, s.crops[i].id, s.crops[j].id);
                w[i][j] += o > 0 ? 1.0 : o == 0 ? 0.5 : 0.0;
                w[j][i] += o < 0 ? 1.0 : o == 0 ? 0.5 : 0.0;
            }
    }
    return w;
}

StudyAnalysis analyseStudy(const StudyKey& key, const std::vector<ObserverVotes>& votes, int bootstrapSamples,
                           uint64_t seed) {
    StudyAnalysis a;
    a.bootstrapSamples = bootstrapSamples;
    a.seed = seed;
    std::vector<const ObserverVotes*> kept;
    for (const auto& v : votes) {
        a.screens.push_back(screenObserver(v, key));
        if (!a.screens.back().excluded) kept.push_back(&v);
    }
    a.included = int(kept.size());
    std::mt19937_64 rng(seed);
    int concordantFlip = 0, concordantRms = 0, pairs = 0;
    for (size_t si = 0; si < key.sets.size(); ++si) {
        const StudySet& set = key.sets[si];
        const size_t n = set.crops.size();
        SetAnalysis sa;
        sa.observers = a.included;
        std::vector<std::vector<std::vector<double>>> perObserver;
        for (const auto* v : kept) perObserver.push_back(observerWins(*v, key, si));
        auto scale = [&](const std::vector<size_t>& pick) {
            std::vector<std::vector<double>> w(n, std::vector<double>(n, 0));
            for (size_t o : pick)
                for (size_t i = 0; i < n; ++i)
                    for (size_t j = 0; j < n; ++j) w[i][j] += perObserver[o][i][j];
            return thurstoneScores(w);
        };
        std::vector<size_t> all(kept.size());
        for (size_t i = 0; i < all.size(); ++i) all[i] = i;
        sa.score = scale(all);
        // Bootstrap over observers: each replicate draws as many observers as were kept, with replacement.
        std::vector<std::vector<double>> replicate;
        if (!kept.empty())
            for (int b = 0; b < bootstrapSamples; ++b) {
                std::vector<size_t> pick(kept.size());
                std::uniform_int_distribution<size_t> draw(0, kept.size() - 1);
                for (auto& p : pick) p = draw(rng);
                replicate.push_back(scale(pick));
            }
        auto column = [&](auto f) {
            std::vector<double> v;
            for (const auto& r : replicate) v.push_back(f(r));
            return v;
        };
        for (size_t i = 0; i < n; ++i) {
            const auto v = column([i](const std::vector<double>& r) { return r[i]; });
            const BootstrapInterval ci = bootstrapInterval(sa.score[i], v, kept.size(), 0.95);
            sa.lo95.push_back(i == 0 ? 0 : ci.lo);
            sa.hi95.push_back(i == 0 ? 0 : ci.hi);
        }
        for (size_t i = 0; i < n; ++i)
            for (size_t j = i + 1; j < n; ++j) {
                PairVerdict p;
                p.a = i;
                p.b = j;
                p.observers = a.included;
                p.difference = sa.score[i] - sa.score[j];
                const auto v = column([i, j](const std::vector<double>& r) { return r[i] - r[j]; });
                const BootstrapInterval c95 = bootstrapInterval(p.difference, v, kept.size(), 0.95);
                const BootstrapInterval c90 = bootstrapInterval(p.difference, v, kept.size(), 0.90);
                p.lo95 = c95.lo;
                p.hi95 = c95.hi;
                p.lo90 = c90.lo;
                p.hi90 = c90.hi;
                if (p.lo95 > 0) p.verdict = PairVerdictKind::PreferredA;
                else if (p.hi95 < 0) p.verdict = PairVerdictKind::PreferredB;
                else if (p.lo90 > -key.margin && p.hi90 < key.margin) p.verdict = PairVerdictKind::Equivalent;
                // Observers a decided verdict would need at this effect with 80% power: the standard error
                // (from the 95% interval) shrinks as 1/√observers.
                const double se = std::isfinite(p.hi95 - p.lo95)
                                      ? (p.hi95 - p.lo95) / (2 * statistics::studentTQuantile(0.975, double(kept.size() - 1)))
                                      : 0,
                             d = std::fabs(p.difference);
                double need = INFINITY;
                if (se > 0 && d > 1e-9) need = std::min(need, a.included * std::pow((1.959964 + 0.841621) * se / d, 2));
                if (se > 0 && d < key.margin)
                    need = std::min(need, a.included * std::pow((1.644854 + 0.841621) * se / (key.margin - d), 2));
                p.observersNeeded = std::isfinite(need) ? std::max(1, int(std::ceil(need))) : 0;
                sa.pairs.push_back(p);
            }
        std::vector<double> negFlip, negRms;
        for (const auto& c : set.crops) {
            negFlip.push_back(-c.flip);
            negRms.push_back(-c.rms);
        }
        sa.kendallFlip = kendall(sa.score, negFlip, &concordantFlip, &pairs);
        int unused = 0;
        sa.kendallRms = kendall(sa.score, negRms, &concordantRms, &unused);
        a.sets.push_back(std::move(sa));
    }
    a.agreementPairs = pairs;
    a.agreementFlip = pairs ? double(concordantFlip) / pairs : NAN;
    a.agreementRms = pairs ? double(concordantRms) / pairs : NAN;
    return a;
}

namespace {

std::string pairText(const StudySet& set, const PairVerdict& p) {
    const std::string& a = set.crops[p.a].pattern;
    const std::string& b = set.crops[p.b].pattern;
    std::string word = pairVerdictName(p.verdict);
    if (p.verdict == PairVerdictKind::PreferredA) word = a + " PREFERRED";
    if (p.verdict == PairVerdictKind::PreferredB) word = b + " PREFERRED";
    return fmt("%s vs %s: %+.2f JOD [%+.2f, %+.2f] %s; %d observers, %s", a.c_str(), b.c_str(), p.difference,
               p.lo95, p.hi95, word.c_str(), p.observers,
               p.observersNeeded ? fmt("a decided verdict needs ~%d", p.observersNeeded).c_str()
                                 : "no estimate of the observers needed");
}

} // namespace

std::string studyAnalysisText(const StudyKey& key, const StudyAnalysis& a) {
    std::string s = fmt("perceptual experiment %s: %zu observers, %d kept (control and consistency repeat: README)\n",
                        key.study.c_str(), a.screens.size(), a.included);
    for (const auto& o : a.screens)
        s += fmt("  %-20s controls %d/%d, consistency %s, median %.1f s per screen%s\n", o.observer.c_str(),
                 o.controlsPassed, o.controls, std::isnan(o.consistency) ? "–" : fmt("%.2f", o.consistency).c_str(),
                 o.medianSeconds, o.excluded ? (": EXCLUDED, " + o.reason).c_str() : "");
    for (size_t si = 0; si < key.sets.size(); ++si) {
        const StudySet& set = key.sets[si];
        const SetAnalysis& sa = a.sets[si];
        s += fmt("%s at %u spp (JOD relative to %s, 95%% bootstrap interval over observers; mean FLIP, RMS):\n",
                 set.name.c_str(), set.spp, set.crops[0].pattern.c_str());
        for (size_t i = 0; i < set.crops.size(); ++i)
            s += fmt("  %-22s %+6.2f [%+.2f, %+.2f]   FLIP %.4f   RMS %.4g\n", set.crops[i].pattern.c_str(), sa.score[i],
                     sa.lo95[i], sa.hi95[i], set.crops[i].flip, set.crops[i].rms);
        for (const auto& p : sa.pairs) s += "  " + pairText(set, p) + "\n";
        s += fmt("  rank agreement with FLIP: Kendall tau %.2f; with RMS: %.2f\n", sa.kendallFlip, sa.kendallRms);
    }
    if (a.included == 0) s += "no observer kept: nothing to scale\n";
    else
        s += fmt("people and FLIP order %.0f%% of %d pairs the same way (RMS: %.0f%%)\n", 100 * a.agreementFlip,
                 a.agreementPairs, 100 * a.agreementRms);
    return s;
}

std::string studyAnalysisJson(const StudyKey& key, const StudyAnalysis& a) {
    using nlohmann::json;
    auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    json observers = json::array();
    for (const auto& o : a.screens)
        observers.push_back({{"observer", o.observer}, {"source", o.source}, {"controls_passed", o.controlsPassed},
                             {"controls", o.controls}, {"consistency", num(o.consistency)},
                             {"median_seconds", num(o.medianSeconds)}, {"excluded", o.excluded}, {"reason", o.reason}});
    json sets = json::array();
    for (size_t si = 0; si < key.sets.size(); ++si) {
        const StudySet& set = key.sets[si];
        const SetAnalysis& sa = a.sets[si];
        json crops = json::array(), pairs = json::array();
        for (size_t i = 0; i < set.crops.size(); ++i)
            crops.push_back({{"pattern", set.crops[i].pattern}, {"jod", num(sa.score[i])}, {"lo95", num(sa.lo95[i])},
                             {"hi95", num(sa.hi95[i])}, {"flip", num(set.crops[i].flip)}, {"rms", num(set.crops[i].rms)}});
        for (const auto& p : sa.pairs)
            pairs.push_back({{"a", set.crops[p.a].pattern}, {"b", set.crops[p.b].pattern},
                             {"difference", num(p.difference)}, {"lo95", num(p.lo95)}, {"hi95", num(p.hi95)},
                             {"lo90", num(p.lo90)}, {"hi90", num(p.hi90)},
                             {"verdict", p.verdict == PairVerdictKind::PreferredA   ? "a"
                                         : p.verdict == PairVerdictKind::PreferredB ? "b"
                                         : p.verdict == PairVerdictKind::Equivalent ? "equivalent"
                                                                                    : "not separated"},
                             {"observers", p.observers}, {"observers_needed", p.observersNeeded}});
        sets.push_back({{"name", set.name}, {"spp", set.spp}, {"observers", sa.observers}, {"crops", crops},
                        {"pairs", pairs}, {"kendall_flip", num(sa.kendallFlip)}, {"kendall_rms", num(sa.kendallRms)}});
    }
    json j = {{"format", "stipple-perceptual-analysis"}, {"version", 1}, {"study", key.study},
              {"margin_jod", key.margin}, {"bootstrap_samples", a.bootstrapSamples}, {"seed", a.seed},
              {"observers", observers}, {"included", a.included}, {"sets", sets},
              {"agreement_flip", num(a.agreementFlip)}, {"agreement_rms", num(a.agreementRms)},
              {"agreement_pairs", a.agreementPairs}};
    return j.dump(1) + "\n";
}

} // namespace stipple::validation
