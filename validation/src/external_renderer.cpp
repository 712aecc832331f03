// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "external_renderer.h"
#include "external_command.h"
#include "results.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <stipple/render/content_hash.h>

extern char** environ;

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

std::string signalName(int signal) {
    const char* name = strsignal(signal);
    return std::to_string(signal) + (name ? std::string(" (") + name + ")" : "");
}

// The last lines of a program's output, for an error message.
std::string tail(const std::string& path, size_t maxBytes = 600) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.size() > maxBytes) text = "..." + text.substr(text.size() - maxBytes);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
}

// The executable a program name resolves to (as execvp would find it), or "" if none.
std::string resolveProgram(const std::string& program) {
    if (program.find('/') != std::string::npos) return access(program.c_str(), X_OK) == 0 ? program : "";
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    size_t start = 0;
    while (start <= dirs.size()) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string candidate = (end > start ? dirs.substr(start, end - start) : ".") + "/" + program;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return "";
}

struct ChildRun {
    int status = 0;
    double wallSeconds = 0, cpuSeconds = 0;
};

// Runs argv (no shell) with stdin from /dev/null and stdout + stderr into logPath; waits for it.
ChildRun runChild(const std::vector<std::string>& argv, const std::string& logPath, const std::string& cell) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw std::runtime_error(cell + ": cannot run '" + argv[0] + "': " + std::strerror(spawned));
    ChildRun run;
    struct rusage usage {};
    pid_t waited;
    do {
        waited = wait4(pid, &run.status, 0, &usage);
    } while (waited < 0 && errno == EINTR);
    if (waited != pid) throw std::runtime_error(cell + ": waiting for '" + argv[0] + "' failed: " + std::strerror(errno));
    run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.cpuSeconds = double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec) +
                     double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec);
    return run;
}

bool startsWith(const std::string& path, const char* magic, size_t size) {
    std::ifstream in(path, std::ios::binary);
    char bytes[4] = {};
    return in.read(bytes, std::streamsize(size)) && std::memcmp(bytes, magic, size) == 0;
}

// The cached reference of an external scene: <cache>/external-<key>.exr, -variance.exr and .key (the full key
// material, compared on every use). Written image first, key last, each by writeExr's atomic rename.
struct ExternalCache {
    std::string image, variance, key;
    explicit ExternalCache(const std::string& dir, const std::string& hex)
        : image((fs::path(dir) / ("external-" + hex + ".exr")).string()),
          variance((fs::path(dir) / ("external-" + hex + "-variance.exr")).string()),
          key((fs::path(dir) / ("external-" + hex + ".key")).string()) {}
};

} // namespace

ExternalRenderer::ExternalRenderer(const MatrixScene& scene, const RendererPermission& permission, std::string workDir)
    : scene_(scene), command_(scene.renderer.command), workDir_(std::move(workDir)) {
    if (!permission.program.empty())
        command_[0] = permission.program;
    else if (!permission.allowMatrixProgram)
        throw std::runtime_error("the matrix runs scene " + scene.name + " with an external renderer ('" +
                                 scene.renderer.command[0] + "', " + scene.renderer.where +
                                 "); a matrix alone does not run programs: pass --allow-renderer to run the matrix's "
                                 "command or --renderer PROGRAM to name the program");
    program_ = resolveProgram(command_[0]);
    if (program_.empty())
        throw std::runtime_error("scene " + scene.name + ": the external renderer '" + command_[0] +
                                 "' is not an executable file (nor found on PATH)");
}

std::vector<std::string> ExternalRenderer::expand(const render::RenderOptions& o, const std::string& output) const {
    return expandCommand(command_, {{"scene", scene_.path},
                                    {"pattern", o.pattern},
                                    {"spp", std::to_string(o.spp)},
                                    {"seed", std::to_string(o.seed)},
                                    {"width", std::to_string(o.width)},
                                    {"height", std::to_string(o.height)},
                                    {"output", output}});
}

