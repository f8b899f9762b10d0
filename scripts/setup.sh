#!/usr/bin/env bash
# Installs the Debian packages mtcs needs. Idempotent: packages already present are skipped, so
# a second run costs one dpkg query.
#   setup.sh            everything the tests, benchmarks and optional components use (the test
#                       command's set)
#   setup.sh --minimal  what building and running `mtcs` needs (the demo's set): no test
#                       framework, peers, fuzzer, browser, MPI, OpenCASCADE or matplotlib
#   setup.sh --serve    the minimal set and the review server's libraries (serve_demo.sh)
set -euo pipefail

minimal=0 serve=0
case "${1:-}" in
  --minimal) minimal=1 ;;
  --serve) minimal=1 serve=1 ;;
  "") ;;
  *) echo "usage: setup.sh [--minimal | --serve]" >&2; exit 2 ;;
esac

# Building and running mtcs: the compiler and the libraries every module links.
PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config python3
  libeigen3-dev libnlopt-cxx-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libyaml-cpp-dev libspdlog-dev libfmt-dev libcli11-dev nlohmann-json3-dev
  libsqlite3-dev libtbb-dev libabsl-dev libxxhash-dev
)
# The tests, the benchmarks' peers (mtcs-bench) and the optional components: PNG plots
# (matplotlib), the fuzzers (clang), the report's browser test (chromium, node), STEP export
# (OpenCASCADE), islands across MPI ranks (Open MPI) and the review server, mtcs serve
# (cpp-httplib, libsodium, pugixml and libzip for BCF; xmllint checks its BCF in the tests).
FULL=(
  catch2 libfcl-dev libccd-dev libbenchmark-dev libpagmo-dev
  python3-matplotlib
  clang-14 libfuzzer-14-dev
  nodejs chromium
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-ocaf-dev
  libocct-data-exchange-dev libocct-visualization-dev
  openmpi-bin libopenmpi-dev
  libcpp-httplib-dev libsodium-dev libpugixml-dev libzip-dev libxml2-utils
)
if [ "$minimal" = 0 ]; then PACKAGES+=("${FULL[@]}"); fi
if [ "$serve" = 1 ]; then PACKAGES+=(libcpp-httplib-dev libsodium-dev libpugixml-dev libzip-dev); fi

# The report page's browser test: puppeteer-core (and three.js, which src/report/assets vendors),
# pinned in web/package-lock.json, into web/node_modules; again only when the lock file changed.
web_packages() {
  local web
  web="$(dirname "$0")/../web"
  if cmp -s "$web/package-lock.json" "$web/node_modules/.mtcs-lock" 2>/dev/null; then return 0; fi
  if ! command -v npm >/dev/null 2>&1; then
    echo "setup: npm not found; installing Debian's npm"
    ${SUDO:-} apt-get install -y -qq --no-install-recommends npm
  fi
  npm ci --prefix "$web" --no-audit --no-fund
  cp "$web/package-lock.json" "$web/node_modules/.mtcs-lock"
}

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  if [ "$minimal" = 0 ]; then web_packages; fi
  exit 0
fi

echo "setup: installing ${missing[*]}"
if ! command -v apt-get >/dev/null 2>&1; then
  echo "setup: apt-get not found; install these Debian packages by hand: ${missing[*]}" >&2
  exit 1
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: not root and no sudo; run as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
if [ "$minimal" = 0 ]; then web_packages; fi
echo "setup: done"
