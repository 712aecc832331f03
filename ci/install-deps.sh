#!/usr/bin/env bash
# Installs the Debian 12 packages stipple needs. Idempotent: when everything is present it only checks.
# Non-interactive (CI has no standard input); never installs recommended extras.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools python3-imath
  libopencolorio-dev
  libyaml-cpp-dev nlohmann-json3-dev
  libboost-test-dev
  libbenchmark-dev
  gnuplot-nox
  abigail-tools
  python3
  chromium                # headless: the report's browser test (validation.report_browser)
  clang libclang-rt-14-dev
  slurm-wlm slurmctld slurmd slurm-client munge
  nlohmann-json3-dev
  python3-yaml
  python3-numpy python3-venv python3-pip python3-setuptools   # the Python package, its tests and pip install
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq < /dev/null
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" < /dev/null
