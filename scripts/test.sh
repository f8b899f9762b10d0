#!/usr/bin/env bash
# The test command: installs dependencies, builds, runs every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
# The same tests under AddressSanitizer and UBSan (set MTCS_SKIP_SANITIZE=1 to skip).
if [ "${MTCS_SKIP_SANITIZE:-0}" != 1 ]; then bash scripts/sanitize.sh; fi
