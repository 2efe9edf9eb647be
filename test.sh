#!/usr/bin/env bash
# test.sh — installs what is missing (Debian packages), builds build/ (Release) and runs
# every test (unit, reference, integration) with ctest. Exits non-zero on any failure.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/scripts/setup.sh"

ctest --test-dir "$TOWSIM_BUILD_DIR" --output-on-failure -j2
