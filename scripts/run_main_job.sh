#!/usr/bin/env bash
# Set-up (dependencies, Release build), then the main job: the NUMISHEET'93
# square cup to 20 mm punch travel (results in output-square-cup/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/deepdraw prm/square_cup.prm
