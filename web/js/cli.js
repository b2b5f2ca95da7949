// The page's one owner of the command-line workers. Each part of the page that runs commands
// (the command view, a view such as the Gordon surface) has its own lane: one worker, one
// command at a time, the newest of that lane winning. Lanes never touch each other, so opening
// a view never cancels or orphans the command view's command. Every worker instantiates the
// one WebAssembly module the page compiled (no second download). A worker that cannot start
// is reported once and not retried until the next command asks for it (no request loops when
// the page is offline), and Stop ends a worker without starting another until it is needed.
// Until a lane's worker is ready (the first command of a page load), a command is first tried
// on the main thread under a small work limit (`quick`): a student's small construction answers
// at once, and one above the limit (the operation layer estimates every construction's work
// before it starts) goes to the worker.

import { t } from "./i18n.js";

class Lane {
  constructor(module) {
    this.module = module;
    this.worker = null;
    this.ready = null;
    this.current = null;
    this.nextId = 1;
    /** Whether the worker has its WebAssembly instantiated. */
    this.started = false;
    /** The commands asked of this lane so far, and the one Stop ended last. */
    this.tickets = 0;
    this.stoppedTicket = 0;
  }

  /** Starts the worker (if there is none) and resolves when its WebAssembly is ready. */
  start() {
    if (this.worker) return this.ready;
    const worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
    this.worker = worker;
    this.ready = new Promise((resolve, reject) => {
      worker.onmessage = ({ data }) => {
        if ("ready" in data) {
          if (data.ready) {
            this.started = true;
            resolve();
          } else this.fail(data.error, reject);
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
    Promise.resolve(this.module).then(
      (module) => worker.postMessage({ init: module }),
      (e) => this.fail(e?.message ?? String(e)),
    );
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
    this.started = false;
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
  /**
   * @param {Promise<WebAssembly.Module>} module the page's compiled WebAssembly, once the main
   *   thread has instantiated it
   * @param {(argv: string[], files: object[]) => object | null} quick runs a command on the
   *   main thread under a small work limit: its answer, or null when the command is above it
   */
  constructor(module, quick = () => null) {
    this.module = module;
    this.quick = quick;
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

  /**
   * Runs `argv` (starting with "cagd") with input files [{name, text}] in `owner`'s lane; while
   * its worker is still starting and nothing runs there, a small command answers on the main
   * thread.
   */
  async run(argv, files = [], owner = "command") {
    const lane = this.lane(owner);
    // Commands waiting for the WebAssembly keep the lane's rule: the newest wins, Stop stops.
    const ticket = ++lane.tickets;
    if (!lane.started && !lane.current) {
      try {
        await this.module;
      } catch (e) {
        return { ok: false, code: 1, error: t("workerFailed", { reason: e?.message ?? String(e) }) };
      }
      if (lane.tickets !== ticket) {
        const stopped = lane.stoppedTicket === ticket;
        return { ok: false, stopped: true, superseded: !stopped, error: t("stopped") };
      }
      if (!lane.started && !lane.current) {
        const answer = this.quick(argv, files);
        if (answer) return answer;
      }
    }
    return lane.run(argv, files);
  }

  /** Stops `owner`'s running command (its promise answers {stopped: true}). */
  stop(owner = "command") {
    const lane = this.lanes.get(owner);
    if (!lane) return;
    lane.stoppedTicket = lane.tickets;
    lane.tickets += 1;
    lane.stop();
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
