// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "scene/mesh_io.h"

#include <stipple/render/input_limits.h>

#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <iterator>
#include <string_view>
#include <fstream>
#include <sstream>

namespace stipple::render {

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Invalid };

PlyType plyType(const std::string& s) {
    if (s == "char" || s == "int8") return PlyType::Int8;
    if (s == "uchar" || s == "uint8") return PlyType::UInt8;
    if (s == "short" || s == "int16") return PlyType::Int16;
    if (s == "ushort" || s == "uint16") return PlyType::UInt16;
    if (s == "int" || s == "int32") return PlyType::Int32;
    if (s == "uint" || s == "uint32") return PlyType::UInt32;
    if (s == "float" || s == "float32") return PlyType::Float32;
    if (s == "double" || s == "float64") return PlyType::Float64;
    return PlyType::Invalid;
}

size_t plySize(PlyType t) {
    switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    default: return 0;
    }
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Invalid;
    bool isList = false;
    PlyType countType = PlyType::Invalid;
};

struct PlyElement {
    std::string name;
    size_t count = 0;
    std::vector<PlyProperty> props;
};

// Reads one value at `cur` (binary little endian: this code assumes a little-endian host, as every Debian
// amd64/arm64 is) and advances; false when the data ends.
bool readBinary(const char*& cur, const char* end, PlyType t, double& v) {
    size_t n = plySize(t);
    if (size_t(end - cur) < n) return false;
    unsigned char buf[8];
    std::memcpy(buf, cur, n);
    cur += n;
    switch (t) {
    case PlyType::Int8: {
        int8_t x;
        std::memcpy(&x, buf, 1);
        v = x;
        break;
    }
    case PlyType::UInt8: v = buf[0]; break;
    case PlyType::Int16: {
        int16_t x;
        std::memcpy(&x, buf, 2);
        v = x;
        break;
    }
    case PlyType::UInt16: {
        uint16_t x;
        std::memcpy(&x, buf, 2);
        v = x;
        break;
    }
    case PlyType::Int32: {
        int32_t x;
        std::memcpy(&x, buf, 4);
        v = x;
        break;
    }
    case PlyType::UInt32: {
        uint32_t x;
        std::memcpy(&x, buf, 4);
        v = x;
        break;
    }
    case PlyType::Float32: {
        float x;
        std::memcpy(&x, buf, 4);
        v = x;
        break;
    }
    case PlyType::Float64: {
        double x;
        std::memcpy(&x, buf, 8);
        v = x;
        break;
    }
    default: return false;
    }
    return true;
}

// Reads one ascii number at `cur` within a line ending at `end`.
bool readAscii(const char*& cur, const char* end, double& v) {
    while (cur < end && (*cur == ' ' || *cur == '\t' || *cur == '\r')) ++cur;
    if (cur >= end) return false;
    char* stop = nullptr;
    v = std::strtod(cur, &stop);
    if (stop == cur || stop > end) return false;
    cur = stop;
    return true;
}

// `where` is only called to build an error message.
template <typename Where>
void addPolygon(TriangleMesh& mesh, const std::vector<long long>& idx, size_t vertexCount, const Where& where) {
    if (idx.size() < 3)
        throw MeshFileError(where() + ": a face with " + std::to_string(idx.size()) + " vertices; expected at least 3");
    for (long long i : idx)
        if (i < 0 || size_t(i) >= vertexCount)
            throw MeshFileError(where() + ": vertex index " + std::to_string(i) + " out of range [0, " +
                                std::to_string(vertexCount) + ")");
    for (size_t k = 1; k + 1 < idx.size(); ++k) // fan: exact for triangles and convex quads
        mesh.indices.insert(mesh.indices.end(), {uint32_t(idx[0]), uint32_t(idx[k]), uint32_t(idx[k + 1])});
}

} // namespace

