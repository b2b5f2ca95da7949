#!/usr/bin/env bash
# Builds the Octave package cagd as a tarball that `pkg install` compiles and installs.
#
# Usage: bash octave_pkg/build.sh [OUTDIR]     (default OUTDIR: target/octave-pkg)
# The last line printed is the path of the tarball (OUTDIR/cagd-VERSION.tar.gz).
#
# The tarball holds the package (DESCRIPTION, COPYING, INDEX, inst/*.m) and the sources of its
# oct-file: src/__cagd__.cc, src/Makefile, src/cagd_twin_docs.h (generated here from the .m
# files by src/twin_docs.py), and in src/rust/ the Rust crates it links -- the core
# cagd (src/), cagd-ops, cagd-octave, cagd-octave-pkg, cagd-octave-ffi -- as a workspace of their own with
# the checkout's Cargo.lock. `pkg install` runs src/Makefile: cargo builds the static library
# (release profile; crates.io must be reachable, or the crates vendored/cached), then mkoctfile
# compiles and links __cagd__.oct. The workspace manifest is the checkout's, reduced to those
# crates (their dev-dependencies, benches and tests are not shipped).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
outdir="${1:-$root/target/octave-pkg}"
mkdir -p "$outdir"
outdir="$(cd "$outdir" && pwd)"

version="$(sed -n 's/^Version: *//p' "$here/DESCRIPTION")"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
pkg="$stage/cagd"
mkdir -p "$pkg/inst" "$pkg/src/rust/crates"

# cp -p keeps the checkout's modification times, so that a build reusing a cargo target
# directory (CARGO_TARGET_DIR, see src/Makefile) recompiles only what changed.
cp -p "$here/DESCRIPTION" "$here/COPYING" "$here/INDEX" "$pkg/"
cp -p "$here"/inst/*.m "$pkg/inst/"
cp -p "$here/src/__cagd__.cc" "$here/src/Makefile" "$pkg/src/"
# The builtin twins (see __cagd__.cc): their docstrings from their .m files, and their test
# blocks as NAME.cc-tst in place of the .m files (no .m file of a builtin's name on the path).
python3 "$here/src/twin_docs.py" "$here/inst" "$pkg/src/cagd_twin_docs.h"
python3 "$here/src/twin_docs.py" --tests "$pkg/inst"

rust="$pkg/src/rust"
cp -p "$root/Cargo.toml" "$root/Cargo.lock" "$root/rustfmt.toml" "$rust/"
cp -rp "$root/src" "$rust/src"
for crate in cagd-ops cagd-octave cagd-octave-pkg cagd-octave-ffi; do
    mkdir -p "$rust/crates/$crate"
    cp -p "$root/crates/$crate/Cargo.toml" "$rust/crates/$crate/"
    cp -rp "$root/crates/$crate/src" "$rust/crates/$crate/src"
    if [ -d "$root/crates/$crate/include" ]; then
        cp -rp "$root/crates/$crate/include" "$rust/crates/$crate/include"
    fi
done

# The workspace of the tarball: the five crates only, no dev-dependencies (their test-only
# crates are not shipped), no workspace entries for crates that are not there.
python3 - "$rust" <<'PY'
import re, sys, pathlib
rust = pathlib.Path(sys.argv[1])
shipped = ["crates/cagd-ops", "crates/cagd-octave", "crates/cagd-octave-pkg", "crates/cagd-octave-ffi"]

def drop_sections(text, names):
    out, skip = [], False
    for line in text.splitlines(keepends=True):
        m = re.match(r"^\[([^\]]+)\]\s*$", line)
        if m:
            skip = m.group(1) in names
        if not skip:
            out.append(line)
    return "".join(out)

root = rust / "Cargo.toml"
text = root.read_text()
text = re.sub(r"(?ms)^members = \[.*?\]\n", "members = [\".\", " + ", ".join(f'"{c}"' for c in shipped) + "]\n", text, count=1)
text = re.sub(r"(?ms)^(# [^\n]*\n)*default-members = \[.*?\]\n", "", text)
text = "# The Rust workspace of the Octave package cagd, written by octave_pkg/build.sh from the\n" \
       "# checkout's Cargo.toml: the core and the four crates the oct-file links.\n" + text
text = re.sub(r'(?m)^cagd-(cli|test-support) = \{ path = .*\n', "", text)
text = drop_sections(text, {"dev-dependencies"})
root.write_text(text)
for c in shipped:
    m = rust / c / "Cargo.toml"
    m.write_text(drop_sections(m.read_text(), {"dev-dependencies"}))
PY

tarball="$outdir/cagd-$version.tar.gz"
tar -C "$stage" -czf "$tarball" cagd
echo "$tarball"
