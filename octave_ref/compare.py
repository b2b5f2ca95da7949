#!/usr/bin/env python3
"""Compare Octave `save -text` reference files, number by number.

Usage:
    python3 compare.py EXPECTED RESULT

EXPECTED and RESULT are two directories (every *.txt in either is compared with the file of the
same name in the other; a file present on one side only is a failure) or two files.

The "# Created by Octave ..." line (date, host) is ignored.  Everything else must match:
variable names and order, types, shapes, strings and booleans exactly, and numbers as doubles
within 4 ULPs or 1e-14 relative to the scale of the variable (its largest finite magnitude),
whichever is looser.  The scale, not each number, is the measure because Octave's linear
algebra runs in the BLAS and LAPACK the machine has, whose kernels (chosen per processor) round
differently: a value that is round-off, such as the 3e-16 of a circle point at zero, or a
degree-8 polyfit coefficient, differs in relative terms, never relative to the variable.
A case whose Octave computation is itself less accurate than that declares its tolerance in
its script, `% compare: relative X`, with the reason (see case_tolerance).  Non-finite values must match exactly
(Inf, -Inf, NaN, NA are distinct).  Every difference is printed with file, variable (a path such
as `s.knots{2}` inside structs and cells), Octave-style index and both values; the exit status is
1 when anything differs, 2 on unreadable input, 0 otherwise.

Python 3 standard library only.
"""

import math
import os
import struct
import sys

MAX_ULPS = 4
MAX_REL = 1e-14
MAX_REPORTS_PER_FILE = 25

NUMERIC_TYPES = {"scalar", "matrix", "bool", "bool matrix"}
INT_PREFIXES = ("int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64")


class ParseError(Exception):
    """A file that does not follow the `save -text` layout."""


class Value:
    """One parsed variable: type, shape and flat data (column-major), or children."""

    def __init__(self, type_name, shape, data=None, children=None):
        self.type_name = type_name
        self.shape = shape
        self.data = data if data is not None else []
        self.children = children if children is not None else []


class Reader:
    """Line cursor over a file decoded as latin-1 (one character per byte)."""

    def __init__(self, path):
        with open(path, "rb") as f:
            self.text = f.read().decode("latin-1")
        self.pos = 0
        self.line = 0
        self.path = path

    def fail(self, message):
        raise ParseError(f"{self.path}:{self.line}: {message}")

    def next_line(self):
        if self.pos >= len(self.text):
            self.fail("unexpected end of file")
        end = self.text.find("\n", self.pos)
        if end < 0:
            end = len(self.text)
        line = self.text[self.pos:end]
        self.pos = end + 1
        self.line += 1
        return line

    def peek_line(self):
        if self.pos >= len(self.text):
            return None
        end = self.text.find("\n", self.pos)
        return self.text[self.pos:end if end >= 0 else len(self.text)]

    def skip_blank(self):
        while True:
            line = self.peek_line()
            if line is None or line.strip() != "":
                return
            self.next_line()

    def read_chars(self, n):
        if self.pos + n > len(self.text):
            self.fail("unexpected end of file inside a string")
        s = self.text[self.pos:self.pos + n]
        self.line += s.count("\n")
        self.pos += n
        # the newline that ends the string row
        if self.pos < len(self.text):
            if self.text[self.pos] != "\n":
                self.fail("string longer than its '# length:'")
            self.pos += 1
            self.line += 1
        return s

    def header(self, key):
        line = self.next_line()
        prefix = f"# {key}:"
        if not line.startswith(prefix):
            self.fail(f"expected '{prefix}', found {line!r}")
        return line[len(prefix):].strip()

    def int_header(self, key):
        value = self.header(key)
        try:
            return int(value)
        except ValueError:
            self.fail(f"'# {key}:' is not an integer: {value!r}")


def parse_number(token):
    """The double a token stands for; NA is kept distinct from NaN by the caller."""
    if token == "NA":
        return math.nan
    return float(token)


def read_numbers(rd, count_per_line, lines):
    data_rows = []
    for _ in range(lines):
        line = rd.next_line()
        tokens = line.split()
        if len(tokens) != count_per_line:
            rd.fail(f"expected {count_per_line} value(s) on the line, found {len(tokens)}")
        for tok in tokens:
            try:
                parse_number(tok)
            except ValueError:
                rd.fail(f"not a number: {tok!r}")
        data_rows.append(tokens)
    return data_rows


def read_dims(rd):
    nd = rd.int_header("ndims")
    dims = rd.next_line().split()
    if len(dims) != nd:
        rd.fail(f"expected {nd} dimension(s), found {len(dims)}")
    return tuple(int(d) for d in dims)


