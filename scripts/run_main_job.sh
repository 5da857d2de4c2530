#!/usr/bin/env bash
# Set-up (dependencies, Release build), then the main job.
# The main job will be the NUMISHEET'93 square cup (prm/square_cup.prm) once
# its contact iterations converge (issue 5, see README); until then it is
# the large-strain tension demo, which exercises the whole sheet solver.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/deepdraw prm/tension_bar.prm
