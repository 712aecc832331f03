// validate_args_fuzzer.cpp — libFuzzer harness of stipple-validate's command-line parser. The input is split at
// NUL bytes into arguments (at most 64). Expected: Args within the documented ranges, or a UsageError with a
// message; any other exception, a crash or a sanitizer report is a finding.
#include "cli_args.h"

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
    using namespace stipple::validation;
    try {
        const Args a = parseArgs(argv);
        if (a.help || a.version) return 0; // both stop before the arguments a run needs
        require(!a.matrix.empty());
        require(a.threads >= 0 && a.threads <= 1024);
        require(a.shardCount >= 1 && a.shardIndex >= 1 && a.shardIndex <= a.shardCount);
        require(a.merge.empty() || (a.shardCount == 1 && !a.referencesOnly));
    } catch (const UsageError& e) {
        require(e.what()[0] != '\0');
    }
    return 0;
}
