// Command lines as a POSIX shell reads them: split into arguments and quote them back, so that
// a command copied from the page runs the same in a terminal, and one pasted into the page
// gives the same arguments as in a terminal.

/** Splits a command line into its arguments (quotes '…' and "…", backslash escapes). */
export function split(line) {
  const args = [];
  let current = null;
  let i = 0;
  const push = () => {
    if (current !== null) args.push(current);
    current = null;
  };
  while (i < line.length) {
    const c = line[i];
    if (c === "\\" && line[i + 1] === "\n") {
      i += 2;
    } else if (/\s/.test(c)) {
      push();
      i += 1;
    } else if (c === "'") {
      const end = line.indexOf("'", i + 1);
      if (end < 0) throw new Error("a quote ' is not closed");
      current = (current ?? "") + line.slice(i + 1, end);
      i = end + 1;
    } else if (c === '"') {
      let text = "";
      i += 1;
      for (;;) {
        if (i >= line.length) throw new Error('a quote " is not closed');
        const d = line[i];
        if (d === '"') break;
        if (d === "\\" && i + 1 < line.length && '"\\$`\n'.includes(line[i + 1])) {
          if (line[i + 1] !== "\n") text += line[i + 1];
          i += 2;
        } else {
          text += d;
          i += 1;
        }
      }
      current = (current ?? "") + text;
      i += 1;
    } else if (c === "\\" && i + 1 < line.length) {
      current = (current ?? "") + line[i + 1];
      i += 2;
    } else {
      current = (current ?? "") + c;
      i += 1;
    }
  }
  push();
  return args;
}

/** One argument quoted for a POSIX shell (bare when safe, else "…" or '…'). */
export function quote(arg) {
  if (arg !== "" && /^[A-Za-z0-9_\-+.,:/=@%^]+$/.test(arg)) return arg;
  if (!/["\\$`!]/.test(arg)) return `"${arg}"`;
  return `'${arg.replaceAll("'", "'\\''")}'`;
}

/** A command line from its arguments. */
export function join(args) {
  return args.map(quote).join(" ");
}
