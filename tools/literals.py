"""Numeric literals per category module: how much coordinate arithmetic a category still writes itself.

    python tools/literals.py [FILE ...]     # default: every categories/*.py (parts/ excluded)

Counts int and float constants in code (docstrings and bools excluded; 0, 1, 2 and -1 counted like any
other: `x / 2` is arithmetic too), per module, and prints the median. The part contract's goal is a
category that places parts by anchors and reads sizes from sourced tables: a median under 40.
"""

from __future__ import annotations

import ast
import statistics
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def count(path: Path) -> int:
    tree = ast.parse(path.read_text())
    docstrings = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = getattr(node, "body", [])
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                docstrings.add(id(body[0].value))
    n = 0
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and id(node) not in docstrings:
            v = node.value
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                n += 1
    return n


def main(argv: list[str]) -> int:
    files = [Path(a) for a in argv] or sorted(p for p in (ROOT / "categories").glob("*.py") if p.stem != "__init__")
    counts = {}
    for f in files:
        counts[f.stem] = count(f)
        print(f"{f.stem:20s} {counts[f.stem]:5d}")
    if counts:
        print(f"{'median':20s} {statistics.median(counts.values()):5.0f}  ({len(counts)} modules)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
