#!/usr/bin/env bash
# Runs every test of the workspace. This is the README's test command; .ci/run calls it.
# It installs the system packages the tests need, runs `cargo test`, and ends with one line
# adding up the passed and failed tests of all binaries.
set -euo pipefail
cd "$(dirname "$0")/.."

# The runtime's Modbus tests use mbpoll and pymodbus as independent clients (Debian packages),
# and socat's pseudo-terminal pairs as virtual serial cables for Modbus RTU;
# the studio's image snapshots render with Mesa's software Vulkan driver (lavapipe).
# Debian's pymodbus is seen by /usr/bin/python3 only, not by a pyenv python3 earlier on the
# path; the test tries both. pymodbus's servers import serial_asyncio (python3-serial-asyncio),
# which Debian's python3-pymodbus only recommends (an install without recommends lacks it), so
# it is installed and checked on its own. The PLCopen export is validated against the TC6
# schema with xmllint (libxml2-utils).
pymodbus_importable() {
    python3 -c 'import pymodbus' 2>/dev/null || /usr/bin/python3 -c 'import pymodbus' 2>/dev/null
}
serial_asyncio_importable() {
    /usr/bin/python3 -c 'import serial_asyncio' 2>/dev/null
}
lavapipe_installed() {
    ls /usr/share/vulkan/icd.d/lvp_icd.*.json >/dev/null 2>&1
}
if ! command -v mbpoll >/dev/null || ! command -v socat >/dev/null || ! command -v xmllint >/dev/null || ! pymodbus_importable || ! serial_asyncio_importable || ! lavapipe_installed; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y mbpoll socat python3-pymodbus python3-serial-asyncio mesa-vulkan-drivers libxml2-utils
fi

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
