// The command line in a Web Worker, so that a long computation never freezes the page. The page
// first posts {init: module} (the WebAssembly module it compiled: the worker downloads
// nothing), then {id, argv, files}; the worker answers {ready} once, then {id, ok, stdout,
// warnings, files, error} per command. A fault in the WebAssembly (a bug) is answered with the
// program's internal-error line and `fatal: true`, after which the page ends this worker.
// The WebAssembly asks nothing of the DOM (the pictures measure their text from the font's
// advances), so the same module runs here as on the page.

import init, { file_bytes, run } from "../pkg/cagd_web.js";

let panicMessage = null;
globalThis.cagdPanic = (message) => {
  panicMessage = message;
};

let ready = null;

self.onmessage = async ({ data }) => {
  if (data.init) {
    ready = init({ module_or_path: data.init }).then(
      () => self.postMessage({ ready: true }),
      (e) => self.postMessage({ ready: false, error: String(e) }),
    );
    return;
  }
  await ready;
  const { id, argv, files = [] } = data;
  panicMessage = null;
  let answer;
  try {
    answer = JSON.parse(
      run(
        argv,
        files.map((f) => f.name),
        files.map((f) => f.text),
      ),
    );
    if (answer.ok) answer.files = answer.files.map((f, i) => ({ ...f, bytes: file_bytes(i) }));
  } catch (e) {
    answer = {
      ok: false,
      code: 1,
      fatal: true,
      error: panicMessage ?? `cagd: internal error: ${e}; this is a bug in cagd`,
    };
  }
  self.postMessage({ id, ...answer });
};
