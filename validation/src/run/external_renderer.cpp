// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/external_renderer.h"
#include "matrix/external_command.h"
#include "metrics/pfm_image.h"
#include "run/reference_integrity.h"
#include "run/results.h"

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
#include <sstream>
#include <stdexcept>

#include <stipple/render/content_hash.h>
#include <stipple/render/input_limits.h>
#include <stipple/render/temp_files.h>

extern char** environ;

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

std::string signalName(int signal) {
    const char* name = strsignal(signal);
    return std::to_string(signal) + (name ? std::string(" (") + name + ")" : "");
}

// The last lines of a program's output, for an error message: only the file's last maxBytes are read (a
// renderer's log may be gigabytes).
std::string tail(const std::string& path, size_t maxBytes = 600) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = in ? std::streamoff(in.tellg()) : 0;
    const std::streamoff from = size > std::streamoff(maxBytes) ? size - std::streamoff(maxBytes) : 0;
    std::string text(size_t(size - from), '\0');
    in.seekg(from);
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
    for (char& c : text) // a NUL or an escape sequence of the program's must not cut or garble the message
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7f) c = '?';
    if (from > 0) text = "..." + text;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
}

// The file a program name resolves to, as execvp would find it (the first PATH entry where it is executable),
// or "" with `why`: the result must be one regular file that is executable and readable (its bytes are hashed into
// the reference key), so a directory, a FIFO or an execute-only program is an error, never hashed as no bytes.
std::string resolveProgram(const std::string& program, std::string& why) {
    auto usable = [&](const std::string& candidate) -> int { // 1 usable, 0 not there, -1 there but unusable
        struct stat st {};
        if (::stat(candidate.c_str(), &st) != 0) return 0;
        if (S_ISDIR(st.st_mode)) {
            why = "resolves to a folder (" + candidate + ")";
            return program.find('/') != std::string::npos ? -1 : 0; // execvp skips a folder on PATH
        }
        if (access(candidate.c_str(), X_OK) != 0) return 0;
        if (!S_ISREG(st.st_mode)) {
            why = "resolves to " + candidate + ", which is not a regular file";
            return -1;
        }
        if (access(candidate.c_str(), R_OK) != 0) {
            why = "resolves to " + candidate + ", which is executable but not readable (its bytes key the reference)";
            return -1;
        }
        return 1;
    };
    why = "is not an executable file (nor found on PATH)";
    if (program.find('/') != std::string::npos) return usable(program) == 1 ? program : "";
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    size_t start = 0;
    while (start <= dirs.size()) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string candidate = (end > start ? dirs.substr(start, end - start) : ".") + "/" + program;
        if (const int u = usable(candidate); u != 0) return u == 1 ? candidate : "";
        start = end + 1;
    }
    return "";
}

struct ChildRun {
    int status = 0;
    double wallSeconds = 0, cpuSeconds = 0;
};

// Runs the executable (resolved once, so the program run is the one hashed) with argv (no shell), stdin from
// /dev/null, stdout + stderr into logPath, in a process group of its own that the signal cleanup kills and reaps
// (render::registerChildGroup). Waits for it; past timeoutSeconds (> 0) kills the group and throws naming the
// cell. Whatever the program left running in its group is killed when it ends.
ChildRun runChild(const std::string& executable, const std::vector<std::string>& argv, const std::string& logPath,
                  const std::string& cell, double timeoutSeconds) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0); // its own group, led by itself
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    int spawned = 0;
    {
        render::SignalHold hold; // started and registered, or (after a signal's cleanup began) never started
        spawned = posix_spawn(&pid, executable.c_str(), &actions, &attributes, args.data(), environ);
        if (spawned == 0) render::registerChildGroup(pid);
    }
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (spawned != 0)
        throw std::runtime_error(cell + ": cannot run '" + argv[0] + "': " + std::strerror(spawned));
    struct Unregister {
        pid_t pid;
        ~Unregister() { render::unregisterChildGroup(pid); }
    } unregister{pid};
    // Poll for its end without reaping it: while the leader is a zombie its group id cannot be reused, so the
    // group can be killed safely once it has ended (or when it has run too long).
    bool timedOut = false;
    for (;;) {
        siginfo_t info{};
        const int w = waitid(P_PID, id_t(pid), &info, WEXITED | WNOHANG | WNOWAIT);
        if (w < 0 && errno == EINTR) continue;
        if (w < 0) throw std::runtime_error(cell + ": waiting for '" + argv[0] + "' failed: " + std::strerror(errno));
        if (info.si_pid == pid) break;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (timeoutSeconds > 0 && elapsed > timeoutSeconds) {
            timedOut = true;
            break;
        }
        usleep(elapsed < 1 ? 2000 : 20000);
    }
    ::kill(-pid, SIGKILL); // the program's own children, or all of it when it ran too long
    ChildRun run;
    struct rusage usage {};
    pid_t waited;
    do {
        waited = wait4(pid, &run.status, 0, &usage);
    } while (waited < 0 && errno == EINTR);
    if (waited != pid) throw std::runtime_error(cell + ": waiting for '" + argv[0] + "' failed: " + std::strerror(errno));
    if (timedOut)
        throw std::runtime_error(cell + ": the renderer ran longer than the per-image timeout of " +
                                 std::to_string(timeoutSeconds).substr(0, std::to_string(timeoutSeconds).find('.') + 2) +
                                 " s (renderer timeout in the matrix, --renderer-timeout) and was killed; its output "
                                 "ends: " + tail(logPath));
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

