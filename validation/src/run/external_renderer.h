// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// An external renderer: a host renderer run as a program, one process per image, from a command template the
// matrix gives (validation/README.md, "Validating a host renderer"). The command is an argument vector; each
// placeholder ({scene}, {pattern}, {spp}, {seed}, {width}, {height}, {output}) is replaced inside its argument,
// never split or interpreted, and the program runs without a shell. The run reads the image the program wrote
// (EXR or PFM) and its CPU seconds from the child's resource usage.
//
// A matrix alone never runs a program: runMatrix refuses a scene with an external renderer unless the command
// line allowed it (--allow-renderer) or named the program itself (--renderer PROGRAM).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <stipple/render/renderer.h>

#include "matrix/matrix.h"
#include "run/reference_cache.h"
#include "run/shard_fingerprint.h"

namespace stipple::validation {

// What the command line allows. Every argument a program receives comes from the trusted side or is the checked
// value of a placeholder: a matrix's template runs only when it is byte-equal to one of `commands` (the templates
// of --renderer-command FILE), in full with allowMatrixProgram (--allow-renderer), or from its second argument on
// with `program` (--renderer PROGRAM), which then replaces the first.
struct RendererPermission {
    bool allowMatrixProgram = false;
    std::string program;
    std::vector<std::vector<std::string>> commands;
    double timeoutSeconds = 0; // --renderer-timeout: per image, over the matrix's; 0: the matrix's (0: none)
    bool granted() const { return allowMatrixProgram || !program.empty(); }
};

// "" when the permission lets the scene's template run; else why not (the message says how to allow it).
std::string checkRendererPermission(const MatrixScene& scene, const RendererPermission& permission);

// One scene rendered by an external program. Every failure throws std::runtime_error naming the cell (scene,
// pattern, spp, seed) and what went wrong: the program's exit status or signal and the end of its output, a
// missing or unreadable image, an image of another size.
class ExternalRenderer {
public:
    // Throws std::runtime_error when the command line did not allow running it (checkRendererPermission) or the
    // program does not resolve to one regular, executable, readable file.
    ExternalRenderer(const MatrixScene& scene, const RendererPermission& permission, std::string workDir);

    // One image: options.pattern, .spp, .seed, .width, .height. renderSeconds is the child's wall time,
    // cpuSeconds its user + system CPU seconds (wait4); the variance is left empty.
    render::RenderResult render(const render::RenderOptions& options) const;

    // The reference: two renders of spp / 2 with different seeds (none of `cellSeeds`), their mean and the
    // variance of the mean from their difference, cached under cacheDir keyed by the command, the program's and
    // the scene file's bytes and the options.
    Reference reference(const render::RenderOptions& options, const std::vector<uint64_t>& cellSeeds,
                        const std::string& cacheDir) const;

    // The scene file's and the program's content hash: the scene's identity in reports and fingerprints.
    std::string contentHash() const;
    // "external: <program>" for the report's integrator column.
    std::string description() const;

private:
    std::vector<std::string> expand(const render::RenderOptions& options, const std::string& output) const;
    std::string cellName(const render::RenderOptions& options) const;

    const MatrixScene& scene_;
    std::vector<std::string> command_; // the template, the program replaced when the command line named one
    std::string program_;              // the resolved executable (for hashing)
    std::string workDir_;              // where images are written before they are read
    double timeoutSeconds_ = 0;        // per image; 0: none
};

// What a run's fingerprint records of an external renderer's scene (the same in every shard, whichever program
// the command line named): the matrix's command template, the scene file's bytes, the size, the reference spp.
SceneFingerprint externalFingerprint(const MatrixScene& scene, uint32_t referenceSpp);

} // namespace stipple::validation
