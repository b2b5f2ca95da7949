// Numbers as the user typed them. The views keep every coordinate, knot, weight and parameter
// as its text ("1/3", "0.25", "-2") and hand that text to the command line, which reads it
// exactly with --exact; doubles are used only to draw. Dragging writes the new position as a
// short decimal text (snapped to the grid when snapping is on).

/** The double of a typed number: an integer, a decimal (with exponent) or a fraction a/b. */
export function toNumber(text) {
  const s = String(text ?? "").replace(/\s+/g, "");
  if (s === "") return NaN;
  const m = s.match(/^([+-]?(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?)(?:\/([+-]?(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?))?$/i);
  if (!m) return NaN;
  const a = Number(m[1]);
  return m[2] === undefined ? a : a / Number(m[2]);
}

/** Whether `text` is a number this page can read (else the command line says what is wrong). */
export function isNumber(text) {
  return Number.isFinite(toNumber(text));
}

/** Shortest text of a double, without binary noise such as 0.30000000000000004. */
export function num(x) {
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return "0";
  const short = Number(x.toPrecision(12));
  return Math.abs(short - x) <= 1e-15 * Math.abs(x) ? String(short) : String(x);
}

/** The text a drag writes: `x` on the grid `step` when snapping, else to 1/1000 of `scale`. */
export function dragText(x, step, scale = 1) {
  if (step) return num(Math.round(x / step) * step);
  const digits = Math.max(0, Math.min(12, 3 - Math.floor(Math.log10(Math.abs(scale) || 1))));
  return num(Number(x.toFixed(digits)));
}

/** One typed entry inside a matrix literal: bare when a plain number, else in parentheses. */
export function entry(text) {
  const s = String(text ?? "").replace(/\s+/g, "");
  if (/^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(s) || /^\d+\/\d+$/.test(s)) return s;
  return s === "" ? "NaN" : `(${s})`;
}

/** A matrix literal with one point per row, transposed: points as columns (`[…; …]'`). */
export function pointsLiteral(points) {
  return `[${points.map((p) => p.map(entry).join(" ")).join("; ")}]'`;
}

/** A row literal of typed values (`[0 0 0 1/3 …]`). */
export function rowLiteral(values) {
  return `[${values.map(entry).join(" ")}]`;
}

/** The typed values of a row literal such as "[0 0 1/3 1]" (or "0, 1/3, 1"). */
export function splitRow(text) {
  return String(text ?? "")
    .replace(/^\s*\[|\]\s*$/g, "")
    .split(/[\s,;]+/)
    .filter(Boolean);
}

/** A number printed by the command line (integer, decimal or a/b) as a double. */
export function valueOf(printed) {
  return typeof printed === "number" ? printed : toNumber(printed);
}

/** The columns of a JSON matrix (rows of printed numbers) as points of doubles. */
export function columnsOf(rows) {
  if (!Array.isArray(rows)) return [[valueOf(rows)]];
  const m = rows.map((r) => (Array.isArray(r) ? r : [r]));
  return m[0].map((_, j) => m.map((r) => valueOf(r[j])));
}

/** A JSON row vector (1×k, or a scalar) as a list of printed values. */
export function rowOf(value) {
  if (!Array.isArray(value)) return [value];
  return value.flat();
}

function gcd(a, b) {
  a = Math.abs(a);
  b = Math.abs(b);
  while (b) [a, b] = [b, a % b];
  return a || 1;
}

/** The fraction a/b as the command line prints it (reduced; an integer without /1). */
export function fraction(a, b) {
  const g = gcd(a, b);
  const [n, d] = b < 0 ? [-a / g, -b / g] : [a / g, b / g];
  return d === 1 ? String(n) : `${n}/${d}`;
}

/**
 * The clamped uniform knot vector of degree p for `count` control points over [a, b], as
 * texts: p + 1 times a, the interior knots a + k (b − a)/(count − p) exactly (fractions when a
 * and b are integers), p + 1 times b.
 */
export function uniformKnots(p, count, a = "0", b = "1") {
  const spans = count - p;
  const [x, y] = [toNumber(a), toNumber(b)];
  const whole = Number.isInteger(x) && Number.isInteger(y);
  const inner = [];
  for (let k = 1; k < spans; k++) inner.push(whole ? fraction(x * spans + k * (y - x), spans) : num(x + (k * (y - x)) / spans));
  return [...Array(p + 1).fill(a), ...inner, ...Array(p + 1).fill(b)];
}
