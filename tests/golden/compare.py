"""Compare two generated output trees file by file, numbers within a tolerance.

    python tests/golden/compare.py OLD NEW [--rel 1e-6] [--abs 1e-7]

For refactors that move arithmetic around (a part built in its own frame and placed by an anchor instead of
in world coordinates), the last bits of some floats change and the golden sha256 with them. This tells a
rounding change from a real one: every text file (USDA, URDF, MJCF, OBJ, MTL, JSON, TXT) must have the
same tokens with every number equal within ``abs + rel * max(|a|, |b|)``; a binary USD crate is compared
through its text export; PNG textures must be byte-identical; a GLB's JSON numerically and its binary chunk
as float32. Prints one line per differing file with the worst number, exit 1 if any differ.
"""

from __future__ import annotations

import argparse
import json
import re
import struct
import sys
from pathlib import Path

import numpy as np

NUM = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?|nan|inf")


def _tokens(text: str) -> tuple[list[str], np.ndarray]:
    nums = [float(m) for m in NUM.findall(text)]
    return NUM.sub("#", text).split(), np.asarray(nums, float)


def _text(path: Path) -> str:
    if path.suffix == ".usdc":
        from pxr import Sdf

        return Sdf.Layer.FindOrOpen(str(path)).ExportToString()
    return path.read_text(errors="replace")


def _close(a: np.ndarray, b: np.ndarray, rel: float, abs_: float) -> tuple[bool, float]:
    if a.shape != b.shape:
        return False, float("inf")
    if a.size == 0:
        return True, 0.0
    with np.errstate(invalid="ignore", over="ignore"):
        err = np.abs(a - b)
        ok = np.isclose(a, b, rtol=rel, atol=abs_, equal_nan=True)
    return bool(ok.all()), float(np.nanmax(err)) if err.size else 0.0


def _glb(path: Path) -> tuple[str, np.ndarray]:
    data = path.read_bytes()
    n = struct.unpack_from("<I", data, 12)[0]
    js = data[20:20 + n].decode()
    rest = data[20 + n:]
    binary = rest[8:] if len(rest) >= 8 else b""
    with np.errstate(invalid="ignore"):
        return js, np.frombuffer(binary[: len(binary) // 4 * 4], "<f4").astype(float)


def compare_file(a: Path, b: Path, rel: float, abs_: float) -> str | None:
    if a.suffix == ".png":
        return None if a.read_bytes() == b.read_bytes() else "png bytes differ"
    if a.suffix == ".glb":
        ja, fa = _glb(a)
        jb, fb = _glb(b)
        ta, na = _tokens(json.dumps(json.loads(ja), sort_keys=True))
        tb, nb = _tokens(json.dumps(json.loads(jb), sort_keys=True))
        ok1, e1 = _close(na, nb, rel, abs_)
        ok2, e2 = _close(fa, fb, rel, abs_)
        if ta != tb or not ok1 or not ok2:
            return f"glb differs (json tokens {'same' if ta == tb else 'differ'}, max |d| {max(e1, e2):.3g})"
        return None
    ta, na = _tokens(_text(a))
    tb, nb = _tokens(_text(b))
    if ta != tb:
        for i, (x, y) in enumerate(zip(ta, tb)):
            if x != y:
                return f"text differs at token {i}: {x!r} vs {y!r}"
        return f"text differs in length ({len(ta)} vs {len(tb)} tokens)"
    ok, err = _close(na, nb, rel, abs_)
    return None if ok else f"numbers differ, max |d| {err:.3g}"


def compare_trees(old: Path, new: Path, rel: float = 1e-6, abs_: float = 1e-7) -> list[str]:
    fa = {p.relative_to(old).as_posix() for p in old.rglob("*") if p.is_file()}
    fb = {p.relative_to(new).as_posix() for p in new.rglob("*") if p.is_file()}
    out = [f"missing  {r}" for r in sorted(fa - fb)] + [f"new      {r}" for r in sorted(fb - fa)]
    for r in sorted(fa & fb):
        why = compare_file(old / r, new / r, rel, abs_)
        if why:
            out.append(f"differs  {r}: {why}")
    return out


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old", type=Path)
    ap.add_argument("new", type=Path)
    ap.add_argument("--rel", type=float, default=1e-6)
    ap.add_argument("--abs", dest="abs_", type=float, default=1e-7)
    a = ap.parse_args(argv)
    diff = compare_trees(a.old, a.new, a.rel, a.abs_)
    print("\n".join(diff) if diff else "equal within tolerance")
    return 1 if diff else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
