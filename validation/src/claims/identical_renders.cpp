// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/identical_renders.h"
#include "base/text.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace stipple::validation {

std::vector<std::string> identicalSeedRenders(const std::vector<ResultRow>& rows) {
    std::map<std::tuple<std::string, std::string, uint32_t>, std::vector<const ResultRow*>> cells;
    for (const auto& r : rows) cells[{r.scene, r.pattern, r.spp}].push_back(&r);
    std::vector<std::string> out;
    for (const auto& [key, seeds] : cells) {
        std::vector<std::string> groups;
        std::vector<bool> used(seeds.size(), false);
        for (size_t i = 0; i < seeds.size(); ++i) {
            const auto& blocks = seeds[i]->blockSse;
            if (used[i] || blocks.empty() || std::all_of(blocks.begin(), blocks.end(), [](double v) { return v == 0; }))
                continue;
            std::string same = std::to_string(seeds[i]->seed);
            size_t n = 1;
            for (size_t j = i + 1; j < seeds.size(); ++j)
                if (!used[j] && seeds[j]->blockSse == blocks && seeds[j]->mse == seeds[i]->mse) {
                    used[j] = true;
                    same += ", " + std::to_string(seeds[j]->seed);
                    ++n;
                }
            if (n > 1) groups.push_back("seeds " + same);
        }
        if (groups.empty()) continue;
        std::string all;
        for (const auto& g : groups) all += (all.empty() ? "" : "; ") + g;
        out.push_back(fmt("%s, %s, %u spp: bitwise-equal images from %s (the renderer ignores {seed} or maps these "
                          "seeds to one value; {seed} is any unsigned 64-bit number)",
                          std::get<0>(key).c_str(), std::get<1>(key).c_str(), std::get<2>(key), all.c_str()));
    }
    return out;
}

} // namespace stipple::validation
