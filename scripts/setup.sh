# scripts/setup.sh — shared by test.sh and run.sh (sourced, not executed):
# installs the Debian packages that are missing, exports CYCLONEDDS_URI, configures build/
# (Release) and builds it. Works from a clean clone on a fresh Debian 12 machine; nothing is
# written outside the repository except what apt-get installs.
#
#   source scripts/setup.sh [extra-debian-package ...]
#
# Afterwards the shell is in the repository root and TOWSIM_BUILD_DIR names the build tree.
# Environment: TOWSIM_BUILD_DIR (default build), TOWSIM_JOBS (default $(nproc)),
# TOWSIM_WITH_SLURM=1 (test.sh): also slurm-wlm and munge, for the Slurm sweep test;
# TOWSIM_WITH_NODE=1 (test.sh): also Node.js and npm, for the independent MCAP readers of
# tests/mcap_js; Debian's `nodejs` and `npm`, each only when its command is missing (a
# Node.js already on the PATH, e.g. one that bundles npm, is used as it is).

towsim_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$towsim_root"

# dpkg-dev: dpkg-shlibdeps, with which cpack -G DEB declares the package's dependencies
# libwebsocketpp-dev, libasio-dev and nlohmann-json3-dev: the Foxglove server (towsim_foxglove)
towsim_packages=(build-essential cmake libeigen3-dev libyaml-cpp-dev cyclonedds-dev
                 cyclonedds-tools libgtest-dev libbenchmark-dev dpkg-dev libssl-dev
                 openssl libwebsocketpp-dev libasio-dev nlohmann-json3-dev "$@")
# who asks for python3 (run.sh, test.sh) gets matplotlib too, for scripts/plot_paper.py and
# scripts/plot_sweep.py
for towsim_pkg in "$@"; do
  # and numpy, for scripts/plot_waves.py
  if [[ "$towsim_pkg" == python3 ]]; then towsim_packages+=(python3-matplotlib python3-numpy); fi
done

# test.sh: a one-machine Slurm cluster for tests/integration/sweep_slurm_test.sh (slurmctld,
# slurmd, the client commands) and munge, its authentication
if [[ "${TOWSIM_WITH_SLURM:-0}" == 1 ]]; then
  towsim_packages+=(slurm-wlm munge)
fi

if [[ "${TOWSIM_WITH_NODE:-0}" == 1 ]]; then
  command -v node >/dev/null || towsim_packages+=(nodejs)
  command -v npm >/dev/null || towsim_packages+=(npm)
fi

# install what is missing (apt-get update only when something is)
towsim_missing=()
for towsim_pkg in "${towsim_packages[@]}"; do
  if ! dpkg -s "$towsim_pkg" 2>/dev/null | grep -q '^Status: install ok installed'; then
    towsim_missing+=("$towsim_pkg")
  fi
done
if ((${#towsim_missing[@]} > 0)); then
  echo "[setup] installing: ${towsim_missing[*]}" >&2
  towsim_sudo=()
  if [[ "$(id -u)" != 0 ]]; then
    if ! command -v sudo >/dev/null; then
      echo "[setup] error: not root and sudo not found; install: ${towsim_missing[*]}" >&2
      exit 1
    fi
    towsim_sudo=(sudo)
  fi
  "${towsim_sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
  "${towsim_sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends "${towsim_missing[@]}"
fi

# every DDS participant of the project (sim_node, controllers, tests) talks over loopback only
export CYCLONEDDS_URI="file://$towsim_root/config/cyclonedds.xml"

# configure and build
TOWSIM_BUILD_DIR="${TOWSIM_BUILD_DIR:-build}"
cmake -S . -B "$TOWSIM_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$TOWSIM_BUILD_DIR" -j"${TOWSIM_JOBS:-$(nproc)}"
