#!/usr/bin/env bash
# Sourced by the package tests: installs the build into a fresh staging prefix with
# `cmake --install` (what a user or packager runs) and sets $stage to it.
# Needs: $build (the build folder), $work (the test's own scratch folder).
rm -rf "$work"
mkdir -p "$work"
stage="$work/stage"
cmake --install "$build" --prefix "$stage" >"$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
