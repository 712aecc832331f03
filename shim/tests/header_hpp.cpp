// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// header_hpp.cpp — stipple.hpp compiles alone as strict C++11 to C++20, with and without exceptions
// (shim.header_hpp, shim.header_hpp_cxx11, shim.header_hpp_no_exceptions).
#include <stipple/stipple.hpp>
