// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The multiple-importance weight of one BDPT strategy (power heuristic, beta = 2) over every strategy that could
// have produced the same path (Veach's thesis 10.2). The full path x_0 ... x_{n-1} runs from the light end:
// x_j = lightPath[j] for j < s, x_j = cameraPath[n-1-j] for j >= s. Strategy s' takes x_0 .. x_{s'-1} from the
// light and the rest from the camera; p_{s'+1} / p_{s'} is the area density of x_{s'} from the light side over
// its density from the camera side, so the densities stored on the vertices (area measure) are all that is
// needed, plus the few that depend on the connection, computed here.
//
// Specular vertices: their densities are Dirac terms that cancel between the strategies that remain, so a zero
// density is read as 1 and strategies with a connection ending at a delta vertex are skipped (pbrt-v3's rule).
// The s = 1 strategy draws x_0 with the light's own sampleLi from x_1 (a cone for sphere lights seen from
// outside), not by area: its density is used for that strategy alone.
#pragma once

#include "integrators/bdpt/bdpt_vertex.h"

#include <vector>

namespace stipple::render::bdpt {

// x_0's densities from the light side, by area (pOrigin) and by the s = 1 connection's sampling from x_1
// (pConnect), zeros read as 1: the same for every strategy with s >= 2 of one light subpath, so computed once.
struct LightStart {
    double pOrigin = 1, pConnect = 1;
};

struct ConnectionVertices {
    const PathVertex* freshLight = nullptr;  // s = 1: the fresh light sample replacing lightPath[0]
    const PathVertex* freshCamera = nullptr; // t = 1: the lens point sampled towards the light vertex
    const Link* link = nullptr;              // s >= 1: the connection x_{s-1} -- x_s (fresh vertices included)
    const LightStart* lightStart = nullptr;  // s >= 2: lightStart(lightPath), else computed per call
};

class MisWeights {
public:
    explicit MisWeights(const PathEvaluator& eval) : eval_(eval) {}
    // Weight of strategy (s, t); s + t >= 2, t >= 1; fresh.link is required when s >= 1. Uses per-thread
    // scratch space (no allocation per call once warm).
    float weight(const std::vector<PathVertex>& lightPath, const std::vector<PathVertex>& cameraPath, int s, int t,
                 const ConnectionVertices& fresh) const;
    // x_0's densities for a light subpath of at least two vertices.
    LightStart lightStart(const std::vector<PathVertex>& lightPath) const { return start(lightPath[0], lightPath[1]); }

private:
    LightStart start(const PathVertex& x0, const PathVertex& x1) const;

    const PathEvaluator& eval_;
};

} // namespace stipple::render::bdpt
