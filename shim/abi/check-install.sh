#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Installs the shim component of a build tree into a temporary prefix and checks what a host gets: the header,
# libstipple.so.1 (SONAME link) and libstipple.so, a CMake package a consumer project can find_package and link,
# and a pkg-config file that compiles and links the same consumer. The C++ consumers use stipple.hpp: one linked
# (C++11, no exceptions), one with the header-only target stipple::headers that dlopens the installed library.
#   usage: check-install.sh <build dir> <consumer source dir> <C compiler>
set -euo pipefail
build="$1" consumer="$2" cc="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --component stipple --prefix "$work/prefix" > "$work/install.log"
for f in include/stipple/stipple.h include/stipple/stipple.hpp lib/libstipple.so.1 lib/libstipple.so lib/cmake/stipple/stippleConfig.cmake \
         lib/pkgconfig/stipple.pc; do
  [ -e "$work/prefix/$f" ] || { echo "FAIL: $f not installed"; cat "$work/install.log"; exit 1; }
done
echo "installed: $(cd "$work/prefix" && find . -type f -o -type l | sort | tr '\n' ' ')"
cmake -S "$consumer" -B "$work/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_C_COMPILER="$cc" \
      > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" || { cat "$work/build.log"; exit 1; }
# CMake hosts need no library path: CMake writes the imported library's folder into the build tree's RUNPATH.
"$work/consumer/consumer"
"$work/consumer/consumer_kit"
"$work/consumer/consumer_dlopen" "$work/prefix/lib/libstipple.so.1"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
echo "pkg-config: $(pkg-config --modversion stipple) $(pkg-config --cflags --libs stipple)"
# A pkg-config host sets the run-time path itself, as shim/README.md says (no LD_LIBRARY_PATH).
# shellcheck disable=SC2046
"$cc" -std=c99 -o "$work/consumer-pc" "$consumer/consumer.c" $(pkg-config --cflags --libs stipple) \
      -Wl,-rpath,"$(pkg-config --variable=libdir stipple)"
"$work/consumer-pc"
echo "check-install: ok"
