#!/usr/bin/env bash
# The test command: installs dependencies, builds, runs every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The tests of an optional component skip when it is missing (a user's machine may lack it);
# here setup.sh installed them all, so a missing one is an error, not a quiet pass.
absent=()
/usr/bin/python3 -c 'import matplotlib' 2>/dev/null || absent+=("matplotlib (python3-matplotlib)")
command -v chromium >/dev/null 2>&1 || absent+=("chromium")
[ -d web/node_modules/puppeteer-core ] || absent+=("puppeteer-core (npm ci --prefix web)")
command -v mpirun >/dev/null 2>&1 || absent+=("mpirun (openmpi-bin)")
command -v xmllint >/dev/null 2>&1 || absent+=("xmllint (libxml2-utils)")
if [ ${#absent[@]} -gt 0 ]; then
  echo "test.sh: missing after setup.sh: ${absent[*]}" >&2
  exit 1
fi
export MTCS_FUZZ_REQUIRED=1  # fuzz.sh: no clang or libFuzzer is an error here
# Three build trees (Release, the sanitizers', the fuzzers') take ~10 GB; a full disk fails the
# compiler half-way with "No space left on device". Say so first.
free_gb=$(df -Pk . | awk 'NR == 2 {print int($4 / 1048576)}')
if [ "${free_gb:-0}" -lt 12 ]; then
  echo "test.sh: warning: ${free_gb} GB free here; the build trees need ~10 GB (set MTCS_SKIP_SANITIZE=1 for one tree)" >&2
fi
# ON, not found-or-not: a missing test framework, peer or component is an error here, not a
# silent skip (and a tree the demo configured before they were installed turns them on).
bash scripts/build.sh -DMTCS_BUILD_TESTS=ON -DMTCS_BUILD_BENCH=ON -DMTCS_WITH_OCCT=ON -DMTCS_WITH_MPI=ON -DMTCS_WITH_SERVE=ON
ctest --test-dir build --output-on-failure -j2
# The same tests under AddressSanitizer and UBSan (set MTCS_SKIP_SANITIZE=1 to skip).
if [ "${MTCS_SKIP_SANITIZE:-0}" != 1 ]; then bash scripts/sanitize.sh; fi
