// The Coons view with B-spline boundaries (through the operation layer, as the command line
// and the Octave package build the patch), the views' messages naming their own fields, and
// the command box's notes and warnings shown under the answer.

import assert from "node:assert/strict";
import { join } from "node:path";
import { after, before, test } from "node:test";
import { browser, openPage, resultsDir, runBinary, runOnPage, serve } from "./helpers.mjs";

let server;
let chrome;

before(async () => {
  server = await serve();
  chrome = await browser();
});

after(async () => {
  await chrome?.close();
  await server?.stop();
});

const shot = (page, name) => page.screenshot({ path: join(resultsDir, `${name}.png`), fullPage: true });
const text = (page, sel) => page.locator(sel).textContent();

// The command line's example of a B-spline boundary: c1 = bspline(P, U) on [0, 3], c2 = [4u; 1; 0],
// d1 = [0; v; 0], d2 = [4; v; 0], here with the straight sides as control points. By de Boor at
// t = 3/2 (u = 1/2 mapped onto [0, 3]): c1 = 1/8 (1, 0, 1) + 3/4 (2, 0, 0) + 1/8 (3, 0, 1) =
// (2, 0, 1/4), and x(1/2, 0) = c1(3/2).
const P = "[0 1 2 3 4; 0 0 0 0 0; 0 1 0 1 0]";
const BSPLINE_COONS = `cagd coons --c1 "bspline(${P}, [0 0 0 1 2 3 3 3])" --c2 "[0 4; 1 1; 0 0]" --d1 "[0 0; 0 1; 0 0]" --d2 "[4 4; 0 1; 0 0]" --u 0.5 --v 0 --steps --exact`;

