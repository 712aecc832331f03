// render_args_fuzzer.cpp — libFuzzer harness of stipple-render's command-line parser. The input is split at NUL
// bytes into arguments (at most 64). Expected: RenderArgs within the documented ranges, or a UsageError with a
// message; any other exception, a crash or a sanitizer report is a finding.
#include "render_args.h"

#include <cstdint>
#include <string>
#include <vector>

namespace {

void require(bool condition) {
    if (!condition) __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 4096) return 0;
    std::vector<std::string> argv(1);
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            if (argv.size() == 64) break;
            argv.emplace_back();
        } else {
            argv.back() += char(data[i]);
        }
    }
    using namespace stipple::render;
    try {
        const RenderArgs a = parseRenderArgs(argv);
        if (a.help || a.version) return 0; // both stop before the arguments a run needs
        require(!a.scenePath.empty());
        require(a.options.spp <= (1u << 20));
        require(a.options.width >= 0 && a.options.width <= (1 << 15) && a.options.height >= 0 &&
                a.options.height <= (1 << 15));
        require(a.options.threads >= 0 && a.options.threads <= 4096);
        require(a.options.maxDepth >= -1 && a.options.maxDepth <= 1000);
        require(a.output.empty() || a.output.size() >= 4);
    } catch (const UsageError& e) {
        require(e.what()[0] != '\0');
    }
    return 0;
}
