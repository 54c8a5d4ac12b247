"""Helpers the per-category tests share: a ``make`` per category and the joint states the checks sample."""

from __future__ import annotations

import itertools
import math

import numpy as np

from zoo import make_bp, movable


def maker(name: str, **defaults):
    """``make(seed, **overrides) -> (params, grounded blueprint)`` of category ``name``; ``defaults`` are the
    overrides a test file was written for (its design), under whatever a test asks for; a callable default is
    called with the seed."""

    def make(seed: int, **overrides):
        fixed = {k: v(seed) if callable(v) else v for k, v in defaults.items()}
        return make_bp(None, name, seed, **{**fixed, **overrides})

    make.__doc__ = f"``(params, blueprint)`` of {name} for ``seed``" + (f", {defaults} unless asked" if defaults
                                                                         else "")
    return make


def part_points(bp, part: str, pose=None):
    """The vertices of a blueprint part's pieces, moved by the 4x4 ``pose`` (default: where they are)."""
    pts = np.vstack([pc.vertices for pc in bp.parts[part].pieces])
    pose = np.eye(4) if pose is None else pose
    return pts @ pose[:3, :3].T + pose[:3, 3]


def _at(d, f: float) -> float:
    """A DoF at fraction ``f`` of its range; a continuous one at ``f`` half turns."""
    return f * math.pi if d.type == "continuous" else d.lower + f * (d.upper - d.lower)


def _ends(d) -> tuple[float, ...]:
    return (math.pi / 2, -math.pi / 2, math.pi) if d.type == "continuous" else (d.lower, d.upper)


def labelled_states(bp) -> list[tuple[str, dict]]:
    """``(label, Blueprint.poses values)`` of the states the validators sample, and more: rest; every DoF at
    50 % and 100 % (a continuous one at a quarter and a half turn); each joint alone with all its DoFs at its
    lower and at its upper limits; each DoF alone at each limit (a continuous one at +-90 and 180 degrees)."""
    js = movable(bp)
    out = [("rest", {})]
    for f in (0.5, 1.0):
        out.append((f"all@{f:.0%}", {(j.child, i): _at(d, f) for j in js for i, d in enumerate(j.dofs)}))
    for j in js:
        if len(j.dofs) > 1:
            out += [(f"{j.child}@{f:.0%}", {(j.child, i): _at(d, f) for i, d in enumerate(j.dofs)}) for f in (0, 1)]
        for i, d in enumerate(j.dofs):
            out += [(f"{j.child}.{i}@{q:.3g}", {(j.child, i): q}) for q in _ends(d)]
    seen, unique = set(), []
    for label, q in out:  # a DoF at 0 is where rest puts it: the same pose is checked once
        key = frozenset((k, v) for k, v in q.items() if v != 0.0)
        if key not in seen:
            seen.add(key)
            unique.append((label, q))
    return unique


def states(bp) -> list[dict]:
    """The ``Blueprint.poses`` values of :func:`labelled_states`."""
    return [q for _, q in labelled_states(bp)]


def joint_states(joint, together: bool = False) -> list[tuple[float, ...]]:
    """DoF values of one joint: every DoF together at its lower limit, at 50 % of its range, at half its upper
    limit and at its upper limit; unless ``together``, also rest (all 0), each DoF alone at each limit (the
    others at 0) and every corner of the range (each DoF at either limit)."""
    lims = [(d.lower, d.upper) for d in joint.dofs]
    out = [tuple(lo + f * (hi - lo) for lo, hi in lims) for f in (0.0, 0.5)]
    out += [tuple(0.5 * hi for _, hi in lims), tuple(hi for _, hi in lims)]
    if together:
        return out
    out.append(tuple(0.0 for _ in lims))
    for k, (lo, hi) in enumerate(lims):
        out += [tuple(v if i == k else 0.0 for i in range(len(lims))) for v in (lo, hi)]
    out += list(itertools.product(*lims))
    return list(dict.fromkeys(out))


def _seg(p, a, b):
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-30), 0, 1)
    return np.linalg.norm(p - (a + t[:, None] * ab), axis=1)


def surface_distance(v, f, point) -> float:
    """Distance from ``point`` to the nearest triangle of ``(v, f)`` (exact, every triangle)."""
    p = np.asarray(point, float)[None, :]
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    n = np.cross(b - a, c - a)
    nn = np.linalg.norm(n, axis=1)
    ok = nn > 1e-18
    un = n / np.where(ok, nn, 1.0)[:, None]
    h = np.einsum("ij,ij->i", p - a, un)
    q = p - h[:, None] * un
    inside = ok.copy()
    for x, y in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ij,ij->i", np.cross(y - x, q - x), un) >= -1e-12
    edges = np.minimum(np.minimum(_seg(p, a, b), _seg(p, b, c)), _seg(p, c, a))
    return float(np.where(inside, np.abs(h), edges).min())
