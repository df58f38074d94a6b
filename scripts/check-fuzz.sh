#!/usr/bin/env bash
# Compiles every fuzz target so that none rots: the fuzz crates live outside the workspace (running
# them needs nightly and cargo-fuzz), so `cargo clippy --workspace` never sees them. `cargo check`
# on the stable toolchain type-checks the targets against today's crates; `--locked` fails when a
# fuzz crate's own Cargo.lock no longer matches its dependencies. They share the workspace's
# target directory so the crates they fuzz are not checked a second time. .ci/run calls it.
set -euo pipefail
cd "$(dirname "$0")/.."
for crate in compiler online_protocol plcopen program_image runtime; do
    echo "fuzz targets of $crate"
    cargo check --locked --manifest-path "$crate/fuzz/Cargo.toml" --target-dir target --bins
done