TriangleMesh readPly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MeshFileError(path + ": cannot open file");
    std::error_code sizeError;
    const uint64_t fileBytes = std::filesystem::file_size(path, sizeError);
    if (sizeError) throw MeshFileError(path + ": cannot read file size");
    std::string line;
    int lineNo = 0;
    auto where = [&] { return path + ":" + std::to_string(lineNo); };
    std::getline(in, line);
    ++lineNo;
    if (line.rfind("ply", 0) != 0) throw MeshFileError(where() + ": expected 'ply' as the first line");
    bool binary = false;
    std::vector<PlyElement> elements;
    for (;;) {
        if (!std::getline(in, line)) throw MeshFileError(where() + ": header ends before 'end_header'");
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ls(line);
        std::string word;
        ls >> word;
        if (word == "end_header") break;
        if (word == "comment" || word == "obj_info" || word.empty()) continue;
        if (word == "format") {
            std::string fmt;
            ls >> fmt;
            if (fmt == "ascii")
                binary = false;
            else if (fmt == "binary_little_endian")
                binary = true;
            else
                throw MeshFileError(where() + ": format '" + fmt + "'; expected ascii or binary_little_endian");
        } else if (word == "element") {
            PlyElement e;
            long long n = -1;
            ls >> e.name >> n;
            if (n < 0) throw MeshFileError(where() + ": element without a valid count");
            // Every element takes at least one byte of the file: a larger count is a lie that would allocate.
            if (uint64_t(n) > fileBytes)
                throw MeshFileError(where() + ": element count " + std::to_string(n) + " exceeds the file's " +
                                    std::to_string(fileBytes) + " bytes");
            e.count = size_t(n);
            elements.push_back(e);
        } else if (word == "property") {
            if (elements.empty()) throw MeshFileError(where() + ": property before any element");
            PlyProperty p;
            std::string t;
            ls >> t;
            if (t == "list") {
                std::string ct, it;
                ls >> ct >> it >> p.name;
                p.isList = true;
                p.countType = plyType(ct);
                p.type = plyType(it);
                if (p.countType == PlyType::Invalid || p.type == PlyType::Invalid)
                    throw MeshFileError(where() + ": unknown list types '" + ct + " " + it + "'");
            } else {
                p.type = plyType(t);
                ls >> p.name;
                if (p.type == PlyType::Invalid) throw MeshFileError(where() + ": unknown property type '" + t + "'");
            }
            elements.back().props.push_back(p);
        } else {
            throw MeshFileError(where() + ": unexpected header line '" + line + "'");
        }
    }

    // The body is read at once and parsed in memory (large binary PLY files load at disk speed).
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const char* cur = data.data();
    const char* const dataEnd = data.data() + data.size();
    TriangleMesh mesh;
    size_t vertexCount = 0;
    for (const PlyElement& e : elements)
        if (e.name == "vertex") vertexCount = e.count;
    for (const PlyElement& e : elements) {
        int ix = -1, iy = -1, iz = -1, iface = -1;
        for (size_t i = 0; i < e.props.size(); ++i) {
            const std::string& n = e.props[i].name;
            if (e.name == "vertex" && !e.props[i].isList) {
                if (n == "x") ix = int(i);
                if (n == "y") iy = int(i);
                if (n == "z") iz = int(i);
            }
            if (e.name == "face" && e.props[i].isList && (n == "vertex_indices" || n == "vertex_index")) iface = int(i);
        }
        if (e.name == "vertex" && (ix < 0 || iy < 0 || iz < 0))
            throw MeshFileError(path + ": element vertex lacks x, y or z");
        if (e.name == "face" && iface < 0) throw MeshFileError(path + ": element face lacks a vertex_indices list");
        if (e.name == "vertex") mesh.positions.reserve(e.count);
        if (e.name == "face") mesh.indices.reserve(e.count * 3);
        std::vector<double> values(e.props.size(), 0.0);
        std::vector<long long> face;
        for (size_t r = 0; r < e.count; ++r) {
            const char* lineEnd = dataEnd;
            if (!binary) {
                // Next non-blank line.
                for (;;) {
                    if (cur >= dataEnd)
                        throw MeshFileError(path + ": file ends inside element '" + e.name + "' (" + std::to_string(r) +
                                            " of " + std::to_string(e.count) + " read)");
                    lineEnd = static_cast<const char*>(std::memchr(cur, '\n', size_t(dataEnd - cur)));
                    if (!lineEnd) lineEnd = dataEnd;
                    ++lineNo;
                    if (std::string_view(cur, size_t(lineEnd - cur)).find_first_not_of(" \t\r") !=
                        std::string_view::npos)
                        break;
                    cur = lineEnd < dataEnd ? lineEnd + 1 : dataEnd;
                }
            }
            auto elementWhere = [&] {
                return binary ? path + ": " + e.name + " " + std::to_string(r) : path + ":" + std::to_string(lineNo);
            };
            for (size_t p = 0; p < e.props.size(); ++p) {
                const PlyProperty& prop = e.props[p];
                auto readOne = [&](PlyType t, double& v) {
                    bool ok = binary ? readBinary(cur, dataEnd, t, v) : readAscii(cur, lineEnd, v);
                    if (!ok) throw MeshFileError(elementWhere() + ": cannot read property '" + prop.name + "'");
                };
                if (prop.isList) {
                    double cnt;
                    readOne(prop.countType, cnt);
                    if (cnt < 0 || cnt > 1024) throw MeshFileError(elementWhere() + ": bad list length");
                    face.clear();
                    for (int k = 0; k < int(cnt); ++k) {
                        double v;
                        readOne(prop.type, v);
                        if (int(p) == iface) face.push_back((long long)v);
                    }
                } else {
                    readOne(prop.type, values[p]);
                }
            }
            if (!binary) cur = lineEnd < dataEnd ? lineEnd + 1 : dataEnd;
            if (e.name == "vertex") {
                Vec3 v{float(values[size_t(ix)]), float(values[size_t(iy)]),
                       float(values[size_t(iz)])}; // braces: with parentheses this parses as a function declaration
                                                   // (clang rejects it)
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                    throw MeshFileError(elementWhere() + ": non-finite vertex");
                mesh.positions.push_back(v);
            } else if (e.name == "face") {
                if (face.size() > 4)
                    throw MeshFileError(elementWhere() + ": a face with " + std::to_string(face.size()) +
                                        " vertices; expected triangles or quads");
                addPolygon(mesh, face, vertexCount, elementWhere);
            }
        }
    }
    if (mesh.indices.empty()) throw MeshFileError(path + ": no faces");
    return mesh;
}

