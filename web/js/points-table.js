// Typed entry beside dragging: a table with one row per point and one text field per
// coordinate (and weight), holding the values exactly as typed ("1/3" stays 1/3).

import { t } from "./i18n.js";
import { num, toNumber } from "./numbers.js";

export class PointsTable {
  /**
   * @param {HTMLElement} container
   * @param {{columns: string[], name: (i: number) => string, onInput: (i: number, k: number, text: string) => void, caption: string}} options
   */
  constructor(container, options) {
    this.container = container;
    this.options = options;
    this.shape = "";
  }

  /** Shows `rows` (arrays of texts), rebuilding only when the shape changes. */
  set(rows, columns = this.options.columns) {
    const shape = `${rows.length}x${columns.join(",")}`;
    if (shape !== this.shape) this.build(rows.length, columns);
    rows.forEach((row, i) =>
      row.forEach((text, k) => {
        const input = this.inputs[i]?.[k];
        if (input && document.activeElement !== input && input.value !== text) input.value = text;
      }),
    );
  }

  build(count, columns) {
    this.shape = `${count}x${columns.join(",")}`;
    const table = document.createElement("table");
    table.className = "points";
    const caption = document.createElement("caption");
    caption.textContent = this.options.caption ?? t("points");
    table.append(caption);
    const head = table.createTHead().insertRow();
    for (const text of ["", ...columns]) {
      const th = document.createElement("th");
      th.scope = "col";
      th.textContent = text;
      head.append(th);
    }
    const body = table.createTBody();
    this.inputs = [];
    for (let i = 0; i < count; i++) {
      const row = body.insertRow();
      const th = document.createElement("th");
      th.scope = "row";
      th.textContent = this.options.name(i);
      row.append(th);
      this.inputs.push(
        columns.map((col, k) => {
          const input = document.createElement("input");
          input.type = "text";
          input.inputMode = "decimal";
          input.spellcheck = false;
          input.autocomplete = "off";
          input.setAttribute("aria-label", `${this.options.name(i)} ${col}`);
          input.dataset.row = String(i);
          input.dataset.col = String(k);
          input.addEventListener("input", () => this.options.onInput(i, k, input.value.trim()));
          row.insertCell().append(input);
          return input;
        }),
      );
    }
    this.container.replaceChildren(table);
  }
}

/**
 * The points of a matrix literal (a command line's argument) as typed entries, one array per
 * point: points are columns unless `rows` (a literal ending in ' is transposed). Entries that
 * are plain numbers or fractions keep their text; anything else is read by the library and
 * written as the shortest decimal. Null unless every point has one of the `dims` coordinates.
 */
export function typedPoints(app, text, rows, dims = [2]) {
  if (text === undefined) return null;
  const trimmed = text.trim();
  const transposed = trimmed.endsWith("'");
  const m = trimmed.replace(/'$/, "").match(/^\[(.*)\]$/s);
  let matrix = null;
  if (m) {
    const cells = m[1]
      .split(/;|\n/)
      .map((r) => r.trim())
      .filter(Boolean)
      .map((r) => r.split(/[\s,]+/).filter(Boolean));
    if (cells.length && cells.every((r) => r.length === cells[0].length && r.every((c) => Number.isFinite(toNumber(c))))) matrix = cells;
  }
  if (!matrix) {
    const values = app.matrix(text);
    if (!values) return null;
    matrix = values.map((r) => r.map((x) => num(x)));
  }
  // Columns are points; a literal written with a point per row and transposed (') has them as rows.
  const points = transposed !== rows ? matrix : matrix[0].map((_, j) => matrix.map((r) => r[j]));
  if (points.length < 2 || !dims.includes(points[0].length)) return null;
  return points;
}