// What the .key file holds after the key material: both images' pixel checksums.
std::string checksumLines(const render::Image& image, const render::Image& variance) {
    return "image " + pixelChecksumHex(image) + "\nvariance " + pixelChecksumHex(variance) + "\n";
}

} // namespace

std::string checkRendererPermission(const MatrixScene& scene, const RendererPermission& permission) {
    const std::vector<std::string>& command = scene.renderer.command;
    if (!permission.granted())
        return "the matrix runs scene " + scene.name + " with an external renderer ('" + command[0] + "', " +
               scene.renderer.where +
               "); a matrix alone does not run programs: pass --renderer-command FILE with --allow-renderer to run "
               "the matrix's command or with --renderer PROGRAM to name the program";
    const bool full = permission.program.empty(); // --allow-renderer: the program is the template's too
    for (const auto& allowed : permission.commands)
        if (full ? allowed == command
                 : allowed.size() == command.size() && std::equal(allowed.begin() + 1, allowed.end(), command.begin() + 1))
            return "";
    std::string text;
    for (const std::string& a : command) text += (text.empty() ? "" : " ") + a;
    return scene.renderer.where + ": scene " + scene.name + ": the command [" + text + "] is not one the command line " +
           "allows: a matrix's template runs only when it is byte-equal to a template of --renderer-command FILE" +
           (full ? "" : " (from its second argument on, with --renderer)");
}

ExternalRenderer::ExternalRenderer(const MatrixScene& scene, const RendererPermission& permission, std::string workDir)
    : scene_(scene), command_(scene.renderer.command), workDir_(std::move(workDir)) {
    if (const std::string why = checkRendererPermission(scene, permission); !why.empty()) throw std::runtime_error(why);
    if (!permission.program.empty()) command_[0] = permission.program;
    timeoutSeconds_ = permission.timeoutSeconds > 0 ? permission.timeoutSeconds : scene.renderer.timeoutSeconds;
    std::string why;
    program_ = resolveProgram(command_[0], why);
    if (program_.empty())
        throw std::runtime_error("scene " + scene.name + ": the external renderer '" + command_[0] + "' " + why);
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
    const ChildRun run = runChild(program_, expand(o, output), log, cell, timeoutSeconds_);
    if (WIFSIGNALED(run.status))
        throw std::runtime_error(cell + ": the renderer was killed by signal " + signalName(WTERMSIG(run.status)) +
                                 "; its output ends: " + tail(log));
    if (!WIFEXITED(run.status) || WEXITSTATUS(run.status) != 0)
        throw std::runtime_error(cell + ": the renderer exited with status " + std::to_string(WEXITSTATUS(run.status)) +
                                 "; its output ends: " + tail(log));
    if (!fs::exists(fs::symlink_status(output, ignored)))
        throw std::runtime_error(cell + ": the renderer exited with status 0 but wrote no image at {output} (" +
                                 output + ")");
    render::RenderResult r;
    try {
        requireRegularFile(output);
        r.image = startsWith(output, "PF", 2) || startsWith(output, "Pf", 2) ? readPfm(output, o.width, o.height)
                                                                              : render::readImage(output);
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
    const std::string material = "external reference v2\ncontent " + contentHash() + "\npattern " + o.pattern +
                                 "\nspp " + std::to_string(o.spp) + "\nseeds " + std::to_string(seeds[0]) + " " +
                                 std::to_string(seeds[1]) + "\nsize " + std::to_string(o.width) + "x" +
                                 std::to_string(o.height) + "\n";
    Reference ref;
    ref.key = keyOf(material);
    const ExternalCache cache(cacheDir, ref.key);
    ref.imagePath = cache.image;
    // The .key file is the key material followed by both images' pixel checksums: an entry is used only when all
    // of it verifies and every part is a regular file (reference_integrity.h), as for stipple-render's references.
    std::error_code ignored;
    const bool present = fs::exists(fs::symlink_status(cache.key, ignored)) ||
                         fs::exists(fs::symlink_status(cache.image, ignored)) ||
                         fs::exists(fs::symlink_status(cache.variance, ignored));
    if (present) {
        try {
            requireRegularFile(cache.key);
            const std::string stored = render::readFileBounded(cache.key, 1 << 20, "cache key");
            if (!stored.starts_with(material)) throw std::runtime_error("its key material differs");
            ref.image = readCachedImage(cache.image);
            ref.variance = readCachedImage(cache.variance);
            if (ref.image.width != o.width || ref.image.height != o.height || ref.variance.width != o.width ||
                ref.variance.height != o.height)
                throw std::runtime_error("cached images of another size");
            if (stored.substr(material.size()) != checksumLines(ref.image, ref.variance))
                throw std::runtime_error("the pixels do not match their checksums");
            ref.fromCache = true;
            return ref;
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
    writeTextFile(cache.key, material + checksumLines(ref.image, ref.variance)); // last: it vouches for the images
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

} // namespace stipple::validation
