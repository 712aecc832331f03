// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/study_key.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace stipple::validation {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json cropJson(const StudyCrop& c) {
    return {{"id", c.id},       {"pattern", c.pattern}, {"spp", c.spp},   {"width", c.width},
            {"height", c.height}, {"flip", c.flip},     {"flip_half_width", c.flipHalfWidth}, {"rms", c.rms}};
}

StudyCrop cropFrom(const json& j) {
    StudyCrop c;
    c.id = j.at("id").get<std::string>();
    c.pattern = j.at("pattern").get<std::string>();
    c.spp = j.at("spp").get<uint32_t>();
    c.width = j.at("width").get<int>();
    c.height = j.at("height").get<int>();
    c.flip = j.at("flip").is_number() ? j.at("flip").get<double>() : NAN;
    c.flipHalfWidth = j.at("flip_half_width").is_number() ? j.at("flip_half_width").get<double>() : NAN;
    c.rms = j.at("rms").is_number() ? j.at("rms").get<double>() : NAN;
    return c;
}

} // namespace

std::string studyKeyJson(const StudyKey& key) {
    json sets = json::array();
    for (const auto& s : key.sets) {
        json crops = json::array();
        for (const auto& c : s.crops) crops.push_back(cropJson(c));
        sets.push_back({{"name", s.name}, {"scene", s.scene}, {"region", s.region}, {"spp", s.spp},
                        {"crops", crops}, {"control", cropJson(s.control)}});
    }
    json j = {{"format", "stipple-perceptual-key"}, {"version", 1}, {"study", key.study}, {"matrix", key.matrix},
              {"trials", key.trials}, {"repeats", key.repeats}, {"controls", key.controls},
              {"control_spp", key.controlSpp}, {"margin_jod", key.margin}, {"sets", sets}};
    return j.dump(1) + "\n";
}

std::string studyPlanJson(const StudyKey& key) {
    json sets = json::array();
    auto crop = [](const StudyCrop& c) { return json{{"id", c.id}, {"w", c.width}, {"h", c.height}}; };
    for (const auto& s : key.sets) {
        json crops = json::array();
        for (const auto& c : s.crops) crops.push_back(crop(c));
        sets.push_back({{"name", s.name}, {"crops", crops}, {"control", crop(s.control)}});
    }
    json j = {{"format", "stipple-perceptual-plan"}, {"version", 1}, {"study", key.study}, {"trials", key.trials},
              {"repeats", key.repeats}, {"controls", key.controls}, {"sets", sets}};
    // Inside <script>: "</" must not close the element.
    std::string s = j.dump();
    for (size_t i = 0; (i = s.find("</", i)) != std::string::npos; i += 3) s.replace(i, 2, "<\\/");
    return s;
}

StudyKey parseStudyKey(const std::string& text, const std::string& name) {
    try {
        const json j = json::parse(text);
        if (j.at("format") != "stipple-perceptual-key" || j.at("version") != 1)
            throw StudyError(name + ": not a stipple perceptual key (format/version)");
        StudyKey k;
        k.study = j.at("study").get<std::string>();
        k.matrix = j.at("matrix").get<std::string>();
        k.trials = j.at("trials").get<int>();
        k.repeats = j.at("repeats").get<int>();
        k.controls = j.at("controls").get<int>();
        k.controlSpp = j.at("control_spp").get<uint32_t>();
        k.margin = j.at("margin_jod").get<double>();
        for (const auto& s : j.at("sets")) {
            StudySet set;
            set.name = s.at("name").get<std::string>();
            set.scene = s.at("scene").get<std::string>();
            set.region = s.at("region").get<std::string>();
            set.spp = s.at("spp").get<uint32_t>();
            for (const auto& c : s.at("crops")) set.crops.push_back(cropFrom(c));
            set.control = cropFrom(s.at("control"));
            if (set.crops.size() < 2 || set.crops.size() > 4) throw StudyError(name + ": a set needs 2-4 crops");
            k.sets.push_back(std::move(set));
        }
        if (k.sets.empty()) throw StudyError(name + ": no sets");
        return k;
    } catch (const json::exception& e) {
        throw StudyError(name + ": " + e.what());
    }
}

StudyKey loadStudyKey(const std::string& folder) {
    const std::string path = (fs::path(folder) / kStudyKeyFile).string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw StudyError(path + ": cannot read the experiment's key (is " + folder + " an experiment folder?)");
    std::ostringstream s;
    s << in.rdbuf();
    return parseStudyKey(s.str(), path);
}

} // namespace stipple::validation
