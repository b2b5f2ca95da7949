// The page's side of the command-line worker: one command at a time, the newest wins (a run
// still going when another starts is stopped by ending its worker and starting a new one).

export class CommandLine {
  constructor() {
    this.nextId = 1;
    this.current = null;
    this.spawn();
  }

  spawn() {
    this.worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
    this.ready = new Promise((resolve, reject) => {
      this.readyHooks = { resolve, reject };
    });
    this.worker.onmessage = ({ data }) => {
      if ("ready" in data) {
        if (data.ready) this.readyHooks.resolve();
        else this.readyHooks.reject(new Error(data.error));
        return;
      }
      if (!this.current || data.id !== this.current.id) return;
      const { resolve } = this.current;
      this.current = null;
      if (data.fatal) this.restart();
      resolve(data);
    };
    this.worker.onerror = (e) => {
      e.preventDefault?.();
      const current = this.current;
      this.current = null;
      this.restart();
      current?.resolve({ ok: false, code: 1, error: `cagd: internal error: ${e.message || "the worker failed"}; this is a bug in cagd` });
    };
  }

  restart() {
    this.worker.terminate();
    this.spawn();
  }

  /** Whether a command is running. */
  get busy() {
    return this.current !== null;
  }

  /** Runs `argv` (starting with "cagd") with input files [{name, text}]. */
  async run(argv, files = []) {
    if (this.current) this.stop();
    const id = this.nextId++;
    const answer = new Promise((resolve) => {
      this.current = { id, resolve };
    });
    await this.ready;
    if (this.current?.id === id) this.worker.postMessage({ id, argv, files });
    return answer;
  }

  /** Stops the running command (its promise answers {stopped: true}). */
  stop() {
    const current = this.current;
    if (!current) return;
    this.current = null;
    this.restart();
    current.resolve({ ok: false, stopped: true, error: "Stopped: the command was interrupted before it finished." });
  }
}
