// The page in a real browser: the thesis's worked examples, dragging, errors, keyboard and
// screen-reader labels, the interactive views, screenshots and the measured figures.

import assert from "node:assert/strict";
import { readdirSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { after, before, test } from "node:test";
import { gzipSync } from "node:zlib";
import { browser, openPage, resultsDir, runBinary, runOnPage, serve, webDir } from "./helpers.mjs";

let server;
let chrome;
const figures = {};

before(async () => {
  server = await serve();
  chrome = await browser();
});

after(async () => {
  writeFileSync(join(resultsDir, "figures.json"), JSON.stringify(figures, null, 2));
  await chrome?.close();
  server?.stop();
});

const link = (cmd) => `#cmd=${encodeURIComponent(cmd)}`;
const shot = (page, name) => page.screenshot({ path: join(resultsDir, `${name}.png`), fullPage: true });
const stdout = (page) => page.locator("#stdout").textContent();

const PRIMER_2_4 = `cagd decasteljau "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --t 0.5 --steps --exact --plot decasteljau.svg`;
const PRIMER_4_3 = `cagd coons --c1 "[u;0;u-u^2]" --c2 "[u;1;u]" --d1 "[0;v^2;v-v^2]" --d2 "[1;v;v]" --u 0.2 --v 0.5 --steps --exact --plot coons.svg`;

test("Primer 2.4: the point (7/2, 3/2, 3/4) and the whole de Casteljau scheme, from a link", async () => {
  const page = await openPage(chrome.context, server.url, link(PRIMER_2_4));
  const text = await stdout(page);
  const scheme = [
    "de Casteljau scheme, degree 3, t = 1/2",
    "r = 0       r = 1       r = 2           r = 3",
    "(0, 0, 0)",
    "(0, 2, 2)   (0, 1, 1)",
    "(8, 2, 0)   (4, 2, 1)   (2, 3/2, 1)",
    "(4, 0, 0)   (6, 1, 0)   (5, 3/2, 1/2)   (7/2, 3/2, 3/4)",
  ];
  for (const line of scheme) assert.ok(text.includes(line), `missing ${line} in\n${text}`);
  assert.match(text, /result =\n\n\s+7\/2\n\s+3\/2\n\s+3\/4\n/);
  // The same text as the program, and the same command line to copy.
  const binary = runBinary(["decasteljau", "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", "--t", "0.5", "--steps", "--exact", "--plot", "decasteljau.svg"]);
  assert.equal(text, binary.stdout);
  assert.equal(await page.inputValue("#cmdline"), PRIMER_2_4);
  // The picture (the program's plotting code, SVG) and the Octave code.
  await page.locator("#pictures img").waitFor();
  assert.ok(await page.locator("#pictures img").evaluate((img) => img.complete && img.naturalWidth === 900));
  assert.match(await page.locator("#octave").textContent(), /b = \(1 - t\(k\)\) \* b\(:, 1:end-1\) \+ t\(k\) \* b\(:, 2:end\);/);
  assert.equal(await page.locator("#f-exact").isChecked(), true, "the exact-fractions switch shows the state");
  await shot(page, "command-primer-2-4");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("a link's first command answers on the main thread when its estimated work is small, in a worker when not; the same answers", async () => {
  // Primer 2.4 is small: answered before the worker is ready, the same text as the program.
  let page = await openPage(chrome.context, server.url, link(PRIMER_2_4));
  assert.equal(await page.locator("#result").getAttribute("data-thread"), "main");
  const args = ["decasteljau", "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", "--t", "0.5", "--steps", "--exact", "--plot", "decasteljau.svg"];
  assert.equal(await stdout(page), runBinary(args).stdout);
  await page.locator("#pictures img").waitFor();
  // An error of the command itself is answered there too, in the program's words.
  await page.evaluate(() => window.cagdApp.openCommand(`cagd decasteljau "[1 2; 3]"`));
  await page.waitForFunction(() => document.querySelector("#result").dataset.run === "2");
  assert.match(await page.locator("#error").textContent(), /^cagd: error: CONTROL: /);
  assert.deepEqual(page.errors, []);
  await page.close();
  // Exact Bernstein polynomials of degree 100: estimated above the main thread's work limit,
  // so the worker runs it; no word of that limit reaches the student.
  const big = ["bernstein", "--degree", "100", "--t", "0.5", "--exact"];
  page = await openPage(chrome.context, server.url, link(`cagd ${big.join(" ")}`));
  assert.equal(await page.locator("#result").getAttribute("data-ok"), "true");
  assert.equal(await page.locator("#result").getAttribute("data-thread"), "worker");
  assert.equal(await stdout(page), runBinary(big).stdout);
  assert.equal(await page.locator("#warnings li").count(), 0);
  // A command with a work limit of its own goes to the worker, where that limit answers.
  await page.evaluate(() => window.cagdApp.openCommand("cagd bernstein --degree 3 --n 101 --max-work 10"));
  await page.waitForFunction(() => document.querySelector("#result").dataset.run === "2");
  assert.match(await page.locator("#error").textContent(), /exceeds the limit of 10 \(raise it with --max-work/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("Primer 4.3: x(0.2, 0.5) = (1/5, 3/10, 19/50) with r_c, r_d and r_cd", async () => {
  const page = await openPage(chrome.context, server.url, link(PRIMER_4_3));
  const text = await stdout(page);
  const block = (name, values) => new RegExp(`${name} =\\n\\n${values.map((v) => `\\s+${v.replace("/", "\\/")}\\n`).join("")}`);
  assert.match(text, block("rc", ["1/5", "1/2", "9/50"]));
  assert.match(text, block("rd", ["1/5", "3/10", "3/10"]));
  assert.match(text, block("rcd", ["1/5", "1/2", "1/10"]));
  assert.match(text, block("result", ["1/5", "3/10", "19/50"]));
  await page.locator("#pictures img").waitFor();
  await shot(page, "command-primer-4-3");
  // The Coons view opens on the same patch (as quadratic Bézier boundaries) at (0.2, 0.5).
  await page.click("#tab-coons");
  await page.locator("#coons-steps").filter({ hasText: "19/50" }).waitFor();
  const steps = await page.locator("#coons-steps").textContent();
  assert.match(steps, block("rc", ["1/5", "1/2", "9/50"]));
  assert.match(steps, block("rd", ["1/5", "3/10", "3/10"]));
  assert.match(steps, block("rcd", ["1/5", "1/2", "1/10"]));
  await shot(page, "view-coons");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("dragging a Bézier control point moves the curve and changes the scheme", async () => {
  const page = await openPage(chrome.context, server.url, "#view=bezier");
  const curve = page.locator("#bezier-plane polyline.curve");
  const scheme = page.locator("#bezier-steps");
  await scheme.filter({ hasText: "7/2" }).waitFor();
  const before = { curve: await curve.getAttribute("points"), scheme: await scheme.textContent(), hash: await page.evaluate(() => location.hash) };
  assert.match(before.scheme, /\(7\/2, 3\/2\)/, "Primer 2.4 in the plane: b(1/2) = (7/2, 3/2)");
  const handle = page.locator('#bezier-plane circle.handle[data-index="2"]');
  const box = await handle.boundingBox();
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x - 120, y + 80, { steps: 12 });
  await page.mouse.up();
  const afterDrag = { curve: await curve.getAttribute("points"), scheme: await scheme.textContent(), hash: await page.evaluate(() => location.hash) };
  assert.notEqual(afterDrag.curve, before.curve, "the curve moved");
  assert.notEqual(afterDrag.scheme, before.scheme, "the scheme changed");
  assert.notEqual(afterDrag.hash, before.hash, "the link follows the state");
  assert.match(afterDrag.scheme, /^de Casteljau scheme, degree 3, t = 1\/2/m);
  // The scheme is the program's own for the moved points.
  const cmd = await page.locator("#bezier-cmd").textContent();
  const args = cmd.match(/"[^"]*"|\S+/g).slice(1).map((a) => a.replace(/^"|"$/g, ""));
  assert.equal(afterDrag.scheme, runBinary(args).stdout);
  // The keyboard moves a focused point too.
  await page.locator('#bezier-plane circle.handle[data-index="1"]').focus();
  await page.keyboard.press("ArrowUp");
  assert.match(await page.locator('#bezier-plane circle.handle[data-index="1"]').getAttribute("aria-label"), /^b1 at \(0, 2\.1\)/);
  assert.notEqual(await scheme.textContent(), afterDrag.scheme);
  // The parameter, live (the slider writes its value as typed text).
  await page.fill("#bezier-t", "0.3");
  assert.equal(await page.inputValue("#bezier-t-text"), "0.3");
  assert.match(await scheme.textContent(), /t = 3\/10/);
  await shot(page, "view-bezier-drag");
  // Reloading the link restores the state.
  const hash = await page.evaluate(() => location.hash);
  const again = await openPage(chrome.context, server.url, hash);
  await again.locator("#bezier-steps").filter({ hasText: "t = 3/10" }).waitFor();
  assert.equal(await again.locator("#bezier-steps").textContent(), await scheme.textContent());
  assert.deepEqual(page.errors, []);
  await again.close();
  await page.close();
});

test("a malformed input shows the program's one-line message and the page stays usable", async () => {
  const page = await openPage(chrome.context, server.url);
  const cases = [
    ["decasteljau", "[1 2; 3]", "--t", "0.5"],
    ["decasteljau", "[0 0; 1 1]'", "--t", "2x"],
    ["coons", "--c1", "[u;0;0]", "--c2", "[u;1;0]", "--d1", "[0;v;0]", "--d2", "[2;v;0]"],
    ["bezier-patch", "[0 0 0 1 0 0; 0 1 0 1 1 1]", "--n", "100000"],
    ["nurbs", "[0 0; 1 1]'", "--weights", "[1 -1]", "--degree", "1"],
    ["frobnicate"],
    ["serve"],
  ];
  for (const args of cases) {
    const line = `cagd ${args.map((a) => (/[\s'"[\]();]/.test(a) ? `"${a}"` : a)).join(" ")}`;
    const got = await runOnPage(page, line);
    if (args[0] === "serve") {
      // (The program would serve the page; in the page it is an error.)
      assert.match(got.error, /^cagd: error: serve: serving the page is done by the cagd program itself/);
      continue;
    }
    const want = runBinary(args);
    assert.notEqual(want.status, 0);
    assert.equal(got.ok, false, line);
    assert.equal(got.error, want.stderr.trim(), line);
    assert.equal(got.error.split("\n").length, 1);
  }
  const unclosed = await runOnPage(page, `cagd decasteljau "[0 0; 1 1]'`);
  assert.match(unclosed.error, /^cagd: error: cagd: a quote " is not closed; expected/);
  await shot(page, "command-error");
  // Still usable: the next command answers.
  const ok = await runOnPage(page, "cagd bernstein --degree 3 --t 0.5 --exact");
  assert.ok(ok.ok);
  assert.match(ok.stdout, /1\/8\s+3\/8\s+3\/8\s+1\/8/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("long work runs in the worker: the page answers meanwhile and Stop ends it", async () => {
  const page = await openPage(chrome.context, server.url);
  await page.fill("#cmdline", "cagd surface '[u; v; u.*v + sin(u.*v)]' --n 1500 --format csv -o grid.csv");
  await page.press("#cmdline", "Enter");
  await page.locator("#stop:not([disabled])").waitFor();
  // The main thread is free: the interactive Bézier view works while the command runs.
  const t0 = Date.now();
  const busy = await page.evaluate(() => window.cagdApp.cli.busy);
  assert.equal(busy, true, "the command is still running");
  await page.click("#tab-bezier");
  await page.locator("#bezier-steps").filter({ hasText: "de Casteljau scheme" }).waitFor();
  assert.ok(Date.now() - t0 < 5000);
  await page.click("#tab-command");
  await page.click("#stop");
  await page.locator("#error").filter({ hasText: "Stopped" }).waitFor();
  const ok = await runOnPage(page, "cagd bernstein --degree 2 --t 0.5");
  assert.ok(ok.ok, "a new worker answers after Stop");
  await page.close();
});

test("keyboard use and labels for a screen reader (accessibility snapshot)", async () => {
  const page = await openPage(chrome.context, server.url);
  const snapshot = await page.locator("#view-command").ariaSnapshot();
  writeFileSync(join(resultsDir, "aria-command.yaml"), snapshot);
  for (const expected of [
    'combobox "Construction"',
    'textbox "Control points b_0..b_n (CONTROL)"',
    'textbox "Curve parameters (--t)"',
    'checkbox "Exact fractions (--exact)"',
    'checkbox "Steps (--steps)"',
    'button "Run"',
    'textbox "Command line — edit and press Enter, or copy it to a terminal"',
  ])
    assert.ok(snapshot.includes(expected), `${expected} missing in\n${snapshot}`);
  // Every form control of every construction has a name.
  const unnamed = await page.evaluate(async () => {
    const out = [];
    const sel = document.getElementById("construction");
    for (const option of [...sel.options]) {
      sel.value = option.value;
      sel.dispatchEvent(new Event("change"));
      for (const el of document.querySelectorAll("#view-command input, #view-command select, #view-command textarea"))
        if (!(el.labels?.length || el.getAttribute("aria-label"))) out.push(`${option.value}: ${el.id}`);
    }
    return out;
  });
  assert.deepEqual(unnamed, []);
  // Tabs by keyboard, then the whole form: choose a construction, type, run with Enter.
  await page.focus("#tab-command");
  await page.keyboard.press("ArrowRight");
  // The tab is selected and its panel shown at once; the view's content follows when its
  // module is loaded (asserting visibility before that would race with the import).
  const selected = await page.evaluate(() => ({
    focus: document.activeElement.id,
    selected: document.getElementById("tab-bezier").getAttribute("aria-selected"),
    hidden: document.getElementById("view-bezier").hidden,
    others: [...document.querySelectorAll('[role="tab"]')].filter((t) => t.getAttribute("aria-selected") === "true").map((t) => t.id),
  }));
  assert.deepEqual(selected, { focus: "tab-bezier", selected: "true", hidden: false, others: ["tab-bezier"] });
  await page.locator("#bezier-plane circle.handle").first().waitFor();
  assert.equal(await page.locator("#view-bezier").isVisible(), true);
  const views = await page.locator("#view-bezier").ariaSnapshot();
  writeFileSync(join(resultsDir, "aria-bezier.yaml"), views);
  assert.match(views, /button "b0 at \(0, 0\); arrow keys move it"/);
  assert.match(views, /slider "Parameter t": "0\.5"/);
  assert.match(views, /textbox "t as typed": "0\.5"/);
  assert.match(views, /textbox "b2 x": "8"/);
  await page.keyboard.press("ArrowLeft");
  await page.focus("#construction");
  await page.selectOption("#construction", "bernstein");
  // The explanation, the example button, then the form's first field: the degree.
  for (let k = 0; k < 4 && (await page.evaluate(() => document.activeElement.id)) !== "f-degree"; k++) await page.keyboard.press("Tab");
  assert.equal(await page.evaluate(() => document.activeElement.id), "f-degree");
  await page.keyboard.press("Control+A");
  await page.keyboard.type("4");
  await page.keyboard.press("Enter");
  await page.locator("#stdout").filter({ hasText: "1/16" }).waitFor();
  assert.match(await page.inputValue("#cmdline"), /^cagd bernstein --degree 4 .*--t 0\.5/);
  await page.close();
});

test("fast arrow keys over the tabs: the last tab chosen is the one shown and linked", async () => {
  const page = await openPage(chrome.context, server.url);
  await page.focus("#tab-command");
  // Four tabs to the right before any of their modules has been built.
  for (let k = 0; k < 4; k++) await page.keyboard.press("ArrowRight");
  assert.equal(await page.evaluate(() => document.activeElement.id), "tab-coons");
  // Every view passed over is built in the end; none of them takes over the page or its link.
  await page.waitForFunction(() => ["bezier", "subdivide", "elevate", "coons"].every((v) => window.cagdApp.views[v]));
  await page.locator("#coons-steps").filter({ hasText: "19/50" }).waitFor();
  const state = await page.evaluate(() => ({
    current: window.cagdApp.current,
    hash: decodeURIComponent(location.hash),
    shown: [...document.querySelectorAll('[role="tabpanel"]')].filter((p) => !p.hidden).map((p) => p.id),
    selected: [...document.querySelectorAll('[role="tab"]')].filter((t) => t.getAttribute("aria-selected") === "true").map((t) => t.id),
  }));
  assert.equal(state.current, "coons");
  assert.match(state.hash, /^#view=coons&cmd=cagd coons /);
  assert.deepEqual(state.shown, ["view-coons"]);
  assert.deepEqual(state.selected, ["tab-coons"]);
  // Back leaves the Coons view for the last view entered before it (each tab is an entry).
  await page.goBack();
  await page.waitForFunction(() => window.cagdApp.current === "elevate");
  await page.locator("#elevate-steps").filter({ hasText: "control" }).waitFor();
  assert.match(await page.evaluate(() => decodeURIComponent(location.hash)), /^#view=elevate/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("a view whose module cannot be loaded says so in its panel; the page stays usable", async () => {
  // Without the service worker, so that the browser asks the server (and the route) for it.
  const local = await browser({ serviceWorkers: "block" });
  try {
    let refused = 0;
    await local.context.route(/\/js\/basis\.[0-9a-f]+\.js$/, (route) => {
      refused++;
      return route.abort("connectionfailed");
    });
    const page = await openPage(local.context, server.url);
    await page.click("#tab-basis");
    const message = page.locator("#view-basis .view-failed");
    await message.waitFor();
    assert.ok(refused >= 1);
    assert.match(await message.textContent(), /^cagd: error: the view could not be loaded \(.+\); reload the page/);
    assert.equal(await message.getAttribute("role"), "alert");
    assert.equal(await page.evaluate(() => window.cagdApp.current), "basis");
    // No unhandled rejection: only the refused download is reported by the browser.
    assert.deepEqual(
      page.errors.filter((e) => !/Failed to load resource|ERR_CONNECTION_FAILED|ERR_FAILED/.test(e)),
      [],
    );
    // The other views and the command box still work.
    await page.click("#tab-bezier");
    await page.locator("#bezier-steps").filter({ hasText: "7/2" }).waitFor();
    await page.click("#tab-command");
    const ok = await runOnPage(page, "cagd bernstein --degree 2 --t 0.5 --exact");
    assert.ok(ok.ok, ok.error);
    await page.close();
  } finally {
    await local.close();
  }
});

test("the Coons, Gordon, B-spline and NURBS views draw from the library and follow their controls", async () => {
  const page = await openPage(chrome.context, server.url, "#view=coons");
  await page.locator("#coons-steps").filter({ hasText: "19/50" }).waitFor();
  // r_c, r_d, r_cd toggles and a drag of the corner P4 in the 3-D view.
  for (const id of ["#coons-rc", "#coons-rd", "#coons-rcd"]) await page.check(id);
  const before = await page.locator("#coons-steps").textContent();
  const p4 = await page.evaluate(() => {
    const v = window.cagdApp.views.coons;
    const { project } = v.view.projector();
    const q = project(...v.point("P4"));
    const c = v.view.canvas.getBoundingClientRect();
    return [c.left + (q[0] * c.width) / v.view.canvas.width, c.top + (q[1] * c.height) / v.view.canvas.height];
  });
  await page.mouse.move(p4[0], p4[1]);
  await page.mouse.down();
  await page.mouse.move(p4[0], p4[1] - 60, { steps: 8 });
  await page.mouse.up();
  assert.notEqual(await page.locator("#coons-steps").textContent(), before, "dragging P4 changes r_c, r_d, r_cd and x");
  assert.notEqual(await page.inputValue("#coons-pz"), "1");
  await shot(page, "view-coons-parts");
  // Rotating by keyboard.
  await page.focus("#coons-canvas");
  const az = await page.evaluate(() => window.cagdApp.views.coons.view.az);
  await page.keyboard.press("ArrowLeft");
  assert.notEqual(await page.evaluate(() => window.cagdApp.views.coons.view.az), az);

  await page.click("#tab-gordon");
  await page.locator("#gordon-steps").filter({ hasText: "g12" }).waitFor();
  await page.check("#gordon-g1");
  await shot(page, "view-gordon");

  await page.click("#tab-bspline");
  await page.locator("#bspline-steps").filter({ hasText: "result" }).waitFor();
  const basisBefore = await page.locator('#bspline-basis polyline[data-basis="2"]').getAttribute("points");
  const knot = page.locator('#bspline-basis circle.handle[data-index="0"]');
  await knot.focus();
  await page.keyboard.press("ArrowRight");
  await page.keyboard.press("ArrowRight");
  assert.notEqual(await page.locator('#bspline-basis polyline[data-basis="2"]').getAttribute("points"), basisBefore, "moving a knot changes the basis");
  assert.match(await page.locator("#bspline-cmd").textContent(), /--knots "\[0 0 0 0 0\.55 2\/3 1 1 1 1\]"/);
  await shot(page, "view-bspline");

  await page.click("#tab-nurbs");
  await page.locator("#nurbs-steps").filter({ hasText: "result" }).waitFor();
  const circle = await page.locator("#nurbs-steps").textContent();
  assert.match(circle, /result =\n\n\s+3\/5\n\s+4\/5\n/, "the quarter circle (weights 1, 1, 2) at t = 1/2");
  await page.fill('#view-nurbs table.points input[data-row="1"][data-col="2"]', "2");
  assert.notEqual(await page.locator("#nurbs-steps").textContent(), circle, "the weight changes the curve");
  assert.match(await page.locator("#nurbs-cmd").textContent(), /--weights "\[1 2 2\]"/);
  await shot(page, "view-nurbs");
  assert.deepEqual(page.errors, []);
  await page.close();
});

test("figures: .wasm size, time to the first answer, frame times while dragging", async () => {
  const name = readdirSync(join(webDir, "dist", "pkg")).find((f) => /^cagd_web_bg\.[0-9a-f]+\.wasm$/.test(f));
  const wasm = readFileSync(join(webDir, "dist", "pkg", name));
  figures.wasmBytes = wasm.length;
  figures.wasmGzipBytes = gzipSync(wasm, { level: 9 }).length;
  // Time from navigation to the first answer shown (Primer 2.4 through the worker), on fresh loads.
  const times = [];
  for (let k = 0; k < 5; k++) {
    const page = await openPage(chrome.context, server.url, link(PRIMER_2_4));
    times.push(Number(await page.evaluate(() => document.documentElement.dataset.firstAnswerMs)));
    await page.close();
  }
  times.sort((a, b) => a - b);
  figures.firstAnswerMs = { median: times[2], all: times };
  const stats = (xs) => {
    const s = [...xs].sort((a, b) => a - b);
    return { frames: s.length, median: s[Math.floor(s.length / 2)], p95: s[Math.floor(s.length * 0.95)], max: s[s.length - 1] };
  };
  // Dragging a degree-10 Bézier curve: work per pointer event, and frame to frame times.
  const page = await openPage(chrome.context, server.url, "#view=bezier");
  await page.locator("#bezier-steps").filter({ hasText: "scheme" }).waitFor();
  await page.click("#bezier-degree10");
  const h = await page.locator('#bezier-plane circle.handle[data-index="5"]').boundingBox();
  await page.evaluate(() => (window.cagdApp.views.bezier.frameTimes = []));
  await page.mouse.move(h.x + h.width / 2, h.y + h.height / 2);
  await page.mouse.down();
  await page.mouse.move(h.x - 200, h.y + 100, { steps: 60 });
  await page.mouse.up();
  figures.bezierDegree10 = stats(await page.evaluate(() => window.cagdApp.views.bezier.frameTimes));
  figures.bezierDegree10Frames = stats(
    await page.evaluate(async () => {
      const v = window.cagdApp.views.bezier;
      const out = [];
      let last = await new Promise(requestAnimationFrame);
      for (let k = 0; k < 60; k++) {
        v.dragTo(5, [3 + k / 30, 1 + (k % 10) / 10]);
        const now = await new Promise(requestAnimationFrame);
        out.push(now - last);
        last = now;
      }
      return out;
    }),
  );
  // Dragging a corner of a 50 × 50 Coons grid.
  await page.click("#tab-coons");
  await page.locator("#coons-steps").filter({ hasText: "result" }).waitFor();
  await page.fill("#coons-n", "50");
  await page.evaluate(() => (window.cagdApp.views.coons.frameTimes = []));
  const c = await page.locator("#coons-canvas").boundingBox();
  const p4 = await page.evaluate(() => {
    const v = window.cagdApp.views.coons;
    const q = v.view.projector().project(...v.point("P4"));
    const r = v.view.canvas.getBoundingClientRect();
    return [r.left + (q[0] * r.width) / v.view.canvas.width, r.top + (q[1] * r.height) / v.view.canvas.height];
  });
  await page.mouse.move(p4[0], p4[1]);
  await page.mouse.down();
  await page.mouse.move(p4[0] - 40, p4[1] - 80, { steps: 60 });
  await page.mouse.up();
  assert.ok(c.width > 0);
  figures.coons50x50 = stats(await page.evaluate(() => window.cagdApp.views.coons.frameTimes));
  figures.coons50x50Frames = stats(
    await page.evaluate(async () => {
      const v = window.cagdApp.views.coons;
      const out = [];
      let last = await new Promise(requestAnimationFrame);
      for (let k = 0; k < 60; k++) {
        v.drag("P4", [1, 1, 1 + k / 60]);
        const now = await new Promise(requestAnimationFrame);
        out.push(now - last);
        last = now;
      }
      return out;
    }),
  );
  writeFileSync(join(resultsDir, "figures.json"), JSON.stringify(figures, null, 2));
  console.log(JSON.stringify(figures, null, 2));
  // With the operation layer the .wasm is about 3.4 MB without its name section (no wasm-opt
  // on this machine); what a cold load transfers (brotli, about 0.75 MB) is measured in
  // offline.test.mjs. The bounds here catch a doubling, the issue's 1.2 MB cold-load target
  // bounds the gzipped size.
  assert.ok(figures.wasmBytes <= 4 * 1024 * 1024, `wasm ${figures.wasmBytes} bytes`);
  assert.ok(figures.wasmGzipBytes <= 1.2e6, `wasm gzip ${figures.wasmGzipBytes} bytes`);
  await page.close();
});
