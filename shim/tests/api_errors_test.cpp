// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// api_errors_test.cpp — every error path of the C ABI returns the right status and a message naming the
// argument; nothing crashes. Runs against libstipple.so itself, as hosts see it.
#define BOOST_TEST_MODULE api_errors
#include "sampler_fixture.h"

#include <stipple/stipple.hpp>

#include <cstring>
#include <thread>

using namespace stipple::test;

namespace {

// Checks status and that the thread's message mentions `needle`.
void expectError(stipple_status got, stipple_status expected, const char* needle) {
    const std::string message = stipple_last_error_message();
    BOOST_CHECK_EQUAL(got, expected);
    BOOST_CHECK_MESSAGE(message.find(needle) != std::string::npos,
                        "message \"" << message << "\" should mention \"" << needle << "\"");
}

struct Layout {
    stipple_dimension_desc dims[2];
    stipple_sampler_desc desc;
    Layout() {
        std::memset(this, 0, sizeof *this);
        for (auto& d : dims) {
            d.struct_size = sizeof d;
            d.arity = 2;
            d.count = 1;
        }
        desc.struct_size = sizeof desc;
        desc.pattern = STIPPLE_PATTERN_STRATIFIED;
        desc.samples_per_pixel = 16;
        desc.dimension_count = 2;
        desc.dimensions = dims;
    }
    stipple_status create(stipple_sampler* out) { return stipple_sampler_create(&desc, out); }
};

} // namespace

