#!/usr/bin/env bash
# Set-up (dependencies, Release build), then the main job: the square cup.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/deepdraw prm/square_cup.prm
