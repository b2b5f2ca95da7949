#!/usr/bin/env bash
# The web page's continuous integration, in one script: installs what it needs (Debian's
# Chromium, the wasm32 target, the pinned wasm-bindgen-cli, playwright-core from
# web/package-lock.json), builds the page (web/build.sh) and the cagd binary, and runs the
# browser tests (web/tests/, node's test runner): the page is served by `cagd serve` on
# 127.0.0.1 and driven in headless Chromium with a fresh profile. Exits non-zero on failure.
# Screenshots, the parity summary and the measured figures go to web/test-results/.
#
# Time on the 2-core machine: about 10 minutes from scratch (installing wasm-bindgen-cli takes
# about 7 of them, once; the WebAssembly build 3 to 6), 3 to 4 minutes when both are there.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

export DEBIAN_FRONTEND=noninteractive
sudo=""
if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
fi
missing=()
[ -x /usr/bin/chromium ] || missing+=(chromium)
command -v node >/dev/null 2>&1 || missing+=(nodejs npm)
if [ "${#missing[@]}" -gt 0 ]; then
    echo "== installing: ${missing[*]}"
    $sudo apt-get update
    $sudo apt-get install -y "${missing[@]}"
fi
if ! command -v cargo >/dev/null 2>&1 && [ -f "$HOME/.cargo/env" ]; then
    # shellcheck disable=SC1091
    . "$HOME/.cargo/env"
fi

echo "== web/build.sh"
bash web/build.sh

echo "== clippy for the WebAssembly build (the core without its parallel feature; warnings are errors)"
cargo clippy -p cagd-web --target wasm32-unknown-unknown -- -D warnings

echo "== cargo build -p cagd-cli --bin cagd (the program the page is compared with; it also serves the page)"
cargo build -p cagd-cli --bin cagd

echo "== cargo test -p cagd-web (the WebAssembly exports, natively)"
cargo test -p cagd-web

echo "== npm ci (playwright-core, from web/package-lock.json; no browser download)"
(cd web && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund)

echo "== browser tests (headless /usr/bin/chromium)"
(cd web && CAGD_BIN="$PWD/../target/debug/cagd" node --test --test-concurrency=1 tests/)
