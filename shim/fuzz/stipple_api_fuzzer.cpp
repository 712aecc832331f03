// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple_api_fuzzer.cpp — libFuzzer harness for the C ABI. The input bytes are read as a sequence of API calls
// with their arguments (bad ones included: unknown patterns, arity 0 or 4, struct sizes too small or too large
// with non-zero tails, N = 0 or above the maximum, dimension indices past the layout, short buffers, NULLs).
// Up to four samplers live at once; every call's result is checked against the header's contract:
//   - a failing call leaves a non-empty message; a successful one writes values finite and in [0, 1);
//   - stipple_sampler_sample equals the matching part of stipple_sampler_fill_pixel bitwise.
// A broken invariant calls __builtin_trap() so libFuzzer (and the gcc-built replay test) report it.
//
// Cost caps (the fuzzer must not time out on legitimate but slow requests): values are only requested from
// samplers whose set generation is cheap — independent and stratified up to 2^16 floats per pixel, poisson up
// to 4096 points per set, poisson-seed up to 512. Creation itself is fuzzed with any N.
#include <stipple/stipple.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Reads little pieces of the input; past the end everything reads as zero.
class FuzzInput {
public:
    FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool done() const { return pos_ >= size_; }
    uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t(byte()) << (8 * i);
        return v;
    }
    uint64_t u64() { return uint64_t(u32()) | (uint64_t(u32()) << 32); }
    // A value picked among interesting edges or a small one, steered by one byte.
    uint32_t count(uint32_t smallMax) {
        const uint8_t selector = byte();
        switch (selector % 8) {
        case 0: return 0;
        case 1: return u32();
        case 2: return STIPPLE_MAX_SAMPLES_PER_PIXEL + (byte() % 3) - 1;
        default: return 1 + byte() % smallMax;
        }
    }
    std::string text(size_t maxLength) {
        const size_t length = byte() % (maxLength + 1);
        std::string s;
        for (size_t i = 0; i < length && !done(); ++i) s.push_back(char(byte()));
        return s;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;
};

void require(bool condition) {
    if (!condition) __builtin_trap();
}

void checkFailureHasMessage(stipple_status status) {
    if (status != STIPPLE_OK) {
        const char* message = stipple_last_error_message();
        require(message != nullptr && message[0] != '\0');
        require(status > 0 && status <= STIPPLE_ERROR_INTERNAL);
        require(status != STIPPLE_ERROR_INTERNAL); // INTERNAL means a bug in the library
    }
}

void checkValues(const float* v, size_t n) {
    for (size_t i = 0; i < n; ++i) require(std::isfinite(v[i]) && v[i] >= 0.0f && v[i] < 1.0f);
}

struct Live {
    stipple_sampler sampler = nullptr;
    uint32_t pattern = 0;
    uint32_t samplesPerPixel = 0;
    uint32_t dimensionCount = 0;
};

bool cheapToServe(const Live& live, const stipple_dimension_info& info) {
    const uint64_t points = uint64_t(live.samplesPerPixel) * info.count;
    switch (live.pattern) {
    case STIPPLE_PATTERN_POISSON: return points <= 4096;
    case STIPPLE_PATTERN_POISSON_SEED: return points <= 512;
    default: return info.floats_per_pixel <= (1u << 16);
    }
}

