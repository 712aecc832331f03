// ctest-labels: unit
// stipple-link: shared
// stiff_fuzz_replay_test.cpp — replays the C ABI fuzzer's seed corpus and every input that once crashed it
// (shim/fuzz/corpus, shim/fuzz/regressions) through the same LLVMFuzzerTestOneInput, built by gcc without
// libFuzzer. A broken contract traps, which fails this test.
#define BOOST_TEST_MODULE stiff_fuzz_replay
#include <boost/test/unit_test.hpp>

#include "../fuzz/stipple_api_fuzzer.cpp"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

BOOST_AUTO_TEST_CASE(replay_corpus_and_regressions) {
  const fs::path fuzzDir = fs::path(__FILE__).parent_path().parent_path() / "fuzz";
  size_t files = 0;
  for (const char* sub : {"corpus", "regressions"}) {
    BOOST_REQUIRE_MESSAGE(fs::is_directory(fuzzDir / sub), "missing " << (fuzzDir / sub).string());
    for (const auto& entry : fs::directory_iterator(fuzzDir / sub)) {
      if (!entry.is_regular_file() || entry.path().filename().string()[0] == '.') continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      BOOST_TEST_CHECKPOINT(entry.path().filename().string());
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
      ++files;
    }
  }
  BOOST_TEST_MESSAGE(files << " inputs replayed");
  BOOST_CHECK_GT(files, 0u);
}
