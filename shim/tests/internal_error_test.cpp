// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// internal_error_test.cpp — a failure that is a bug in the library (any exception other than stipple::detail::Error or
// std::bad_alloc) reaches the host as STIPPLE_ERROR_INTERNAL with its text, the library's version and where to
// report it; argument errors keep their own message without that note.
#define BOOST_TEST_MODULE internal_error
#include <boost/test/unit_test.hpp>

#include "error.h"

#include <stdexcept>
#include <string>

BOOST_AUTO_TEST_CASE(internal_errors_say_they_are_bugs_and_where_to_report) {
    const stipple_status status =
        stipple::detail::callGuarded("stipple_test", [] { throw std::logic_error("an invariant broke"); });
    BOOST_TEST(status == STIPPLE_ERROR_INTERNAL);
    const std::string message = stipple::detail::lastErrorMessage(); // read before any other call on this thread
    BOOST_TEST(message.find("stipple_test: internal error: an invariant broke") == 0, message);
    uint32_t major = 0, minor = 0, patch = 0;
    BOOST_TEST_REQUIRE(stipple_get_version(&major, &minor, &patch) == STIPPLE_OK);
    const std::string version =
        "libstipple " + std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
    BOOST_TEST(message.find(version) != std::string::npos, message);
    BOOST_TEST(message.find("stipple maintainers") != std::string::npos, message);

    BOOST_TEST(stipple::detail::callGuarded("stipple_test", [] { throw 7; }) == STIPPLE_ERROR_INTERNAL);
    BOOST_TEST(std::string(stipple::detail::lastErrorMessage()).find("unknown internal exception (a bug") !=
               std::string::npos);
}

BOOST_AUTO_TEST_CASE(argument_errors_carry_no_bug_note) {
    const stipple_status status = stipple::detail::callGuarded(
        "stipple_test", [] { throw stipple::detail::Error(STIPPLE_ERROR_OUT_OF_RANGE, "n is 0; expected 1..16"); });
    BOOST_TEST(status == STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_TEST(std::string(stipple::detail::lastErrorMessage()) == "stipple_test: n is 0; expected 1..16");
}
