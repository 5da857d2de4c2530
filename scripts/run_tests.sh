#!/usr/bin/env bash
# Set-up (dependencies, Release build), then the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests
cd build
ctest -j "$(nproc)" --output-on-failure --timeout 1200
