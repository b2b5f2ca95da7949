// Shared by the browser tests: the cagd binary, `cagd serve` on localhost, Debian's Chromium
// driven by playwright-core with a fresh profile, and the page's command line.

import { spawn, spawnSync } from "node:child_process";
import http from "node:http";
import { mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const here = dirname(fileURLToPath(import.meta.url));
export const webDir = resolve(here, "..");
export const repo = resolve(webDir, "..");
export const cagdBin = process.env.CAGD_BIN ?? join(repo, "target", "debug", "cagd");
export const resultsDir = join(webDir, "test-results");
mkdirSync(resultsDir, { recursive: true });

/** Runs the cagd binary in a scratch folder: {status, stdout, stderr}. */
export function runBinary(args, files = []) {
  const cwd = mkdtempSync(join(tmpdir(), "cagd-run-"));
  try {
    for (const f of files) spawnSync("sh", ["-c", 'cat > "$1"', "sh", join(cwd, f.name)], { input: f.text });
    const r = spawnSync(cagdBin, args, { cwd, encoding: "utf8", env: { PATH: process.env.PATH } });
    return { status: r.status, stdout: r.stdout, stderr: r.stderr };
  } finally {
    rmSync(cwd, { recursive: true, force: true });
  }
}

/** `cagd serve --port 0` on web/dist: {url, stop()}. */
export async function serve() {
  const child = spawn(cagdBin, ["serve", "--port", "0", "--dir", join(webDir, "dist")], { stdio: ["ignore", "pipe", "inherit"] });
  const url = await new Promise((ok, fail) => {
    let text = "";
    child.stdout.on("data", (d) => {
      text += d;
      const m = text.match(/at (http:\/\/127\.0\.0\.1:\d+\/)/);
      if (m) ok(m[1]);
    });
    child.on("exit", (code) => fail(new Error(`cagd serve exited with ${code}`)));
  });
  return {
    url,
    stop: () =>
      new Promise((ok) => {
        if (child.exitCode !== null || child.signalCode !== null) return ok(); // stopped already
        child.once("exit", ok);
        child.kill();
      }),
  };
}

/**
 * A proxy in front of `target` that counts what the browser receives: every response's bytes
 * as sent (compressed body and headers) and the requests by path. Chromium talks to it as to
 * the server; `stop()` ends it (the server behind stays).
 */
export async function countingProxy(target) {
  const upstream = new URL(target);
  const stats = { bytes: 0, requests: [] };
  const server = http.createServer((req, res) => {
    const forward = http.request({ host: upstream.hostname, port: upstream.port, path: req.url, method: req.method, headers: req.headers }, (up) => {
      let bytes = 0;
      for (const [k, v] of Object.entries(up.headers)) bytes += k.length + String(v).length + 4;
      up.on("data", (chunk) => (bytes += chunk.length));
      up.on("end", () => {
        stats.bytes += bytes;
        stats.requests.push({ path: req.url, status: up.statusCode, bytes, encoding: up.headers["content-encoding"] ?? null, cache: up.headers["cache-control"] ?? null });
      });
      res.writeHead(up.statusCode, up.headers);
      up.pipe(res);
    });
    forward.on("error", () => {
      res.writeHead(502);
      res.end();
    });
    req.pipe(forward);
  });
  await new Promise((ok) => server.listen(0, "127.0.0.1", ok));
  return {
    url: `http://127.0.0.1:${server.address().port}/`,
    stats,
    reset() {
      stats.bytes = 0;
      stats.requests = [];
    },
    stop: () =>
      new Promise((ok) => {
        server.close(ok);
        server.closeAllConnections?.();
      }),
  };
}

/** Headless Debian Chromium with a fresh profile, offline but for localhost. */
export async function browser(options = {}) {
  const profile = mkdtempSync(join(tmpdir(), "cagd-chromium-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
    ],
    viewport: { width: 1400, height: 1000 },
    ...options,
  });
  return {
    context,
    close: async () => {
      await context.close();
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

/** Opens the page and waits until it has answered its first command. */
export async function openPage(context, url, hash = "") {
  const page = await context.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => {
    if (m.type() === "error") errors.push(m.text());
  });
  await page.goto(url + hash);
  await page.waitForFunction(
    () => {
      const app = window.cagdApp;
      if (!app?.current) return false;
      return app.current === "command" ? document.documentElement.dataset.firstAnswerMs !== undefined : !!app.views[app.current];
    },
    null,
    { timeout: 30000 },
  );
  page.errors = errors;
  return page;
}

/** Runs a command line typed into the page's command line: {ok, stdout, error, warnings}. */
export async function runOnPage(page, line) {
  const before = Number(await page.locator("#result").getAttribute("data-run"));
  await page.fill("#cmdline", line);
  await page.press("#cmdline", "Enter");
  await page.waitForFunction((n) => Number(document.getElementById("result").dataset.run) > n, before, { timeout: 60000 });
  return page.evaluate(() => ({
    ok: document.getElementById("result").dataset.ok === "true",
    stdout: document.getElementById("stdout").textContent,
    error: document.getElementById("error").textContent,
    warnings: [...document.querySelectorAll("#warnings li")].map((li) => li.textContent),
  }));
}