void create(FuzzInput& in, std::vector<Live>& live) {
    const uint32_t dimensionCount = in.byte() % 6;
    std::vector<std::string> names(dimensionCount);
    // The stride of the array is dimensions[0].struct_size; a larger struct carries a (possibly non-zero) tail.
    const uint32_t stride = sizeof(stipple_dimension_desc) + 8 * (in.byte() % 2);
    std::vector<unsigned char> storage(size_t(stride) * (dimensionCount ? dimensionCount : 1), 0);
    for (uint32_t d = 0; d < dimensionCount; ++d) {
        stipple_dimension_desc desc{};
        const uint8_t shape = in.byte();
        desc.struct_size = (shape & 0x80) ? uint32_t(in.byte() % (stride + 1)) : stride; // never past the storage
        desc.arity = (shape & 0x40) ? in.byte() % 5 : 1 + shape % 3;
        desc.count = (shape & 0x20) ? in.count(8) : shape % 4; // 0 is read as 1
        desc.reserved = (shape & 0x10) ? in.byte() : 0;
        names[d] = in.text(70);
        desc.name = (shape & 0x08) ? nullptr : names[d].c_str();
        std::memcpy(storage.data() + size_t(d) * stride, &desc, sizeof desc);
        if (stride > sizeof desc && (shape & 0x04)) storage[size_t(d) * stride + sizeof desc] = in.byte();
    }
    stipple_sampler_desc desc{};
    const uint8_t shape = in.byte();
    desc.struct_size = (shape & 0x80) ? uint32_t(in.byte()) : uint32_t(sizeof desc);
    desc.pattern = (shape & 0x40) ? in.u32() : in.byte() % STIPPLE_PATTERN_COUNT;
    desc.samples_per_pixel = in.count(64);
    desc.dimension_count = (shape & 0x20) ? in.u32() % (STIPPLE_MAX_DIMENSIONS + 2) : dimensionCount;
    if (desc.dimension_count > dimensionCount)
        desc.dimensions = nullptr; // never let the library read past storage
    else
        desc.dimensions = (shape & 0x10) ? nullptr : reinterpret_cast<const stipple_dimension_desc*>(storage.data());
    desc.seed = in.u64();
    desc.flags = (shape & 0x08) ? in.byte() : 0;
    desc.reserved = (shape & 0x04) ? in.byte() : 0;

    // The library reads struct_size bytes (up to 255 here): the struct sits in zeroed storage that large, with
    // sometimes a non-zero byte in the tail it does not know.
    alignas(stipple_sampler_desc) unsigned char descStorage[256] = {};
    std::memcpy(descStorage, &desc, sizeof desc);
    if (desc.struct_size > sizeof desc && (shape & 0x01))
        descStorage[sizeof desc + in.byte() % (desc.struct_size - sizeof desc)] = 1;
    const auto* descArg = reinterpret_cast<const stipple_sampler_desc*>(descStorage);

    stipple_sampler sampler = nullptr;
    const stipple_status status = stipple_sampler_create((shape & 0x02) && (shape & 0x01) ? nullptr : descArg,
                                                         (shape & 0x02) && !(shape & 0x01) ? nullptr : &sampler);
    checkFailureHasMessage(status);
    if (status != STIPPLE_OK) {
        require(sampler == nullptr);
        return;
    }
    require(sampler != nullptr);
    stipple_sampler_info info{};
    info.struct_size = sizeof info;
    require(stipple_sampler_get_info(sampler, &info) == STIPPLE_OK);
    require(info.pattern == desc.pattern && info.samples_per_pixel == desc.samples_per_pixel &&
            info.dimension_count == desc.dimension_count && info.seed == desc.seed);
    if (live.size() >= 4) {
        stipple_sampler_release(live.front().sampler);
        live.erase(live.begin());
    }
    live.push_back({sampler, desc.pattern, desc.samples_per_pixel, desc.dimension_count});
}

// Streams (1.1): any dimension index and sample index; arity 1..3 and out_count >= arity, else a clean error.
void serveStream(FuzzInput& in, const Live& live, uint32_t dimension, uint32_t x, uint32_t y) {
    const uint32_t points = live.samplesPerPixel;
    if ((live.pattern == STIPPLE_PATTERN_POISSON && points > 4096) ||
        (live.pattern == STIPPLE_PATTERN_POISSON_SEED && points > 512))
        return;
    const uint32_t arity = in.byte() % 5;
    const uint32_t i = (in.byte() & 1) ? in.u32() : in.byte();
    const size_t capacity = in.byte() % 5;
    float out[5] = {-1.0f, -1.0f, -1.0f, -1.0f, -1.0f};
    const stipple_status status = stipple_sampler_stream(live.sampler, x, y, i, dimension, arity, out, capacity);
    checkFailureHasMessage(status);
    require((status == STIPPLE_OK) == (arity >= 1 && arity <= 3 && capacity >= arity));
    if (status != STIPPLE_OK) return;
    checkValues(out, arity);
    for (size_t j = arity; j < 5; ++j) require(out[j] == -1.0f);
}

