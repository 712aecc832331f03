// Image output: float EXR with metadata through OpenImageIO, an sRGB PNG preview through OpenColorIO (a config
// built in code: scene-linear Rec.709 -> sRGB display, the sRGB curve as ExponentWithLinearTransform gamma 2.4
// offset 0.055). Both are written to a temporary file beside the target and renamed into place, so a failed
// run never destroys a good image.
#include <stipple/render/renderer.h>
#include <stipple/render/temp_files.h>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <unistd.h>

namespace OCIO = OCIO_NAMESPACE;

namespace stipple::render {

namespace {

void writeWithOiio(const std::string& path, const OIIO::ImageSpec& spec, const void* pixels, OIIO::TypeDesc type) {
    // A path that is itself a registered temporary (output_publish.h) is written directly.
    const bool direct = isTempName(std::filesystem::path(path).filename().string());
    std::optional<TempPath> temp;
    if (!direct) temp.emplace(path);
    const std::string tmp = direct ? path : temp->path();
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

OCIO::ConstCPUProcessorRcPtr srgbProcessor() {
    static OCIO::ConstCPUProcessorRcPtr processor = [] {
        OCIO::ConfigRcPtr config = OCIO::Config::Create();
        auto linear = OCIO::ColorSpace::Create();
        linear->setName("lin_rec709");
        linear->setEncoding("scene-linear");
        config->addColorSpace(linear);
        auto display = OCIO::ColorSpace::Create();
        display->setName("srgb_display");
        display->setEncoding("sdr-video");
        auto curve = OCIO::ExponentWithLinearTransform::Create();
        double gamma[4] = {2.4, 2.4, 2.4, 1.0}, offset[4] = {0.055, 0.055, 0.055, 0.0};
        curve->setGamma(gamma);
        curve->setOffset(offset);
        display->setTransform(curve, OCIO::COLORSPACE_DIR_TO_REFERENCE);
        config->addColorSpace(display);
        for (const char* role : {OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_REFERENCE, OCIO::ROLE_DEFAULT, OCIO::ROLE_DATA})
            config->setRole(role, "lin_rec709");
        config->addDisplayView("sRGB", "Standard", "srgb_display", "");
        config->validate();
        auto t = OCIO::DisplayViewTransform::Create();
        t->setSrc(OCIO::ROLE_SCENE_LINEAR);
        t->setDisplay("sRGB");
        t->setView("Standard");
        return config->getProcessor(t)->getDefaultCPUProcessor();
    }();
    return processor;
}

} // namespace

void writeExr(const std::string& path, const Image& image,
              const std::vector<std::pair<std::string, std::string>>& metadata) {
    checkImage(image, path);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    for (const auto& [k, v] : metadata) spec.attribute("stipple:" + k, v);
    writeWithOiio(path, spec, image.rgb.data(), OIIO::TypeDesc::FLOAT);
}

void writePng(const std::string& path, const Image& image, float exposureStops) {
    checkImage(image, path);
    std::vector<float> rgb = image.rgb;
    float scale = std::exp2(exposureStops);
    for (float& v : rgb) v = std::isfinite(v) ? std::max(0.0f, v * scale) : 0.0f;
    OCIO::PackedImageDesc desc(rgb.data(), image.width, image.height, 3);
    srgbProcessor()->apply(desc);
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
