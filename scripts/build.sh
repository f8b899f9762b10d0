#!/usr/bin/env bash
# Configure and build mtcs (Release) into build/, with two jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
# Paths relative to the checkout in ccache's hashes: clones and worktrees share the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
# Debug builds (-g) hash the working folder too unless told not to: clones would never hit.
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
# Ninja for a new tree (an existing one keeps its generator): Make waits for a module's
# dependencies to finish before compiling it, and leaves a core idle (experiments/ci/README.md).
if command -v ninja >/dev/null 2>&1; then export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j2 ${MTCS_BUILD_TARGET:+--target "$MTCS_BUILD_TARGET"}
