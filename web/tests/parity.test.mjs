// For every construction of the command line, random inputs give the same output on the page
// as from the cagd binary: the same text (numbers, steps, fractions) or the same one-line
// error. The page runs each command typed into its command line, in its worker.

import assert from "node:assert/strict";
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { after, before, test } from "node:test";
import { join as shellJoin } from "../js/shell.js";
import { browser, openPage, resultsDir, runBinary, runOnPage, serve } from "./helpers.mjs";
import { randomInputs } from "./random-inputs.mjs";

const SEED = Number(process.env.CAGD_WEB_SEED ?? 2014);
const COUNT = Number(process.env.CAGD_WEB_CASES ?? 50);

let server;
let chrome;
let page;
const summary = {};

before(async () => {
  server = await serve();
  chrome = await browser();
  page = await openPage(chrome.context, server.url);
});

after(async () => {
  writeFileSync(join(resultsDir, "parity-summary.json"), JSON.stringify({ seed: SEED, count: COUNT, summary }, null, 2));
  await chrome?.close();
  server?.stop();
});

/** Numbers in a text, for the comparison of results that differ only in the last digits. */
const numbers = (text) => text.match(/-?\d+(\.\d+)?(e[-+]?\d+)?/g) ?? [];
// (Column widths follow the digits, so white space is not compared.)
const skeleton = (text) => text.replace(/-?\d+(\.\d+)?(e[-+]?\d+)?/g, "#").replace(/\s+/g, " ");

function sameNumbers(a, b) {
  if (skeleton(a) !== skeleton(b)) return false;
  const x = numbers(a).map(Number);
  const y = numbers(b).map(Number);
  return x.length === y.length && x.every((v, i) => Math.abs(v - y[i]) <= 1e-12 * Math.max(1, Math.abs(v), Math.abs(y[i])));
}

async function onPage(input) {
  const line = shellJoin(["cagd", ...input.args]);
  if (!input.file) return runOnPage(page, line);
  // A command with a data script goes through a link carrying the file, as a shared link does.
  const before = Number(await page.locator("#result").getAttribute("data-run"));
  await page.evaluate(([cmd, file]) => (location.hash = `cmd=${encodeURIComponent(cmd)}&file=${encodeURIComponent(file)}`), [line, input.file]);
  await page.waitForFunction((n) => Number(document.getElementById("result").dataset.run) > n, before);
  return page.evaluate(() => ({
    ok: document.getElementById("result").dataset.ok === "true",
    stdout: document.getElementById("stdout").textContent,
    error: document.getElementById("error").textContent,
    warnings: [...document.querySelectorAll("#warnings li")].map((li) => li.textContent),
  }));
}

const inputs = randomInputs(SEED, COUNT);

for (const [name, cases] of Object.entries(inputs)) {
  test(`${name}: ${cases.length} random inputs give the binary's output on the page`, async () => {
    const tally = { identical: 0, lastDigits: 0, errors: 0 };
    for (const input of cases) {
      const want = runBinary(input.args, input.file ? [{ name: "data.m", text: input.file }] : []);
      const got = await onPage(input);
      const line = shellJoin(["cagd", ...input.args]);
      if (want.status === 0) {
        assert.ok(got.ok, `${line}\npage error: ${got.error}`);
        let expected = want.stdout;
        let actual = got.stdout;
        if (name === "thesis") {
          // The page draws SVG only (no PNG in the browser): the file list differs by those.
          expected = expected.replace(/^ {2}\S+\.png\n/gm, "");
          actual = actual.replace(/^ {2}\S+\.png\n/gm, "");
        }
        if (actual === expected) tally.identical++;
        else {
          assert.ok(sameNumbers(actual, expected), `${line}\n--- binary\n${expected}\n--- page\n${actual}`);
          tally.lastDigits++;
        }
        const warnings = want.stderr.split("\n").filter((l) => l.startsWith("cagd: warning:"));
        assert.deepEqual(got.warnings, warnings, line);
      } else {
        assert.ok(!got.ok, `${line}: the binary failed (${want.stderr.trim()}) but the page did not`);
        assert.equal(got.error, want.stderr.trim(), line);
        tally.errors++;
      }
    }
    summary[name] = tally;
  });
}