def read_value(rd, type_name):
    """Reads the body of a value whose '# type:' line has been read."""
    if type_name.startswith("global "):
        type_name = type_name[len("global "):]
    if type_name in ("scalar", "bool") or (
        type_name.endswith(" scalar") and type_name.startswith(INT_PREFIXES)
    ):
        rows = read_numbers(rd, 1, 1)
        return Value(type_name, (1, 1), rows[0])
    if type_name in ("matrix", "bool matrix") or (
        type_name.endswith(" matrix") and type_name.startswith(INT_PREFIXES)
    ):
        line = rd.peek_line() or ""
        if line.startswith("# ndims:"):
            shape = read_dims(rd)
            total = 1
            for d in shape:
                total *= d
            rows = read_numbers(rd, 1, total)
            return Value(type_name, shape, [r[0] for r in rows])
        r = rd.int_header("rows")
        c = rd.int_header("columns")
        # an R x 0 matrix has no data lines (blank lines between variables are skipped)
        rows = read_numbers(rd, c, r) if c > 0 else []
        # column-major flat order, like Octave
        data = [rows[i][j] for j in range(c) for i in range(r)]
        return Value(type_name, (r, c), data)
    if type_name in ("range", "double_range"):
        rd.next_line()  # "# base, limit, increment"
        rows = read_numbers(rd, 3, 1)
        return Value(type_name, (1, 3), rows[0])
    if type_name in ("sq_string", "string"):
        line = rd.peek_line() or ""
        if line.startswith("# ndims:"):
            shape = read_dims(rd)
            total = 1
            for d in shape:
                total *= d
            return Value(type_name, shape, [rd.read_chars(total)])
        elements = rd.int_header("elements")
        data = []
        for _ in range(elements):
            length = rd.int_header("length")
            data.append(rd.read_chars(length))
        return Value(type_name, (elements,), data)
    if type_name == "cell":
        line = rd.peek_line() or ""
        if line.startswith("# ndims:"):
            shape = read_dims(rd)
        else:
            shape = (rd.int_header("rows"), rd.int_header("columns"))
        total = 1
        for d in shape:
            total *= d
        children = []
        for _ in range(total):
            rd.skip_blank()
            name, value = read_named(rd)
            children.append((name, value))
        return Value(type_name, shape, children=children)
    if type_name in ("scalar struct", "struct"):
        shape = read_dims(rd)
        n = rd.int_header("length")
        children = []
        for _ in range(n):
            rd.skip_blank()
            children.append(read_named(rd))
        return Value(type_name, shape, children=children)
    if type_name.startswith("complex"):
        rd.fail(f"complex values are not compared by this script ({type_name})")
    rd.fail(f"unknown type {type_name!r}")


def read_named(rd):
    name = rd.header("name")
    type_name = rd.header("type")
    return name, read_value(rd, type_name)


def parse_file(path):
    rd = Reader(path)
    variables = []
    while True:
        line = rd.peek_line()
        if line is None:
            return variables
        if line.startswith("# name:"):
            variables.append(read_named(rd))
        elif line.strip() == "" or line.startswith("#"):
            # blank lines, the "# Created by Octave" line and other comments
            rd.next_line()
        else:
            rd.next_line()
            rd.fail(f"data outside any variable: {line!r}")


def ordered_bits(x):
    """Maps a double to an integer so that adjacent doubles differ by 1."""
    (i,) = struct.unpack("<q", struct.pack("<d", x))
    return i if i >= 0 else -(i & 0x7FFFFFFFFFFFFFFF)


def ulp_distance(a, b):
    return abs(ordered_bits(a) - ordered_bits(b))


def octave_index(flat, shape):
    """1-based Octave subscript of a column-major flat index."""
    subs = []
    for d in shape:
        if d == 0:
            break
        subs.append(flat % d + 1)
        flat //= d
    return "(" + ",".join(str(s) for s in subs) + ")"


