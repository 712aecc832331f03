#include "sampling/pixel_sampler.h"

#include <chrono>
#include <stdexcept>

namespace stipple::render {

PixelSampler::PixelSampler(const ShimLibrary& shim, const std::string& pattern, uint32_t spp, uint64_t seed,
                           const SampleLayout& layout)
    : shim_(shim), spp_(spp), layout_(layout) {
    const stipple_api& api = shim.api();
    // "<name>" or "<name>+blue-noise" (the shim's STIPPLE_SAMPLER_FLAG_BLUE_NOISE); names come from the shim.
    static const std::string kBlueNoise = "+blue-noise";
    std::string name = pattern;
    uint32_t flags = 0;
    if (name.size() > kBlueNoise.size() &&
        name.compare(name.size() - kBlueNoise.size(), kBlueNoise.size(), kBlueNoise) == 0) {
        name.resize(name.size() - kBlueNoise.size());
        flags |= STIPPLE_SAMPLER_FLAG_BLUE_NOISE;
    }
    uint32_t patternId = 0;
    if (api.pattern_from_name(name.c_str(), &patternId) != STIPPLE_OK) {
        // A bad name is the caller's argument, not a shim failure (stipple-render exits with 2 on it).
        std::string known;
        for (const std::string& n : shim.patternNames()) known += (known.empty() ? "" : ", ") + n;
        throw std::invalid_argument("unknown pattern '" + pattern + "' (" + shim.lastError() + "); expected one of " +
                                    known + ", optionally followed by " + kBlueNoise);
    }
    std::vector<stipple_dimension_desc> dims;
    for (const Dimension& d : layout.dimensions()) {
        stipple_dimension_desc desc{};
        desc.struct_size = sizeof(stipple_dimension_desc);
        desc.arity = d.arity;
        desc.count = d.count;
        desc.name = d.name.c_str();
        dims.push_back(desc);
    }
    stipple_sampler_desc desc{};
    desc.struct_size = sizeof(stipple_sampler_desc);
    desc.pattern = patternId;
    desc.samples_per_pixel = spp;
    desc.dimension_count = uint32_t(dims.size());
    desc.seed = seed;
    desc.dimensions = dims.data();
    desc.flags = flags;
    if (api.sampler_create(&desc, &sampler_) != STIPPLE_OK)
        throw ShimError("cannot create a '" + pattern + "' sampler with " + std::to_string(spp) + " spp and " +
                        std::to_string(dims.size()) + " dimensions: " + shim.lastError());
}

PixelSampler::~PixelSampler() { shim_.api().sampler_release(sampler_); }

void PixelSampler::fillPixel(uint32_t x, uint32_t y, PixelSamples& out) const {
    auto start = std::chrono::steady_clock::now();
    const stipple_api& api = shim_.api();
    for (size_t d = 0; d < out.offset_.size(); ++d) {
        size_t n = size_t(spp_) * out.stride_[d];
        if (api.sampler_fill_pixel(sampler_, x, y, uint32_t(d), out.values_.data() + out.offset_[d], n) != STIPPLE_OK)
            throw ShimError("stipple_sampler_fill_pixel(" + std::to_string(x) + ", " + std::to_string(y) +
                            ", dimension " + std::to_string(d) + ") failed: " + shim_.lastError());
    }
    out.samplerSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

PixelSamples::PixelSamples(const PixelSampler& sampler) {
    size_t total = 0;
    for (const Dimension& d : sampler.layout().dimensions()) {
        offset_.push_back(total);
        stride_.push_back(d.count * d.arity);
        arity_.push_back(d.arity);
        total += size_t(sampler.samplesPerPixel()) * d.count * d.arity;
    }
    values_.assign(total, 0.0f);
}

} // namespace stipple::render
