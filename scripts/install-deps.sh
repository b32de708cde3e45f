#!/usr/bin/env bash
# Installs edgefit's build and test dependencies from Debian 12's packages.
# Idempotent: installs only what is missing. Needs root (or sudo) for apt-get.
#   ./scripts/install-deps.sh            build + test dependencies
#   EDGEFIT_WITH_CLOUDCOMPARE=0 ...      skip CloudCompare (used by one interop test)
#   EDGEFIT_WITH_BROWSER=0 ...           skip Chromium (the report's page test skips)
#   EDGEFIT_WITH_SLURM=0 ...             skip Slurm and munge (the Slurm test installs them
#                                        itself when it may, else skips)
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libceres-dev libgoogle-glog-dev libgflags-dev
  liburdfdom-dev liburdfdom-headers-dev libassimp-dev libnanoflann-dev
  libomp-dev libembree-dev nlohmann-json3-dev libfast-float-dev libtinyxml2-dev libpng-dev
  libyaml-cpp-dev liblzf-dev liboctomap-dev libfcl-dev
  libgtest-dev libgmock-dev libbenchmark-dev liburdfdom-tools python3-open3d
  clang libclang-rt-14-dev
  python3
)
# The fit report embeds three.js; its test opens it in headless Chromium.
packages+=(libjs-three)
if [[ "${EDGEFIT_WITH_BROWSER:-1}" == "1" ]]; then
  packages+=(chromium)
fi
# scripts/slurm/ and its test: a one-node cluster of Debian's Slurm (the
# daemons are started by the test in a folder of its own, never as services).
if [[ "${EDGEFIT_WITH_SLURM:-1}" == "1" ]]; then
  packages+=(slurmctld slurmd slurm-client munge)
fi
if [[ "${EDGEFIT_WITH_CLOUDCOMPARE:-1}" == "1" ]]; then
  packages+=(cloudcompare xvfb)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ "$(id -u)" != "0" ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 2; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
