#!/usr/bin/env python3
"""Counts the core's public functions that the hostile calls reach.

Reads the public API of the crate `cagd` from rustdoc's JSON output (argument 1) and the names
the calls check under (the string literals given to `ok`, `any`, `total`, `grid_into` and the
type names given to `curve_methods`, `deriv_methods` / `surface_methods` in
crates/cagd-test-support/src/hostile_calls/), and prints how many of the public functions are
called, by which check (`ok`: an `Ok` must hold finite numbers only; `any`: it must return;
`total`: an infallible function, it must return), and the list of those that are not called.
Exits with status 1 when a public function is not called or a name in the calls is not a
public function, so that CI (fuzz/smoke.sh) catches a new function left out. Run it through
fuzz/api_coverage.sh.
"""
import json
import re
import sys
from pathlib import Path

doc = json.load(open(sys.argv[1]))
index = doc["index"]
SKIPPED_TRAITS = {
    "Clone", "Debug", "PartialEq", "Default", "Display", "Index", "IndexMut", "Copy", "Eq",
    "Hash", "Error", "From", "Send", "Sync", "StructuralPartialEq", "Freeze", "Unpin",
    "UnwindSafe", "RefUnwindSafe", "Any", "Borrow", "BorrowMut", "Into", "TryFrom", "TryInto",
    "ToOwned", "ToString", "IntoIterator", "Scalar",
}
found = {}  # item id (or impl, method) -> every public path of it


def trait_methods(trait_path_id):
    item = index.get(str(trait_path_id))
    if not item or "trait" not in item["inner"]:
        return []
    return [index[str(i)]["name"] for i in item["inner"]["trait"]["items"]
            if "function" in index[str(i)]["inner"]]


def walk(module_id, prefix):
    for item_id in index[str(module_id)]["inner"]["module"]["items"]:
        item = index[str(item_id)]
        if item.get("visibility") != "public":
            continue
        name, inner = item["name"], item["inner"]
        kind = next(iter(inner))
        if kind == "use":
            use = inner["use"]
            if use.get("is_glob") or use.get("id") is None or str(use["id"]) not in index:
                continue
            item_id, item, name = use["id"], index[str(use["id"])], use["name"]
            inner = item["inner"]
            kind = next(iter(inner))
            if kind == "module":
                continue
        if kind == "module":
            walk(item_id, prefix + name + "::")
        elif kind == "function":
            found.setdefault(item_id, set()).add(prefix + name)
        elif kind == "trait" and name not in ("Curve", "CurveDeriv", "CurveDeriv2", "Surface"):
            # Curve, CurveDeriv(2) and Surface are counted per implementation (below); other traits (Scalar)
            # by their own methods.
            for method in trait_methods(item_id):
                found.setdefault((item_id, method), set()).add(f"{prefix}{name}::{method}")
        elif kind in ("struct", "enum"):
            for impl_id in inner[kind]["impls"]:
                imp = index[str(impl_id)]["inner"]["impl"]
                if imp.get("is_synthetic") or imp.get("synthetic") or imp.get("blanket_impl"):
                    continue
                trait = imp.get("trait")
                tname = trait["path"].split("::")[-1] if trait else None
                if tname in SKIPPED_TRAITS:
                    continue
                if trait:
                    for method in trait_methods(trait["id"]):
                        key = (impl_id, method)
                        found.setdefault(key, set()).add(f"{prefix}{name} as {tname}::{method}")
                    continue
                for mid in imp["items"]:
                    m = index[str(mid)]
                    if "function" in m["inner"] and m.get("visibility") == "public":
                        found.setdefault(mid, set()).add(f"{prefix}{name}::{m['name']}")


walk(doc["root"], "")
# One entry per function, under its longest path (a module's rather than a re-export at the
# root); it counts as called under any of its paths.
api = sorted((max(sorted(paths), key=len), paths) for paths in found.values() if paths)

source = "".join(p.read_text() for p in sorted(Path(sys.argv[2]).glob("*.rs")))
called = {}  # name -> the strongest check it is called under
STRENGTH = {"ok": 3, "any": 2, "total": 1}


def note(name, kind):
    if STRENGTH[kind] > STRENGTH.get(called.get(name), 0):
        called[name] = kind


# Every string literal naming a function: the checks' names (`ok("bezier::BezierCurve::new",
# …)`, the check being the call it is the first argument of) and the names in tables of
# functions checked in a loop (through `ok`).
NAME = r'"([a-z_]+::[A-Za-z0-9_:]+(?: as (?:Curve|CurveDeriv|CurveDeriv2|Surface)::[a-z0-9_]+)?)(?: \([^"]*\))?"'
for m in re.finditer(NAME, source):
    before = re.search(r'\b(ok_with|ok|any|total|grid_into)\(\s*(?:rng,\s*)?$', source[: m.start()])
    kind = before.group(1) if before else "ok"
    note(m.group(1), "ok" if kind in ("grid_into", "ok_with") else kind)
types = set()
CURVE = [("dim", "total"), ("domain", "total"), ("eval", "total"), ("try_eval", "ok"),
         ("point_cost", "total"), ("eval_many_into", "ok")]
METHODS = {
    "curve": [("Curve", m, k) for m, k in CURVE],
    "deriv": [("Curve", m, k) for m, k in CURVE]
    + [("CurveDeriv", "eval_derivative", "total"), ("CurveDeriv", "try_eval_derivative", "ok")],
    "surface": [("Surface", m, k)
                for m, k in [("dim", "total"), ("domain", "total"), ("eval", "total"),
                             ("try_eval", "ok"), ("eval_grid", "total"),
                             ("eval_grid_into", "ok")]],
}
for m in re.finditer(r'\b(curve|deriv|surface)_methods\(\s*rng,\s*"([^"]+)"', source):
    types.add(m.group(2))
    for trait, method, kind in METHODS[m.group(1)]:
        note(f"{m.group(2)} as {trait}::{method}", kind)


def check_of(paths):
    kinds = [called[p] for p in paths if p in called]
    return max(kinds, key=STRENGTH.get) if kinds else None


covered = [(name, check_of(paths)) for name, paths in api if check_of(paths)]
missing = [name for name, paths in api if not check_of(paths)]
print(f"public functions and methods of cagd: {len(api)}")
print(f"called by the hostile calls: {len(covered)}")
for kind, what in [("ok", "Result-returning, an Ok must hold finite numbers only"),
                   ("any", "Result-returning, no numbers of its own to read, checked through its evaluations"),
                   ("total", "infallible, must return")]:
    print(f"  through check::{kind} ({what}): {sum(1 for _, k in covered if k == kind)}")
print(f"not called: {len(missing)}")
for f in missing:
    print(f"  {f}")
every_path = set().union(*(paths for _, paths in api))
unknown = sorted(c for c in called if c not in every_path and c not in types)
if unknown:
    print("names in the hostile calls that are not public functions (typos?):")
    for c in unknown:
        print(f"  {c}")
sys.exit(1 if missing or unknown else 0)