TriangleMesh readObj(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw MeshFileError(path + ": cannot open file");
    TriangleMesh mesh;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream ls(line);
        std::string tag;
        if (!(ls >> tag) || tag[0] == '#') continue;
        std::string where = path + ":" + std::to_string(lineNo);
        if (tag == "v") {
            float x, y, z;
            if (!(ls >> x >> y >> z)) throw MeshFileError(where + ": expected 3 numbers after 'v'");
            mesh.positions.emplace_back(x, y, z);
        } else if (tag == "f") {
            std::vector<long long> idx;
            std::string tok;
            while (ls >> tok) {
                long long i = 0;
                try {
                    size_t used = 0;
                    i = std::stoll(tok, &used);
                    if (used != tok.size() && tok[used] != '/') throw std::invalid_argument(tok);
                } catch (const std::exception&) {
                    throw MeshFileError(where + ": bad vertex reference '" + tok + "'");
                }
                if (i == 0) throw MeshFileError(where + ": vertex index 0 (OBJ indices start at 1)");
                // Negative: relative to the vertices defined so far.
                idx.push_back(i > 0 ? i - 1 : (long long)(mesh.positions.size()) + i);
            }
            addPolygon(mesh, idx, mesh.positions.size(), [&] { return where; });
        }
    }
    if (mesh.indices.empty()) throw MeshFileError(path + ": no faces");
    return mesh;
}

TriangleMesh readMeshFile(const std::string& path) {
    // A bound on the file before any parsing: devices and FIFOs never start, huge files fail at once.
    {
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0) throw MeshFileError(path + ": cannot open file");
        if (!S_ISREG(st.st_mode)) throw MeshFileError(path + ": not a regular file");
        if (uint64_t(st.st_size) > limits::kMaxMeshFileBytes)
            throw MeshFileError(path + ": " + std::to_string(st.st_size) + " bytes; the limit for a mesh file is " +
                                std::to_string(limits::kMaxMeshFileBytes) + " bytes");
    }
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".ply") return readPly(path);
    if (ext == ".obj") return readObj(path);
    throw MeshFileError(path + ": unknown mesh file extension; expected .ply or .obj");
}

} // namespace stipple::render
