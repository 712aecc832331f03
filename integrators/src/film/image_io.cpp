// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Image output: float EXR with the project's metadata vocabulary through OpenImageIO, and an sRGB PNG preview:
// through the user's OpenColorIO config ($OCIO: its scene_linear role to its default display and view) when one
// is set, else OIIO's built-in linear -> sRGB. Both are written to a temporary file beside the target and renamed
// into place, so a failed run never destroys a good image.
#include <stipple/render/image_io.h>
#include <stipple/render/renderer_identity.h>
#include <stipple/render/temp_files.h>

#include <OpenImageIO/color.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace stipple::render {

namespace {

void writeWithOiio(const std::string& path, const OIIO::ImageSpec& spec, const void* pixels, OIIO::TypeDesc type) {
    // A path that is itself a registered temporary (output_publish.h) is written directly.
    const bool direct = isTempName(std::filesystem::path(path).filename().string());
    std::optional<TempPath> temp;
    if (!direct) temp.emplace(path);
    const std::string tmp = direct ? path : temp->path();
    SignalHold hold; // created and closed (and renamed) before a signal's cleanup, or not at all
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error("cannot write '" + path + "': " + OIIO::geterror());
    if (!out->open(tmp, spec) || !out->write_image(type, pixels)) {
        std::string e = out->geterror();
        out->close();
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot write '" + path + "': " + e);
    }
    if (!out->close()) {
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
    }
    if (direct) return;
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "': " + ec.message());
    temp->release();
}

void checkImage(const Image& image, const std::string& path) {
    if (image.width <= 0 || image.height <= 0 || image.rgb.size() != size_t(image.width) * image.height * 3)
        throw std::invalid_argument("cannot write '" + path + "': the image is empty or its size does not match");
}

// Scene-linear to display-referred [0, 1], in place. OIIO's ColorConfig reads $OCIO when it is set.
// A preview is small: converting it on the calling thread keeps OIIO's own thread pool (which the renderer's
// thread count does not govern, and which ThreadSanitizer cannot see into) out of the process.
void toDisplay(OIIO::ImageBuf& buffer) {
    constexpr int kThreads = 1;
    static OIIO::ColorConfig config;
    static std::mutex mutex; // a ColorConfig caches its processors: one caller at a time
    std::lock_guard<std::mutex> lock(mutex);
    const char* ocio = std::getenv("OCIO");
    bool ok;
    if (ocio && *ocio) {
        const char* linear = config.getColorSpaceNameByRole("scene_linear");
        ok = OIIO::ImageBufAlgo::ociodisplay(buffer, buffer, config.getDefaultDisplayName(),
                                             config.getDefaultViewName(), linear ? linear : "linear", "", false, "", "",
                                             &config, OIIO::ROI(), kThreads);
    } else {
        ok = OIIO::ImageBufAlgo::colorconvert(buffer, buffer, "linear", "sRGB", false, "", "", &config, OIIO::ROI(),
                                              kThreads);
    }
    if (!ok) throw std::runtime_error("colour conversion to the display failed: " + buffer.geterror());
}

} // namespace

void writeExr(const std::string& path, const Image& image, const ImageMetadata& metadata) {
    checkImage(image, path);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    // Standard attributes image tools look for: the writer and the colour space (scene-linear Rec.709 primaries,
    // D65 white: x,y of red, green, blue, white).
    spec.attribute("Software", rendererVersion());
    const float rec709[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), rec709);
    spec.attribute("oiio:ColorSpace", "lin_rec709");
    for (const auto& [key, value] : metadata) {
        if (key.empty() || key.find(':') != std::string::npos)
            throw std::invalid_argument("cannot write '" + path + "': metadata key '" + key +
                                        "' must be a bare name (writeExr adds the " + std::string(kMetadataPrefix) +
                                        " prefix)");
        spec.attribute(kMetadataPrefix + key, value);
    }
    writeWithOiio(path, spec, image.rgb.data(), OIIO::TypeDesc::FLOAT);
}

ImageMetadata readExrMetadata(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read '" + path + "': " + OIIO::geterror());
    ImageMetadata metadata;
    const std::string prefix = kMetadataPrefix;
    for (const OIIO::ParamValue& p : in->spec().extra_attribs) {
        const std::string name = p.name().string();
        if (name.rfind(prefix, 0) == 0) metadata.emplace_back(name.substr(prefix.size()), p.get_string());
    }
    return metadata;
}

void writePng(const std::string& path, const Image& image, float exposureStops) {
    checkImage(image, path);
    std::vector<float> rgb = image.rgb;
    float scale = std::exp2(exposureStops);
    for (float& v : rgb) v = std::isfinite(v) ? std::max(0.0f, v * scale) : 0.0f;
    OIIO::ImageBuf buffer(OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT), rgb.data());
    toDisplay(buffer);
    std::vector<unsigned char> bytes(rgb.size());
    for (size_t i = 0; i < rgb.size(); ++i)
        bytes[i] = static_cast<unsigned char>(std::lround(std::min(1.0f, std::max(0.0f, rgb[i])) * 255.0f));
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    writeWithOiio(path, spec, bytes.data(), OIIO::TypeDesc::UINT8);
}

Image readImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3) throw std::runtime_error("cannot read '" + path + "': fewer than 3 channels");
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read '" + path + "': " + in->geterror());
    image.rgb.resize(size_t(spec.width) * spec.height * 3);
    for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = all[i * spec.nchannels + c];
    return image;
}

} // namespace stipple::render
