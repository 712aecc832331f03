// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "scene/scene_loader.h"

#include "scene/scene_extent.h"
#include "scene/shape_builders.h"
#include <stipple/render/input_limits.h>
#include <stipple/render/scene_error.h>

#include <stipple/yaml/strict_yaml.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace stipple::render {

namespace {

namespace fs = std::filesystem;

class Loader {
public:
    explicit Loader(SceneDescription& desc) : desc_(desc) {}

    void loadMain(const std::string& path);

private:
    // ---- error helpers ---------------------------------------------------------------------------------------
    std::string where(const yaml::Node& n) const { return yaml::StrictYaml(file_).where(n); }
    static std::string show(const yaml::Node& n) {
        if (!n || n.IsNull()) return "nothing";
        if (n.IsScalar()) return "'" + n.Scalar() + "'";
        if (n.IsSequence()) return "a list";
        if (n.IsMap()) return "a map";
        return "?";
    }
    [[noreturn]] void fail(const yaml::Node& n, const std::string& key, const std::string& expected) const {
        throw SceneError(where(n) + ": key '" + key + "': expected " + expected + ", got " + show(n));
    }
    [[noreturn]] void failMsg(const yaml::Node& n, const std::string& key, const std::string& msg) const {
        throw SceneError(where(n) + ": key '" + key + "': " + msg);
    }
    void checkKeys(const yaml::Node& map, const std::string& ctx, const std::vector<std::string>& allowed) const {
        try {
            yaml::StrictYaml(file_).onlyKeys(map, allowed, ctx);
        } catch (const yaml::Error& e) {
            throw SceneError(e.what());
        }
    }
    yaml::Node require(const yaml::Node& map, const std::string& key, const std::string& ctx) const {
        yaml::Node n = map[key];
        if (!n) throw SceneError(where(map) + ": key '" + key + "': required in " + ctx + " but missing");
        return n;
    }

