// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pointsets_threads_test.cpp — the generators are pure functions with no shared state: the same (dim, n, seed)
// gives bitwise the same set whether generated alone or while other threads generate (run under TSan too).
#define BOOST_TEST_MODULE pointsets_threads
#include <boost/test/unit_test.hpp>

#include "pointsets/pointsets.h"

#include <cstdint>
#include <thread>
#include <vector>

using namespace stipple::detail::pointsets;

BOOST_AUTO_TEST_CASE(concurrent_generation_is_bitwise_serial_generation) {
    struct Job {
        bool seedPattern;
        int dim;
        uint32_t n;
        uint64_t seed;
    };
    std::vector<Job> jobs;
    for (int dim = 1; dim <= 3; ++dim)
        for (uint32_t n : {7u, 64u, 700u})
            for (uint64_t seed : {1ull, 99ull}) {
                jobs.push_back({false, dim, n, seed});
                jobs.push_back({true, dim, n, seed});
            }
    auto run = [](const Job& j) {
        return j.seedPattern ? generatePoissonSeed(j.dim, j.n, j.seed) : generatePoisson(j.dim, j.n, j.seed);
    };
    std::vector<std::vector<float>> serial;
    for (const Job& j : jobs) serial.push_back(run(j));

    constexpr int kThreads = 4;
    std::vector<std::vector<std::vector<float>>> results(kThreads, std::vector<std::vector<float>>(jobs.size()));
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            // Each thread walks the jobs from its own starting point (a rotation), odd threads backwards, so
            // different sets are generated at the same time.
            for (size_t k = 0; k < jobs.size(); ++k) {
                size_t r = (k + size_t(t) * jobs.size() / kThreads) % jobs.size();
                size_t i = t % 2 ? jobs.size() - 1 - r : r;
                results[t][i] = run(jobs[i]);
            }
        });
    for (auto& th : threads) th.join();
    for (int t = 0; t < kThreads; ++t)
        for (size_t i = 0; i < jobs.size(); ++i) BOOST_CHECK(results[t][i] == serial[i]);
}
