#!/usr/bin/env bash
# Runs every test of the workspace. This is the README's test command; .ci/run calls it.
# It installs the system packages the tests need (none yet beyond the Rust toolchain), runs
# `cargo test`, and ends with one line adding up the passed and failed tests of all binaries.
set -euo pipefail
cd "$(dirname "$0")/.."

log=$(mktemp)
trap 'rm -f "$log"' EXIT
set +e
cargo test --workspace --locked 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
set -e
awk '/^test result:/ {
        for (i = 2; i <= NF; i++) {
            if ($i ~ /^passed;?$/) passed += $(i - 1)
            if ($i ~ /^failed;?$/) failed += $(i - 1)
        }
    }
    END { printf "tests: %d passed, %d failed\n", passed, failed }' "$log"
exit "$status"
