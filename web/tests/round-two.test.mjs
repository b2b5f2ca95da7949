// The page's second round (issue 26): each defect D1–D11 the student met, the seven homework
// tasks done in a view and by a generated form (exact, with steps and a picture), forms for
// every subcommand, languages, the phone layout, history entries, and the screenshots.

import assert from "node:assert/strict";
import { readdirSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { after, before, test } from "node:test";
import { browser, openPage, resultsDir, runBinary, runOnPage, serve, webDir } from "./helpers.mjs";

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

const link = (cmd, view) => `#${view ? `view=${view}&` : ""}cmd=${encodeURIComponent(cmd)}`;
const shot = (page, name, fullPage = true) => page.screenshot({ path: join(resultsDir, `${name}.png`), fullPage });
const text = (page, sel) => page.locator(sel).textContent();

/** Opens a view and waits until its numbers are there. */
async function openView(view, cmd) {
  const page = await openPage(chrome.context, server.url, cmd ? link(cmd, view) : `#view=${view}`);
  await page.locator(`#${view}-steps`).filter({ hasText: ANSWERS[view] ?? "result" }).waitFor();
  return page;
}

/** The item each view's steps end with (elevation and insertion answer control points). */
const ANSWERS = { elevate: "control", insert: "control" };

/** Fills the generated form of `name` (values by argument id) and runs it with its Run button. */
async function runForm(page, name, values, switches = {}) {
  if (name) {
    await page.selectOption("#construction", name);
    // Start from an empty form (not the example's values).
    await page.evaluate(() => {
      for (const e of document.querySelectorAll("#command-form [data-arg]")) {
        if (e.type === "checkbox") e.checked = false;
        else e.value = "";
      }
    });
  }
  for (const [id, value] of Object.entries(values)) await page.fill(`#f-${id}`, value);
  for (const [id, on] of Object.entries(switches)) await page.locator(`#f-${id}`).setChecked(on);
  const before = Number(await page.locator("#result").getAttribute("data-run"));
  await page.click("#run");
  // The answer to this Run (not the example's own run, started when it was chosen, should
  // that one land meanwhile): the result's line is the command line shown.
  await page.waitForFunction(
    (n) => {
      const r = document.getElementById("result");
      return Number(r.dataset.run) > n && r.dataset.line === document.getElementById("cmdline").value;
    },
    before,
    { timeout: 60000 },
  );
  return {
    line: await page.inputValue("#cmdline"),
    stdout: await text(page, "#stdout"),
    error: await text(page, "#error"),
    pictures: await page.locator("#pictures img").count(),
  };
}

test("D1: uniform knots are exact fractions (1/3, not 0.3333) and the basis at 1/2 is 1/32 … exactly", async () => {
  const page = await openView("bspline");
  await page.click("#bspline-uniform");
  assert.equal(await page.inputValue("#bspline-knots"), "[0 0 0 0 1/3 2/3 1 1 1 1]");
  await page.fill("#bspline-t-text", "1/2");
  await page.locator("#bspline-steps").filter({ hasText: "15/32" }).waitFor();
  const steps = await text(page, "#bspline-steps");
  assert.match(steps, /basis =\n\n\s+0\s+1\/32\s+15\/32\s+15\/32\s+1\/32\s+0\n/);
  assert.doesNotMatch(steps, /2778889|0\.3333/);
  assert.match(await text(page, "#bspline-cmd"), /--knots "\[0 0 0 0 1\/3 2\/3 1 1 1 1\]"/);
  // A knot typed as 1/3 stays 1/3; without snapping a drag reaches any value.
  await page.fill("#bspline-knots", "[0 0 0 0 1/3 1/2 1 1 1 1]");
  await page.locator("#bspline-cmd").filter({ hasText: "1/3 1/2" }).waitFor();
  await page.locator("#bspline-snap").uncheck();
  const knot = page.locator('#bspline-basis circle.handle[data-index="0"]');
  await knot.focus();
  await page.keyboard.press("Shift+ArrowRight");
  assert.match(await text(page, "#bspline-cmd"), /--knots "\[0 0 0 0 0\.343 1\/2 1 1 1 1\]"/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D2: a B-spline on [0, 3] keeps --t 1.5 as typed, its slider and basis cover [0, 3], the marker is the answer", async () => {
  const cmd = `cagd bspline "[0 0; 1 2; 2 3; 3 1; 4 2; 5 0]'" --degree 2 --knots "[0 0 0 1 2 2 3 3 3]" --t 1.5 --steps --exact`;
  const page = await openView("bspline", cmd);
  assert.equal(await page.inputValue("#bspline-t-text"), "1.5");
  assert.match(await page.evaluate(() => decodeURIComponent(location.hash)), /--t 1\.5 /);
  assert.equal(await page.getAttribute("#bspline-t", "max"), "3");
  assert.equal(await page.getAttribute("#bspline-t", "min"), "0");
  const binary = runBinary(["bspline", "[0 0; 1 2; 2 3; 3 1; 4 2; 5 0]'", "--degree", "2", "--knots", "[0 0 0 1 2 2 3 3 3]", "--t", "1.5", "--steps", "--exact"]);
  assert.equal(await text(page, "#bspline-steps"), binary.stdout);
  // x(3/2) = (17/8, 19/8) by de Boor; the marker sits exactly there.
  assert.match(binary.stdout, /result =\n\n\s+17\/8\n\s+19\/8\n/);
  const marker = await page.locator("#bspline-plane circle.point-at-t").evaluate((c) => [Number(c.getAttribute("cx")), -Number(c.getAttribute("cy"))]);
  assert.deepEqual(marker, [2.125, 2.375]);
  assert.match(await text(page, "#bspline-answer"), /x\(1\.5\) = \(17\/8, 19\/8\)/);
  // The basis is drawn over the whole domain, up to 3.
  const xmax = await page.locator('#bspline-basis polyline[data-basis="5"]').evaluate((p) => Math.max(...p.getAttribute("points").split(" ").map((q) => Number(q.split(",")[0]))));
  assert.equal(xmax, 3);
  await shot(page, "view-bspline-domain-0-3");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D3: every subcommand has a form from the command line's definitions; a typed command shows its own form and Run runs it", async () => {
  const page = await openPage(chrome.context, server.url);
  const schema = await page.evaluate(() => window.cagdApp.schema.map((c) => ({ name: c.name, args: c.args.filter((a) => a.id !== "lang").map((a) => a.id) })));
  const subcommands = runBinary(["--help"])
    .stdout.split("Commands:")[1]
    .split("Options:")[0]
    .split("\n")
    .map((l) => l.trim().split(/\s+/)[0])
    .filter((n) => n && n !== "help");
  assert.deepEqual(
    schema.map((c) => c.name),
    subcommands,
  );
  const missing = await page.evaluate((all) => {
    const out = [];
    const sel = document.getElementById("construction");
    for (const { name, args } of all) {
      sel.value = name;
      sel.dispatchEvent(new Event("change"));
      const shown = new Set([...document.querySelectorAll("#command-form [data-arg]")].flatMap((e) => [e.dataset.arg, e.dataset.of]));
      for (const id of args) if (!shown.has(id)) out.push(`${name}: ${id}`);
      for (const el of document.querySelectorAll("#view-command input, #view-command select, #view-command textarea"))
        if (!(el.labels?.length || el.getAttribute("aria-label"))) out.push(`${name}: unnamed ${el.id}`);
    }
    return out;
  }, schema);
  assert.deepEqual(missing, []);
  // A typed elevate shows the elevate form and elevate's Octave code, never the form before.
  await page.selectOption("#construction", "coons");
  const elevate = await runOnPage(page, `cagd elevate "[0 0; 1 2; 3 2]'" --by 1 --exact`);
  assert.ok(elevate.ok, elevate.error);
  assert.equal(await page.inputValue("#construction"), "elevate");
  assert.equal(await page.inputValue("#f-control"), "[0 0; 1 2; 3 2]'");
  assert.doesNotMatch(await text(page, "#octave"), /rc|coons|c1/);
  assert.match(await text(page, "#octave"), /b_i\^\(1\)|bspdegelev|elevate/);
  // The form's Run runs what the form shows (elevate), not an older construction.
  await page.fill("#f-by", "2");
  const again = await runForm(page, null, {});
  assert.equal(again.line, `cagd elevate "[0 0; 1 2; 3 2]'" --by 2 --exact`);
  assert.equal(again.stdout, runBinary(["elevate", "[0 0; 1 2; 3 2]'", "--by", "2", "--exact"]).stdout);
  const insert = await runOnPage(page, `cagd insert-knot "[0 0; 1 2; 2 3; 3 1; 4 2; 5 0]'" --degree 2 --knots "[0 0 0 1 2 2 3 3 3]" --insert 3/2 --exact`);
  assert.ok(insert.ok, insert.error);
  assert.equal(await page.inputValue("#construction"), "insert-knot");
  assert.equal(await page.inputValue("#f-insert"), "3/2");
  assert.match(await text(page, "#octave"), /bspkntins/);
  await shot(page, "command-insert-knot-form");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D4: opening the Gordon view while a command runs neither cancels nor orphans it", async () => {
  const page = await openPage(chrome.context, server.url);
  await page.fill("#cmdline", "cagd surface '[u; v; u.*v + sin(u.*v)]' --n 1500 --format csv -o grid.csv");
  await page.press("#cmdline", "Enter");
  await page.locator("#stop:not([disabled])").waitFor();
  await page.click("#tab-gordon");
  await page.locator("#gordon-steps").filter({ hasText: "g12" }).waitFor({ timeout: 60000 });
  assert.equal(await page.evaluate(() => window.cagdApp.cli.busy), true, "the command view's command still runs");
  await page.click("#tab-command");
  assert.equal(await text(page, "#busy"), "Running…");
  assert.equal(await page.locator("#stdout").textContent(), "", "no old output beside Running…");
  await page.click("#stop");
  await page.locator("#error").filter({ hasText: "Stopped" }).waitFor();
  assert.equal(await page.locator("#stop").isDisabled(), true);
  assert.equal(await text(page, "#busy"), "");
  const ok = await runOnPage(page, "cagd bernstein --degree 2 --t 0.5");
  assert.ok(ok.ok);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D6: the point at t is a marker, in the page's views and in the command's picture", async () => {
  const page = await openPage(chrome.context, server.url, link(`cagd decasteljau "[0 0; 0 2; 8 2; 4 0]'" --t 0.5 --exact --plot decasteljau.svg`));
  await page.locator("#pictures img").waitFor();
  const svg = await page.evaluate(async () => (await fetch(document.querySelector("#pictures img").src)).text());
  assert.match(svg, /<circle/, "the point at t = 1/2 is drawn as a circle");
  assert.match(svg, /t = 1\/2/, "and labelled");
  await page.click("#tab-bezier");
  await page.locator("#bezier-plane circle.point-at-t").waitFor();
  const [cx, cy] = await page.locator("#bezier-plane circle.point-at-t").evaluate((c) => [Number(c.getAttribute("cx")), -Number(c.getAttribute("cy"))]);
  assert.deepEqual([cx, cy], [3.5, 1.5]);
  await page.close();
});

test("D7: subdivision and elevation in the views are exact fractions", async () => {
  const page = await openPage(chrome.context, server.url, link(`cagd subdivide "[0 0; 0 2; 8 2; 4 0]'" --t 1/3 --steps --exact`, "subdivide"));
  await page.locator("#subdivide-steps").filter({ hasText: "right" }).waitFor();
  const answer = await text(page, "#subdivide-answer");
  assert.match(answer, /\(8\/9, 10\/9\)/, answer);
  assert.doesNotMatch(answer + (await text(page, "#subdivide-steps")), /\d\.\d{5,}/);
  await shot(page, "view-subdivide");
  await page.click("#tab-elevate");
  await page.locator("#elevate-steps").filter({ hasText: "control" }).waitFor();
  await page.selectOption("#elevate-by", "2");
  await page.locator("#elevate-answer").filter({ hasText: "6" }).waitFor();
  const elevated = await text(page, "#elevate-answer");
  assert.match(elevated, /\(0, 6\/5\)/, elevated);
  assert.doesNotMatch(elevated, /\d\.\d{5,}/);
  await shot(page, "view-elevate");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D8: a #view=bezier link with 3-D points opens the 3-D view (rotate, drag along the screen)", async () => {
  const cmd = `cagd decasteljau "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --t 0.5 --steps --exact`;
  const page = await openView("bezier", cmd);
  assert.equal(await page.locator("#bezier-canvas").isVisible(), true);
  assert.equal(await page.locator("#bezier-plane").isVisible(), false);
  assert.match(await text(page, "#bezier-answer"), /b\(0\.5\) = \(7\/2, 3\/2, 3\/4\)/);
  assert.equal(await text(page, "#bezier-steps"), runBinary(["decasteljau", "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", "--t", "0.5", "--steps", "--exact"]).stdout);
  const az = await page.evaluate(() => window.cagdApp.views.bezier.space.az);
  await page.focus("#bezier-canvas");
  await page.keyboard.press("ArrowLeft");
  assert.notEqual(await page.evaluate(() => window.cagdApp.views.bezier.space.az), az);
  const at = await page.evaluate(() => {
    const v = window.cagdApp.views.bezier;
    const q = v.space.projector().project(...v.doubles()[2]);
    const r = v.space.canvas.getBoundingClientRect();
    return [r.left + (q[0] * r.width) / v.space.canvas.width, r.top + (q[1] * r.height) / v.space.canvas.height];
  });
  await page.mouse.move(at[0], at[1]);
  await page.mouse.down();
  await page.mouse.move(at[0] - 40, at[1] + 30, { steps: 10 });
  await page.mouse.up();
  const moved = await page.evaluate(() => window.cagdApp.views.bezier.points[2]);
  assert.notDeepEqual(moved, ["8", "2", "0"], "the point moved");
  assert.equal(moved.length, 3);
  assert.match(await page.inputValue('#view-bezier table.points input[data-row="2"][data-col="0"]'), /^-?\d+(\.\d+)?$/);
  // The table keeps its z column after a drag (four points, three coordinates each).
  assert.equal(await page.locator('#view-bezier table.points input[data-col="2"]').count(), 4);
  await shot(page, "view-bezier-3d");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D9: spline, coons-bicubic and discrete-coons have their Steps switch, and it shows their steps", async () => {
  const page = await openPage(chrome.context, server.url);
  // Each form's example (from the command's help) with Steps and exact fractions on, run by
  // the form's Run button.
  const withSteps = async (name) => {
    await page.selectOption("#construction", name);
    assert.equal(await page.locator("#f-steps").count(), 1, name);
    await page.locator("#f-steps").setChecked(true);
    await page.locator("#f-exact").setChecked(true);
    const before = Number(await page.locator("#result").getAttribute("data-run"));
    await page.click("#run");
    // The answer of this run (the example's own run without steps may land meanwhile).
    await page.waitForFunction((n) => {
      const r = document.getElementById("result");
      return Number(r.dataset.run) > n && / --steps\b/.test(r.dataset.line ?? "");
    }, before);
    assert.match(await page.inputValue("#cmdline"), new RegExp(`^cagd ${name} .*--steps`));
    assert.equal(await text(page, "#error"), "", name);
    return text(page, "#stdout");
  };
  // The clamped spline of the lecture notes through (0,0), (2,1), (4,4), (6,0), y'0 = (1,1),
  // y'3 = (−1,1): the tangent system y'(i−1) + 4 y'(i) + y'(i+1) = 3 (y(i+1) − y(i−1)) with the
  // ends given, its right-hand side 3 (4, 6) − …: x: 1, 12, 12, −1; y: 1, 12, −3, 1.
  const spline = await withSteps("spline");
  assert.match(spline, /system =\n\n\s+1\s+0\s+0\s+0\n\s+1\s+4\s+1\s+0\n\s+0\s+1\s+4\s+1\n\s+0\s+0\s+0\s+1\n/, spline);
  assert.match(spline, /rhs =\n\n\s+1\s+12\s+12\s+-1\n\s+1\s+12\s+-3\s+1\n/, spline);
  assert.match(spline, /segment_1\.hermite =/);
  // The bicubic patch of the unit square's sides with cross derivatives (0,1,0), (1,0,0): in
  // y the u-blend is c1 H0(v) + c2 H3(v) + c1v H1(v) + c2v H2(v) = H3 + H1 + H2 = v on every row.
  const bicubic = await withSteps("coons-bicubic");
  for (const step of ["hc", "hd", "hcd"]) assert.match(bicubic, new RegExp(`^${step}\\(:,:,1\\) =$`, "m"), bicubic);
  assert.match(bicubic, /hc\(:,:,2\) =\n\n(\s+0\s+1\/4\s+1\/2\s+3\/4\s+1\n){5}/, bicubic);
  // The discrete Coons net: its middle point from the boundary, z: bu = (0 + 1)/2 between
  // b(0,1) and b(2,1), bv = (0 + 1)/2 between b(1,0) and b(1,2), buv = 0 (the corners), and
  // the result bu + bv − buv = 1.
  const discrete = await withSteps("discrete-coons");
  assert.match(discrete, /bu\(:,:,3\) =\n\n\s+0\s+0\s+0\n\s+0\s+1\/2\s+0\n\s+0\s+1\s+0\n/, discrete);
  assert.match(discrete, /bv\(:,:,3\) =\n\n\s+0\s+0\s+0\n\s+0\s+1\/2\s+1\n\s+0\s+0\s+0\n/, discrete);
  assert.match(discrete, /buv\(:,:,3\) =\n\n(\s+0\s+0\s+0\n){3}/, discrete);
  assert.match(discrete, /result\(:,:,3\) =\n\n\s+0\s+0\s+0\n\s+0\s+1\s+1\n\s+0\s+1\s+0\n/, discrete);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("D10: the Gordon view shows no old numbers or picture after an error", async () => {
  const page = await openPage(chrome.context, server.url, "#view=gordon");
  await page.locator("#gordon-steps").filter({ hasText: "g12" }).waitFor();
  await page.fill("#gordon-ucurves", "[0;v;v]\n[0.5;v;0.25+v+]\n[1;v;v]");
  await page.click("#gordon-form button[type=submit]");
  await page.locator("#gordon-error:not([hidden])").waitFor();
  // Named by the view's own field (the command line calls it --u-curve).
  assert.match(await text(page, "#gordon-error"), /^cagd: error: Curves g\(u_i, v\) in v, one per line: column \d+: /);
  assert.doesNotMatch(await text(page, "#gordon-error"), /--/);
  assert.equal(await text(page, "#gordon-steps"), "");
  assert.equal(await page.evaluate(() => window.cagdApp.views.gordon.grids), null);
  assert.equal(await page.evaluate(() => window.cagdApp.views.gordon.view.scene.surfaces.length), 0);
  await page.close();
});

test("D11: --t 1e308 fails the same with the form's picture as without, blaming --t", async () => {
  const page = await openPage(chrome.context, server.url);
  // A line at t = 1e308 stays finite: it is computed, with or without the picture, and the
  // warning blames --t (not the picture).
  const plain = await runOnPage(page, `cagd decasteljau "[0 0; 1 1]'" --t 1e308`);
  const pictured = await runOnPage(page, `cagd decasteljau "[0 0; 1 1]'" --t 1e308 --plot decasteljau.svg`);
  assert.equal(plain.ok, true, plain.error);
  assert.equal(pictured.ok, true, pictured.error);
  assert.equal(await page.locator("#pictures img").count(), 1);
  assert.equal(pictured.stdout, plain.stdout);
  for (const w of [plain.warnings, pictured.warnings]) assert.deepEqual(w, ["cagd: warning: --t: t = 1e308 lies outside [0, 1]; the curve is extrapolated there"]);
  // A parabola there overflows (t² = 1e616): the same error with and without the picture,
  // blaming --t, never the picture.
  const line = `cagd decasteljau "[0 0; 1 1; 2 0]'" --t 1e308`;
  const bad = await runOnPage(page, line);
  const badPictured = await runOnPage(page, `${line} --plot decasteljau.svg`);
  assert.equal(bad.ok, false);
  assert.equal(badPictured.ok, false);
  assert.match(bad.error, /^cagd: error: --t: /);
  assert.equal(badPictured.error, bad.error);
  assert.doesNotMatch(badPictured.error, /--plot|picture|svg/i);
  assert.equal(await page.locator("#pictures img").count(), 0, "no old picture beside the error");
  await page.close();
});

test("the seven homework tasks, each in a view and by a form: exact, with steps and a picture", async () => {
  const page = await openPage(chrome.context, server.url);
  const form = async (name, values, expect) => {
    const got = await runForm(page, name, values, { steps: true, exact: true, plot: true });
    for (const e of expect) assert.match(got.stdout, e, `${name}: ${got.line}\n${got.stdout}${got.error}`);
    assert.equal(got.pictures, 1, `${name}: a picture`);
    return got;
  };
  // 1. Primer 2.4 with its scheme.
  await form("decasteljau", { control: "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", t: "1/2" }, [/\(7\/2, 3\/2, 3\/4\)/, /de Casteljau scheme/]);
  // 2. The elevation of Primer 2.4.
  // Its step: b'_i = i/4 b_(i−1) + (1 − i/4) b_i, e.g. b'_1 = (0, 3/2, 3/2), b'_2 = (4, 2, 1).
  await form("elevate", { control: "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", by: "1" }, [
    /control =\n\n\s+0\s+0\s+4\s+7\s+4\n\s+0\s+3\/2\s+2\s+3\/2\s+0\n\s+0\s+3\/2\s+1\s+0\s+0\n/,
    /degree_4 =\n\n\s+0\s+0\s+4\s+7\s+4\n\s+0\s+3\/2\s+2\s+3\/2\s+0\n/,
  ]);
  // 3. Primer 4.3.
  // Its steps: Primer 4.3's r_c, r_d and r_cd.
  await form("coons", { c1: "[u;0;u-u^2]", c2: "[u;1;u]", d1: "[0;v^2;v-v^2]", d2: "[1;v;v]", u: "0.2", v: "0.5" }, [
    /result =\n\n\s+1\/5\n\s+3\/10\n\s+19\/50\n/,
    /rc =\n\n\s+1\/5\n\s+1\/2\n\s+9\/50\n/,
    /rd =\n\n\s+1\/5\n\s+3\/10\n\s+3\/10\n/,
    /rcd =\n\n\s+1\/5\n\s+1\/2\n\s+1\/10\n/,
  ]);
  // 4. Knot insertion u = 3/2.
  // Boehm's step: u = 3/2 in [u_3, u_4) = [1, 2) (span 4 counting from 1), α = (3/2 − 0)/2 = 3/4
  // and (3/2 − 1)/1 = 1/2.
  await form("insert-knot", { control: "[0 0; 1 2; 2 3; 3 1; 4 2; 5 0]'", degree: "2", knots: "[0 0 0 1 2 2 3 3 3]", insert: "3/2" }, [
    /7\/4\s+5\/2/,
    /11\/4\s+2\b/,
    /insert_1\.span = 4\n/,
    /insert_1\.alpha =\n\n\s+3\/4\s+1\/2\n/,
  ]);
  // 5. The clamped spline of the lecture notes: y' = (15, 48, -27, 15)/15.
  // Its steps: the tangent system (1 4 1 rows) and its right-hand side 3 (y(i+1) − y(i−1)).
  await form("spline", { points: "[0 0; 2 1; 4 4; 6 0]'", start_tangent: "[1;1]", end_tangent: "[-1;1]" }, [
    /1\s+16\/5\s+-9\/5\s+1\n/,
    /system =\n\n\s+1\s+0\s+0\s+0\n\s+1\s+4\s+1\s+0\n\s+0\s+1\s+4\s+1\n\s+0\s+0\s+0\s+1\n/,
    /rhs =\n\n\s+1\s+12\s+12\s+-1\n\s+1\s+12\s+-3\s+1\n/,
  ]);
  // 6. The NURBS quarter circle with weights 1, 1, 2 at 1/2.
  // Its step: the rational basis (1/4, 1/2, 1/4)·(1, 1, 2) / (5/4) = (1/5, 2/5, 2/5).
  await form("nurbs", { control: "[1 0; 1 1; 0 1]'", weights: "[1 1 2]", degree: "2", knots: "[0 0 0 1 1 1]", t: "1/2" }, [
    /result =\n\n\s+3\/5\n\s+4\/5\n/,
    /basis =\n\n\s+1\/5\s+2\/5\s+2\/5\n/,
  ]);
  // 7. The cubic basis at 1.5.
  // Its steps: the Cox–de Boor triangle, degree 1 (1/2, 1/2) and 2 (1/8, 3/4, 1/8) at 3/2.
  await form("bspline-basis", { knots: "[0 0 0 0 1 2 3 3 3 3]", degree: "3", t: "1.5" }, [
    /0\s+1\/32\s+15\/32\s+15\/32\s+1\/32\s+0/,
    /triangle\.p1 =\n\n\s+0\s+0\s+0\s+1\/2\s+1\/2\s+0\s+0\s+0\n/,
    /triangle\.p2 =\n\n\s+0\s+0\s+1\/8\s+3\/4\s+1\/8\s+0\s+0\n/,
  ]);
  await shot(page, "command-task-bspline-basis");
  await page.close();

  // The same in the views (their defaults are the tasks), each with its picture.
  const view = async (name, cmd, expect, picture) => {
    const p = await openPage(chrome.context, server.url, cmd ? link(cmd, name) : `#view=${name}`);
    await p.locator(`#${name}-steps`).filter({ hasText: ANSWERS[name] ?? "result" }).waitFor();
    const all = `${await text(p, `#${name}-answer`)}\n${await text(p, `#${name}-steps`)}`;
    for (const e of expect) assert.match(all, e, `${name}:\n${all}`);
    assert.ok((await p.locator(picture).count()) > 0, `${name}: ${picture}`);
    await shot(p, `task-view-${name}`);
    assert.deepEqual(p.errors, []);
    await p.close();
  };
  await view("bezier", `cagd decasteljau "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --t 1/2 --steps --exact`, [/\(7\/2, 3\/2, 3\/4\)/, /de Casteljau scheme, degree 3, t = 1\/2/], "#bezier-canvas");
  await view("elevate", `cagd elevate "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --by 1 --steps --exact`, [/\(0, 3\/2, 3\/2\)/, /\(4, 2, 1\)/, /\(7, 3\/2, 0\)/], "#elevate-canvas");
  await view("coons", null, [/19\/50/, /rcd =/], "#coons-canvas");
  await view("insert", null, [/\(7\/4, 11\/4\)/, /\(5\/2, 2\)/, /alpha/], "#insert-plane polyline.inserted");
  await view("spline", null, [/\(1, 1\)\s+\(31\/15, 16\/5\)\s+\(41\/15, -9\/5\)\s+\(-1, 1\)/], "#spline-plane polyline.curve");
  await view("nurbs", null, [/x\(1\/2\) = \(3\/5, 4\/5\)/], "#nurbs-plane circle.point-at-t");
  await view("basis", null, [/1\/32, 15\/32, 15\/32, 1\/32/, /triangle/], "#basis-plane polyline[data-basis]");
});

/** The labels of the command form, in order (a checkbox's label is its text). */
const formLabels = (page) => page.locator("#command-form label").evaluateAll((list) => list.map((l) => l.textContent.trim()));

/** What the Slovenian and Czech decasteljau forms say: the command line's own translations. */
const DECASTELJAU_FORM = {
  sl: {
    option: "decasteljau — Točke Bézierove krivulje z de Casteljaujevim algoritmom (zaključna naloga, algoritem 1)",
    control: "Kontrolne točke b_0..b_n (CONTROL)",
    t: "Parametri krivulje (--t)",
    tHint: "število, seznam \"[0 0.25 0.5]\" ali razpon 0:0.1:1",
    interval: "Parametrski interval [a, b] krivulje (zaključna naloga §2.3.2) (--interval)",
    source: "Vir: zaključna naloga (thesis), algoritem 1 (Primer 2.4)",
  },
  cs: {
    option: "decasteljau — Body Bézierovy křivky de Casteljauovým algoritmem (závěrečná práce, algoritmus 1)",
    control: "Řídicí body b_0..b_n (CONTROL)",
    t: "Parametry křivky (--t)",
    tHint: "číslo, seznam \"[0 0.25 0.5]\" nebo rozsah 0:0.1:1",
    interval: "Parametrický interval [a, b] křivky (závěrečná práce §2.3.2) (--interval)",
    source: "Zdroj: závěrečná práce (thesis), algoritmus 1 (Primer 2.4)",
  },
};

test("languages: Slovenian and Czech pages from the browser's language, the switch, and the steps' labels", async () => {
  const english = await openPage(chrome.context, server.url, link(`cagd decasteljau "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --t 0.5 --steps --exact`));
  const englishLabels = await formLabels(english);
  assert.equal(englishLabels.find((l) => l.endsWith("(--t)")), "Curve parameters (--t)");
  await english.close();
  for (const [locale, tab, label] of [
    ["sl-SI", "Bézierova krivulja", "% de Casteljaujeva shema"],
    ["cs-CZ", "Bézierova křivka", "% de Casteljauovo schéma"],
  ]) {
    const local = await browser({ locale });
    const page = await openPage(local.context, server.url, link(`cagd decasteljau "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --t 0.5 --steps --exact`));
    assert.equal(await text(page, "#tab-bezier"), tab);
    const lang = locale.slice(0, 2);
    // The command form in the page's language: the construction list, its summary, every
    // label (none as in English), the hints and the source, the option names kept.
    const form = DECASTELJAU_FORM[lang];
    const option = await page.locator('#construction option[value="decasteljau"]').textContent();
    assert.equal(option, form.option);
    assert.equal(await text(page, "#construction-about"), form.option.split(" — ")[1]);
    assert.equal(await text(page, 'label[for="f-control"]'), form.control);
    assert.equal(await text(page, 'label[for="f-t"]'), form.t);
    assert.equal(await text(page, "#f-t-hint"), form.tHint);
    assert.equal(await text(page, 'label[for="f-interval"]'), form.interval);
    assert.equal(await text(page, "#command-explain .source"), form.source);
    const labels = await formLabels(page);
    assert.equal(labels.length, englishLabels.length);
    labels.forEach((l, i) => assert.notEqual(l, englishLabels[i], `${lang}: a label as in English: ${l}`));
    assert.equal(await page.evaluate(() => document.documentElement.lang), lang);
    assert.match(await page.inputValue("#cmdline"), new RegExp(`--lang ${lang}$`));
    const steps = await text(page, "#stdout");
    assert.ok(steps.includes(label), steps);
    assert.equal(steps, runBinary(["decasteljau", "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", "--t", "0.5", "--steps", "--exact", "--plot", "decasteljau.svg", "--lang", lang]).stdout);
    await shot(page, `page-${lang}`, false);
    await page.click("#tab-coons");
    await page.locator("#coons-steps").filter({ hasText: "19/50" }).waitFor();
    await shot(page, `page-${lang}-coons`, false);
    await page.close();
    await local.close();
  }
  const page = await openPage(chrome.context, server.url, "#view=basis");
  await page.locator("#basis-steps").filter({ hasText: "result" }).waitFor();
  await page.selectOption("#lang", "cs");
  await page.locator("#tab-basis").filter({ hasText: "Bázové funkce" }).waitFor();
  await page.locator("#basis-steps").filter({ hasText: "% trojúhelník Cox–de Boor" }).waitFor();
  assert.match(await text(page, "#view-basis details.explain"), /rekurze Cox–de Boor/);
  await page.selectOption("#lang", "en");
  await page.close();
});

test("phone (390 × 844): one row of tabs, 44 px targets, the answer above the fold", async () => {
  const phone = await browser({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 });
  // Closed even when an assertion fails (an open browser would keep the test runner waiting).
  try {
    const page = await openPage(phone.context, server.url, "#view=bezier");
    await page.locator("#bezier-steps").filter({ hasText: "result" }).waitFor();
    const tabs = await page.locator('[role="tab"]').evaluateAll((list) => list.map((t) => t.getBoundingClientRect()).map((r) => ({ top: r.top, h: r.height })));
    assert.equal(new Set(tabs.map((r) => Math.round(r.top))).size, 1, "the tabs are one row");
    assert.ok(tabs.every((r) => r.h >= 44), JSON.stringify(tabs));
    const hits = await page.locator("#bezier-plane circle.hit").evaluateAll((list) => list.map((c) => c.getBoundingClientRect().width));
    assert.ok(hits.length >= 4 && hits.every((w) => w >= 44), JSON.stringify(hits));
    for (const sel of ["#bezier-add", "#bezier-exact", "#bezier-t-text", '#view-bezier table.points input[data-row="0"][data-col="0"]']) {
      const box = await page.locator(sel).evaluate((e) => (e.closest("label") ?? e).getBoundingClientRect().height);
      assert.ok(box >= 44, `${sel}: ${box}`);
    }
    const answer = await page.locator("#bezier-answer").boundingBox();
    assert.ok(answer.y + answer.height <= 844, `the answer ends at ${answer.y + answer.height}`);
    assert.match(await text(page, "#bezier-answer"), /7\/2/);
    await shot(page, "phone-bezier", false);
    await page.click("#tab-command");
    await page.locator("#stdout").filter({ hasText: "result" }).waitFor();
    const out = await page.locator("#stdout").boundingBox();
    assert.ok(out.y < 844, `the command's output starts at ${out.y}`);
    await shot(page, "phone-command", false);
    await page.close();
  } finally {
    await phone.close();
  }
});

test("history: views and commands are entries, Back returns to them", async () => {
  const page = await openPage(chrome.context, server.url);
  await runOnPage(page, "cagd bernstein --degree 2 --t 0.5 --exact");
  await page.click("#tab-bezier");
  await page.locator("#bezier-steps").filter({ hasText: "result" }).waitFor();
  await page.click("#tab-basis");
  await page.locator("#basis-steps").filter({ hasText: "result" }).waitFor();
  await page.goBack();
  await page.waitForFunction(() => window.cagdApp.current === "bezier");
  assert.equal(await page.locator("#view-bezier").isVisible(), true);
  await page.goBack();
  await page.waitForFunction(() => window.cagdApp.current === "command");
  await page.locator("#stdout").filter({ hasText: "1/4" }).waitFor();
  assert.match(await page.inputValue("#cmdline"), /bernstein --degree 2/);
  await page.goForward();
  await page.waitForFunction(() => window.cagdApp.current === "bezier");
  await page.close();
});

test("every page word exists in the three languages, every subcommand has an explanation", async () => {
  const page = await openPage(chrome.context, server.url);
  const { keys, explained, names, sources } = await page.evaluate(async () => {
    const i18n = await import(document.querySelector('script[type="module"]').src.replace(/main\.[0-9a-f]+\.js$/, (m) => m.replace("main", "i18n")));
    const explain = await import(document.querySelector('script[type="module"]').src.replace(/main\.[0-9a-f]+\.js$/, (m) => m.replace("main", "explain")));
    return { keys: i18n.keys(), explained: explain.explained, names: window.cagdApp.schema.map((c) => c.name), sources: explain.sources };
  });
  assert.deepEqual(keys.sl, keys.en);
  assert.deepEqual(keys.cs, keys.en);
  // Every source in Slovenian and Czech, each short name of docs/SOURCES.md kept beside the
  // source's own name: "zaključna naloga (thesis) §4.1".
  const shortNames = ["matrix-form notes", "lecture notes", "CAD notes", "thesis"];
  for (const [name, source] of Object.entries(sources)) {
    for (const l of ["sl", "cs"]) {
      assert.ok(source[l], `${name}: no ${l} source`);
      let en = source.en;
      for (const short of shortNames) {
        if (!en.includes(short)) continue;
        en = en.replaceAll(short, "");
        assert.ok(source[l].includes(`(${short})`), `${name} ${l}: ${source[l]} lacks (${short})`);
      }
      const bare = source[l].replace(/\([^()]*\)/g, "");
      for (const short of shortNames) assert.ok(!bare.includes(short), `${name} ${l}: ${source[l]}`);
    }
  }
  assert.deepEqual(
    names.filter((n) => !explained.includes(n)),
    [],
  );
  writeFileSync(join(resultsDir, "languages.json"), JSON.stringify({ keys: keys.en.length, explained }, null, 2));
  await page.close();
});

test("the WebAssembly asks nothing of the DOM: a picture's texts (its legend too) are measured from the font, so drawing one forces no layout of the page and runs the same in a worker", () => {
  const pkg = join(webDir, "dist", "pkg");
  const glue = readdirSync(pkg).find((f) => /^cagd_web\.[0-9a-f]+\.js$/.test(f));
  assert.ok(glue, "the built glue (web/build.sh)");
  const text = readFileSync(join(pkg, glue), "utf8");
  for (const name of ["document", "createElement", "offsetWidth", "offsetHeight", "getBoundingClientRect", "HTMLElement"]) {
    assert.ok(!text.includes(name), `the WebAssembly's imports name ${name}`);
  }
});
