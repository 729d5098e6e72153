#!/bin/sh
# Installs the Debian 12 packages sgtllc builds with, if any is missing. Needs root or sudo only when installing.
#   --dev  also the reliability checks' toolchain (`make test-sanitize`, `make test-tsan`, `make fuzz`): clang with
#          its sanitizer and libFuzzer runtimes.
set -eu
PACKAGES="cmake ninja-build ccache g++ xz-utils libeigen3-dev libnanoflann-dev libyaml-cpp-dev liblzf-dev libcli11-dev \
nlohmann-json3-dev zlib1g-dev libcairo2-dev fonts-dejavu-core libgtest-dev libgmock-dev libbenchmark-dev libceres-dev \
pybind11-dev python3-dev python3-numpy python3-pytest python3-venv python3-pip python3-setuptools python3-wheel libfaiss-dev"
if [ "${1:-}" = "--dev" ]; then
  PACKAGES="$PACKAGES clang libclang-rt-14-dev"
fi

missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

echo "Installing Debian packages:$missing"
if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $missing