def case_tolerance(case_name):
    """The relative tolerance a case script declares for itself, `% compare: relative X` in
    `cases/<case>.m` next to this script (for Octave computations whose own round-off is
    larger than 1e-14: a least-squares polyfit carries about cond(V)·eps), else MAX_REL."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cases", case_name + ".m")
    try:
        with open(path, encoding="utf-8") as f:
            for line in f:
                words = line.split()
                if words[:3] == ["%", "compare:", "relative"] and len(words) > 3:
                    return float(words[3])
    except (OSError, ValueError):
        pass
    return MAX_REL


class Comparison:
    def __init__(self, fname):
        self.fname = fname
        self.max_rel = case_tolerance(os.path.splitext(os.path.basename(fname))[0])
        self.failures = 0
        self.worst_ulps = 0
        self.worst_rel = 0.0

    def fail(self, var, message):
        self.failures += 1
        if self.failures <= MAX_REPORTS_PER_FILE:
            print(f"DIFFERENT {self.fname}: {var}: {message}")
        elif self.failures == MAX_REPORTS_PER_FILE + 1:
            print(f"DIFFERENT {self.fname}: ... (further differences not shown)")

    def numbers(self, var, shape, exp, got):
        var_scale = 0.0
        for te in exp:
            try:
                x = parse_number(te)
            except ValueError:
                continue
            if math.isfinite(x):
                var_scale = max(var_scale, abs(x))
        for k, (te, tg) in enumerate(zip(exp, got)):
            if te == tg:
                continue
            where = f"{var}{octave_index(k, shape)}"
            try:
                a, b = parse_number(te), parse_number(tg)
            except ValueError:
                self.fail(where, f"expected {te}, found {tg}")
                continue
            if not (math.isfinite(a) and math.isfinite(b)):
                if te != tg and not (a == b):
                    self.fail(where, f"expected {te}, found {tg}")
                continue
            ulps = ulp_distance(a, b)
            scale = max(var_scale, abs(a), abs(b))
            rel = abs(a - b) / scale if scale > 0 else 0.0
            self.worst_ulps = max(self.worst_ulps, ulps)
            self.worst_rel = max(self.worst_rel, rel)
            if ulps > MAX_ULPS and rel > self.max_rel:
                self.fail(
                    where,
                    f"expected {te}, found {tg} ({ulps} ULPs, relative {rel:.3g}; "
                    f"allowed {MAX_ULPS} ULPs or {self.max_rel:g} relative to the variable's scale)",
                )

    def value(self, var, exp, got):
        if exp.type_name != got.type_name:
            self.fail(var, f"type: expected {exp.type_name!r}, found {got.type_name!r}")
            return
        if exp.shape != got.shape:
            self.fail(var, f"shape: expected {exp.shape}, found {got.shape}")
            return
        if exp.type_name in ("cell",):
            for k, ((_, e), (_, g)) in enumerate(zip(exp.children, got.children)):
                self.value(f"{var}{{{k + 1}}}", e, g)
        elif exp.type_name in ("scalar struct", "struct"):
            en = [n for n, _ in exp.children]
            gn = [n for n, _ in got.children]
            if en != gn:
                self.fail(var, f"fields: expected {en}, found {gn}")
                return
            for (n, e), (_, g) in zip(exp.children, got.children):
                self.value(f"{var}.{n}", e, g)
        elif exp.type_name in ("sq_string", "string"):
            for k, (e, g) in enumerate(zip(exp.data, got.data)):
                if e != g:
                    self.fail(f"{var} row {k + 1}", f"expected {e!r}, found {g!r}")
        else:
            self.numbers(var, exp.shape, exp.data, got.data)


def compare_files(expected_path, result_path, label):
    cmp = Comparison(label)
    try:
        exp = parse_file(expected_path)
        got = parse_file(result_path)
    except (ParseError, OSError, UnicodeError) as err:
        print(f"UNREADABLE {label}: {err}")
        return cmp, 2
    en = [n for n, _ in exp]
    gn = [n for n, _ in got]
    if en != gn:
        only_e = [n for n in en if n not in gn]
        only_g = [n for n in gn if n not in en]
        if only_e:
            cmp.fail("(variables)", f"only in expected: {', '.join(only_e)}")
        if only_g:
            cmp.fail("(variables)", f"only in result: {', '.join(only_g)}")
        if not only_e and not only_g:
            cmp.fail("(variables)", "same variables in a different order")
    gd = dict(got)
    for name, value in exp:
        if name in gd:
            cmp.value(name, value, gd[name])
    return cmp, 1 if cmp.failures else 0


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    expected, result = argv[1], argv[2]
    if os.path.isdir(expected) and os.path.isdir(result):
        e_files = {f for f in os.listdir(expected) if f.endswith(".txt")}
        r_files = {f for f in os.listdir(result) if f.endswith(".txt")}
        pairs = [(os.path.join(expected, f), os.path.join(result, f), f)
                 for f in sorted(e_files & r_files)]
        status = 0
        for f in sorted(e_files - r_files):
            print(f"MISSING {f}: in {expected} but not regenerated into {result}")
            status = 1
        for f in sorted(r_files - e_files):
            print(f"MISSING {f}: regenerated into {result} but not in {expected} (commit it)")
            status = 1
    elif os.path.isfile(expected) and os.path.isfile(result):
        pairs = [(expected, result, os.path.basename(expected))]
        status = 0
    else:
        print(f"compare.py: need two directories or two files: {expected}, {result}",
              file=sys.stderr)
        return 2
    for e, r, label in pairs:
        cmp, st = compare_files(e, r, label)
        status = max(status, st)
        verdict = "ok" if st == 0 else "FAILED"
        print(f"{verdict:6} {label}: worst {cmp.worst_ulps} ULPs, relative {cmp.worst_rel:.3g}"
              + (f", {cmp.failures} difference(s)" if cmp.failures else ""))
    if not pairs and status == 0:
        print("compare.py: no reference files found", file=sys.stderr)
        return 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
