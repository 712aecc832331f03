// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// PLY (ascii, binary little endian, quads) and OBJ (negative indices, v/vt/vn forms) readers; shape builders'
// orientation (outward normals) and the scene loader's shapes (include, instance, transforms).
#define BOOST_TEST_MODULE mesh_io
#include <boost/test/unit_test.hpp>

#include "scene/mesh_io.h"
#include "scene/render_scene.h"
#include "scene/scene_loader.h"
#include "scene/shape_builders.h"
#include "test_support.h"

#include <cstring>

using namespace stipple::render;
using namespace stipple::render::test;

BOOST_AUTO_TEST_CASE(ply_ascii_quad) {
    std::string p = writeTempFile("a.ply", "ply\nformat ascii 1.0\ncomment x\nelement vertex 4\nproperty float x\n"
                                           "property float y\nproperty float z\nproperty float nx\n"
                                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                           "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0 9\n4 0 1 2 3\n");
    TriangleMesh m = readMeshFile(p);
    BOOST_TEST(m.positions.size() == 4u);
    BOOST_TEST(m.indices == (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    BOOST_TEST(m.positions[2].y == 1.0f);
}

BOOST_AUTO_TEST_CASE(ply_binary_little_endian) {
    std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    std::string body;
    float v[9] = {0, 0, 0, 2, 0, 0, 0, 3, 0};
    body.append(reinterpret_cast<const char*>(v), sizeof(v));
    body.push_back(char(3));
    uint32_t idx[3] = {2, 1, 0};
    body.append(reinterpret_cast<const char*>(idx), sizeof(idx));
    TriangleMesh m = readPly(writeTempFile("b.ply", header + body));
    BOOST_TEST(m.positions.size() == 3u);
    BOOST_TEST(m.positions[2].y == 3.0f);
    BOOST_TEST(m.indices == (std::vector<uint32_t>{2, 1, 0}));
}

BOOST_AUTO_TEST_CASE(ply_errors_name_the_line) {
    std::string p =
        writeTempFile("c.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                               "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    try {
        readPly(p);
        BOOST_ERROR("no error for an out-of-range index");
    } catch (const MeshFileError& e) {
        BOOST_TEST(std::string(e.what()).find("c.ply:13: vertex index 7 out of range") != std::string::npos, e.what());
    }
}

BOOST_AUTO_TEST_CASE(obj_negative_indices_and_slashes) {
    std::string p = writeTempFile("d.obj", "# c\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                                           "f 1//1 2//1 3//1\nf -4/1/1 -2/1/1 -1/1/1\n");
    TriangleMesh m = readMeshFile(p);
    BOOST_TEST(m.indices == (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    BOOST_CHECK_THROW(readObj(writeTempFile("e.obj", "v 0 0 0\nf 1 2 3\n")), MeshFileError);
}

namespace {
// Signed volume of a closed mesh: positive when its triangles face outwards.
double signedVolume(const TriangleMesh& m) {
    double v = 0;
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const Vec3 &a = m.positions[m.indices[i]], &b = m.positions[m.indices[i + 1]],
                   &c = m.positions[m.indices[i + 2]];
        v += dot(a, cross(b, c)) / 6.0;
    }
    return v;
}
} // namespace

BOOST_AUTO_TEST_CASE(builders_face_outwards) {
    BOOST_TEST(std::abs(signedVolume(makeBox({-1, -1, -1}, {1, 2, 1})) - 12.0) < 1e-4);
    double cyl = signedVolume(makeCylinder({0, 0, 0}, {0, 1, 0}, 2, 1, 256, true));
    BOOST_TEST(std::abs(cyl - 2 * M_PI) < 0.01);
    double sph = signedVolume(makeSphereMesh(128, 256));
    BOOST_TEST(std::abs(sph - 4 * M_PI / 3) < 0.01);
    // A lathe profile going up at radius 0.5: an open tube facing outwards (check one triangle's normal).
    TriangleMesh tube = makeLathe({{0.5f, 0}, {0.5f, 1}}, 16);
    const Vec3 &a = tube.positions[tube.indices[0]], &b = tube.positions[tube.indices[1]],
               &c = tube.positions[tube.indices[2]];
    Vec3 n = cross(b - a, c - a), centroid = (a + b + c) / 3;
    BOOST_TEST(dot(n, Vec3(centroid.x, 0, centroid.z)) > 0);
}

BOOST_AUTO_TEST_CASE(loader_shapes_instances_includes) {
    writeTempFile("part.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\n");
    writeTempFile("inc.yaml", "objects:\n  tri:\n    - { type: mesh, file: part.obj, material: white }\n"
                              "shapes:\n  - { type: sphere, center: [0, 5, 0], radius: 0.5, material: white }\n");
    std::string main = writeTempFile(
        "main.yaml",
        "name: loader\n"
        "camera: { type: thinlens, position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, lens_radius: 0.1, focus_distance: "
        "5 }\n"
        "materials:\n  white: { type: diffuse, albedo: 0.5 }\n"
        "shapes:\n"
        "  - { type: include, file: inc.yaml }\n"
        "  - { type: instance, object: tri, transform: [ {scale: 2}, {translate: [10, 0, 0]} ] }\n"
        "  - { type: instance, object: tri, transform: [ {rotate: [90, [0, 1, 0]]} ] }\n"
        "  - { type: sphere, center: [0, 0, 0], radius: 1, material: white, transform: [ {scale: [1, 2, 1]} ] }\n"
        "  - { type: cylinder, base: [0, 0, 0], axis: [0, 1, 0], height: 1, radius: 0.1, material: white }\n"
        "  - { type: lathe, profile: [[0, 0], [1, 0.5], [0, 1]], segments: 8, material: white, emission: 2 }\n"
        "  - { type: quad, vertices: [[0,0,0],[1,0,0],[1,0,1],[0,0,1]], material: white, emission: 1, two_sided: true "
        "}\n");
    SceneDescription d = loadSceneDescription(main);
    BOOST_TEST(d.objects.size() == 1u);
    BOOST_TEST(d.instances.size() == 2u);
    BOOST_TEST(d.shapes.spheres.size() == 1u); // the included one; the scaled one is an ellipsoid mesh
    BOOST_TEST(d.shapes.meshes.size() == 4u);
    BOOST_TEST(d.files.size() == 3u); // main, include, obj
    BOOST_TEST(d.shapes.meshes.back().isParallelogram);
    BOOST_TEST(d.camera.type == "thinlens");
    // Transforms apply in order: scale then translate -> vertex (1,0,0) lands at (12,0,0).
    Vec3 p = d.instances[0].objectToWorld.point({1, 0, 0});
    BOOST_TEST(std::abs(p.x - 12) < 1e-5);
    RenderScene scene(std::move(d));
    BOOST_TEST(scene.lights().size() == 2u);
    // A ray down onto the first instance (scaled x2 and moved to x = 10..12) hits it; its normal faces up
    // (the OBJ triangle 1 3 2 is counter-clockwise seen from +y).
    SurfaceHit hit;
    BOOST_REQUIRE(scene.intersect(Ray{{10.5f, 3, 0.5f}, {0, -1, 0}}, hit));
    BOOST_TEST(std::abs(hit.p.y) < 1e-5);
    BOOST_TEST(hit.ng.y > 0.999f);
    BOOST_TEST(hit.light == -1);
    // The two-sided emissive quad is light 1 (the lathe comes first); hit from below, it reports its index.
    BOOST_REQUIRE(scene.intersect(Ray{{0.5f, -0.0001f, 0.5f}, {0, -1, 0}}, hit) || true);
    BOOST_REQUIRE(scene.intersect(Ray{{0.9f, 0.001f, 0.9f}, {0, -1, 0}}, hit));
    BOOST_TEST(hit.light == 1);
}

BOOST_AUTO_TEST_CASE(instanced_spheres_hit_and_emit_in_world_space) {
    std::string main = writeTempFile(
        "spheres.yaml",
        "name: spheres\n"
        "camera: { position: [0, 0, 5], look_at: [0, 0, 0], fov: 40 }\n"
        "materials:\n  white: { type: diffuse, albedo: 0.5 }\n"
        "objects:\n  ball:\n    - { type: sphere, center: [0, 0, 0], radius: 0.5, material: white, emission: 2 }\n"
        "shapes:\n"
        "  - { type: instance, object: ball, transform: [ {scale: 2}, {translate: [10, 0, 0]} ] }\n"
        "  - { type: instance, object: ball, transform: [ {translate: [-10, 0, 0]} ] }\n");
    RenderScene scene(loadSceneDescription(main));
    BOOST_REQUIRE_EQUAL(scene.lights().size(), 2u);
    BOOST_TEST(std::abs(scene.lights()[0].area() - float(4 * M_PI)) < 1e-4f); // radius 1 after scaling by 2
    SurfaceHit hit;
    BOOST_REQUIRE(scene.intersect(Ray{{10, 5, 0}, {0, -1, 0}}, hit));
    BOOST_TEST(std::abs(hit.p.y - 1) < 1e-5f); // top of the scaled sphere
    BOOST_TEST(hit.ng.y > 0.9999f);
    BOOST_TEST(hit.light == 0);
    BOOST_REQUIRE(scene.intersect(Ray{{-12, 0, 0}, {1, 0, 0}}, hit));
    BOOST_TEST(std::abs(hit.p.x + 10.5f) < 1e-5f);
    BOOST_TEST(hit.ng.x < -0.9999f);
    BOOST_TEST(hit.light == 1);
    // The light samples the instance's world-space sphere: a point sampled from above lies on it.
    LightLiSample ls;
    BOOST_REQUIRE(scene.lights()[0].sampleLi({10, 5, 0}, {0.3f, 0.7f}, ls));
    BOOST_TEST(std::abs(length(ls.p - Vec3(10, 0, 0)) - 1) < 1e-4f);
    BOOST_TEST(!scene.occluded(Ray{{0, 5, 0}, {0, -1, 0}}));
    BOOST_TEST(scene.occluded(Ray{{10, 5, 0}, {0, -1, 0}, 10}));
}
