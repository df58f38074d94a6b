#!/usr/bin/env bash
# Runs every test of the workspace. This is the README's test command; .ci/run calls it.
# It installs the system packages the tests need (none yet beyond the Rust toolchain).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --locked
