"""Runs every code cell of a notebook in order, in one namespace, as Jupyter would (without a
kernel), and renders each cell's displayed value with its ``_repr_html_``/``_repr_svg_``: the
notebook's code is tested by CI without installing Jupyter. Usage:
``python run_notebook.py NOTEBOOK.ipynb``."""

import ast
import json
import sys


def run_cell(source, name, namespace):
    """Executes a cell; returns the value of its last line if that is an expression."""
    tree = ast.parse(source, name)
    last = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
    exec(compile(tree, name, "exec"), namespace)
    if last is None:
        return None
    return eval(compile(ast.Expression(last.value), name, "eval"), namespace)


def main(path):
    cells = json.load(open(path, encoding="utf-8"))["cells"]
    namespace = {"__name__": "__main__"}
    code = [c for c in cells if c["cell_type"] == "code"]
    for k, cell in enumerate(code, 1):
        value = run_cell("".join(cell["source"]), f"{path}[{k}]", namespace)
        for method in ("_repr_html_", "_repr_svg_"):
            if hasattr(value, method):
                assert getattr(value, method)()
    print(f"{path}: {len(code)} code cells ran")


if __name__ == "__main__":
    main(sys.argv[1])
