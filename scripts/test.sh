#!/usr/bin/env bash
# Builds everything (Release, warnings as errors) and runs the whole test suite. Benchmarks
# are not tests: run them with  ctest --test-dir build -L bench --output-on-failure
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache (when installed) keys on paths relative to the clone, so every clone of the project
# shares one cache: a fresh clone rebuilds in minutes, not half an hour.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true

scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPKM_WARNINGS_AS_ERRORS=ON -DPKM_BUILD_TESTS=ON
cmake --build build
ctest --test-dir build --output-on-failure --label-exclude bench -j 2

# The fuzz targets (tests/fuzz): a tree of their own, built with clang's libFuzzer and the
# address and undefined-behaviour sanitizers; each runs PKM_FUZZ_SECONDS (60 s) on its corpus.
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPKM_FUZZ=ON
cmake --build build-fuzz --target pkm_fuzzers
ctest --test-dir build-fuzz --output-on-failure -j 2
