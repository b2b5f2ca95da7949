// Text measurement for the picture code inside a Web Worker.
//
// Compiled to WebAssembly, plotters (the drawing library of the cagd program) sizes text with
// the page's DOM: it appends a <span> to document.body, reads offsetWidth and offsetHeight, and
// removes it. The picture code measures its own labels from the font's advances
// (crates/cagd-cli/src/plot/text_size.rs); only plotters' legend box still asks the DOM. A
// worker has no DOM, so this gives it just those pieces, measuring with an OffscreenCanvas
// (same fonts as the page). On the main thread, where the real DOM exists, nothing is
// installed.

if (typeof document === "undefined") {
  const context = typeof OffscreenCanvas === "function" ? new OffscreenCanvas(1, 1).getContext("2d") : null;

  const styleOf = (css) => {
    const get = (name) => (css.match(new RegExp(`${name}\\s*:\\s*([^;]+)`)) || [])[1]?.trim();
    return {
      family: get("font-family") || "sans-serif",
      style: get("font-style") || "normal",
      size: parseFloat(get("font-size")) || 16,
    };
  };

  class HTMLElement {
    constructor() {
      this.textContent = "";
      this.css = "";
    }
    setAttribute(name, value) {
      if (name === "style") this.css = String(value);
    }
    append() {}
    appendChild(node) {
      return node;
    }
    remove() {}
    get offsetWidth() {
      const { family, style, size } = styleOf(this.css);
      if (!context) return Math.round(0.6 * size * this.textContent.length);
      context.font = `${style === "normal" ? "" : style} ${size}px ${family}`;
      return Math.round(context.measureText(this.textContent).width);
    }
    get offsetHeight() {
      return Math.round(1.15 * styleOf(this.css).size);
    }
  }

  const body = new HTMLElement();
  globalThis.HTMLElement = HTMLElement;
  globalThis.document = {
    body,
    createElement: () => new HTMLElement(),
  };
  // web_sys::window() asks whether the global object is a Window.
  globalThis.Window = class Window {
    static [Symbol.hasInstance](object) {
      return object === globalThis;
    }
  };
}
