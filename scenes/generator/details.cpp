// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "details.h"

namespace stipple::citygen {

DetailPrototype makeBalcony() {
    DetailPrototype d{"balcony", {}};
    Mesh stone, iron;
    Frame f;
    stone.addBox(f, {-0.95, -0.16, 0}, {0.95, 0, 0.95});
    for (double x : {-0.7, 0.7}) {
        // corbels under the slab
        stone.addBox(f, {x - 0.1, -0.5, 0}, {x + 0.1, -0.16, 0.55});
        stone.addBox(f, {x - 0.1, -0.3, 0.55}, {x + 0.1, -0.16, 0.8});
    }
    // railing: top rail on three sides, a lower rail and round bars
    iron.addBox(f, {-0.9, 0.95, 0.85}, {0.9, 1.0, 0.9});
    iron.addBox(f, {-0.9, 0.12, 0.85}, {0.9, 0.16, 0.9});
    for (double x : {-0.9, 0.85}) {
        iron.addBox(f, {x, 0.95, 0}, {x + 0.05, 1.0, 0.9});
        iron.addBox(f, {x, 0.12, 0}, {x + 0.05, 0.16, 0.9});
    }
    Frame bar;
    for (int i = 0; i <= 16; ++i) {
        bar.o = {-0.875 + i * 1.75 / 16, 0, 0.875};
        iron.addCylinder(bar, 0.012, 0, 0.97, 6, false);
    }
    for (int i = 0; i < 7; ++i) {
        for (double x : {-0.875, 0.875}) {
            bar.o = {x, 0, 0.1 + i * 0.75 / 6};
            iron.addCylinder(bar, 0.012, 0, 0.97, 6, false);
        }
    }
    d.parts = {{"stone", stone}, {"iron", iron}};
    return d;
}

DetailPrototype makeChimney() {
    DetailPrototype d{"chimney", {}};
    Mesh plaster, stone, pots;
    Frame f;
    plaster.addBox(f, {-0.35, 0, -0.3}, {0.35, 2.0, 0.3});
    stone.addBox(f, {-0.45, 2.0, -0.4}, {0.45, 2.08, 0.4});
    for (double x : {-0.18, 0.18}) {
        Frame p;
        p.o = {x, 2.08, 0};
        pots.addLathe(p, {{0, 0}, {0.11, 0}, {0.12, 0.25}, {0.09, 0.4}, {0.1, 0.45}}, 10);
    }
    // a little tiled hood over the pots
    pots.addQuad({-0.45, 2.65, -0.4}, {0.45, 2.65, -0.4}, {0.45, 2.85, 0}, {-0.45, 2.85, 0}, {0, 1, -1});
    pots.addQuad({-0.45, 2.65, 0.4}, {0.45, 2.65, 0.4}, {0.45, 2.85, 0}, {-0.45, 2.85, 0}, {0, 1, 1});
    for (double x : {-0.4, 0.4})
        for (double z : {-0.35, 0.35}) stone.addBox(f, {x - 0.03, 2.08, z - 0.03}, {x + 0.03, 2.7, z + 0.03});
    d.parts = {{"plaster_cream", plaster}, {"stone", stone}, {"roof_tiles", pots}};
    return d;
}

DetailPrototype makeStreetLamp() {
    DetailPrototype d{"street_lamp", {}};
    Mesh iron, glass;
    Frame post;
    iron.addLathe(post, {{0, 0}, {0.16, 0}, {0.16, 0.1}, {0.1, 0.2}, {0.09, 0.6}, {0.06, 0.7}, {0.05, 3.5}, {0, 3.5}},
                  12);
    Frame arm = Frame::alongAxis({0, 3.4, 0}, {0, 0.25, 1});
    iron.addCylinder(arm, 0.03, 0, 0.75, 8, true);
    // the lantern hangs at the arm's end: glass body, iron cap and finial
    Frame lantern;
    lantern.o = {0, 3.0, 0.72};
    glass.addLathe(lantern, {{0.05, 0}, {0.16, 0.1}, {0.2, 0.45}, {0.22, 0.5}}, 6);
    iron.addLathe(lantern, {{0.22, 0.5}, {0.26, 0.52}, {0.05, 0.75}, {0.03, 0.85}, {0, 0.9}}, 6);
    iron.addLathe(lantern, {{0, -0.05}, {0.06, -0.05}, {0.05, 0}}, 6);
    d.parts = {{"iron", iron}, {"lamp_glass", glass}};
    return d;
}

DetailPrototype makeFountain() {
    DetailPrototype d{"fountain", {}};
    Mesh stone, water;
    Frame f;
    constexpr int kSegments = 64;
    // basin, outside then inside; the water surface; the column, upper bowl and finial
    stone.addLathe(f, {{3.3, 0}, {3.3, 0.45}, {3.45, 0.5}, {3.45, 0.7}, {3.0, 0.7}, {3.0, 0.4}}, kSegments);
    water.addLathe(f, {{3.0, 0.4}, {0.55, 0.4}}, kSegments);
    stone.addLathe(f,
                   {{0.55, 0.4},
                    {0.5, 0.6},
                    {0.38, 0.8},
                    {0.38, 1.5},
                    {0.5, 1.6},
                    {1.5, 1.95},
                    {1.6, 2.1},
                    {1.45, 2.1},
                    {1.35, 2.0}},
                   kSegments);
    water.addLathe(f, {{1.35, 2.0}, {0.3, 2.0}}, kSegments);
    stone.addLathe(f,
                   {{0.3, 2.0}, {0.22, 2.4}, {0.4, 2.6}, {0.35, 2.75}, {0.15, 2.8}, {0.12, 3.3}, {0.2, 3.4}, {0, 3.6}},
                   kSegments);
    // steps around the basin
    stone.addLathe(f, {{4.1, 0}, {4.1, 0.15}, {3.7, 0.15}, {3.7, 0.3}, {3.3, 0.3}}, kSegments);
    d.parts = {{"stone", stone}, {"water", water}};
    return d;
}

} // namespace stipple::citygen
