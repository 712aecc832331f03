// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "building.h"

#include "roof.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stipple::citygen {

namespace {

constexpr double kRecess = 0.24;      // window reveal depth
constexpr double kPorticoDepth = 3.2; // arcade: front wall to the shop fronts behind
constexpr double kArchWall = 0.55;    // arcade: thickness of the arched wall

enum class Opening { Window, Door, Shop, Arch, Blank };

struct Window {
    double width, height, sill;
};

// Four reveal faces of a rectangular hole (a0..a1) x (b0..b1), `depth` into the wall.
void reveal(Mesh& m, const Frame& f, double a0, double a1, double b0, double b1, double depth) {
    m.addQuad(f(a0, b0, 0), f(a0, b0, -depth), f(a0, b1, -depth), f(a0, b1, 0), f.ex);
    m.addQuad(f(a1, b0, 0), f(a1, b0, -depth), f(a1, b1, -depth), f(a1, b1, 0), f.ex * -1.0);
    m.addQuad(f(a0, b0, 0), f(a1, b0, 0), f(a1, b0, -depth), f(a0, b0, -depth), f.ey);
    m.addQuad(f(a0, b1, 0), f(a1, b1, 0), f(a1, b1, -depth), f(a0, b1, -depth), f.ey * -1.0);
}

// An open louvred shutter flat against the wall, (s0..s1) x (t0..t1).
void shutterPanel(Mesh& m, const Frame& f, double s0, double s1, double t0, double t1) {
    m.addBox(f, {s0, t0, 0}, {s1, t1, 0.03});
    for (double t = t0 + 0.08; t + 0.05 < t1 - 0.05; t += 0.13)
        m.addBox(f, {s0 + 0.04, t, 0.03}, {s1 - 0.04, t + 0.05, 0.05});
}

// One bay of one storey, (s0..s1) x (t0..t1), with a rectangular opening of the given kind.
void rectangularCell(BuildingParts& p, const Frame& f, double s0, double s1, double t0, double t1, Opening kind,
                     const Window& w, bool shutters, bool pediment) {
    if (kind == Opening::Blank) {
        p.wall.addRect(f, s0, t0, s1, t1, 0);
        return;
    }
    const double mid = 0.5 * (s0 + s1);
    double width = w.width, b0 = t0 + w.sill, b1 = t0 + w.sill + w.height;
    if (kind == Opening::Door) {
        width = std::min(1.3, s1 - s0 - 0.8);
        b0 = t0;
        b1 = t0 + 2.7;
    }
    if (kind == Opening::Shop) {
        width = std::min(2.2, s1 - s0 - 0.7);
        b0 = t0;
        b1 = t0 + 2.9;
    }
    b1 = std::min(b1, t1 - 0.3);
    const double a0 = mid - width / 2, a1 = mid + width / 2;

    p.wall.addRect(f, s0, t0, s1, b0, 0);
    p.wall.addRect(f, s0, b1, s1, t1, 0);
    p.wall.addRect(f, s0, b0, a0, b1, 0);
    p.wall.addRect(f, a1, b0, s1, b1, 0);
    reveal(p.trim, f, a0, a1, b0, b1, kRecess);

    if (kind == Opening::Door) {
        // panelled double door
        p.shutter.addRect(f, a0, b0, a1, b1, -kRecess);
        for (int leaf = 0; leaf < 2; ++leaf) {
            double l0 = a0 + leaf * width / 2, l1 = l0 + width / 2;
            for (int row = 0; row < 3; ++row) {
                double r0 = b0 + 0.2 + row * (b1 - b0 - 0.3) / 3, r1 = r0 + (b1 - b0 - 0.3) / 3 - 0.15;
                p.shutter.addBox(f, {l0 + 0.1, r0, -kRecess}, {l1 - 0.1, r1, -kRecess + 0.04});
            }
        }
    } else {
        p.glass.addRect(f, a0, b0, a1, b1, -kRecess);
        // frame: mullion and transom
        p.shutter.addBox(f, {mid - 0.03, b0, -kRecess}, {mid + 0.03, b1, -kRecess + 0.06});
        double tt = b0 + 0.72 * (b1 - b0);
        p.shutter.addBox(f, {a0, tt - 0.03, -kRecess}, {a1, tt + 0.03, -kRecess + 0.06});
        if (kind == Opening::Window && b0 > t0 + 0.1) p.trim.addBox(f, {a0 - 0.08, b0 - 0.07, 0}, {a1 + 0.08, b0, 0.1});
    }
    // lintel, and on the piano nobile a triangular pediment
    p.trim.addBox(f, {a0 - 0.12, b1, 0}, {a1 + 0.12, b1 + 0.14, 0.08});
    if (pediment && b1 + 0.6 < t1) {
        double y0 = b1 + 0.14, y1 = y0 + 0.4, e0 = a0 - 0.16, e1 = a1 + 0.16, d = 0.12;
        p.trim.addTriangle(f(e0, y0, d), f(e1, y0, d), f(mid, y1, d), f.ez);
        p.trim.addQuad(f(e0, y0, 0), f(e0, y0, d), f(mid, y1, d), f(mid, y1, 0), f.ex * -(y1 - y0) + f.ey * (mid - e0));
        p.trim.addQuad(f(e1, y0, 0), f(e1, y0, d), f(mid, y1, d), f(mid, y1, 0), f.ex * (y1 - y0) + f.ey * (e1 - mid));
        p.trim.addQuad(f(e0, y0, 0), f(e1, y0, 0), f(e1, y0, d), f(e0, y0, d), f.ey * -1.0);
    }
    if (shutters && kind == Opening::Window) {
        double sw = width / 2;
        shutterPanel(p.shutter, f, std::max(s0 + 0.02, a0 - sw - 0.03), a0 - 0.03, b0, b1);
        shutterPanel(p.shutter, f, a1 + 0.03, std::min(s1 - 0.02, a1 + sw + 0.03), b0, b1);
    }
}

// One bay with a round arch. `portico`: the arch opens into a portico (its back faces up to `ceiling`);
// otherwise it is a blind niche closed by a dark back.
void archCell(BuildingParts& p, const Frame& f, double s0, double s1, double t0, double t1, double pier,
              double springHeight, bool portico, double ceiling) {
    constexpr int kSegments = 14;
    const double xc = 0.5 * (s0 + s1), r = 0.5 * (s1 - s0) - pier, spring = t0 + springHeight;
    const double thick = portico ? kArchWall : 0.35;
    auto A = [&](int k) {
        double th = std::numbers::pi * (1.0 - double(k) / kSegments);
        return std::pair{xc + r * std::cos(th), spring + r * std::sin(th)};
    };
    for (int side = 0; side < (portico ? 2 : 1); ++side) {
        const double d = side ? -thick : 0;
        const bool back = side == 1;
        const double top = back ? ceiling : t1;
        p.wall.addRect(f, s0, t0, xc - r, top, d, back);
        p.wall.addRect(f, xc + r, t0, s1, top, d, back);
        for (int k = 0; k < kSegments; ++k) {
            auto [x0, y0] = A(k);
            auto [x1, y1] = A(k + 1);
            if (top <= std::max(y0, y1)) continue;
            p.wall.addQuad(f(x0, y0, d), f(x1, y1, d), f(x1, top, d), f(x0, top, d), back ? f.ez * -1.0 : f.ez);
        }
    }
    // jambs and the intrados, in stone
    p.trim.addQuad(f(xc - r, t0, 0), f(xc - r, t0, -thick), f(xc - r, spring, -thick), f(xc - r, spring, 0), f.ex);
    p.trim.addQuad(f(xc + r, t0, 0), f(xc + r, t0, -thick), f(xc + r, spring, -thick), f(xc + r, spring, 0),
                   f.ex * -1.0);
    for (int k = 0; k < kSegments; ++k) {
        auto [x0, y0] = A(k);
        auto [x1, y1] = A(k + 1);
        Vec3 inward = f.ex * (xc - 0.5 * (x0 + x1)) + f.ey * (spring - 0.5 * (y0 + y1));
        p.trim.addQuad(f(x0, y0, 0), f(x1, y1, 0), f(x1, y1, -thick), f(x0, y0, -thick), inward);
        // archivolt: a stone band around the arch, proud of the wall
        auto [X0, Y0] = std::pair{xc + (x0 - xc) * (r + 0.18) / r, spring + (y0 - spring) * (r + 0.18) / r};
        auto [X1, Y1] = std::pair{xc + (x1 - xc) * (r + 0.18) / r, spring + (y1 - spring) * (r + 0.18) / r};
        if (std::max(Y0, Y1) < t1)
            p.trim.addQuad(f(x0, y0, 0.03), f(x1, y1, 0.03), f(X1, Y1, 0.03), f(X0, Y0, 0.03), f.ez);
    }
    if (!portico) {
        // dark back of the niche: the rectangle below the spring and a fan for the half disc
        p.glass.addRect(f, xc - r, t0, xc + r, spring, -thick);
        for (int k = 0; k < kSegments; ++k) {
            auto [x0, y0] = A(k);
            auto [x1, y1] = A(k + 1);
            p.glass.addTriangle(f(xc, spring, -thick), f(x0, y0, -thick), f(x1, y1, -thick), f.ez);
        }
    }
}

struct FacadeInfo {
    Frame frame;
    double length;
    int bays;
    double yawDegrees;
    bool front;
    // side facades of an arcaded building: the bays next to the front stay blank on the ground floor
    int blankGroundFrom = -1, blankGroundTo = -1;
};

void facade(BuildingParts& p, const BuildingSpec& spec, const FacadeInfo& fi, const std::vector<Window>& windows,
            const std::vector<Opening>& ground, const std::vector<int>& balconyBays, bool shutters) {
    const Frame& f = fi.frame;
    const double bay = fi.length / fi.bays;
    const double H = spec.height();
    for (int k = 0; k < spec.floors; ++k) {
        const double t0 = k == 0 ? 0 : spec.groundHeight + (k - 1) * spec.storeyHeight;
        const double t1 = k == 0 ? spec.groundHeight : t0 + spec.storeyHeight;
        const bool top = k == spec.floors - 1;
        for (int i = 0; i < fi.bays; ++i) {
            const double s0 = i * bay, s1 = s0 + bay;
            if (k == 0) {
                Opening kind = ground[size_t(i)];
                if (i >= fi.blankGroundFrom && i <= fi.blankGroundTo) kind = Opening::Blank;
                if (kind == Opening::Arch)
                    archCell(p, f, s0, s1, t0, t1, 0.38, 2.6, fi.front && spec.arcade, t1 - 0.25);
                else
                    rectangularCell(p, f, s0, s1, t0, t1, kind, windows[0], false, false);
            } else if (top && spec.belfry) {
                archCell(p, f, s0, s1, t0, t1, 0.3, 1.2, false, t1);
            } else {
                Window w = windows[size_t(std::min(k, int(windows.size()) - 1))];
                bool balcony =
                    fi.front && k == 1 && std::find(balconyBays.begin(), balconyBays.end(), i) != balconyBays.end();
                if (balcony) {
                    w.height += w.sill - 0.05;
                    w.sill = 0.05;
                    double mid = 0.5 * (s0 + s1);
                    p.details.push_back({"balcony", fi.yawDegrees, f(mid, t0, 0)});
                }
                rectangularCell(p, f, s0, s1, t0, t1, Opening::Window, w, shutters && !balcony, k == 1 && !top);
            }
        }
    }
    // string course over the ground floor, cornice under the eaves (past the corners so they meet)
    p.trim.addBox(f, {-0.1, spec.groundHeight - 0.12, 0}, {fi.length + 0.1, spec.groundHeight + 0.05, 0.1});
    p.trim.addBox(f, {-0.2, H - 0.45, 0}, {fi.length + 0.2, H - 0.25, 0.2});
    p.trim.addBox(f, {-0.35, H - 0.25, 0}, {fi.length + 0.35, H, 0.35});
    // a stone plinth course
    p.trim.addBox(f, {-0.04, 0, 0}, {fi.length + 0.04, 0.05, 0.04});
}

} // namespace

