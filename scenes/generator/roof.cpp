// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "roof.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stipple::citygen {

namespace {

constexpr double kOverhang = 0.45;
constexpr double kRaise = 0.1; // roof plane sits this far above the wall top at the wall line
constexpr double kTileSpacing = 0.30;
constexpr double kTileRadius = 0.11;
constexpr double kCourse = 0.45;
constexpr double kCourseLift = 0.035; // each course's lower end overlaps the one below

// Roof-local coordinates put the ridge along +x: long side Wr, short side Dr. `base` maps them to the building.
struct RoofSetup {
    Frame base;
    double Wr, Dr;
};

RoofSetup setupFor(const BuildingSpec& spec) {
    RoofSetup r;
    double W = spec.width(), D = spec.depth();
    if (W >= D) {
        r.Wr = W;
        r.Dr = D;
    } else {
        // roof x -> building z, roof z -> building W - x (right-handed: ex x ey = ez)
        r.base.o = {W, 0, 0};
        r.base.ex = {0, 0, 1};
        r.base.ey = {0, 1, 0};
        r.base.ez = {-1, 0, 0};
        r.Wr = D;
        r.Dr = W;
    }
    return r;
}

// One roof face: frame origin at the start of the eave, ex along the eave, ey up the slope, ez outward.
void tiledFace(Mesh& m, const Frame& F, double eaveLength, double planRun, double cosPitch, bool hip) {
    const double slope = planRun / cosPitch;
    const Vec3 out = F.ez;
    if (!hip) {
        m.addQuad(F(0, 0, 0), F(eaveLength, 0, 0), F(eaveLength, slope, 0), F(0, slope, 0), out);
    } else if (eaveLength - 2 * planRun > 1e-6) {
        m.addQuad(F(0, 0, 0), F(eaveLength, 0, 0), F(eaveLength - planRun, slope, 0), F(planRun, slope, 0), out);
    } else {
        m.addTriangle(F(0, 0, 0), F(eaveLength, 0, 0), F(eaveLength / 2, slope, 0), out);
    }

    const int columns = int(eaveLength / kTileSpacing);
    const double margin = (eaveLength - columns * kTileSpacing) / 2;
    constexpr int kSegments = 4;
    for (int j = 0; j < columns; ++j) {
        double s = margin + (j + 0.5) * kTileSpacing;
        double plan = hip ? std::min({planRun, s, eaveLength - s}) : planRun;
        double length = (plan - 0.06) / cosPitch;
        for (double u0 = 0; u0 < length - 0.05; u0 += kCourse) {
            double u1 = std::min(u0 + kCourse, length);
            auto at = [&](double theta, double u, double lift) {
                return F(s + kTileRadius * std::cos(theta), u, lift + kTileRadius * std::sin(theta));
            };
            Vec3 centre = F(s, u0, kCourseLift);
            for (int q = 0; q < kSegments; ++q) {
                double a0 = std::numbers::pi * q / kSegments, a1 = std::numbers::pi * (q + 1) / kSegments;
                double am = 0.5 * (a0 + a1);
                Vec3 radial = F.dir({std::cos(am), 0, std::sin(am)});
                m.addQuad(at(a0, u0, kCourseLift), at(a1, u0, kCourseLift), at(a1, u1, 0), at(a0, u1, 0), radial);
                m.addTriangle(centre, at(a0, u0, kCourseLift), at(a1, u0, kCourseLift), F.ey * -1.0);
            }
        }
    }
}

void roll(Mesh& m, Vec3 a, Vec3 b, double radius) {
    Frame f = Frame::alongAxis(a, b - a);
    double len = std::sqrt(dot(b - a, b - a));
    m.addCylinder(f, radius, 0, len, 8, true);
}

} // namespace

double roofHeightAt(const BuildingSpec& spec, double x, double z) {
    RoofSetup r = setupFor(spec);
    double xr = x, zr = z;
    if (spec.width() < spec.depth()) {
        xr = z;
        zr = spec.width() - x;
    }
    double t = std::tan(spec.pitchDegrees * std::numbers::pi / 180);
    double run = std::min(zr, r.Dr - zr);
    if (spec.roof == RoofKind::Hip) run = std::min({run, xr, r.Wr - xr});
    return spec.height() + kRaise + std::max(0.0, run) * t;
}

void buildRoof(const BuildingSpec& spec, BuildingParts& parts) {
    RoofSetup r = setupFor(spec);
    const Frame& B = r.base;
    const double pitch = spec.pitchDegrees * std::numbers::pi / 180;
    const double c = std::cos(pitch), s = std::sin(pitch), t = std::tan(pitch);
    const double H = spec.height();
    const double ov = kOverhang;
    const double eaveY = H + kRaise - ov * t;
    const double planRun = r.Dr / 2 + ov;
    const double ridgeY = eaveY + planRun * t;
    const bool hip = spec.roof == RoofKind::Hip;
    const double L = r.Wr + 2 * ov;

    auto face = [&](Vec3 origin, Vec3 ex, Vec3 ey) {
        Frame f;
        f.o = origin;
        f.ex = ex;
        f.ey = ey;
        f.ez = cross(ex, ey);
        return f.inside(B);
    };
    // front (+z) and back (-z) faces
    tiledFace(parts.roof, face({-ov, eaveY, r.Dr + ov}, {1, 0, 0}, {0, s, -c}), L, planRun, c, hip);
    tiledFace(parts.roof, face({r.Wr + ov, eaveY, -ov}, {-1, 0, 0}, {0, s, c}), L, planRun, c, hip);

    Vec3 ridgeA{-ov + (hip ? planRun : 0), ridgeY, r.Dr / 2};
    Vec3 ridgeB{r.Wr + ov - (hip ? planRun : 0), ridgeY, r.Dr / 2};
    auto toB = [&](Vec3 p) { return B(p.x, p.y, p.z); };
    if (ridgeB.x - ridgeA.x > 1e-3) roll(parts.roof, toB(ridgeA), toB(ridgeB), 0.15);

    if (hip) {
        const double Ls = r.Dr + 2 * ov;
        tiledFace(parts.roof, face({-ov, eaveY, -ov}, {0, 0, 1}, {c, s, 0}), Ls, planRun, c, true);
        tiledFace(parts.roof, face({r.Wr + ov, eaveY, r.Dr + ov}, {0, 0, -1}, {-c, s, 0}), Ls, planRun, c, true);
        roll(parts.roof, toB({-ov, eaveY, -ov}), toB(ridgeA), 0.13);
        roll(parts.roof, toB({-ov, eaveY, r.Dr + ov}), toB(ridgeA), 0.13);
        roll(parts.roof, toB({r.Wr + ov, eaveY, -ov}), toB(ridgeB), 0.13);
        roll(parts.roof, toB({r.Wr + ov, eaveY, r.Dr + ov}), toB(ridgeB), 0.13);
    } else {
        // gable walls close the attic at both ends
        const double top = H + kRaise + (r.Dr / 2) * t;
        for (int end = 0; end < 2; ++end) {
            double x = end ? r.Wr : 0;
            Vec3 facing = B.dir({end ? 1.0 : -1.0, 0, 0});
            Vec3 p0 = toB({x, H, 0}), p1 = toB({x, H, r.Dr}), p2 = toB({x, H + kRaise, r.Dr});
            Vec3 p3 = toB({x, top, r.Dr / 2}), p4 = toB({x, H + kRaise, 0});
            parts.wall.addQuad(p0, p1, p2, p4, facing);
            parts.wall.addTriangle(p4, p2, p3, facing);
        }
    }
}

} // namespace stipple::citygen
