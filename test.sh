#!/usr/bin/env bash
# test.sh — installs what is missing (Debian packages, Node.js, npm, Slurm and munge, python3 with
# matplotlib included), builds build/
# (Release), installs the Node.js test dependencies of tests/ from their lockfiles (npm ci) and
# runs every test (unit, reference, integration, and package: the installed package and the
# Debian package, tests/package/) with ctest. Exits non-zero on any failure.
set -euo pipefail
TOWSIM_WITH_NODE=1
TOWSIM_WITH_SLURM=1
# python3 (with matplotlib and numpy): the sweep test draws scripts/plot_sweep.py's plots
source "$(dirname "${BASH_SOURCE[0]}")/scripts/setup.sh" python3

# the independent readers of the recordings (@mcap/core, @foxglove/rosmsg,
# @foxglove/rosmsg2-serialization): exactly the locked versions; a failure stops the run
for towsim_lock in tests/*/package-lock.json; do
  towsim_js_dir="$(dirname "$towsim_lock")"
  echo "[test] npm ci in $towsim_js_dir" >&2
  if ! (cd "$towsim_js_dir" && npm ci --no-audit --no-fund); then
    echo "[test] error: npm ci failed in $towsim_js_dir (the npm registry must be reachable)" >&2
    exit 1
  fi
done

ctest --test-dir "$TOWSIM_BUILD_DIR" --output-on-failure -j2