test("the Coons view takes B-spline boundaries: x(1/2, 0) = (2, 0, 1/4) exactly, in the numbers and the grid", async () => {
  const page = await openPage(chrome.context, server.url, `#view=coons&cmd=${encodeURIComponent(BSPLINE_COONS)}`);
  await page.locator("#coons-answer").filter({ hasText: "1/4" }).waitFor();
  assert.equal(await text(page, "#coons-answer"), "x(0.5, 0) = (2, 0, 1/4)");
  assert.match(await text(page, "#coons-steps"), /result =\n\n\s+2\n\s+0\n\s+1\/4\n/);
  // The boundary's fields: a B-spline of degree 2 on its typed knots.
  assert.equal(await page.inputValue("#coons-curve"), "c1");
  assert.equal(await page.inputValue("#coons-kind"), "bspline");
  assert.equal(await page.inputValue("#coons-degree"), "2");
  assert.equal(await page.inputValue("#coons-knots"), "[0 0 0 1 2 3 3 3]");
  assert.match(await text(page, "#coons-cmd"), /--c1 "bspline\(\[0 0 0; 1 0 1; 2 0 0; 3 0 1; 4 0 0\]', \[0 0 0 1 2 3 3 3\]\)"/);
  // The command shown is the program's, and the program prints the same.
  const args = (await text(page, "#coons-cmd")).match(/"[^"]*"|\S+/g).slice(1).map((a) => a.replace(/^"|"$/g, ""));
  assert.equal(await text(page, "#coons-steps"), runBinary(args).stdout);
  // The picture's grid, from coons_view (the operation layer's coons request, in doubles):
  // on 21 × 21 points, u = 1/2 is row 10; v = 0 column 0.
  await page.fill("#coons-n", "21");
  const grid = await page.evaluate(() => {
    const g = window.cagdApp.views.coons.grids;
    const k = (10 * 21 + 0) * 3;
    return [g[k], g[k + 1], g[k + 2], g.length];
  });
  assert.deepEqual(grid, [2, 0, 0.25, 21 * 21 * 3]);
  await shot(page, "view-coons-bspline");
  // The same curve on knots typed as fractions over [0, 1]: kept as typed, still exact.
  await page.fill("#coons-knots", "[0 0 0 1/3 2/3 1 1 1]");
  await page.locator("#coons-cmd").filter({ hasText: "1/3 2/3" }).waitFor();
  assert.equal(await text(page, "#coons-answer"), "x(0.5, 0) = (2, 0, 1/4)");
  assert.match(await text(page, "#coons-cmd"), /\[0 0 0 1\/3 2\/3 1 1 1\]\)"/);
  // A Bézier side turned into a B-spline is the same curve ([0 0 1 1] for a line): same answer.
  await page.selectOption("#coons-curve", "d1");
  assert.equal(await page.inputValue("#coons-kind"), "bezier");
  await page.selectOption("#coons-kind", "bspline");
  assert.equal(await page.inputValue("#coons-knots"), "[0 0 1 1]");
  await page.locator("#coons-cmd").filter({ hasText: "--d1 \"bspline(" }).waitFor();
  assert.equal(await text(page, "#coons-answer"), "x(0.5, 0) = (2, 0, 1/4)");
  // Its control point added: the degree stays 1 and the knots follow ([0 0 1/2 1 1]).
  await page.click("#coons-add");
  assert.equal(await page.inputValue("#coons-knots"), "[0 0 1/2 1 1]");
  assert.equal(await text(page, "#coons-answer"), "x(0.5, 0) = (2, 0, 1/4)");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("the Coons view's messages name its fields, never an option it lacks", async () => {
  const page = await openPage(chrome.context, server.url, `#view=coons&cmd=${encodeURIComponent(BSPLINE_COONS)}`);
  await page.locator("#coons-answer").filter({ hasText: "1/4" }).waitFor();
  // Knots that decrease: the operation layer's words under the field's label.
  await page.fill("#coons-knots", "[0 0 0 1 1/2 3 3 3]");
  const error = page.locator("#coons-error");
  await error.filter({ hasText: "Boundary c1 = x(u, 0): " }).waitFor();
  const message = await error.textContent();
  assert.match(message, /^cagd: error: Boundary c1 = x\(u, 0\): .*knot/);
  assert.doesNotMatch(message, /--/);
  assert.equal(await text(page, "#coons-answer"), "", "no old answer beside the message");
  assert.equal(await text(page, "#coons-steps"), "");
  // A corner typed apart from its boundaries' ends cannot happen (corners are shared); a
  // control point that is not a number is named by its boundary.
  await page.fill("#coons-knots", "[0 0 0 1 2 3 3 3]");
  await error.waitFor({ state: "hidden" });
  await page.selectOption("#coons-point", "c1:2");
  await page.fill("#coons-px", "2,");
  await error.filter({ hasText: "Boundary c1 = x(u, 0): " }).waitFor();
  assert.doesNotMatch(await error.textContent(), /--/);
  await page.fill("#coons-px", "2");
  await error.waitFor({ state: "hidden" });
  assert.equal(await text(page, "#coons-answer"), "x(0.5, 0) = (2, 0, 1/4)");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("every view's message names the view's own field (the page's label, in its language)", async () => {
  const cases = [
    // view, what to type where, the label the message starts with
    ["bezier", '#view-bezier table.points input[data-row="1"][data-col="0"]', "x", "Control points"],
    ["bezier", "#bezier-t-text", "1/0", "Parameter t"],
    ["bspline", "#bspline-knots", "[0 0 0 0 2/3 1/3 1 1 1 1]", "Knot vector"],
    ["nurbs", '#view-nurbs table.points input[data-row="1"][data-col="2"]', "-1", "Weights"],
    ["insert", "#insert-t-text", "7", "Insert the knot u"],
    ["basis", "#basis-knots", "[0 0 1 0.5 2 2]", "Knot vector"],
    ["spline", "#spline-start", "[1;", "Start tangent"],
  ];
  const page = await openPage(chrome.context, server.url);
  for (const [view, field, typed, label] of cases) {
    await page.click(`#tab-${view}`);
    await page.locator(`#${view}-steps`).filter({ hasText: /\S/ }).waitFor();
    const before = await page.inputValue(field);
    await page.fill(field, typed);
    const error = page.locator(`#${view}-error`);
    await error.waitFor();
    const message = await error.textContent();
    assert.ok(message.startsWith(`cagd: error: ${label}: `), `${view}: ${message}`);
    assert.doesNotMatch(message, /--[a-z]|CONTROL|POINTS/, `${view}: ${message}`);
    await page.fill(field, before);
    await error.waitFor({ state: "hidden" });
  }
  // In Slovenian the field's Slovenian label, and the operation layer's words in Slovenian
  // (the catalogue of cagd_web::messages), in the view and in the command box.
  await page.selectOption("#lang", "sl");
  await page.click("#tab-bspline");
  await page.fill("#bspline-knots", "[0 0 0 0 2/3 1/3 1 1 1 1]");
  const error = page.locator("#bspline-error");
  await error.filter({ hasText: "cagd: napaka: Vozliščni vektor: " }).waitFor();
  const knots = await error.textContent();
  assert.match(knots, /^cagd: napaka: Vozliščni vektor: vozliščni vektor: vozel 6 \(\S+\) je manjši od vozla pred njim \(\S+\); vozli morajo biti nepadajoči; pričakovano: n \+ p \+ 1 nepadajočih vozlov za n kontrolnih točk stopnje p \(n ≥ p \+ 1\), pri čemer u_\(p\+1\) < u_\(n\+1\)$/);
  await page.click("#tab-command");
  const bad = `cagd bspline "[0 0; 1 1; 2 0; 3 1]'" --degree 2 --knots "[0 0 0 1 0.5 1 1]"`;
  const sl = await runOnPage(page, bad);
  assert.equal(
    sl.error,
    "cagd: napaka: --knots: vozliščni vektor: vozel 5 (0.5) je manjši od vozla pred njim (1); vozli morajo biti nepadajoči; pričakovano: n + p + 1 nepadajočih vozlov za n kontrolnih točk stopnje p (n ≥ p + 1), pri čemer u_(p+1) < u_(n+1)",
  );
  await shot(page, "command-error-sl");
  await page.selectOption("#lang", "cs");
  assert.equal(
    await page.locator("#error").textContent(),
    "cagd: chyba: --knots: uzlový vektor: uzel 5 (0.5) je menší než uzel před ním (1); uzly musí být neklesající; očekává se: n + p + 1 neklesajících uzlů pro n řídicích bodů stupně p (n ≥ p + 1), přičemž u_(p+1) < u_(n+1)",
  );
  // In English, the program's own line, as the cagd binary prints it.
  await page.selectOption("#lang", "en");
  const en = await runOnPage(page, bad);
  const binary = runBinary(["bspline", "[0 0; 1 1; 2 0; 3 1]'", "--degree", "2", "--knots", "[0 0 0 1 0.5 1 1]"]);
  assert.equal(en.error, binary.stderr.trim());
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("the command box shows a slip's note under the answer, and none for the explicit reading", async () => {
  const page = await openPage(chrome.context, server.url);
  // Rows (0, 0), (4, 2) meant; read as columns (0, 4), (0, 2): b(1/4) = (0, 7/2), with the note.
  const slip = await runOnPage(page, `cagd decasteljau "[0 0; 4 2]" --t 1/4 --exact`);
  assert.ok(slip.ok, slip.error);
  assert.deepEqual(slip.warnings, ["cagd: warning: CONTROL: read as 2 points in 2-D, one per column; --rows if each row is a point"]);
  assert.equal(await page.locator("#warnings li").count(), 1);
  assert.equal(await page.locator("#warnings li").isVisible(), true);
  assert.match(slip.stdout, /result =\n\n\s+0\n\s+7\/2\n/);
  await shot(page, "command-note");
  // Stated: 3/4 (0, 0) + 1/4 (4, 2) = (1, 1/2), and nothing under the answer.
  const stated = await runOnPage(page, `cagd decasteljau "[0 0; 4 2]" --rows --t 1/4 --exact`);
  assert.deepEqual(stated.warnings, []);
  assert.equal(await page.locator("#warnings li").count(), 0);
  assert.match(stated.stdout, /result =\n\n\s+1\n\s+1\/2\n/);
  // A decimal comma in a list inside the domain: the warning, then 2.5 meant: p(5/2) = 87/32.
  const comma = await runOnPage(page, `cagd lagrange --nodes 1:5 --points "[1 2 3 2 1]" --t "[2,5]"`);
  assert.deepEqual(comma.warnings, ["cagd: warning: --t: `2,5` read as two numbers 2 and 5; a decimal point is `2.5`"]);
  const meant = await runOnPage(page, `cagd lagrange --nodes 1:5 --points "[1 2 3 2 1]" --t 2.5 --exact`);
  assert.deepEqual(meant.warnings, []);
  assert.match(meant.stdout, /87\/32/);
  assert.deepEqual(page.errors, []);
  await page.close();
});
