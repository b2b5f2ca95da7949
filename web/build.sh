#!/usr/bin/env bash
# Builds the web page into web/dist/: the WebAssembly of crates/cagd-web (the cagd library and
# command line, profile `web`), its JavaScript glue (wasm-bindgen, ES module), and the page's
# static files. Installs what is missing: the wasm32-unknown-unknown target (rustup) and the
# wasm-bindgen-cli of exactly the version of the wasm-bindgen crate (cargo install). wasm-opt
# (Debian package binaryen) shrinks the .wasm further when it is installed. Needs node (the
# forms' tables are read from the .wasm at build time, and the files are compressed with it).
#
#   bash web/build.sh          then   cagd serve   (or copy web/dist/ to any static host)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

if ! command -v cargo >/dev/null 2>&1 && [ -f "$HOME/.cargo/env" ]; then
    # shellcheck disable=SC1091
    . "$HOME/.cargo/env"
fi

# The version the workspace pins (Cargo.toml: wasm-bindgen = "=X.Y.Z").
version=$(sed -n 's/^wasm-bindgen = "=\([0-9.]*\)"/\1/p' Cargo.toml)
if [ -z "$version" ]; then
    echo "web/build.sh: no pinned wasm-bindgen version in Cargo.toml" >&2
    exit 1
fi

if command -v rustup >/dev/null 2>&1 && ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    echo "== rustup target add wasm32-unknown-unknown"
    rustup target add wasm32-unknown-unknown
fi

if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$version" ]; then
    echo "== cargo install wasm-bindgen-cli $version (a few minutes, once)"
    # --locked keeps the versions wasm-bindgen-cli was released with; should one of them be
    # missing from the registry (yanked), resolve afresh.
    cargo install --locked wasm-bindgen-cli --version "$version" ||
        cargo install wasm-bindgen-cli --version "$version"
fi

if ! command -v node >/dev/null 2>&1; then
    echo "web/build.sh: node is needed (it reads the forms' tables from the .wasm): apt-get install nodejs" >&2
    exit 1
fi

echo "== cargo build -p cagd-web --target wasm32-unknown-unknown --profile web"
cargo build -p cagd-web --target wasm32-unknown-unknown --profile web

dist=web/dist
rm -rf "$dist"
mkdir -p "$dist/pkg"
# The `name` section (Rust function names for a browser's debugger, about 600 kB, a sixth of
# the .wasm) is left out: nothing on the page reads it (a fault is reported by the panic hook
# with the program's own message and source location), and every visitor would download it.
wasm-bindgen --target web --no-typescript --remove-name-section --out-dir "$dist/pkg" \
    target/wasm32-unknown-unknown/web/cagd_web.wasm
wasm="$dist/pkg/cagd_web_bg.wasm"
if command -v wasm-opt >/dev/null 2>&1; then
    echo "== wasm-opt -Os"
    if wasm-opt -Os --all-features "$wasm" -o "$wasm.opt"; then
        mv "$wasm.opt" "$wasm"
    else
        echo "wasm-opt failed; keeping the unoptimised .wasm" >&2
        rm -f "$wasm.opt"
    fi
fi
cp web/index.html web/style.css web/sw.js "$dist/"
cp -r web/js "$dist/js"

echo "== pkg/tables.json (the forms' schema and the steps' labels, read from the .wasm by node)"
# What the page builds its forms from, computed once here by the same WebAssembly instead of on
# every visitor's main thread: the page fetches it while the .wasm compiles.
node --input-type=module -e '
    import { readFileSync, writeFileSync } from "node:fs";
    import { pathToFileURL } from "node:url";
    const [glue, wasm, out] = process.argv.slice(1);
    const bindings = await import(pathToFileURL(glue));
    bindings.initSync({ module: readFileSync(wasm) });
    const tables = { schema: JSON.parse(bindings.schema()), steps: JSON.parse(bindings.step_tables()) };
    writeFileSync(out, JSON.stringify(tables));
' "$dist/pkg/cagd_web.js" "$wasm" "$dist/pkg/tables.json"

echo "== hashed file names"
build=$(cat "$dist"/js/*.js "$dist"/pkg/*.js "$dist/pkg/tables.json" "$wasm" "$dist/style.css" "$dist/index.html" "$dist/sw.js" |
    sha256sum | cut -c1-16)
for f in "$dist"/js/*.js "$dist/pkg/cagd_web.js"; do
    mv "$f" "${f%.js}.$build.js"
done
mv "$wasm" "$dist/pkg/cagd_web_bg.$build.wasm"
mv "$dist/pkg/tables.json" "$dist/pkg/tables.$build.json"
wasm="$dist/pkg/cagd_web_bg.$build.wasm"
mv "$dist/style.css" "$dist/style.$build.css"
# Module specifiers ("./plane.js", "../pkg/cagd_web.js") and the .wasm's name, in every module;
# not the glue's "./cagd_web_bg.js", the name of the .wasm's imports (no file has it).
sed -i -E "s#([\"'])(\.{1,2}/[A-Za-z0-9_/-]+)\.js\1#\1\2.$build.js\1#g; s#cagd_web_bg\.$build\.js#cagd_web_bg.js#g; s#cagd_web_bg\.wasm#cagd_web_bg.$build.wasm#g; s#pkg/tables\.json#pkg/tables.$build.json#g" \
    "$dist"/js/*.js "$dist"/pkg/*.js
sed -i -E "s#\"(js/[A-Za-z0-9_-]+|pkg/cagd_web)\.js\"#\"\1.$build.js\"#g; s#pkg/cagd_web_bg\.wasm#pkg/cagd_web_bg.$build.wasm#; s#pkg/tables\.json#pkg/tables.$build.json#; s#style\.css#style.$build.css#" \
    "$dist/index.html"
files=$(cd "$dist" && { echo "./"; echo "index.html"; find js pkg -type f -name "*.$build.*"; echo "style.$build.css"; } |
    sed 's/.*/"&"/' | paste -sd, -)
sed -i "s#__BUILD__#$build#; s#__FILES__#[$files]#" "$dist/sw.js"

echo "== brotli (node's zlib, quality 11)"
    (cd "$dist" && find . -type f \( -name "*.js" -o -name "*.css" -o -name "*.html" -o -name "*.wasm" -o -name "*.json" \) -print0 |
        xargs -0 node -e '
            const fs = require("fs"), zlib = require("zlib");
            for (const f of process.argv.slice(1)) {
                const bytes = fs.readFileSync(f);
                const br = zlib.brotliCompressSync(bytes, { params: {
                    [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
                    [zlib.constants.BROTLI_PARAM_LGWIN]: 24,
                    [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length } });
                if (br.length < bytes.length) fs.writeFileSync(f + ".br", br);
            }')

bytes=$(wc -c <"$wasm")
gz=$(gzip -9 -c "$wasm" | wc -c)
br=$([ -f "$wasm.br" ] && wc -c <"$wasm.br" || echo "-")
echo "== built $dist (build $build): $(basename "$wasm") $bytes bytes ($gz gzipped, $br brotli)"