void serve(FuzzInput& in, const Live& live, bool batch) {
    const uint32_t dimension = (in.byte() & 0x80) ? in.u32() : in.byte() % (live.dimensionCount + 1);
    const uint32_t x = (in.byte() & 1) ? in.u32() : in.byte(), y = (in.byte() & 1) ? in.u32() : in.byte();
    stipple_dimension_info info{};
    info.struct_size = sizeof info;
    const stipple_status infoStatus = stipple_sampler_get_dimension_info(live.sampler, dimension, &info);
    checkFailureHasMessage(infoStatus);
    require((infoStatus == STIPPLE_OK) == (dimension < live.dimensionCount));
    if (infoStatus != STIPPLE_OK) {
        float scratch[4];
        require(stipple_sampler_fill_pixel(live.sampler, x, y, dimension, scratch, 4) == STIPPLE_ERROR_OUT_OF_RANGE);
        serveStream(in, live, dimension, x, y);
        return;
    }
    require(info.floats_per_pixel == uint64_t(live.samplesPerPixel) * info.count * info.arity);
    if (!cheapToServe(live, info)) return;
    const size_t perSample = size_t(info.count) * info.arity;
    // The buffer is exactly as large as the capacity we claim; sometimes too small (must fail cleanly).
    const bool shortBuffer = (in.byte() % 8) == 0;
    if (batch) {
        const size_t capacity = shortBuffer ? in.u32() % info.floats_per_pixel : info.floats_per_pixel;
        std::vector<float> out(capacity + 1, -1.0f);
        const stipple_status status = stipple_sampler_fill_pixel(live.sampler, x, y, dimension, out.data(), capacity);
        checkFailureHasMessage(status);
        require((status == STIPPLE_OK) == !shortBuffer);
        if (status != STIPPLE_OK) return;
        checkValues(out.data(), capacity);
        require(out[capacity] == -1.0f); // nothing written past the capacity
        // Random access agrees bitwise with the batch.
        const uint32_t i = in.u32() % live.samplesPerPixel;
        std::vector<float> one(perSample);
        require(stipple_sampler_sample(live.sampler, x, y, i, dimension, one.data(), one.size()) == STIPPLE_OK);
        require(std::memcmp(one.data(), out.data() + size_t(i) * perSample, perSample * sizeof(float)) == 0);
    } else {
        const uint32_t i = (in.byte() & 1) ? in.u32() : in.byte() % live.samplesPerPixel;
        const size_t capacity = shortBuffer ? perSample - 1 : perSample + in.byte() % 4;
        std::vector<float> out(capacity + 1, -1.0f);
        const stipple_status status = stipple_sampler_sample(live.sampler, x, y, i, dimension, out.data(), capacity);
        checkFailureHasMessage(status);
        require((status == STIPPLE_OK) == !shortBuffer); // any sample index is served (1.1)
        if (status == STIPPLE_OK) {
            checkValues(out.data(), perSample);
            for (size_t j = perSample; j <= capacity; ++j) require(out[j] == -1.0f);
        }
    }
}

void queryInfo(FuzzInput& in, const Live& live) {
    const uint8_t shape = in.byte();
    // struct_size: the real one, too small, or larger with a zeroed tail (output structs are zeroed then filled).
    unsigned char buffer[sizeof(stipple_dimension_info) + 16];
    std::memset(buffer, 0xab, sizeof buffer);
    const uint32_t size = (shape & 1) ? uint32_t(in.byte() % sizeof buffer) : uint32_t(sizeof(stipple_dimension_info));
    std::memcpy(buffer, &size, sizeof size);
    stipple_status status;
    if (shape & 2) {
        uint32_t infoSize =
            (shape & 1) ? size % (sizeof(stipple_sampler_info) + 16) : uint32_t(sizeof(stipple_sampler_info));
        std::memcpy(buffer, &infoSize, sizeof infoSize);
        status = stipple_sampler_get_info(live.sampler,
                                          (shape & 4) ? nullptr : reinterpret_cast<stipple_sampler_info*>(buffer));
    } else {
        status = stipple_sampler_get_dimension_info(live.sampler, in.byte() % (live.dimensionCount + 2),
                                                    (shape & 4) ? nullptr
                                                                : reinterpret_cast<stipple_dimension_info*>(buffer));
        if (status == STIPPLE_OK) {
            stipple_dimension_info info;
            std::memcpy(&info, buffer, sizeof info);
            require(info.name != nullptr && std::strlen(info.name) <= STIPPLE_MAX_NAME_LENGTH);
            uint32_t found = ~0u;
            const stipple_status findStatus = stipple_sampler_find_dimension(live.sampler, info.name, &found);
            if (info.name[0] != '\0') require(findStatus == STIPPLE_OK && found < live.dimensionCount);
        }
    }
    checkFailureHasMessage(status);
}

