// The page's one owner of the command-line workers. Each part of the page that runs commands
// (the command view, a view such as the Gordon surface) has its own lane: one worker, one
// command at a time, the newest of that lane winning. Lanes never touch each other, so opening
// a view never cancels or orphans the command view's command. Every worker instantiates the
// one WebAssembly module the page compiled (no second download). A worker that cannot start
// is reported once and not retried until the next command asks for it (no request loops when
// the page is offline), and Stop ends a worker without starting another until it is needed.

import { t } from "./i18n.js";

class Lane {
  constructor(module) {
    this.module = module;
    this.worker = null;
    this.ready = null;
    this.current = null;
    this.nextId = 1;
  }

  /** Starts the worker (if there is none) and resolves when its WebAssembly is ready. */
  start() {
    if (this.worker) return this.ready;
    const worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
    this.worker = worker;
    this.ready = new Promise((resolve, reject) => {
      worker.onmessage = ({ data }) => {
        if ("ready" in data) {
          if (data.ready) resolve();
          else this.fail(data.error, reject);
          return;
        }
        if (!this.current || data.id !== this.current.id) return;
        const { resolve: answer } = this.current;
        this.current = null;
        if (data.fatal) this.end();
        answer(data);
      };
      worker.onerror = (e) => {
        e.preventDefault?.();
        this.fail(e.message || "the worker failed", reject);
      };
    });
    // Nobody may be waiting when a worker fails between commands.
    this.ready.catch(() => {});
    worker.postMessage({ init: this.module });
    return this.ready;
  }

  /** The worker failed: end it, answer the running command, and wait for the next one. */
  fail(reason, reject) {
    const current = this.current;
    this.current = null;
    this.end();
    reject?.(new Error(reason));
    current?.resolve({ ok: false, code: 1, error: t("workerFailed", { reason }) });
  }

  end() {
    this.worker?.terminate();
    this.worker = null;
    this.ready = null;
  }

  async run(argv, files) {
    if (this.current) this.stop(true);
    const id = this.nextId++;
    const answer = new Promise((resolve) => {
      this.current = { id, resolve };
    });
    try {
      await this.start();
    } catch (e) {
      if (this.current?.id === id) {
        const { resolve } = this.current;
        this.current = null;
        resolve({ ok: false, code: 1, error: t("workerFailed", { reason: e.message }) });
      }
      return answer;
    }
    if (this.current?.id === id) this.worker.postMessage({ id, argv, files });
    return answer;
  }

  stop(superseded = false) {
    const current = this.current;
    if (!current) return;
    this.current = null;
    this.end();
    current.resolve({ ok: false, stopped: true, superseded, error: t("stopped") });
  }
}

export class CommandLine {
  /** @param {WebAssembly.Module} module the page's compiled WebAssembly */
  constructor(module) {
    this.module = module;
    this.lanes = new Map();
  }

  lane(owner) {
    if (!this.lanes.has(owner)) this.lanes.set(owner, new Lane(this.module));
    return this.lanes.get(owner);
  }

  /** Starts the command view's worker ahead of its first command. */
  warm(owner = "command") {
    this.lane(owner)
      .start()
      .catch(() => {});
  }

  /** Runs `argv` (starting with "cagd") with input files [{name, text}] in `owner`'s lane. */
  run(argv, files = [], owner = "command") {
    return this.lane(owner).run(argv, files);
  }

  /** Stops `owner`'s running command (its promise answers {stopped: true}). */
  stop(owner = "command") {
    this.lanes.get(owner)?.stop();
  }

  /** Whether `owner` has a command running. */
  isBusy(owner = "command") {
    return !!this.lanes.get(owner)?.current;
  }

  /** Whether the command view has a command running. */
  get busy() {
    return this.isBusy("command");
  }
}
