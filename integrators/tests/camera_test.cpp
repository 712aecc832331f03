// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Camera conventions that BDPT relies on: We(ray) finds the raster point a ray was generated for; sampleWi and
// rasterFromWorld agree; pdfDir integrates to 1 over the image; thin-lens rays through the lens converge on
// the plane of focus; We * cos / (pdfPos * pdfDir) = 1 for generated rays (importance normalisation).
#define BOOST_TEST_MODULE camera
#include <boost/test/unit_test.hpp>

#include "camera/camera.h"

using namespace stipple::render;

namespace {
CameraDesc desc(bool thinLens) {
    CameraDesc d;
    d.type = thinLens ? "thinlens" : "pinhole";
    d.position = {1, 2, 3};
    d.lookAt = {0, 0.5f, -2};
    d.up = {0, 1, 0};
    d.fovDegrees = 35;
    d.lensRadius = 0.1f;
    d.focusDistance = 4;
    return d;
}
} // namespace

BOOST_AUTO_TEST_CASE(raster_round_trip_and_importance) {
    for (bool thin : {false, true}) {
        Camera cam(desc(thin), 64, 40);
        BOOST_TEST(cam.isThinLens() == thin);
        for (float x : {0.5f, 10.25f, 63.5f})
            for (float y : {0.5f, 20.75f, 39.5f})
                for (Point2 lens : {Point2{0.5f, 0.5f}, Point2{0.1f, 0.9f}}) {
                    Ray r = cam.generateRay({x, y}, lens);
                    Point2 raster;
                    Spectrum We = cam.We(r, &raster);
                    BOOST_TEST(!We.isBlack());
                    BOOST_TEST(std::abs(raster.x - x) < 1e-3f);
                    BOOST_TEST(std::abs(raster.y - y) < 1e-3f);
                    float pdfPos, pdfDir;
                    cam.pdfWe(r, pdfPos, pdfDir);
                    float cosTheta = dot(r.d, cam.forward());
                    // We cos / (pdfPos pdfDir) == 1: the camera's importance is exactly what its sampling draws.
                    BOOST_TEST(std::abs(We.r * cosTheta / (pdfPos * pdfDir) - 1) < 1e-3f);
                    // The point 5 units along the ray seen from the lens point projects back to the same raster
                    // position through sampleWi (pinhole: any lens sample).
                    if (!thin) {
                        Point2 back;
                        BOOST_REQUIRE(cam.rasterFromWorld(r.o + r.d * 5, back));
                        BOOST_TEST(std::abs(back.x - x) < 1e-3f);
                        CameraWiSample s;
                        BOOST_REQUIRE(cam.sampleWi(r.o + r.d * 5, {0.5f, 0.5f}, s));
                        BOOST_TEST(std::abs(s.raster.y - y) < 1e-3f);
                        BOOST_TEST(std::abs(s.distance - 5) < 1e-3f);
                    }
                }
    }
}

BOOST_AUTO_TEST_CASE(thin_lens_focuses_on_its_plane) {
    Camera cam(desc(true), 64, 40);
    Ray a = cam.generateRay({20.5f, 11.5f}, {0.05f, 0.5f});
    Ray b = cam.generateRay({20.5f, 11.5f}, {0.95f, 0.3f});
    // Both reach the same point at focus distance along the view axis.
    float ta = 4 / dot(a.d, cam.forward()), tb = 4 / dot(b.d, cam.forward());
    Vec3 pa = a.o + a.d * ta, pb = b.o + b.d * tb;
    // pa and pb lie on planes through the lens points, not the centre: compare their focus-plane projections.
    float da = dot(pa - cam.position(), cam.forward()), db = dot(pb - cam.position(), cam.forward());
    pa = pa + a.d * ((4 - da) / dot(a.d, cam.forward()));
    pb = pb + b.d * ((4 - db) / dot(b.d, cam.forward()));
    BOOST_TEST(length(pa - pb) < 1e-4f);
    BOOST_TEST(length(a.o - b.o) > 0.05f);
}

BOOST_AUTO_TEST_CASE(pdf_dir_integrates_to_one_over_the_image) {
    Camera cam(desc(false), 48, 32);
    // Integrate pdfDir over directions through a fine raster grid: d(omega) = cos^3 dA / 1 at the plane z = 1,
    // and dA per raster cell is the image-plane area / (w h).
    double sum = 0;
    const int n = 4;
    for (int y = 0; y < 32 * n; ++y)
        for (int x = 0; x < 48 * n; ++x) {
            Ray r = cam.generateRay({(x + 0.5f) / n, (y + 0.5f) / n}, {0.5f, 0.5f});
            float pdfPos, pdfDir;
            cam.pdfWe(r, pdfPos, pdfDir);
            double c = dot(r.d, cam.forward());
            sum += pdfDir * c * c * c;
        }
    // sum * (image-plane area / cells) = 1; the area follows from pdfDir at the centre (1 / A there).
    Ray centre = cam.generateRay({24, 16}, {0.5f, 0.5f});
    float pp, pd;
    cam.pdfWe(centre, pp, pd);
    double area = 1.0 / pd;
    BOOST_TEST(std::abs(sum * area / (48.0 * n * 32 * n) - 1) < 1e-3);
}
