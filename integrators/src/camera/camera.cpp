// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "camera/camera.h"

namespace stipple::render {

Camera::Camera(const CameraDesc& d, int width, int height) : width_(width), height_(height) {
    position_ = d.position;
    forward_ = normalize(d.lookAt - d.position);
    right_ = normalize(cross(forward_, d.up));
    up_ = cross(right_, forward_);
    float t = std::tan(d.fovDegrees * kPi / 360.0f);
    if (width >= height) {
        halfH_ = t;
        halfW_ = t * float(width) / float(height);
    } else {
        halfW_ = t;
        halfH_ = t * float(height) / float(width);
    }
    imagePlaneArea_ = 4 * halfW_ * halfH_;
    if (d.type == "thinlens") {
        lensRadius_ = d.lensRadius;
        focusDistance_ = d.focusDistance;
    }
}

Ray Camera::generateRay(Point2 p, Point2 uLens) const {
    float sx = (2 * p.x / float(width_) - 1) * halfW_;
    float sy = (1 - 2 * p.y / float(height_)) * halfH_;
    Vec3 dir = right_ * sx + up_ * sy + forward_;
    Ray ray;
    if (lensRadius_ > 0) {
        Point2 l = sampleUniformDiskConcentric(uLens);
        Vec3 offset = right_ * (l.x * lensRadius_) + up_ * (l.y * lensRadius_);
        Vec3 focus = position_ + dir * focusDistance_;
        ray.o = position_ + offset;
        ray.d = normalize(focus - ray.o);
    } else {
        ray.o = position_;
        ray.d = normalize(dir);
    }
    return ray;
}

bool Camera::rasterFromCameraDirection(const Vec3& c, Point2& raster) const {
    if (c.z <= 0) return false;
    float sx = c.x / c.z, sy = c.y / c.z;
    raster.x = (sx / halfW_ + 1) * 0.5f * float(width_);
    raster.y = (1 - sy / halfH_) * 0.5f * float(height_);
    return raster.x >= 0 && raster.x < float(width_) && raster.y >= 0 && raster.y < float(height_);
}

bool Camera::rasterFromWorld(const Vec3& p, Point2& raster) const {
    return rasterFromCameraDirection(toCamera(p - position_), raster);
}

Spectrum Camera::We(const Ray& ray, Point2* raster) const {
    float cosTheta = dot(ray.d, forward_);
    if (cosTheta <= 0) return {};
    // The point the ray passes on the plane of focus (distance 1 for the pinhole), seen from the centre.
    float focus = lensRadius_ > 0 ? focusDistance_ : 1.0f;
    Vec3 pFocus = ray.o + ray.d * (focus / cosTheta);
    Point2 r;
    if (!rasterFromCameraDirection(toCamera(pFocus - position_), r)) return {};
    if (raster) *raster = r;
    float cos2 = cosTheta * cosTheta;
    return Spectrum(1 / (imagePlaneArea_ * lensArea() * cos2 * cos2));
}

void Camera::pdfWe(const Ray& ray, float& pdfPos, float& pdfDir) const {
    pdfPos = pdfDir = 0;
    float cosTheta = dot(ray.d, forward_);
    if (cosTheta <= 0) return;
    float focus = lensRadius_ > 0 ? focusDistance_ : 1.0f;
    Vec3 pFocus = ray.o + ray.d * (focus / cosTheta);
    Point2 r;
    if (!rasterFromCameraDirection(toCamera(pFocus - position_), r)) return;
    pdfPos = 1 / lensArea();
    pdfDir = 1 / (imagePlaneArea_ * cosTheta * cosTheta * cosTheta);
}

bool Camera::sampleWi(const Vec3& ref, Point2 uLens, CameraWiSample& out) const {
    Vec3 pLens = position_;
    if (lensRadius_ > 0) {
        Point2 l = sampleUniformDiskConcentric(uLens);
        pLens = position_ + right_ * (l.x * lensRadius_) + up_ * (l.y * lensRadius_);
    }
    Vec3 d = pLens - ref;
    float dist2 = lengthSquared(d);
    if (dist2 == 0) return false;
    float dist = std::sqrt(dist2);
    out.wi = d / dist;
    out.distance = dist;
    out.pLens = pLens;
    out.nLens = forward_;
    float cosLens = absDot(forward_, out.wi);
    if (cosLens == 0) return false;
    // Area density 1/lensArea on the lens converted to solid angle at ref.
    out.pdf = dist2 / (cosLens * lensArea());
    Ray r{pLens, -out.wi};
    out.We = We(r, &out.raster);
    return !out.We.isBlack();
}

} // namespace stipple::render
