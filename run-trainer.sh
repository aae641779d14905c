#!/usr/bin/env bash
# Installs what is missing, builds (Release) and starts the Piano Action Trainer.
# Arguments are passed to the program, e.g. ./run-trainer.sh simulate --action grand ...
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
exec build/app/pianoaction "$@"
