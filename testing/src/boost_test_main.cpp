// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The main of every Boost.Test executable. Test sources are compiled with the precompiled Boost.Test header
// (testing/CMakeLists.txt), which comes before their first line, so the `#define BOOST_TEST_MODULE` they keep
// generates nothing there; the main is this one, and the master test suite is named after the executable
// (<part>_<name>_test) so that reports still say which suite ran.
#include <boost/test/unit_test.hpp>

#include <filesystem>

namespace {

bool nameMasterSuite() {
    boost::unit_test::master_test_suite_t& master = boost::unit_test::framework::master_test_suite();
    if (master.argc > 0) master.p_name.value = std::filesystem::path(master.argv[0]).filename().string();
    return true;
}

} // namespace

int main(int argc, char* argv[]) { return boost::unit_test::unit_test_main(&nameMasterSuite, argc, argv); }