BuildingParts buildBuilding(const BuildingSpec& spec, Rng& rng) {
    BuildingParts p;
    const double W = spec.width(), D = spec.depth();

    // one window family per building, smaller towards the top
    std::vector<Window> windows;
    double ww = spec.slitWindows ? 0.45 : rng.uniform(0.9, 1.15);
    windows.push_back({ww * 0.8, 1.1, 1.5});                     // ground floor: small, high
    windows.push_back({ww, spec.slitWindows ? 1.3 : 2.0, 0.75}); // piano nobile
    windows.push_back({ww, spec.slitWindows ? 1.1 : 1.7, 0.9});  // upper floors
    if (spec.floors >= 5) windows.push_back({ww, 1.15, 1.1});    // attic
    const bool shutters = !spec.slitWindows && rng.chance(0.8);

    std::vector<Opening> frontGround(size_t(spec.baysX));
    for (int i = 0; i < spec.baysX; ++i) {
        if (spec.arcade)
            frontGround[size_t(i)] = Opening::Arch;
        else if (i == spec.baysX / 2)
            frontGround[size_t(i)] = Opening::Door;
        else
            frontGround[size_t(i)] = rng.chance(0.55) ? Opening::Shop : Opening::Window;
    }
    std::vector<int> balconies;
    for (int b = 0; b < spec.balconies; ++b) {
        int bay = spec.baysX / 2 + (b % 2 ? -(b + 1) / 2 : b / 2);
        if (bay >= 0 && bay < spec.baysX) balconies.push_back(bay);
    }
    auto sideGround = [&](int bays) {
        std::vector<Opening> g(static_cast<size_t>(bays));
        for (auto& o : g) o = rng.chance(0.3) ? Opening::Blank : Opening::Window;
        return g;
    };
    auto backGround = [&](int bays) {
        std::vector<Opening> g = sideGround(bays);
        g[size_t(bays / 2)] = Opening::Door;
        return g;
    };
    const int porticoBays = spec.arcade ? int(std::ceil(kPorticoDepth / spec.bay)) : 0;

    FacadeInfo front{Frame::facade({0, 0, D}, {0, 0, 1}), W, spec.baysX, 0, true};
    FacadeInfo right{Frame::facade({W, 0, D}, {1, 0, 0}), D, spec.baysZ, 90, false};
    FacadeInfo back{Frame::facade({W, 0, 0}, {0, 0, -1}), W, spec.baysX, 180, false};
    FacadeInfo left{Frame::facade({0, 0, 0}, {-1, 0, 0}), D, spec.baysZ, 270, false};
    if (porticoBays > 0) {
        right.blankGroundFrom = 0;
        right.blankGroundTo = porticoBays - 1;
        left.blankGroundFrom = spec.baysZ - porticoBays;
        left.blankGroundTo = spec.baysZ - 1;
    }
    facade(p, spec, front, windows, frontGround, balconies, shutters);
    facade(p, spec, right, windows, sideGround(spec.baysZ), {}, shutters);
    facade(p, spec, back, windows, backGround(spec.baysX), {}, shutters);
    facade(p, spec, left, windows, sideGround(spec.baysZ), {}, shutters);
    if (spec.arcade) {
        // the portico behind the arches: ceiling, end walls and shop fronts at the back
        const Frame& f = front.frame;
        const double ceil = spec.groundHeight - 0.25;
        p.wall.addQuad(f(0, ceil, -kArchWall), f(W, ceil, -kArchWall), f(W, ceil, -kPorticoDepth),
                       f(0, ceil, -kPorticoDepth), f.ey * -1.0);
        p.wall.addQuad(f(0, 0, -kArchWall), f(0, ceil, -kArchWall), f(0, ceil, -kPorticoDepth), f(0, 0, -kPorticoDepth),
                       f.ex);
        p.wall.addQuad(f(W, 0, -kArchWall), f(W, ceil, -kArchWall), f(W, ceil, -kPorticoDepth), f(W, 0, -kPorticoDepth),
                       f.ex * -1.0);
        Frame inner = f;
        inner.o = f(0, 0, -kPorticoDepth);
        const double bay = W / spec.baysX;
        for (int i = 0; i < spec.baysX; ++i)
            rectangularCell(p, inner, i * bay, (i + 1) * bay, 0, ceil, i % 2 ? Opening::Door : Opening::Shop,
                            windows[0], false, false);
    }

    buildRoof(spec, p);

    // chimneys: on the roof, away from the eaves
    for (int c = 0; c < spec.chimneys; ++c) {
        double x = rng.uniform(1.2, W - 1.2), z = rng.uniform(D * 0.3, D * 0.7);
        double y = roofHeightAt(spec, x, z) - 0.6;
        p.details.push_back({"chimney", double(90 * rng.range(0, 3)), {x, y, z}});
    }
    return p;
}

} // namespace stipple::citygen