std::string ExternalRenderer::cellName(const render::RenderOptions& o) const {
    return "scene " + scene_.name + ", " + o.pattern + ", " + std::to_string(o.spp) + " spp, seed " +
           std::to_string(o.seed) + " (external renderer " + command_[0] + ")";
}

render::RenderResult ExternalRenderer::render(const render::RenderOptions& o) const {
    const std::string cell = cellName(o);
    const std::string stem = (fs::path(workDir_) / ("image-" + std::to_string(o.seed) + "-" + std::to_string(o.spp)))
                                 .string();
    const std::string output = stem + (scene_.renderer.format == "pfm" ? ".pfm" : ".exr"), log = stem + ".log";
    std::error_code ignored;
    fs::remove(output, ignored);
    const ChildRun run = runChild(expand(o, output), log, cell);
    if (WIFSIGNALED(run.status))
        throw std::runtime_error(cell + ": the renderer was killed by signal " + signalName(WTERMSIG(run.status)) +
                                 "; its output ends: " + tail(log));
    if (!WIFEXITED(run.status) || WEXITSTATUS(run.status) != 0)
        throw std::runtime_error(cell + ": the renderer exited with status " + std::to_string(WEXITSTATUS(run.status)) +
                                 "; its output ends: " + tail(log));
    if (!fs::is_regular_file(output, ignored))
        throw std::runtime_error(cell + ": the renderer exited with status 0 but wrote no image at {output} (" +
                                 output + ")");
    render::RenderResult r;
    try {
        r.image = startsWith(output, "PF", 2) || startsWith(output, "Pf", 2) ? readPfm(output) : render::readImage(output);
    } catch (const std::exception& e) {
        throw std::runtime_error(cell + ": cannot read the image it wrote (" + output + "): " + e.what());
    }
    fs::remove(output, ignored);
    fs::remove(log, ignored);
    if (r.image.width != o.width || r.image.height != o.height)
        throw std::runtime_error(cell + ": the image is " + std::to_string(r.image.width) + "x" +
                                 std::to_string(r.image.height) + "; the matrix asks for " + std::to_string(o.width) +
                                 "x" + std::to_string(o.height));
    for (float v : r.image.rgb) r.nonFiniteSamples += std::isfinite(v) ? 0 : 1; // pixels' channels, not samples
    r.renderSeconds = run.wallSeconds;
    r.cpuSeconds = run.cpuSeconds;
    r.settings = o;
    return r;
}

std::string ExternalRenderer::contentHash() const {
    render::ContentHash hash;
    hash.add("external\n");
    for (const std::string& a : command_) hash.add(a).add('\0');
    hash.addFile(program_);
    hash.addFile(scene_.path);
    return hash.hex();
}

std::string ExternalRenderer::description() const { return "external: " + fs::path(command_[0]).filename().string(); }