    // ---- typed readers ---------------------------------------------------------------------------------------
    double number(const yaml::Node& n, const std::string& key) const {
        if (!n.IsScalar()) fail(n, key, "a number");
        double v = 0;
        switch (yaml::StrictYaml::parseNumber(n, v)) {
        case yaml::StrictYaml::Number::Ok: return v;
        case yaml::StrictYaml::Number::NotFinite: fail(n, key, "a finite number");
        case yaml::StrictYaml::Number::NotANumber: break;
        }
        fail(n, key, "a number");
    }
    float numberIn(const yaml::Node& n, const std::string& key, double lo, double hi, const std::string& range) const {
        double v = number(n, key);
        if (v < lo || v > hi) fail(n, key, "a number " + range);
        return float(v);
    }
    long long integer(const yaml::Node& n, const std::string& key, long long lo, long long hi) const {
        long long v = 0;
        if (!yaml::StrictYaml::parseInteger(n, v)) fail(n, key, "an integer");
        if (v < lo || v > hi) fail(n, key, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return v;
    }
    bool boolean(const yaml::Node& n, const std::string& key) const {
        if (n.IsScalar()) {
            const std::string& s = n.Scalar();
            if (s == "true" || s == "yes" || s == "on") return true;
            if (s == "false" || s == "no" || s == "off") return false;
        }
        fail(n, key, "true or false");
    }
    std::string string(const yaml::Node& n, const std::string& key) const {
        if (!n.IsScalar() || n.Scalar().empty()) fail(n, key, "a non-empty string");
        return n.Scalar();
    }
    std::string oneOf(const yaml::Node& n, const std::string& key, const std::vector<std::string>& options) const {
        std::string s = n.IsScalar() ? n.Scalar() : "";
        for (const auto& o : options)
            if (s == o) return s;
        std::string list;
        for (size_t i = 0; i < options.size(); ++i)
            list += (i ? (i + 1 == options.size() ? " or " : ", ") : "") + options[i];
        fail(n, key, list);
    }
    Vec3 vec3(const yaml::Node& n, const std::string& key) const {
        if (!n.IsSequence() || n.size() != 3) fail(n, key, "a list of 3 numbers [x, y, z]");
        return Vec3(float(number(n[0], key)), float(number(n[1], key)), float(number(n[2], key)));
    }
    // A colour: [r, g, b] or one number for grey; each component in [lo, hi].
    Spectrum spectrum(const yaml::Node& n, const std::string& key, double lo, double hi) const {
        std::string range = hi < 1e30 ? "in [" + fmt(lo) + ", " + fmt(hi) + "]" : ">= " + fmt(lo);
        if (n.IsScalar()) {
            float v = numberIn(n, key, lo, hi, range);
            return Spectrum(v);
        }
        if (!n.IsSequence() || n.size() != 3) fail(n, key, "an RGB list [r, g, b] or one number");
        Spectrum s;
        for (int i = 0; i < 3; ++i) s[i] = numberIn(n[i], key, lo, hi, range);
        return s;
    }
    static std::string fmt(double v) {
        std::ostringstream o;
        o << v;
        return o.str();
    }

    // ---- sections --------------------------------------------------------------------------------------------
    void parseRender(const yaml::Node& n);
    void parseCamera(const yaml::Node& n);
    void parseMaterials(const yaml::Node& n);
    void parseObjects(const yaml::Node& n);
    void parseShapeList(const yaml::Node& list, ShapeGroup& group, bool inObject, const std::string& listKey);
    void parseShape(const yaml::Node& n, ShapeGroup& group, bool inObject);
    void allowShapeKeys(const yaml::Node& n, const std::string& ctx, std::initializer_list<const char*> keys) const;
    void parseInstance(const yaml::Node& n, const std::string& ctx, const std::string& origin);
    TriangleMesh parseMeshGeometry(const yaml::Node& n, const std::string& type, const std::string& ctx,
                                   bool& parallelogramCandidate);
    void addMesh(TriangleMesh tm, const Transform& xf, int material, const Emission& emission,
                 const std::string& origin, bool parallelogramCandidate, ShapeGroup& group);
    Transform parseTransform(const yaml::Node& n) const;
    void include(const yaml::Node& n);
    std::string resolve(const std::string& rel) const {
        fs::path p(rel);
        if (p.is_relative()) p = fs::path(file_).parent_path() / p;
        return p.lexically_normal().string();
    }
    yaml::Node loadYaml(const std::string& path, const yaml::Node* from, const std::string& key);

    SceneDescription& desc_;
    std::string file_;               // the file being parsed (for messages)
    std::vector<std::string> stack_; // include chain, to reject cycles
    std::map<std::string, int> materialIndex_;
    std::map<std::string, int> objectIndex_;
};

yaml::Node Loader::loadYaml(const std::string& path, const yaml::Node* from, const std::string& key) {
    std::string text;
    try {
        text = readFileBounded(path, limits::kMaxYamlFileBytes, "scene file");
    } catch (const InputLimitError& e) {
        if (from) failMsg(*from, key, e.what());
        throw SceneError(e.what());
    }
    try {
        yaml::Node root = yaml::StrictYaml(path).parse(text);
        desc_.files.push_back(path);
        return root;
    } catch (const yaml::Error& e) {
        throw SceneError(e.what());
    }
}

void Loader::loadMain(const std::string& path) {
    file_ = path;
    desc_.path = path;
    yaml::Node root = loadYaml(path, nullptr, "");
    stack_.push_back(fs::absolute(path).lexically_normal().string());
    if (!root.IsMap())
        throw SceneError(where(root) +
                         ": expected a map with keys name, render, camera, materials, "
                         "objects, shapes; got " +
                         show(root));
    checkKeys(root, "the scene file", {"name", "render", "camera", "materials", "objects", "shapes"});
    desc_.name = string(require(root, "name", "the scene file"), "name");
    if (root["render"]) parseRender(root["render"]);
    parseCamera(require(root, "camera", "the scene file"));
    if (root["materials"]) parseMaterials(root["materials"]);
    if (root["objects"]) parseObjects(root["objects"]);
    if (root["shapes"]) parseShapeList(root["shapes"], desc_.shapes, false, "shapes");
    if (desc_.shapes.meshes.empty() && desc_.shapes.spheres.empty() && desc_.instances.empty())
        throw SceneError(where(root) + ": key 'shapes': expected at least one shape, got none");
    checkSceneExtent(desc_);
}

void Loader::parseRender(const yaml::Node& n) {
    if (!n.IsMap()) fail(n, "render", "a map");
    checkKeys(n, "render", {"integrator", "max_depth", "width", "height", "spp", "light_samples", "light_selection"});
    RenderSettings& s = desc_.settings;
    if (n["integrator"]) s.integrator = oneOf(n["integrator"], "integrator", {"path", "direct", "bdpt"});
    if (n["max_depth"]) s.maxDepth = int(integer(n["max_depth"], "max_depth", 0, 1000));
    if (n["width"]) s.width = int(integer(n["width"], "width", 1, 1 << 15));
    if (n["height"]) s.height = int(integer(n["height"], "height", 1, 1 << 15));
    if (n["spp"]) s.spp = uint32_t(integer(n["spp"], "spp", 1, 1 << 20));
    if (n["light_samples"]) s.lightSamples = uint32_t(integer(n["light_samples"], "light_samples", 1, 1024));
    try {
        checkRenderBudget(s.width, s.height, s.spp);
    } catch (const std::invalid_argument& e) {
        failMsg(n, "render", e.what());
    }
    if (n["light_selection"])
        s.uniformLightSelection = oneOf(n["light_selection"], "light_selection", {"power", "uniform"}) == "uniform";
}

void Loader::parseCamera(const yaml::Node& n) {
    if (!n.IsMap()) fail(n, "camera", "a map");
    checkKeys(n, "camera", {"type", "position", "look_at", "up", "fov", "lens_radius", "focus_distance"});
    CameraDesc& c = desc_.camera;
    c.type = n["type"] ? oneOf(n["type"], "type", {"pinhole", "thinlens"}) : "pinhole";
    c.position = vec3(require(n, "position", "camera"), "position");
    c.lookAt = vec3(require(n, "look_at", "camera"), "look_at");
    if (n["up"]) c.up = vec3(n["up"], "up");
    for (const char* k : {"position", "look_at"})
        if (std::string bad = beyondCoordinateLimit(k[0] == 'p' ? c.position : c.lookAt); !bad.empty())
            failMsg(n[k], k, bad);
    c.fovDegrees = numberIn(require(n, "fov", "camera"), "fov", 1e-3, 179.0, "in (0, 179] degrees");
    if (lengthSquared(c.lookAt - c.position) == 0) fail(n["look_at"], "look_at", "a point different from position");
    if (lengthSquared(cross(c.lookAt - c.position, c.up)) == 0)
        fail(n["up"] ? n["up"] : n, "up", "a direction not parallel to the view direction");
    if (c.type == "thinlens") {
        // Below the coordinate limit, as every length the ray tracer sees (|x| < kMaxCoordinate).
        c.lensRadius = numberIn(require(n, "lens_radius", "a thinlens camera"), "lens_radius", 0,
                                std::nextafter(double(float(limits::kMaxCoordinate)), 0.0),
                                "in [0, " + fmt(limits::kMaxCoordinate) + ")");
        c.focusDistance =
            numberIn(require(n, "focus_distance", "a thinlens camera"), "focus_distance", 1e-6, 1e30, "> 0");
    } else {
        for (const char* k : {"lens_radius", "focus_distance"})
            if (n[k]) failMsg(n[k], k, "only valid for a camera of type thinlens (this one is pinhole)");
    }
}

void Loader::parseMaterials(const yaml::Node& n) {
    if (!n.IsMap()) fail(n, "materials", "a map of name -> material");
    for (auto it = n.begin(); it != n.end(); ++it) {
        std::string name = it->first.Scalar();
        const yaml::Node m = it->second;
        if (!m.IsMap()) fail(m, name, "a material map with a 'type'");
        std::string type = oneOf(require(m, "type", "material '" + name + "'"), "type",
                                 {"diffuse", "plastic", "conductor", "mirror", "dielectric"});
        Material mat;
        std::string ctx = "material '" + name + "' (" + type + ")";
        auto roughness = [&] {
            return numberIn(require(m, "roughness", ctx), "roughness", 0.001, 1.0,
                            "in [0.001, 1] (GGX alpha; smaller is not supported)");
        };
        if (type == "diffuse") {
            checkKeys(m, ctx, {"type", "albedo"});
            mat.type = MaterialType::Diffuse;
            mat.albedo = spectrum(require(m, "albedo", ctx), "albedo", 0, 1);
        } else if (type == "plastic") {
            checkKeys(m, ctx, {"type", "roughness", "diffuse", "ior"});
            mat.type = MaterialType::Plastic;
            mat.roughness = roughness();
            mat.albedo = spectrum(require(m, "diffuse", ctx), "diffuse", 0, 1);
            mat.ior = m["ior"] ? numberIn(m["ior"], "ior", 1.0001, 10, "in (1, 10]") : 1.5f;
        } else if (type == "conductor") {
            checkKeys(m, ctx, {"type", "roughness", "eta", "k"});
            mat.type = MaterialType::Conductor;
            mat.roughness = roughness();
            mat.eta = spectrum(require(m, "eta", ctx), "eta", 1e-4, 1e30);
            mat.k = spectrum(require(m, "k", ctx), "k", 0, 1e30);
        } else if (type == "mirror") {
            checkKeys(m, ctx, {"type", "reflectance"});
            mat.type = MaterialType::Mirror;
            mat.albedo = m["reflectance"] ? spectrum(m["reflectance"], "reflectance", 0, 1) : Spectrum(1);
        } else {
            checkKeys(m, ctx, {"type", "ior"});
            mat.type = MaterialType::Dielectric;
            mat.ior = numberIn(require(m, "ior", ctx), "ior", 1.0001, 10, "in (1, 10]");
        }
        if (materialIndex_.count(name)) failMsg(it->first, name, "material defined twice");
        materialIndex_[name] = int(desc_.materials.size());
        desc_.materials.push_back(mat);
        desc_.materialNames.push_back(name);
    }
}

void Loader::parseObjects(const yaml::Node& n) {
    if (!n.IsMap()) fail(n, "objects", "a map of name -> list of shapes");
    for (auto it = n.begin(); it != n.end(); ++it) {
        std::string name = it->first.Scalar();
        if (objectIndex_.count(name)) failMsg(it->first, name, "object defined twice");
        ShapeGroup group;
        parseShapeList(it->second, group, true, name);
        objectIndex_[name] = int(desc_.objects.size());
        desc_.objects.push_back(std::move(group));
        desc_.objectNames.push_back(name);
    }
}

void Loader::parseShapeList(const yaml::Node& list, ShapeGroup& group, bool inObject, const std::string& listKey) {
    if (!list.IsSequence()) fail(list, listKey, "a list of shapes");
    for (const yaml::Node& s : list) parseShape(s, group, inObject);
}

Transform Loader::parseTransform(const yaml::Node& n) const {
    if (!n.IsSequence()) fail(n, "transform", "a list of {translate|rotate|scale|matrix: ...} steps");
    Transform xf;
    for (const yaml::Node& step : n) {
        if (!step.IsMap() || step.size() != 1)
            fail(step, "transform",
                 "one of {translate: [x,y,z]}, "
                 "{rotate: [degrees, [axis]]}, {scale: s|[x,y,z]}, {matrix: [16 numbers]}");
        std::string op = step.begin()->first.Scalar();
        const yaml::Node v = step.begin()->second;
        Transform t;
        if (op == "translate") {
            t = Transform::translate(vec3(v, "translate"));
        } else if (op == "rotate") {
            if (!v.IsSequence() || v.size() != 2) fail(v, "rotate", "[degrees, [x, y, z]]");
            Vec3 axis = vec3(v[1], "rotate");
            if (lengthSquared(axis) == 0) fail(v[1], "rotate", "a non-zero axis");
            t = Transform::rotate(float(number(v[0], "rotate")), axis);
        } else if (op == "scale") {
            Vec3 s = v.IsScalar() ? Vec3(1, 1, 1) * float(number(v, "scale")) : vec3(v, "scale");
            if (s.x == 0 || s.y == 0 || s.z == 0) fail(v, "scale", "non-zero scale factors");
            t = Transform::scale(s);
        } else if (op == "matrix") {
            if (!v.IsSequence() || v.size() != 16) fail(v, "matrix", "16 numbers, row-major");
            float m[16];
            for (int i = 0; i < 16; ++i) m[i] = float(number(v[i], "matrix"));
            if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
                fail(v, "matrix", "an affine matrix (last row 0 0 0 1)");
            t = Transform::fromRows(m);
            if (t.determinant() == 0) fail(v, "matrix", "an invertible matrix");
        } else {
            throw SceneError(where(step.begin()->first) + ": key '" + op +
                             "': unknown transform step; expected translate, rotate, scale or matrix");
        }
        xf = t * xf; // applied in order: later steps act on the result of earlier ones
    }
    return xf;
}

void Loader::include(const yaml::Node& n) {
    checkKeys(n, "an include", {"type", "file"});
    std::string rel = string(require(n, "file", "an include"), "file");
    std::string path = resolve(rel);
    std::string canonical = fs::absolute(path).lexically_normal().string();
    for (const auto& s : stack_)
        if (s == canonical) failMsg(n["file"], "file", "includes itself (cycle through '" + path + "')");
    // Each level recurses through parseShapeList: a chain thousands deep would overflow the stack.
    if (stack_.size() >= size_t(limits::kMaxIncludeDepth))
        failMsg(n["file"], "file",
                "includes nested deeper than the limit of " + std::to_string(limits::kMaxIncludeDepth) + " files");
    yaml::Node fileNode = n["file"];
    yaml::Node root = loadYaml(path, &fileNode, "file");
    std::string saved = file_;
    file_ = path;
    stack_.push_back(canonical);
    // Any readable file can be named here: what is not a scene fragment is refused without quoting its text.
    const std::string notFragment = ": an included file must be a map with only objects: and shapes: (this file is "
                                    "not a scene fragment)";
    if (!root.IsMap()) throw SceneError(where(root) + notFragment);
    for (const auto& kv : root)
        if (!kv.first.IsScalar() || (kv.first.ScalarView() != "objects" && kv.first.ScalarView() != "shapes"))
            throw SceneError(where(kv.first) + notFragment);
    if (root["objects"]) parseObjects(root["objects"]);
    if (root["shapes"]) parseShapeList(root["shapes"], desc_.shapes, false, "shapes");
    stack_.pop_back();
    file_ = saved;
}

void Loader::parseShape(const yaml::Node& n, ShapeGroup& group, bool inObject) {
    if (!n.IsMap()) fail(n, "shapes", "a shape map with a 'type'");
    std::string type = oneOf(require(n, "type", "a shape"), "type",
                             {"quad", "mesh", "box", "sphere", "cylinder", "lathe", "instance", "include"});
    std::string ctx = "a " + type + " shape";
    std::string origin = where(n);
    if (type == "include") {
        if (inObject) failMsg(n["type"], "type", "include may appear only in the top-level shapes list");
        include(n);
        return;
    }
    if (type == "instance") {
        if (inObject) failMsg(n["type"], "type", "instances cannot be nested inside objects (one instance level)");
        parseInstance(n, ctx, origin);
        return;
    }

    std::string matName = string(require(n, "material", ctx), "material");
    auto mit = materialIndex_.find(matName);
    if (mit == materialIndex_.end()) failMsg(n["material"], "material", "no material named '" + matName + "'");
    Emission emission;
    if (n["emission"]) emission.radiance = spectrum(n["emission"], "emission", 0, 1e30);
    if (n["two_sided"]) {
        emission.twoSided = boolean(n["two_sided"], "two_sided");
        if (!n["emission"]) failMsg(n["two_sided"], "two_sided", "only meaningful with 'emission'");
    }
    Transform xf = n["transform"] ? parseTransform(n["transform"]) : Transform();
    if (xf.determinant() == 0) fail(n["transform"], "transform", "an invertible transform");

    TriangleMesh tm;
    bool parallelogramCandidate = false;
    if (type == "sphere") {
        allowShapeKeys(n, ctx, {"center", "radius"});
        Vec3 c = vec3(require(n, "center", ctx), "center");
        float r = numberIn(require(n, "radius", ctx), "radius", 1e-30, 1e30, "> 0");
        float scale = 1;
        if (xf.isSimilarity(scale)) {
            SphereShape s{xf.point(c), r * scale, mit->second, emission, origin};
            group.spheres.push_back(s);
            return;
        }
        // An ellipsoid: tessellate the unit sphere, then scale, place and transform it.
        tm = makeSphereMesh(48, 96);
        for (Vec3& p : tm.positions) p = c + p * r;
    } else {
        tm = parseMeshGeometry(n, type, ctx, parallelogramCandidate);
    }
    addMesh(std::move(tm), xf, mit->second, emission, origin, parallelogramCandidate, group);
}

void Loader::allowShapeKeys(const yaml::Node& n, const std::string& ctx,
                            std::initializer_list<const char*> keys) const {
    std::vector<std::string> allowed{"type", "material", "emission", "two_sided", "transform"};
    allowed.insert(allowed.end(), keys.begin(), keys.end());
    checkKeys(n, ctx, allowed);
}

void Loader::parseInstance(const yaml::Node& n, const std::string& ctx, const std::string& origin) {
    checkKeys(n, ctx, {"type", "object", "transform"});
    std::string obj = string(require(n, "object", ctx), "object");
    auto it = objectIndex_.find(obj);
    if (it == objectIndex_.end()) failMsg(n["object"], "object", "no object named '" + obj + "' is defined above");
    InstanceShape inst;
    inst.object = it->second;
    inst.objectToWorld = n["transform"] ? parseTransform(n["transform"]) : Transform();
    inst.origin = origin;
    desc_.instances.push_back(inst);
}

// The triangles of a quad, mesh, box, cylinder or lathe, in object space.
TriangleMesh Loader::parseMeshGeometry(const yaml::Node& n, const std::string& type, const std::string& ctx,
                                       bool& parallelogramCandidate) {
    TriangleMesh tm;
    if (type == "quad") {
        allowShapeKeys(n, ctx, {"vertices"});
        yaml::Node v = require(n, "vertices", ctx);
        if (!v.IsSequence() || v.size() != 4) fail(v, "vertices", "a list of 4 points");
        Vec3 p[4];
        for (int i = 0; i < 4; ++i) p[i] = vec3(v[i], "vertices");
        tm = makeQuad(p);
        if (lengthSquared(cross(p[1] - p[0], p[2] - p[0])) == 0) fail(v, "vertices", "a non-degenerate quad");
        parallelogramCandidate = true;
    } else if (type == "mesh") {
        allowShapeKeys(n, ctx, {"vertices", "indices", "file"});
        if (n["file"]) {
            if (n["vertices"] || n["indices"])
                failMsg(n["file"], "file", "give either file or vertices+indices, not both");
            std::string path = resolve(string(n["file"], "file"));
            try {
                tm = readMeshFile(path);
            } catch (const MeshFileError& e) {
                failMsg(n["file"], "file", std::string("cannot read mesh: ") + e.what());
            } catch (const InputLimitError& e) {
                failMsg(n["file"], "file", std::string("cannot read mesh: ") + e.what());
            } catch (const std::bad_alloc&) {
                failMsg(n["file"], "file", "cannot read mesh '" + path + "': out of memory");
            }
            desc_.files.push_back(path);
        } else {
            yaml::Node v = require(n, "vertices", ctx), idx = require(n, "indices", ctx);
            if (!v.IsSequence() || v.size() < 3) fail(v, "vertices", "a list of at least 3 points");
            for (const yaml::Node& p : v) tm.positions.push_back(vec3(p, "vertices"));
            if (!idx.IsSequence() || idx.size() == 0 || idx.size() % 3 != 0)
                fail(idx, "indices", "a flat list of vertex indices, 3 per triangle");
            for (const yaml::Node& i : idx)
                tm.indices.push_back(uint32_t(integer(i, "indices", 0, (long long)tm.positions.size() - 1)));
        }
    } else if (type == "box") {
        allowShapeKeys(n, ctx, {"min", "max"});
        Vec3 lo = vec3(require(n, "min", ctx), "min"), hi = vec3(require(n, "max", ctx), "max");
        if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) fail(n["max"], "max", "max > min on every axis");
        tm = makeBox(lo, hi);
    } else if (type == "cylinder") {
        allowShapeKeys(n, ctx, {"base", "axis", "height", "radius", "segments", "caps"});
        Vec3 base = vec3(require(n, "base", ctx), "base");
        Vec3 axis = n["axis"] ? vec3(n["axis"], "axis") : Vec3(0, 1, 0);
        if (lengthSquared(axis) == 0) fail(n["axis"], "axis", "a non-zero direction");
        float h = numberIn(require(n, "height", ctx), "height", 1e-30, 1e30, "> 0");
        float r = numberIn(require(n, "radius", ctx), "radius", 1e-30, 1e30, "> 0");
        int seg = n["segments"] ? int(integer(n["segments"], "segments", 3, 65536)) : 32;
        bool caps = n["caps"] ? boolean(n["caps"], "caps") : true;
        tm = makeCylinder(base, axis, h, r, seg, caps);
    } else if (type == "lathe") {
        allowShapeKeys(n, ctx, {"profile", "segments"});
        yaml::Node prof = require(n, "profile", ctx);
        if (!prof.IsSequence() || prof.size() < 2) fail(prof, "profile", "a list of at least 2 [radius, height] pairs");
        std::vector<std::pair<float, float>> pts;
        for (const yaml::Node& p : prof) {
            if (!p.IsSequence() || p.size() != 2) fail(p, "profile", "a [radius, height] pair");
            pts.push_back({numberIn(p[0], "profile", 0, 1e30, "(radius) >= 0"), float(number(p[1], "profile"))});
        }
        int seg = n["segments"] ? int(integer(n["segments"], "segments", 3, 65536)) : 64;
        if (uint64_t(pts.size()) * uint64_t(seg) * 2 > limits::kMaxTrianglesPerShape)
            failMsg(n["segments"] ? n["segments"] : prof, "segments",
                    std::to_string(pts.size()) + " profile points x " + std::to_string(seg) +
                        " segments exceed the limit of " + std::to_string(limits::kMaxTrianglesPerShape) +
                        " triangles per shape");
        tm = makeLathe(pts, seg);
        if (tm.indices.empty()) fail(prof, "profile", "a profile that sweeps a surface (some radius > 0)");
    }
    return tm;
}

// Places the mesh in the world and adds it to the group.
void Loader::addMesh(TriangleMesh tm, const Transform& xf, int material, const Emission& emission,
                     const std::string& origin, bool parallelogramCandidate, ShapeGroup& group) {
    if (!xf.isIdentity())
        for (Vec3& p : tm.positions) p = xf.point(p);
    if (xf.determinant() < 0) // a mirroring transform flips winding: restore the front side
        for (size_t i = 0; i + 2 < tm.indices.size(); i += 3) std::swap(tm.indices[i + 1], tm.indices[i + 2]);
    MeshShape mesh;
    mesh.positions = std::move(tm.positions);
    mesh.indices = std::move(tm.indices);
    mesh.material = material;
    mesh.emission = emission;
    mesh.origin = origin;
    if (parallelogramCandidate) {
        const auto& p = mesh.positions;
        Vec3 d = (p[0] + p[2]) - (p[1] + p[3]);
        float size = std::max(length(p[1] - p[0]), length(p[3] - p[0]));
        mesh.isParallelogram = length(d) <= 1e-5f * size;
        if (xf.determinant() < 0) mesh.isParallelogram = false; // winding swapped: keep the generic path
    }
    group.meshes.push_back(std::move(mesh));
}

} // namespace

SceneDescription loadSceneDescription(const std::string& path) {
    SceneDescription desc;
    Loader loader(desc);
    loader.loadMain(path);
    return desc;
}

} // namespace stipple::render