void independentStream(FuzzInput& in, const Live& live) {
    const uint32_t x = in.u32(), y = in.u32(), i = in.u32(), stream = in.u32();
    const size_t count = in.byte() % 64;
    std::vector<float> out(count + 1, -1.0f);
    const stipple_status status = stipple_sampler_sample_independent(live.sampler, x, y, i, stream,
                                                                     (in.byte() % 16) ? out.data() : nullptr, count);
    checkFailureHasMessage(status);
    if (status == STIPPLE_OK) checkValues(out.data(), count);
    require(out[count] == -1.0f);
}

void names(FuzzInput& in) {
    const std::string name = in.text(24);
    uint32_t pattern = ~0u;
    stipple_status status = stipple_pattern_from_name((in.byte() % 16) ? name.c_str() : nullptr, &pattern);
    checkFailureHasMessage(status);
    if (status == STIPPLE_OK) {
        const char* back = nullptr;
        // The library reads the name up to its first NUL: compare that much (the input may hold NULs after it).
        require(stipple_pattern_name(pattern, &back) == STIPPLE_OK && back && std::strcmp(name.c_str(), back) == 0);
    }
    const char* out = nullptr;
    status = stipple_pattern_name(in.u32() % 8, (in.byte() % 16) ? &out : nullptr);
    checkFailureHasMessage(status);
    if (status == STIPPLE_OK) require(out != nullptr);
    const stipple_api* api = nullptr;
    status = stipple_get_api(in.byte() % 3, &api);
    checkFailureHasMessage(status);
    if (status == STIPPLE_OK) require(api && api->struct_size >= sizeof(stipple_api) && api->sampler_create);
    uint32_t major, minor, patch;
    const uint8_t nulls = in.byte();
    checkFailureHasMessage(stipple_get_version((nulls & 1) ? nullptr : &major, (nulls & 2) ? nullptr : &minor,
                                               (nulls & 4) ? nullptr : &patch));
    uint32_t found;
    checkFailureHasMessage(stipple_sampler_find_dimension(nullptr, name.c_str(), &found));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzInput in(data, size);
    std::vector<Live> live;
    for (int calls = 0; calls < 64 && !in.done(); ++calls) {
        const uint8_t op = in.byte();
        if (op % 8 == 0 || live.empty()) {
            if (op % 16 == 8)
                names(in);
            else
                create(in, live);
            continue;
        }
        Live& target = live[in.byte() % live.size()];
        switch (op % 8) {
        case 1: serve(in, target, true); break;
        case 2: serve(in, target, false); break;
        case 3: queryInfo(in, target); break;
        case 4: independentStream(in, target); break;
        case 5: {
            uint32_t found = 0;
            const std::string name = in.text(70);
            checkFailureHasMessage(stipple_sampler_find_dimension(target.sampler, name.c_str(), &found));
            break;
        }
        case 6:
            require(stipple_sampler_release(target.sampler) == STIPPLE_OK);
            live.erase(live.begin() + (&target - live.data()));
            break;
        default: names(in); break;
        }
    }
    for (const Live& l : live) require(stipple_sampler_release(l.sampler) == STIPPLE_OK);
    require(stipple_sampler_release(nullptr) == STIPPLE_OK);
    return 0;
}
