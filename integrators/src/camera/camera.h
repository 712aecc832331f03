// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Pinhole and thin-lens perspective cameras. fov spans the SHORTER image axis. Raster space: x right, y down,
// pixel (x, y) covers [x, x+1) x [y, y+1). Besides primary rays it exposes what a bidirectional integrator
// needs (pbrt-v3 PerspectiveCamera conventions):
//   We(ray)            importance emitted along a ray leaving the lens, and its raster position;
//   pdfWe(ray)         pdfPos (area measure on the lens; 1 for a pinhole) and pdfDir (solid angle);
//   sampleWi(ref, u)   a lens point seen from a scene point: importance, direction, pdf (SOLID ANGLE at ref),
//                      raster position — the t = 1 (light tracing) connection.
#pragma once

#include "core/geometry.h"
#include "sampling/warps.h"

#include <string>

namespace stipple::render {

struct CameraDesc {
    std::string type = "pinhole"; // pinhole | thinlens
    Vec3 position{0, 0, 0};
    Vec3 lookAt{0, 0, -1};
    Vec3 up{0, 1, 0};
    float fovDegrees = 45;
    float lensRadius = 0;    // thinlens only
    float focusDistance = 1; // thinlens only
};

struct CameraWiSample {
    Spectrum We;   // importance
    Vec3 wi;       // from the reference point towards the lens point
    float pdf = 0; // solid angle at the reference point
    Vec3 pLens;    // the lens point (world)
    Vec3 nLens;    // the lens normal (camera forward)
    float distance = 0;
    Point2 raster;
};

class Camera {
public:
    Camera(const CameraDesc& desc, int width, int height);

    bool isThinLens() const { return lensRadius_ > 0; }
    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& position() const { return position_; }
    const Vec3& forward() const { return forward_; }

    // Ray through raster point pRaster; uLens is ignored by the pinhole.
    Ray generateRay(Point2 pRaster, Point2 uLens) const;

    // Importance along a ray from the lens; returns 0 when the ray leaves the image. raster may be null.
    Spectrum We(const Ray& ray, Point2* raster) const;
    void pdfWe(const Ray& ray, float& pdfPos, float& pdfDir) const;
    // False when the point is behind the camera or projects outside the image.
    bool sampleWi(const Vec3& ref, Point2 uLens, CameraWiSample& out) const;
    // Raster position of a world point seen through the camera centre; false when outside or behind.
    bool rasterFromWorld(const Vec3& p, Point2& raster) const;
    float lensArea() const { return lensRadius_ > 0 ? kPi * lensRadius_ * lensRadius_ : 1.0f; }

private:
    bool rasterFromCameraDirection(const Vec3& dCam, Point2& raster) const;
    Vec3 toCamera(const Vec3& w) const { return {dot(w, right_), dot(w, up_), dot(w, forward_)}; }

    int width_, height_;
    Vec3 position_, right_, up_, forward_;
    float halfW_, halfH_;  // image plane half-extents at distance 1
    float imagePlaneArea_; // at distance 1
    float lensRadius_ = 0, focusDistance_ = 1;
};

} // namespace stipple::render
