// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// One list of fields per record type: its JSON object (written and read back) and its CSV row and header all
// come from that list, so a column is added in one place.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

namespace stipple::validation {

using Json = nlohmann::ordered_json;

template <class Record>
struct Field {
    std::string name;
    std::function<Json(const Record&)> toJson;
    std::function<void(Record&, const Json&)> fromJson; // empty: written only
    std::function<std::string(const Record&)> toCsv; // empty: results.json only (e.g. per-block lists)
    bool required = false; // reading fails when it is absent
};

template <class Record>
using Fields = std::vector<Field<Record>>;

// A CSV field: quoted (doubling inner quotes) when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text);

namespace detail {

template <class T>
Json valueToJson(const T& v) {
    if constexpr (std::is_floating_point_v<T>)
        return std::isfinite(v) ? Json(v) : Json(nullptr);
    else
        return Json(v);
}

template <class T>
T valueFromJson(const Json& j) {
    // Non-finite numbers are written as null and read back as NaN.
    if constexpr (std::is_floating_point_v<T>)
        return j.is_null() ? std::numeric_limits<T>::quiet_NaN() : j.get<T>();
    else
        return j.get<T>();
}

template <class T>
std::string valueToCsv(const T& v, const char* format) {
    if constexpr (std::is_same_v<T, std::string>)
        return csvField(v);
    else if constexpr (std::is_same_v<T, bool>)
        return v ? "1" : "0";
    else if constexpr (std::is_floating_point_v<T>) {
        char buf[64];
        std::snprintf(buf, sizeof buf, format, double(v));
        return buf;
    } else
        return std::to_string(v);
}

} // namespace detail

// A field read from and written to `get(record)`; `format` is the printf format of a number in the CSV.
template <class Record, class Get>
Field<Record> field(std::string name, Get get, const char* format = "%.9g", bool required = false) {
    using T = std::remove_cvref_t<decltype(get(std::declval<Record&>()))>;
    Field<Record> f;
    f.name = name;
    f.toJson = [get](const Record& r) { return detail::valueToJson(get(const_cast<Record&>(r))); };
    f.fromJson = [get](Record& r, const Json& j) {
        if (j.is_null() && !std::is_floating_point_v<T>) return; // keeps the default
        get(r) = detail::valueFromJson<T>(j);
    };
    f.toCsv = [get, format](const Record& r) { return detail::valueToCsv(get(const_cast<Record&>(r)), format); };
    f.required = required;
    return f;
}

// The same for a data member.
template <class Record, class T>
Field<Record> field(std::string name, T Record::*member, const char* format = "%.9g", bool required = false) {
    return field<Record>(
        std::move(name), [member](Record& r) -> T& { return r.*member; }, format, required);
}

// A list of numbers (e.g. one per region): a JSON array (non-finite entries as null, read back as NaN); in the CSV
// one field of the values joined by ';'.
template <class Record>
Field<Record> doublesField(std::string name, std::vector<double> Record::*member) {
    Field<Record> f;
    f.name = std::move(name);
    f.toJson = [member](const Record& r) {
        Json a = Json::array();
        for (double v : r.*member) a.push_back(detail::valueToJson(v));
        return a;
    };
    f.fromJson = [member](Record& r, const Json& j) {
        (r.*member).clear();
        if (j.is_null()) return; // absent in older files
        for (const auto& v : j) (r.*member).push_back(detail::valueFromJson<double>(v));
    };
    f.toCsv = [member](const Record& r) {
        std::string s;
        for (double v : r.*member) s += (s.empty() ? "" : ";") + detail::valueToCsv(v, "%.9g");
        return s;
    };
    return f;
}

// The same, in results.json only: lists too long for a CSV cell (one number per block of the image).
template <class Record>
Field<Record> jsonOnlyDoublesField(std::string name, std::vector<double> Record::*member) {
    Field<Record> f = doublesField<Record>(std::move(name), member);
    f.toCsv = nullptr;
    return f;
}

template <class Record>
Json toJson(const Record& record, const Fields<Record>& fields) {
    Json j = Json::object();
    for (const auto& f : fields) j[f.name] = f.toJson(record);
    return j;
}

// Reads the fields present in `j`; an absent one keeps its default (NaN for a number: "not measured"), a
// required one throws std::runtime_error naming it.
template <class Record>
Record fromJson(const Json& j, const Fields<Record>& fields, const std::string& what) {
    if (!j.is_object()) throw std::runtime_error(what + " is not an object");
    Record r{};
    for (const auto& f : fields) {
        if (!f.fromJson) continue;
        auto it = j.find(f.name);
        if (it == j.end()) {
            if (f.required) throw std::runtime_error(what + " lacks '" + f.name + "'");
            f.fromJson(r, Json(nullptr));
            continue;
        }
        try {
            f.fromJson(r, *it);
        } catch (const nlohmann::json::exception& e) {
            throw std::runtime_error(what + ": '" + f.name + "': " + e.what());
        }
    }
    return r;
}

template <class Record>
std::string csvHeader(const Fields<Record>& fields) {
    std::string line;
    for (const auto& f : fields)
        if (f.toCsv) line += (line.empty() ? "" : ",") + f.name;
    return line + "\n";
}

template <class Record>
std::string csvRow(const Record& record, const Fields<Record>& fields) {
    std::string line;
    bool first = true;
    for (const auto& f : fields)
        if (f.toCsv) {
            line += (first ? "" : ",") + f.toCsv(record);
            first = false;
        }
    return line + "\n";
}

template <class Record>
std::string csvTable(const std::vector<Record>& records, const Fields<Record>& fields) {
    std::string text = csvHeader(fields);
    for (const auto& r : records) text += csvRow(r, fields);
    return text;
}

} // namespace stipple::validation