Reference ExternalRenderer::reference(const render::RenderOptions& o, const std::vector<uint64_t>& cellSeeds,
                                      const std::string& cacheDir) const {
    // Two halves with seeds the cells do not use.
    uint64_t seeds[2] = {o.seed, o.seed ^ 0x9e3779b97f4a7c15ull};
    for (uint64_t& s : seeds)
        while (std::find(cellSeeds.begin(), cellSeeds.end(), s) != cellSeeds.end()) ++s;
    const std::string material = "external reference v1\ncontent " + contentHash() + "\npattern " + o.pattern +
                                 "\nspp " + std::to_string(o.spp) + "\nseeds " + std::to_string(seeds[0]) + " " +
                                 std::to_string(seeds[1]) + "\nsize " + std::to_string(o.width) + "x" +
                                 std::to_string(o.height) + "\n";
    Reference ref;
    ref.key = keyOf(material);
    const ExternalCache cache(cacheDir, ref.key);
    ref.imagePath = cache.image;
    std::error_code ignored;
    if (fs::is_regular_file(cache.key, ignored)) {
        std::ifstream in(cache.key, std::ios::binary);
        const std::string stored((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        try {
            if (stored == material) {
                ref.image = render::readImage(cache.image);
                ref.variance = render::readImage(cache.variance);
                if (ref.image.width == o.width && ref.image.height == o.height &&
                    ref.variance.width == o.width && ref.variance.height == o.height) {
                    ref.fromCache = true;
                    return ref;
                }
                ref.cacheProblem = "cached images of another size";
            } else {
                ref.cacheProblem = "its key material differs";
            }
        } catch (const std::exception& e) {
            ref.cacheProblem = e.what();
        }
    }
    render::RenderOptions half = o;
    half.spp = std::max<uint32_t>(1, o.spp / 2);
    half.seed = seeds[0];
    const render::RenderResult a = render(half);
    half.seed = seeds[1];
    const render::RenderResult b = render(half);
    // Equal halves: the program ignores {seed} or maps both seeds to one value; every verdict would be confident
    // and wrong.
    if (a.image.rgb == b.image.rgb)
        throw std::runtime_error(scene_.name + ": the reference's two halves (seeds " + std::to_string(seeds[0]) +
                                 " and " + std::to_string(seeds[1]) + ", " + std::to_string(half.spp) +
                                 " spp) are bitwise equal: the renderer ignores {seed} or maps these seeds to one "
                                 "value ({seed} is any unsigned 64-bit number)");
    ref.image = a.image;
    ref.variance = a.image;
    for (size_t i = 0; i < a.image.rgb.size(); ++i) {
        ref.image.rgb[i] = 0.5f * (a.image.rgb[i] + b.image.rgb[i]);
        const double d = double(a.image.rgb[i]) - b.image.rgb[i];
        ref.variance.rgb[i] = float(d * d / 4); // the variance of the mean of two equal-spp halves
    }
    ref.renderSeconds = a.renderSeconds + b.renderSeconds;
    ref.fromCache = false;
    fs::create_directories(cacheDir, ignored);
    const render::ImageMetadata meta = {{"scene", scene_.name}, {"reference_key", ref.key}};
    render::writeExr(cache.image, ref.image, meta);
    render::writeExr(cache.variance, ref.variance, meta);
    writeTextFile(cache.key, material); // last: it vouches for the two images
    return ref;
}

SceneFingerprint externalFingerprint(const MatrixScene& scene, uint32_t referenceSpp) {
    render::ContentHash hash;
    hash.add("external\n");
    for (const std::string& a : scene.renderer.command) hash.add(a).add('\0');
    hash.addFile(scene.path);
    SceneFingerprint f;
    f.loaded = true;
    f.contentHash = hash.hex();
    f.width = scene.width;
    f.height = scene.height;
    f.integrator = "external: " + fs::path(scene.renderer.command[0]).filename().string();
    f.referenceSpp = referenceSpp;
    return f;
}

render::Image readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open");
    std::string magic;
    long long width = 0, height = 0;
    double scale = 0;
    in >> magic >> width >> height >> scale;
    if (!in || (magic != "PF" && magic != "Pf")) throw std::runtime_error(path + ": not a PFM file (header)");
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || scale == 0)
        throw std::runtime_error(path + ": bad PFM size or scale");
    in.get(); // the single whitespace after the scale
    const int channels = magic == "PF" ? 3 : 1;
    std::vector<float> data(size_t(width) * height * channels);
    if (!in.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size() * sizeof(float))))
        throw std::runtime_error(path + ": PFM data shorter than " + std::to_string(width) + "x" +
                                 std::to_string(height) + "x" + std::to_string(channels) + " floats");
    const bool bigEndian = scale > 0;
    if (bigEndian)
        for (float& v : data) {
            uint32_t bits;
            std::memcpy(&bits, &v, 4);
            bits = __builtin_bswap32(bits);
            std::memcpy(&v, &bits, 4);
        }
    render::Image image;
    image.width = int(width);
    image.height = int(height);
    image.rgb.resize(size_t(width) * height * 3);
    for (long long y = 0; y < height; ++y) // PFM rows run bottom to top
        for (long long x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                image.rgb[(size_t(height - 1 - y) * width + x) * 3 + c] =
                    data[(size_t(y) * width + x) * channels + (channels == 3 ? c : 0)];
    return image;
}

} // namespace stipple::validation
