// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// shim_identity_test.cpp — shimIdentity, the shim's part of every reference-cache key: stable for one file,
// different for a rebuilt one even when the version string is the same.
#define BOOST_TEST_MODULE shim_identity
#include <boost/test/unit_test.hpp>

#include <stipple/render/renderer.h>
#include <stipple/testing/scratch_folder.h>

#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

// The library the renderer would pick with no option: $STIPPLE_LIBRARY (or $STIPPLE_SHIM), else <exe dir>/../lib.
fs::path defaultShim() {
    for (const char* variable : {"STIPPLE_LIBRARY", "STIPPLE_SHIM"})
        if (const char* env = std::getenv(variable); env && *env && !fs::is_directory(env)) return env;
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    BOOST_REQUIRE(n > 0);
    exe[n] = 0;
    return fs::path(exe).parent_path() / ".." / "lib" / "libstipple.so.1";
}

} // namespace

BOOST_AUTO_TEST_CASE(identity_follows_the_file_bytes) {
    const fs::path original = defaultShim();
    BOOST_REQUIRE(fs::exists(original));
    const std::string id = stipple::render::shimIdentity("");
    BOOST_TEST_MESSAGE("default shim: " << id);
    BOOST_CHECK(id.rfind("libstipple 1.", 0) == 0);
    BOOST_CHECK_EQUAL(stipple::render::shimIdentity(""), id);

    // Same bytes under another name: the same identity. One byte appended (ELF ignores trailing bytes, so it
    // still loads and reports the same version): another identity.
    const fs::path dir = stipple::testing::freshScratchFolder("shim-identity");
    fs::create_directories(dir);
    const fs::path same = dir / "same.so", changed = dir / "changed.so";
    fs::copy_file(original, same, fs::copy_options::overwrite_existing);
    fs::copy_file(original, changed, fs::copy_options::overwrite_existing);
    std::ofstream(changed, std::ios::binary | std::ios::app).put('\0');
    const std::string idSame = stipple::render::shimIdentity(same.string());
    const std::string idChanged = stipple::render::shimIdentity(changed.string());
    BOOST_CHECK_EQUAL(idSame, id);
    BOOST_CHECK_NE(idChanged, id);
    BOOST_CHECK_EQUAL(idChanged.substr(0, idChanged.rfind(' ')), id.substr(0, id.rfind(' '))); // same version
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(no_library_is_an_error_naming_the_path) {
    try {
        stipple::render::shimIdentity("/nonexistent/libstipple.so.1");
        BOOST_FAIL("expected an error");
    } catch (const std::runtime_error& e) {
        BOOST_CHECK(std::string(e.what()).find("/nonexistent/libstipple.so.1") != std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(renderer_identity_names_its_sources) {
    // The reference cache keys on it: the version and the build's hash of the renderer's sources.
    const std::string hash = stipple::render::rendererSourceHash();
    BOOST_TEST(hash.size() == 16u);
    BOOST_TEST(hash.find_first_not_of("0123456789abcdef") == std::string::npos);
    const std::string id = stipple::render::rendererIdentity();
    BOOST_TEST(id.rfind(stipple::render::rendererVersion(), 0) == 0u);
    BOOST_TEST(id.find(hash) != std::string::npos);
}
