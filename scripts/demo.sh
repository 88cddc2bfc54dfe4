#!/usr/bin/env bash
# README command 1: set up, build in release mode, and run the main job on the embedded
# default input (a generated r-sample of the paper's double torus; nothing is downloaded).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=build-release
if [[ ! -f "$build/build.ninja" ]]; then
  meson setup "$build" --buildtype=release -Dtests=false -Dproofs=false -Dbench=false >/dev/null
fi
ninja -C "$build" src/cli/rstruct >/dev/null
mkdir -p demo-output
exec "$build/src/cli/rstruct" demo --out-dir demo-output "$@"
