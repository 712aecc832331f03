// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Reading a matrix file: the strict YAML reader of the file (positions, keys, numbers) and the names and ranges a
// matrix's values must respect. Every error is a MatrixError naming file:line:column. The matrix's sections
// (matrix.cpp) and the check kinds' keys (check_kind.h) read through it.
#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <stipple/render/input_limits.h>
#include <stipple/yaml/strict_yaml.h>

#include "matrix/external_command.h"
#include "matrix/matrix.h"

namespace stipple::validation {

// "a, b, c": the names a message lists as allowed.
inline std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

// The strict YAML reader of the file and the names the matrix may use.
struct MatrixReader {
    yaml::StrictYaml yaml;
    const MatrixVocabulary& vocabulary;

    [[noreturn]] void fail(const yaml::Node& node, const std::string& what) const {
        throw MatrixError(yaml.where(node) + ": " + what);
    }

    void expectMap(const yaml::Node& node, const std::string& what) const {
        if (!node.IsMap()) fail(node, what + " must be a map");
    }
    // Unknown keys are errors: a typo must not silently become a default.
    void onlyKeys(const yaml::Node& map, const std::vector<std::string>& allowed, const std::string& what) const {
        try {
            yaml.onlyKeys(map, allowed, what);
        } catch (const yaml::Error& e) {
            throw MatrixError(e.what());
        }
    }
    template <typename T>
    T get(const yaml::Node& node, const std::string& what) const {
        if (!node.IsScalar()) fail(node, what + " must be a scalar");
        if constexpr (std::is_same_v<T, std::string>) {
            return node.Scalar();
        } else if (node.IsQuoted()) {
            fail(node, what + " must be a number, not quoted text ('" + node.Scalar() + "')");
        } else if constexpr (std::is_floating_point_v<T>) {
            double v = 0;
            if (yaml::StrictYaml::parseNumber(node, v) != yaml::StrictYaml::Number::Ok)
                fail(node, "cannot read " + what + " from '" + node.Scalar() + "'");
            return T(v);
        } else {
            long long v = 0;
            if (!yaml::StrictYaml::parseInteger(node, v) || v < (long long)std::numeric_limits<T>::min() ||
                (v > 0 && (unsigned long long)v > (unsigned long long)std::numeric_limits<T>::max()))
                fail(node, "cannot read " + what + " from '" + node.Scalar() + "'");
            return T(v);
        }
    }
    double positive(const yaml::Node& node, const std::string& what) const {
        double v = get<double>(node, what);
        if (!(v > 0)) fail(node, what + " must be > 0, got " + node.Scalar());
        return v;
    }
    // A sample count: at most the library's N limit (STIPPLE_MAX_SAMPLES_PER_PIXEL), checked here rather than
    // after every render; a reference is rendered as two halves, so its limit is twice that.
    uint32_t spp(const yaml::Node& node, const std::string& what, bool reference = false) const {
        const long long limit = kMaxSamplesPerPixel * (reference ? 2 : 1);
        long long v = get<long long>(node, what);
        if (v < 1 || v > limit)
            fail(node, what + " must be in [1, " + std::to_string(limit) + "] (the library's limit on samples per " +
                           "pixel" + (reference ? ", for each of the reference's two halves" : "") + "), got " +
                           node.Scalar());
        return uint32_t(v);
    }
    // A name shown in reports, file names and messages: valid UTF-8, 1 to kMaxNameBytes bytes, no control
    // characters.
    static constexpr size_t kMaxNameBytes = 128;
    std::string name(const yaml::Node& node, const std::string& what) const {
        const std::string v = get<std::string>(node, what);
        if (v.empty() || v.size() > kMaxNameBytes)
            fail(node, what + " must be 1 to " + std::to_string(kMaxNameBytes) + " bytes long, got " +
                           std::to_string(v.size()));
        for (size_t i = 0; i < v.size();) {
            const unsigned char c = static_cast<unsigned char>(v[i]);
            const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
            bool ok = n > 0 && i + n <= v.size() && !(n == 1 && (c < 0x20 || c == 0x7f));
            for (size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(v[i + k]) >> 6) == 0x2;
            if (ok && n > 1) { // no overlong forms, surrogates or code points past U+10FFFF
                uint32_t cp = c & (0xff >> (n + 1));
                for (size_t k = 1; k < n; ++k) cp = (cp << 6) | (static_cast<unsigned char>(v[i + k]) & 0x3f);
                ok = cp >= (n == 2 ? 0x80u : n == 3 ? 0x800u : 0x10000u) && cp <= 0x10ffff && !(cp >= 0xd800 && cp <= 0xdfff);
            }
            if (!ok)
                fail(node, what + " must be valid UTF-8 without control characters (byte " + std::to_string(i) + ")");
            i += n;
        }
        return v;
    }
    // An image side: the renderer's range (render::checkRenderSettings refuses the same).
    int imageSide(const yaml::Node& node, const std::string& what) const {
        long long v = get<long long>(node, what);
        if (v < 1 || v > render::limits::kMaxImageSide)
            fail(node, what + " must be in [1, " + std::to_string(render::limits::kMaxImageSide) + "], got " +
                           node.Scalar());
        return int(v);
    }
    int dimension(const yaml::Node& node, const std::string& what) const {
        long long v = get<long long>(node, what);
        if (v < 1 || v > 16384) fail(node, what + " must be in [1, 16384], got " + node.Scalar());
        return int(v);
    }
    std::string pattern(const yaml::Node& node) const {
        auto p = get<std::string>(node, "pattern");
        const auto& known = vocabulary.patterns;
        // "<pattern>+blue-noise": the shim's screen-space blue-noise option on that pattern.
        static const std::string kBlueNoise = "+blue-noise";
        std::string base = p;
        if (base.size() > kBlueNoise.size() && base.ends_with(kBlueNoise)) base.resize(base.size() - kBlueNoise.size());
        if (std::find(known.begin(), known.end(), base) == known.end())
            fail(node, "unknown pattern '" + p + "' (known: " + joined(known) + ", each optionally followed by " +
                           kBlueNoise + ")");
        return p;
    }
    // renderer: { command: [program, arg, ...], format: exr | pfm } (external_renderer.h).
    ExternalCommand renderer(const yaml::Node& node) const {
        expectMap(node, "renderer");
        onlyKeys(node, {"command", "format", "timeout"}, "renderer");
        ExternalCommand r;
        r.where = yaml.where(node);
        const yaml::Node command = required(node, "command", "renderer");
        if (!command.IsSequence() || command.size() == 0)
            fail(command, "command must be a list: the program, then its arguments (no shell)");
        for (const auto& a : command) r.command.push_back(get<std::string>(a, "a command argument"));
        if (const std::string why = checkCommandTemplate(r.command); !why.empty()) fail(command, why);
        if (node["timeout"]) {
            r.timeoutSeconds = get<double>(node["timeout"], "timeout");
            if (!(r.timeoutSeconds > 0 && r.timeoutSeconds <= 1e6))
                fail(node["timeout"], "timeout must be seconds in (0, 1000000]");
        }
        if (node["format"]) {
            r.format = get<std::string>(node["format"], "format");
            if (r.format != "exr" && r.format != "pfm") fail(node["format"], "format must be exr or pfm");
        }
        return r;
    }
    const yaml::Node required(const yaml::Node& map, const std::string& key, const std::string& what) const {
        const yaml::Node n = map[key];
        if (!n) fail(map, what + " needs '" + key + "'");
        return n;
    }
};

} // namespace stipple::validation