BOOST_AUTO_TEST_CASE(get_api_checks_version_and_pointer) {
    const stipple_api* api = nullptr;
    expectError(stipple_get_api(STIPPLE_ABI_MAJOR + 1, &api), STIPPLE_ERROR_ABI_VERSION, "abi_major");
    BOOST_CHECK(api == nullptr);
    expectError(stipple_get_api(0, &api), STIPPLE_ERROR_ABI_VERSION, "abi_major is 0");
    expectError(stipple_get_api(STIPPLE_ABI_MAJOR, nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_api");
    BOOST_REQUIRE_EQUAL(stipple_get_api(STIPPLE_ABI_MAJOR, &api), STIPPLE_OK);
    BOOST_CHECK_EQUAL(api->struct_size, sizeof(stipple_api));
    BOOST_CHECK_EQUAL(api->abi_major, uint32_t(STIPPLE_ABI_MAJOR));
    BOOST_CHECK(api->sampler_create == &stipple_sampler_create);
    BOOST_CHECK(api->sampler_sample_independent == &stipple_sampler_sample_independent);
}

BOOST_AUTO_TEST_CASE(version_and_pattern_names) {
    uint32_t major = 0, minor = 0, patch = 0;
    BOOST_CHECK_EQUAL(stipple_get_version(&major, &minor, &patch), STIPPLE_OK);
    BOOST_CHECK_EQUAL(major, uint32_t(STIPPLE_ABI_MAJOR));
    expectError(stipple_get_version(nullptr, &minor, &patch), STIPPLE_ERROR_NULL_ARGUMENT, "major");
    expectError(stipple_get_version(&major, &minor, nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "patch");

    uint32_t pattern = 99;
    BOOST_CHECK_EQUAL(stipple_pattern_from_name("poisson-seed", &pattern), STIPPLE_OK);
    BOOST_CHECK_EQUAL(pattern, STIPPLE_PATTERN_POISSON_SEED);
    expectError(stipple_pattern_from_name("hammersley", &pattern), STIPPLE_ERROR_INVALID_ARGUMENT, "hammersley");
    expectError(stipple_pattern_from_name("Stratified", &pattern), STIPPLE_ERROR_INVALID_ARGUMENT, "name");
    expectError(stipple_pattern_from_name(nullptr, &pattern), STIPPLE_ERROR_NULL_ARGUMENT, "name");
    expectError(stipple_pattern_from_name("poisson", nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_pattern");
    const std::string longName(500, 'x');
    expectError(stipple_pattern_from_name(longName.c_str(), &pattern), STIPPLE_ERROR_INVALID_ARGUMENT, "name");

    const char* name = nullptr;
    for (uint32_t p = 0; p < STIPPLE_PATTERN_COUNT; ++p) {
        BOOST_REQUIRE_EQUAL(stipple_pattern_name(p, &name), STIPPLE_OK);
        uint32_t back = 99;
        BOOST_CHECK_EQUAL(stipple_pattern_from_name(name, &back), STIPPLE_OK);
        BOOST_CHECK_EQUAL(back, p);
    }
    expectError(stipple_pattern_name(STIPPLE_PATTERN_COUNT, &name), STIPPLE_ERROR_INVALID_ARGUMENT,
                ("pattern is " + std::to_string(STIPPLE_PATTERN_COUNT) + ";").c_str());
    expectError(stipple_pattern_name(0, nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_name");
}

BOOST_AUTO_TEST_CASE(create_rejects_bad_descriptions) {
    stipple_sampler s = reinterpret_cast<stipple_sampler>(uintptr_t(1));
    {
        Layout l;
        expectError(stipple_sampler_create(nullptr, &s), STIPPLE_ERROR_NULL_ARGUMENT, "desc");
        BOOST_CHECK(s == nullptr); // the out handle is cleared on failure
        expectError(l.create(nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_sampler");
    }
    struct Case {
        const char* what;
        void (*edit)(Layout&);
        stipple_status status;
        const char* needle;
    };
    const Case cases[] = {
        {"N = 0", [](Layout& l) { l.desc.samples_per_pixel = 0; }, STIPPLE_ERROR_OUT_OF_RANGE,
         "samples_per_pixel is 0"},
        {"N too large", [](Layout& l) { l.desc.samples_per_pixel = STIPPLE_MAX_SAMPLES_PER_PIXEL + 1; },
         STIPPLE_ERROR_OUT_OF_RANGE, "samples_per_pixel"},
        {"unknown pattern", [](Layout& l) { l.desc.pattern = STIPPLE_PATTERN_COUNT; }, STIPPLE_ERROR_INVALID_ARGUMENT,
         "desc->pattern is"},
        {"unknown pattern, named", [](Layout& l) { l.desc.pattern = 1000; }, STIPPLE_ERROR_INVALID_ARGUMENT,
         "pattern is 1000; expected 0 (independent), 1 (stratified)"},
        {"unknown pattern, large", [](Layout& l) { l.desc.pattern = 0xffffffffu; }, STIPPLE_ERROR_INVALID_ARGUMENT,
         "pattern"},
        {"too many dimensions", [](Layout& l) { l.desc.dimension_count = STIPPLE_MAX_DIMENSIONS + 1; },
         STIPPLE_ERROR_OUT_OF_RANGE, "dimension_count"},
        {"null layout", [](Layout& l) { l.desc.dimensions = nullptr; }, STIPPLE_ERROR_NULL_ARGUMENT,
         "desc->dimensions"},
        {"desc struct too small", [](Layout& l) { l.desc.struct_size = sizeof(stipple_sampler_desc) - 8; },
         STIPPLE_ERROR_STRUCT_SIZE, "desc->struct_size"},
        {"desc struct zero", [](Layout& l) { l.desc.struct_size = 0; }, STIPPLE_ERROR_STRUCT_SIZE, "struct_size is 0"},
        {"unknown flag bit", [](Layout& l) { l.desc.flags = 2; }, STIPPLE_ERROR_INVALID_ARGUMENT, "unknown bits 2"},
        {"unknown flag bit beside blue noise",
         [](Layout& l) { l.desc.flags = STIPPLE_SAMPLER_FLAG_BLUE_NOISE | 0x80000000u; },
         STIPPLE_ERROR_INVALID_ARGUMENT, "unknown bits 2147483648"},
        {"unknown flag bit, no layout",
         [](Layout& l) {
             l.desc.dimension_count = 0;
             l.desc.flags = 4;
         },
         STIPPLE_ERROR_INVALID_ARGUMENT, "unknown bits 4"},
        {"pmj02 streams above its set limit",
         [](Layout& l) {
             l.desc.pattern = STIPPLE_PATTERN_PMJ02;
             l.desc.dimension_count = 0;
             l.desc.samples_per_pixel = 65537;
         },
         STIPPLE_ERROR_OUT_OF_RANGE, "samples_per_pixel is 65537; the pmj02 pattern serves sets of at most 65536"},
        {"reserved", [](Layout& l) { l.desc.reserved = 3; }, STIPPLE_ERROR_INVALID_ARGUMENT, "desc->reserved"},
        {"arity 0", [](Layout& l) { l.dims[1].arity = 0; }, STIPPLE_ERROR_INVALID_ARGUMENT, "dimensions[1].arity is 0"},
        {"arity 4", [](Layout& l) { l.dims[0].arity = 4; }, STIPPLE_ERROR_INVALID_ARGUMENT, "dimensions[0].arity is 4"},
        {"count too large", [](Layout& l) { l.dims[1].count = STIPPLE_MAX_VALUES_PER_SAMPLE + 1; },
         STIPPLE_ERROR_OUT_OF_RANGE, "dimensions[1].count"},
        {"set too large",
         [](Layout& l) {
             l.desc.samples_per_pixel = 1u << 16;
             l.dims[0].count = 128;
         },
         STIPPLE_ERROR_OUT_OF_RANGE, "dimensions[0].count"},
        {"dimension reserved", [](Layout& l) { l.dims[1].reserved = 1; }, STIPPLE_ERROR_INVALID_ARGUMENT,
         "dimensions[1].reserved"},
        {"dimension struct too small", [](Layout& l) { l.dims[0].struct_size = 8; }, STIPPLE_ERROR_STRUCT_SIZE,
         "dimensions[0].struct_size"},
        {"dimension struct inconsistent", [](Layout& l) { l.dims[1].struct_size = 100; }, STIPPLE_ERROR_STRUCT_SIZE,
         "dimensions[1].struct_size"},
        {"name too long",
         [](Layout& l) {
             l.dims[1].name = "a-name-that-is-much-longer-than-sixty-three-characters-allowed-by-the-abi";
         },
         STIPPLE_ERROR_OUT_OF_RANGE, "dimensions[1].name"},
    };
    for (const Case& c : cases) {
        BOOST_TEST_CONTEXT(c.what) {
            Layout l;
            c.edit(l);
            s = reinterpret_cast<stipple_sampler>(uintptr_t(1));
            expectError(l.create(&s), c.status, c.needle);
            BOOST_CHECK(s == nullptr);
        }
    }
}

BOOST_AUTO_TEST_CASE(create_accepts_larger_structs_with_zero_tails_only) {
    struct BiggerDesc {
        stipple_sampler_desc desc;
        uint64_t future;
    } big{};
    stipple_dimension_desc dim{};
    dim.struct_size = sizeof dim;
    dim.arity = 1;
    big.desc.struct_size = sizeof big;
    big.desc.pattern = STIPPLE_PATTERN_INDEPENDENT;
    big.desc.samples_per_pixel = 4;
    big.desc.dimension_count = 1;
    big.desc.dimensions = &dim;
    stipple_sampler s = nullptr;
    BOOST_CHECK_EQUAL(stipple_sampler_create(&big.desc, &s), STIPPLE_OK);
    BOOST_CHECK_EQUAL(stipple_sampler_release(s), STIPPLE_OK);
    big.future = 1;
    expectError(stipple_sampler_create(&big.desc, &s), STIPPLE_ERROR_INVALID_ARGUMENT, "desc");
    BOOST_CHECK(s == nullptr);

    // A larger dimension entry: the array stride follows struct_size.
    struct BiggerDim {
        stipple_dimension_desc d;
        uint64_t future;
    } dims[2]{};
    for (auto& e : dims) {
        e.d.struct_size = sizeof e;
        e.d.arity = 3;
    }
    dims[1].d.name = "second";
    big.future = 0;
    big.desc.dimension_count = 2;
    big.desc.dimensions = &dims[0].d;
    BOOST_REQUIRE_EQUAL(stipple_sampler_create(&big.desc, &s), STIPPLE_OK);
    uint32_t found = 9;
    BOOST_CHECK_EQUAL(stipple_sampler_find_dimension(s, "second", &found), STIPPLE_OK);
    BOOST_CHECK_EQUAL(found, 1u);
    stipple_sampler_release(s);
    dims[1].future = 7;
    expectError(stipple_sampler_create(&big.desc, &s), STIPPLE_ERROR_INVALID_ARGUMENT, "dimensions[1]");
}

BOOST_AUTO_TEST_CASE(sampling_calls_check_their_arguments) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 3, {{2, 1, "lens"}, {1, 4, "light"}});
    std::vector<float> buffer(1024);
    expectError(stipple_sampler_fill_pixel(nullptr, 0, 0, 0, buffer.data(), buffer.size()), STIPPLE_ERROR_NULL_ARGUMENT,
                "sampler");
    expectError(stipple_sampler_fill_pixel(s.get(), 0, 0, 2, buffer.data(), buffer.size()), STIPPLE_ERROR_OUT_OF_RANGE,
                "dimension is 2");
    expectError(stipple_sampler_fill_pixel(s.get(), 0, 0, 0, nullptr, 32), STIPPLE_ERROR_NULL_ARGUMENT, "out");
    expectError(stipple_sampler_fill_pixel(s.get(), 0, 0, 0, buffer.data(), 31), STIPPLE_ERROR_OUT_OF_RANGE,
                "out_count is 31");
    expectError(stipple_sampler_fill_pixel(s.get(), 0, 0, 1, buffer.data(), 63), STIPPLE_ERROR_OUT_OF_RANGE,
                "expected at least 64");
    BOOST_CHECK_EQUAL(stipple_sampler_fill_pixel(s.get(), 0, 0, 1, buffer.data(), 64), STIPPLE_OK);

    expectError(stipple_sampler_sample(nullptr, 0, 0, 0, 0, buffer.data(), 2), STIPPLE_ERROR_NULL_ARGUMENT, "sampler");
    BOOST_CHECK_EQUAL(stipple_sampler_sample(s.get(), 0, 0, 16, 0, buffer.data(), 2), STIPPLE_OK); // block 1 (1.1)
    expectError(stipple_sampler_sample(s.get(), 0, 0, 0, 7, buffer.data(), 2), STIPPLE_ERROR_OUT_OF_RANGE,
                "dimension is 7");
    expectError(stipple_sampler_sample(s.get(), 0, 0, 0, 1, buffer.data(), 3), STIPPLE_ERROR_OUT_OF_RANGE, "out_count");
    expectError(stipple_sampler_sample(s.get(), 0, 0, 0, 0, nullptr, 2), STIPPLE_ERROR_NULL_ARGUMENT, "out");

    expectError(stipple_sampler_sample_independent(nullptr, 0, 0, 0, 0, buffer.data(), 1), STIPPLE_ERROR_NULL_ARGUMENT,
                "sampler");
    expectError(stipple_sampler_sample_independent(s.get(), 0, 0, 0, 0, nullptr, 1), STIPPLE_ERROR_NULL_ARGUMENT,
                "out");
    expectError(stipple_sampler_sample_independent(s.get(), 0, 0, 0, 0, buffer.data(), 0), STIPPLE_ERROR_OUT_OF_RANGE,
                "out_count");

    stipple_sampler_info info{};
    expectError(stipple_sampler_get_info(s.get(), &info), STIPPLE_ERROR_STRUCT_SIZE, "out_info->struct_size");
    expectError(stipple_sampler_get_info(s.get(), nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_info");
    info.struct_size = sizeof info;
    expectError(stipple_sampler_get_info(nullptr, &info), STIPPLE_ERROR_NULL_ARGUMENT, "sampler");
    stipple_dimension_info dinfo{};
    dinfo.struct_size = sizeof dinfo - 4;
    expectError(stipple_sampler_get_dimension_info(s.get(), 0, &dinfo), STIPPLE_ERROR_STRUCT_SIZE, "struct_size");
    dinfo.struct_size = sizeof dinfo;
    expectError(stipple_sampler_get_dimension_info(s.get(), 2, &dinfo), STIPPLE_ERROR_OUT_OF_RANGE, "dimension is 2");

    uint32_t index = 0;
    expectError(stipple_sampler_find_dimension(s.get(), "pixel", &index), STIPPLE_ERROR_INVALID_ARGUMENT, "pixel");
    expectError(stipple_sampler_find_dimension(s.get(), nullptr, &index), STIPPLE_ERROR_NULL_ARGUMENT, "name");
    expectError(stipple_sampler_find_dimension(s.get(), "lens", nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_dimension");

    BOOST_CHECK_EQUAL(stipple_sampler_release(nullptr), STIPPLE_OK);
}

BOOST_AUTO_TEST_CASE(messages_are_per_thread_and_survive_success) {
    expectError(stipple_pattern_name(77, nullptr), STIPPLE_ERROR_NULL_ARGUMENT, "out_name");
    uint32_t major, minor, patch;
    BOOST_CHECK_EQUAL(stipple_get_version(&major, &minor, &patch), STIPPLE_OK);
    BOOST_CHECK(std::string(stipple_last_error_message()).find("out_name") != std::string::npos);
    std::string other;
    std::thread([&] { other = stipple_last_error_message(); }).join();
    BOOST_CHECK_EQUAL(other, "");
}

BOOST_AUTO_TEST_CASE(larger_output_structs_are_zeroed_past_what_we_know) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 3, {{2, 1, "lens"}});
    struct BiggerInfo {
        stipple_dimension_info info;
        uint64_t future;
    } big;
    std::memset(&big, 0xab, sizeof big);
    big.info.struct_size = sizeof big;
    BOOST_REQUIRE_EQUAL(stipple_sampler_get_dimension_info(s.get(), 0, &big.info), STIPPLE_OK);
    BOOST_CHECK_EQUAL(big.info.struct_size, sizeof big);
    BOOST_CHECK_EQUAL(big.info.floats_per_pixel, 32u);
    BOOST_CHECK_EQUAL(big.info.strata[0] * big.info.strata[1], 16u);
    BOOST_CHECK_EQUAL(big.info.strata[2], 0u);
    BOOST_CHECK_EQUAL(big.info.reserved, 0u);
    BOOST_CHECK_EQUAL(big.future, 0u);
}

BOOST_AUTO_TEST_CASE(stream_calls_check_their_arguments) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 3, {}); // no declared layout
    std::vector<float> buffer(64, 0.0f);
    expectError(stipple_sampler_stream(nullptr, 0, 0, 0, 0, 1, buffer.data(), 1), STIPPLE_ERROR_NULL_ARGUMENT,
                "sampler");
    expectError(stipple_sampler_stream(s.get(), 0, 0, 0, 0, 0, buffer.data(), 4), STIPPLE_ERROR_INVALID_ARGUMENT,
                "arity is 0; expected 1, 2 or 3");
    expectError(stipple_sampler_stream(s.get(), 0, 0, 0, 0, 4, buffer.data(), 4), STIPPLE_ERROR_INVALID_ARGUMENT,
                "arity is 4");
    expectError(stipple_sampler_stream(s.get(), 0, 0, 0, 0, 2, nullptr, 2), STIPPLE_ERROR_NULL_ARGUMENT, "out");
    expectError(stipple_sampler_stream(s.get(), 0, 0, 0, 0, 3, buffer.data(), 2), STIPPLE_ERROR_OUT_OF_RANGE,
                "out_count is 2; expected at least 3");
    BOOST_CHECK_EQUAL(stipple_sampler_stream(s.get(), 0, 0, 0xffffffffu, 0xffffffffu, 3, buffer.data(), 3), STIPPLE_OK);

    expectError(stipple_sampler_stream_fill(nullptr, 0, 0, 0, 1, 0, 1, buffer.data(), 1), STIPPLE_ERROR_NULL_ARGUMENT,
                "sampler");
    expectError(stipple_sampler_stream_fill(s.get(), 0, 0, 0, 0, 0, 1, buffer.data(), 1), STIPPLE_ERROR_OUT_OF_RANGE,
                "sample_count is 0");
    expectError(stipple_sampler_stream_fill(s.get(), 0, 0, 0xfffffff0u, 17, 0, 1, buffer.data(), 64),
                STIPPLE_ERROR_OUT_OF_RANGE, "first_sample + sample_count is 4294967297");
    expectError(stipple_sampler_stream_fill(s.get(), 0, 0, 0, 4, 0, 7, buffer.data(), 64),
                STIPPLE_ERROR_INVALID_ARGUMENT, "arity is 7");
    expectError(stipple_sampler_stream_fill(s.get(), 0, 0, 0, 22, 0, 3, buffer.data(), 64), STIPPLE_ERROR_OUT_OF_RANGE,
                "out_count is 64; expected at least 66");
    expectError(stipple_sampler_stream_fill(s.get(), 0, 0, 0, 4, 0, 1, nullptr, 4), STIPPLE_ERROR_NULL_ARGUMENT, "out");
    BOOST_CHECK_EQUAL(stipple_sampler_stream_fill(s.get(), 0, 0, 0xfffffff0u, 16, 0, 1, buffer.data(), 16), STIPPLE_OK);

    // Without a declared layout the layout calls name the way out.
    expectError(stipple_sampler_fill_pixel(s.get(), 0, 0, 0, buffer.data(), 64), STIPPLE_ERROR_OUT_OF_RANGE,
                "declares no layout");
    expectError(stipple_sampler_sample(s.get(), 0, 0, 0, 0, buffer.data(), 64), STIPPLE_ERROR_OUT_OF_RANGE,
                "use stipple_sampler_stream");
    stipple_dimension_info info{};
    info.struct_size = sizeof info;
    expectError(stipple_sampler_get_dimension_info(s.get(), 0, &info), STIPPLE_ERROR_OUT_OF_RANGE, "dimension is 0");
}

// The C++ kit's call-order cursor: the counter's last value is getPixel2D's stream, so the counter stops before it.
BOOST_AUTO_TEST_CASE(cursor_counter_stops_before_the_pixel_stream) {
    const stipple::Sampler sampler("stratified", 4, 1);
    stipple::PixelSampleCursor cursor(sampler);
    cursor.start({3, 5}, 1, STIPPLE_STREAM_RESERVED_FIRST - 1);
    BOOST_CHECK_NO_THROW(cursor.get1D()); // the last dimension the counter may use
    try {
        cursor.get2D();
        BOOST_ERROR("the counter reached getPixel2D's dimension");
    } catch (const stipple::Error& e) {
        BOOST_CHECK_EQUAL(e.status(), STIPPLE_ERROR_OUT_OF_RANGE);
        BOOST_CHECK(std::string(e.what()).find("getPixel2D") != std::string::npos);
    }
}
