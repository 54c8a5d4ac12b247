"""Interaction annotations: for every joint a person operates, where and how a gripper opens it.

Parts that know their grasp carry it (:class:`~infmob_usd.grasps.Grasp` on their pieces: a handle, a
knob, a dial, a button, a lever); every other operated part gets a grasp derived here from its link's
geometry (:func:`derived_grasps`): the free edge of a door or lid pinched across its thickness, a drawer
front's top edge, a rim from above, a small turning part across its cap. :func:`annotate` builds the
targets that the writers emit (``annotations.json``, ``metadata.json`` "interaction", grasp Xforms in the
USD); the schema is ``infmob-annotations/1`` (docs/format.md).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from trimesh.intersections import slice_faces_plane

from .clipping import EXACT, clip, gemv_rows
from .grasps import Grasp
from .joints import gate_chain
from .rotation import motion

FORMAT = "infmob-annotations/1"
UNITS = "metres, radians for revolute/continuous joints, metres for prismatic; Z up, fronts face +X"
OPEN_THRESHOLD = 0.9
"""Fraction of the range past which a joint is open: ManiSkill's OpenCabinetDrawer success
(qpos >= lower + 0.9 (upper - lower))."""
CLOSED_THRESHOLD = 0.05
"""Fraction of the range under which a joint is closed (RoboCasa's fixture ``is_closed``: near the closed
limit)."""
PATH_STEPS = 10  # the path's points at fractions 0, 0.1, ..., 1
TURN = math.pi / 2
"""rad, the "open" of a continuous joint (it has no open state): a quarter turn, what a hand turns a dial."""

PAD = 0.01  # m, half a finger pad's width (a Panda finger pad is ~20 mm wide)
REACH = 0.03  # m, how deep past the surface the fingers may close
FINGER = 0.012  # m, the room a finger needs beside the part (a gap narrower than this is bridged)
KNOB_REACH = 0.06  # m, a turning part no farther than this from its axis is turned across its cap
PALM = (0.204, 0.063, 0.058, 0.1034 + 0.10)
"""m, the Panda hand's body behind its fingers (Franka Hand drawings, ManiSkill's panda_v2_gripper.urdf): across
the closing axis, across the pad, and from / to how far behind the pads' centre (the fingers' base, the
hand's flange, and 10 cm on: the hand comes in along the approach, as the robot check's pre-grasp), where its
body must be free for a grasp to be taken."""
GRIP = 0.075  # m, the widest opening accepted for a derived grasp (MAX_WIDTH less a margin)

SQUARE = math.cos(math.radians(10))  # a far edge within 10 degrees of a world axis is taken square to it

ACTIONS = ("pull", "push", "turn", "press", "lift", "slide")


def operated(joint, joints) -> bool:
    """A joint a person operates: movable, not a wheel, not following another joint (a coupled joint moves
    with its leader), not a caster's swivel (a freely turning part that carries a wheel follows the floor)."""
    if not joint.movable or joint.role == "wheel" or joint.mimic is not None:
        return False
    if joint.type == "continuous" and joint.role == "swivel":
        return not any(j.parent == joint.child and j.role == "wheel" for j in joints)
    return True


def action(joint) -> str:
    """What opens it: ``turn`` a continuous joint or a knob, swivel or turntable; ``press`` a button, lever,
    pedal, toggle (a switch's bat or rocker) or plunger (a pump head pushed down its stroke); ``lift`` a lid,
    a lift-off part, a plate or grate; ``slide`` a telescope; else ``pull``."""
    if joint.type == "continuous" or joint.role in ("knob", "swivel", "turntable"):
        return "turn"
    if joint.role in ("button", "lever", "pedal_lid", "toggle", "plunger"):
        return "press"
    if joint.role in ("lid", "lift_off", "plate", "grate"):
        return "lift"
    if joint.role == "telescope":
        return "slide"
    return "pull"


def _mesh(pieces) -> tuple[np.ndarray, np.ndarray]:
    vs, fs, n = [], [], 0
    for p in pieces:
        vs.append(p.vertices)
        fs.append(p.faces + n)
        n += len(p.vertices)
    return np.concatenate(vs), np.concatenate(fs)


def _cross(a, b) -> np.ndarray:
    """``np.cross`` of two 3-vectors, the same floats (its products and differences, in its order), without
    its per-call overhead."""
    a0, a1, a2 = np.asarray(a, float).tolist()
    b0, b1, b2 = np.asarray(b, float).tolist()
    return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])


def _soup(pieces) -> tuple:
    """A link's ``_mesh``, its triangles, their bounds and the mesh's bounds."""
    v, f = _mesh(pieces)
    tri = v[f]
    return v, f, tri, tri.min(1), tri.max(1), v.min(0), v.max(0)


def raycast(v: np.ndarray, f: np.ndarray, origin, direction, edges=None, facing=None) -> float | None:
    """Distance along ``direction`` (unit) from ``origin`` to the first triangle hit, or ``None``
    (Moeller-Trumbore over every triangle); ``edges``: :func:`_edges` of ``(v, f)`` and ``facing``:
    :func:`_facing` of them along ``direction``, where the caller has them."""
    o, d = np.asarray(origin, float), np.asarray(direction, float)
    a, e1, e2 = edges if edges is not None else _edges(v, f)
    p, ok, inv = facing if facing is not None else _facing(d, e1, e2)
    s = o - a
    u = np.einsum("ij,ij->i", s, p) * inv
    q = np.cross(s, e1)
    w = (q @ d) * inv
    t = np.einsum("ij,ij->i", e2, q) * inv
    hit = ok & (u >= -1e-9) & (w >= -1e-9) & (u + w <= 1 + 1e-9) & (t > 1e-9)
    return float(t[hit].min()) if hit.any() else None


def _facing(d: np.ndarray, e1: np.ndarray, e2: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """What :func:`raycast` reads of the triangles along ``d`` wherever the ray starts."""
    p = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, p)
    ok = np.abs(det) > 1e-12
    return p, ok, np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)


def _edges(v: np.ndarray, f: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each triangle's first corner and its two edges from it, as :func:`raycast` reads them."""
    a = v[f[:, 0]]
    return a, v[f[:, 1]] - a, v[f[:, 2]] - a


def _crop(v, f, point, planes):
    """The triangles of ``(v, f)`` inside every half-space ``(normal, offset)``: ``(x - point) . n >= -offset``."""
    point = np.asarray(point, float)
    normals = np.array([n for n, _ in planes], float)
    offsets = np.array([off for _, off in planes], float)
    # a triangle wholly outside one half-space (beyond the slicer's tolerance) is one slicing would drop: drop it
    # first, so the slicer reads a handful of triangles instead of the whole link (same triangles out, same order)
    outside = ((v[f] - point) @ normals.T < -offsets - 1e-6).all(axis=1).any(axis=1)
    f = f[~outside]
    used, f = np.unique(f, return_inverse=True)  # only the vertices of these triangles: slicing reads them all
    v, f = v[used], f.reshape(-1, 3)
    for n, off in planes:
        if len(f) == 0:
            break
        n = np.asarray(n, float)
        if ((v - point) @ n >= -off + 1e-6).all():  # nothing to cut off: the slicer would give it back as it is
            continue
        v, f = slice_faces_plane(v, f, n, point - n * off)[:2]
    return v, f


def pinch(v, f, c, approach, closing) -> tuple[float, float, float] | None:
    """``(width, depth, middle)`` of the material a pinch at surface point ``c`` closes on: the part between
    planes ``PAD`` either side along the pad's width, from ``c`` to ``REACH`` deep along ``approach``,
    taken along ``closing`` as the stretch of solid that holds ``c`` (gaps narrower than a finger joined
    to it; ``middle``: where its middle is from ``c`` along ``closing``). ``None``: nothing there."""
    d, k = np.asarray(approach, float), np.asarray(closing, float)
    w = np.cross(d, k)
    cv, cf = _crop(v, f, c, [(d, 1e-4), (-d, REACH), (w, PAD), (-w, PAD), (k, 0.15), (-k, 0.15)])
    if len(cf) == 0:
        return None
    tri = cv[cf]
    along = (tri - c) @ k
    spans = np.stack([along.min(1), along.max(1)], 1)
    spans = spans[np.argsort(spans[:, 0])]
    lo, hi, merged = spans[0, 0], spans[0, 1], []
    for s0, s1 in spans[1:]:
        if s0 <= hi + FINGER:
            hi = max(hi, s1)
        else:
            merged.append((lo, hi))
            lo, hi = s0, s1
    merged.append((lo, hi))
    at = [m for m in merged if m[0] - 1e-4 <= 0.0 <= m[1] + 1e-4]
    if not at:
        return None
    lo, hi = at[0]
    inside = (((tri - c) @ k >= lo - 1e-9) & ((tri - c) @ k <= hi + 1e-9)).all(1)
    deep = float(((tri[inside] - c) @ d).max()) if inside.any() else 0.0
    return float(hi - lo), min(deep, REACH / 2), float(lo + hi) / 2


def _perps(a: np.ndarray) -> list[np.ndarray]:
    """Unit directions perpendicular to ``a``: the world axes projected, up first."""
    out: list[np.ndarray] = []
    for e in ((0, 0, 1), (1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, -1)):
        p = np.array(e, float) - (np.array(e, float) @ a) * a
        n = np.linalg.norm(p)
        if n > 0.5 and not any((np.abs(p / n - q) <= 1e-6 + 1e-5 * np.abs(q)).all() for q in out):  # np.allclose
            out.append(p / n)
    return out


def _fan(a: np.ndarray, count: int = 12) -> list[np.ndarray]:
    """``count`` unit directions perpendicular to ``a``, half a turn."""
    u = _perps(a)[0]
    w = _cross(a, u)
    return [math.cos(t) * u + math.sin(t) * w for t in np.arange(count) * math.pi / count]


def _rays(v: np.ndarray, d: np.ndarray, k: np.ndarray) -> list[np.ndarray]:
    """Ray origins for a pinch across ``k`` of the part's edge facing ``-d``: the middle of that edge's
    strip, then its ``+k`` and ``-k`` sides, each at the middle of the strip's width."""
    up, w = -d, _cross(d, k)
    top = float((v @ up).max())
    strip = v[v @ up >= top - 0.01]
    kc = strip @ k
    out = []
    for sel, kk in ((strip, 0.5 * (kc.min() + kc.max())), (strip[kc >= kc.max() - 0.005], kc.max() - 0.002),
                    (strip[kc <= kc.min() + 0.005], kc.min() + 0.002)):
        wc = sel @ w
        out.append(up * (top + 0.05) + k * kk + w * 0.5 * (wc.min() + wc.max()))
    return out


class _Part:
    """A part's mesh with its triangles, their bounds and edges, read once for all of its candidate pinches
    (and, per direction, what a ray reads of them)."""

    def __init__(self, v: np.ndarray, f: np.ndarray):
        self.v, self.f = v, f
        self.tri = v[f]
        self.lo, self.hi = self.tri.min(1), self.tri.max(1)
        self.edges = _edges(v, f)
        self._facing: dict[bytes, tuple] = {}

    def near(self, c: np.ndarray) -> np.ndarray:
        """Which faces are within 20 cm of ``c``: what a hand there can meet."""
        return ((self.lo <= c + 0.2) & (self.hi >= c - 0.2)).all(1)

    def cast(self, origin: np.ndarray, d: np.ndarray, rows=None) -> float | None:
        """:func:`raycast` on the part (on its faces ``rows`` only, where given)."""
        key = d.tobytes()
        if key not in self._facing:
            self._facing[key] = _facing(d, *self.edges[1:])
        edges, facing = self.edges, self._facing[key]
        if rows is not None:
            edges, facing = tuple(x[rows] for x in edges), tuple(x[rows] for x in facing)
        return raycast(self.v, self.f, origin, d, edges, facing)


_PINCH_OFFSETS = np.array([1e-4, REACH, PAD, PAD, 0.15, 0.15])  # pinch's half-spaces: how far each reaches past c


def _pinch_planes(c: np.ndarray, d: np.ndarray, k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The half-spaces :func:`pinch` crops to (``(P, 3)`` rows of ``c``, ``d``, ``k``), as
    :func:`~infmob_usd.clipping.clip` takes them: normals and points on the planes, the same floats."""
    w = np.cross(d, k)
    normals = np.stack([d, -d, w, -w, k, -k], 1)
    return normals, c[:, None, :] - normals * _PINCH_OFFSETS[:, None]


def _box_faces(lo, hi, centres, reaches) -> tuple[np.ndarray, np.ndarray]:
    """``(problem, face)`` of every face whose bounds ``lo``/``hi`` meet a problem's box (``centres`` ± ``reaches``,
    a margin wider than the slicer's tolerance: a face outside it has nothing left after the crop)."""
    hit = ((lo[None] <= (centres + reaches)[:, None]) & (hi[None] >= (centres - reaches)[:, None])).all(2)
    return np.nonzero(hit)


def _stretches(pid: np.ndarray, s0: np.ndarray, s1: np.ndarray, deep: np.ndarray, count: int) -> list:
    """:func:`pinch`'s reading of its cut triangles, for every problem at once: each triangle's span
    ``(s0, s1)`` along the closing axis and its deepest point along the approach, tagged with its problem
    ``pid``; per problem ``(width, depth, middle)`` or ``None``, the same floats as :func:`pinch`'s loop."""
    out: list = [None] * count
    if not len(pid):
        return out
    order = np.lexsort((s0, pid))  # each problem's spans by their start, as pinch sorts them
    pid, s0, s1, deep = pid[order], s0[order], s1[order], deep[order]
    n = len(pid)
    start = np.ones(n, bool)
    start[1:] = pid[1:] != pid[:-1]
    seg = np.cumsum(start) - 1
    # the highest end so far within the problem (= within the merged stretch, whose first span ends past
    # every span before it): a running maximum of ranks, the problem's index above them, so no float is redone
    by = np.argsort(s1, kind="stable")
    rank = np.empty(n, np.int64)
    rank[by] = np.arange(n)
    high = s1[by[np.maximum.accumulate(seg * n + rank) - seg * n]]
    brk = start.copy()
    brk[1:] |= s0[1:] > high[:-1] + FINGER  # a gap a finger fits: a new stretch
    first = np.flatnonzero(brk)
    lo, hi, of = s0[first], high[np.r_[first[1:] - 1, n - 1]], pid[first]
    holds = (lo - 1e-4 <= 0.0) & (0.0 <= hi + 1e-4)
    taken, at = np.unique(of[holds], return_index=True)  # each problem's first stretch that holds c
    if not len(taken):
        return out
    lo, hi = lo[holds][at], hi[holds][at]
    where = np.full(count, -1)
    where[taken] = np.arange(len(taken))
    row = where[pid]
    inside = (row >= 0) & (s0 >= lo[row] - 1e-9) & (s1 <= hi[row] + 1e-9)
    deepest = np.full(len(taken), -np.inf)
    np.maximum.at(deepest, row[inside], deep[inside])
    for p, a, b, dp in zip(taken.tolist(), lo.tolist(), hi.tolist(), deepest.tolist()):
        out[p] = (float(b - a), min(dp if dp > -np.inf else 0.0, REACH / 2), float(a + b) / 2)
    return out


def _pinches(part: _Part, problems: list) -> list:
    """:func:`pinch` of every ``(c, approach, closing)`` of ``problems`` on ``part``, the same floats, all cut
    at once (:func:`~infmob_usd.clipping.clip`)."""
    if not EXACT or not problems:  # this machine's BLAS rounds unlike the batched cut: one slicer call per plane
        return [pinch(part.v, part.f[part.near(c)], c, d, k) for c, d, k in problems]
    c, d, k = (np.array([p[i] for p in problems], float) for i in range(3))
    normals, origins = _pinch_planes(c, d, k)
    half = np.array([(REACH + 1e-4) / 2, PAD, 0.15])
    reach = np.abs(normals[:, ::2]).transpose(0, 2, 1) @ half + 1e-5
    pid, face = _box_faces(part.lo, part.hi, c + d * (REACH - 1e-4) / 2, reach)
    tri, pid = clip(part.tri[face], pid, normals, origins)
    rel = tri - c[pid][:, None, :]
    along = gemv_rows(rel, k[pid][:, None, :])  # pinch's (tri - c) @ k
    deep = gemv_rows(rel, d[pid][:, None, :]).max(1)
    return _stretches(pid, along.min(1), along.max(1), deep, len(problems))


def _tries(part: _Part, candidates: list) -> list:
    """:func:`_try` of each candidate ``(origin, d, closings)`` on ``part``, their pinches cut at once."""
    hits = []
    for origin, d, _ in candidates:
        origin, d = np.asarray(origin, float), np.asarray(d, float)
        t = part.cast(origin, d)
        hits.append(None if t is None else (origin + t * d, d))
    problems = [(i, k) for i, (hit, cand) in enumerate(zip(hits, candidates)) if hit is not None for k in cand[2]]
    got = _pinches(part, [(hits[i][0], hits[i][1], np.asarray(k, float)) for i, k in problems])
    best: dict[int, tuple] = {}
    for (i, k), g in zip(problems, got):
        if g is not None and 0.001 <= g[0] <= GRIP and (i not in best or g[0] < best[i][0]):
            best[i] = (*g, k)
    out = []
    for i, hit in enumerate(hits):
        if i not in best:
            out.append(None)
            continue
        (c, d), (width, depth, middle, k) = hit, best[i]
        # the fingers straddle the pinched stretch: the grasp on the surface over its middle
        mid = c + middle * k
        t = part.cast(mid - 0.05 * d, d, part.near(c))
        if t is not None and abs(t - 0.05) < REACH / 2:
            c = mid - 0.05 * d + t * d
        out.append(Grasp.make(c, d, k, width, depth))
    return out


def _try(v, f, origin, d, closings) -> Grasp | None:
    """The narrowest pinch across one of ``closings`` where a ray from ``origin`` along ``d`` meets the part."""
    return _tries(_Part(v, f), [(origin, d, closings)])[0]


def _candidates(v: np.ndarray, joint, pivot: np.ndarray):
    """``(ray origin, approach, closing directions)`` to try, most natural first (see the module)."""
    a = np.asarray(joint.axis, float)
    if joint.type == "prismatic":
        if action(joint) == "press":  # onto its face, along the way it presses
            yield from ((o, a, _fan(a)) for o in _rays(v, a, _perps(a)[0])[:1])
            faces = [-a]
        else:
            yield from ((o, -a, _fan(a)) for o in _rays(v, -a, _perps(a)[0])[:1])
            faces = []
        for u in _perps(a):  # an edge facing u pinched along the slide (a drawer front's top edge)
            yield from ((o, -u, [a]) for o in _rays(v, -u, a))
        for u in _perps(a):  # ... or across it
            yield from ((o, -u, [_cross(a, u)]) for o in _rays(v, -u, _cross(a, u)))
        for d in faces + [-a]:  # a rim from its end
            for u in _perps(a):
                yield from ((o, d, [u]) for o in _rays(v, d, u)[1:])
        yield from _sides(v, a)
        return
    rel = v - pivot
    radial = rel - np.outer(rel @ a, a)
    r = np.linalg.norm(radial, axis=1)
    if r.max() < KNOB_REACH:  # a knob: across its cap, from its free end
        along = rel @ a
        end = a if along.max() >= -along.min() else -a
        for e in (end, -end):  # the end farther from the pivot, else the other (a cap hinged at its top)
            yield from ((o, -e, _fan(a)) for o in _rays(v, -e, _perps(a)[0])[:1])
    e = radial[int(np.argmax(r))] / max(r.max(), 1e-9)
    # square to the part where it is nearly so: a leaf's far corner is off its mid-plane by its thickness
    e = next((q for q in _perps(a) if e @ q > SQUARE), e)
    n = _cross(a, e)
    for u in (e, n, -n, -e):  # the far edge first: across the leaf, then along the axis
        yield from ((o, -u, [_cross(a, u)]) for o in _rays(v, -u, _cross(a, u)))
        yield from ((o, -u, [a]) for o in _rays(v, -u, a))
    for d in (-a, a):
        yield from ((o, d, [n, e]) for o in _rays(v, d, n))
    yield from _sides(v, a)


def _sides(v: np.ndarray, a: np.ndarray):
    """Pinches of the part's sides at heights along ``a`` (a pole, a mug by its body or handle): from each
    side, across it, then along ``a``."""
    along = v @ a
    lo, hi = along.min(), along.max()
    for u in _perps(a):
        w = _cross(a, u)
        for frac in (0.5, 0.25, 0.75, 0.1, 0.9):
            s = lo + frac * (hi - lo)
            slab = v[np.abs(along - s) < 0.01]
            if len(slab):
                wc = slab @ w
                yield u * (float((slab @ u).max()) + 0.05) + a * s + w * 0.5 * (wc.min() + wc.max()), -u, [w, a]


TRIES = 12  # fitting pinches tried for one the neighbours leave free before the first is kept anyway


def derived_grasps(v: np.ndarray, f: np.ndarray, joint, pivot, blocked=None) -> list[Grasp]:
    """A grasp on a part that declares none, from its link's mesh ``(v, f)`` (link frame) and its joint
    (``pivot``: a point of its axis in the link frame): the first candidate (:func:`_candidates`) whose
    pinch needs at most :data:`GRIP` and whose fingers ``blocked(grasp)`` finds free (a list of the links in
    their way); else the first that fits, blocked. ``blocked`` may offer ``many(grasps)``: the lists of a
    batch at once."""
    part, first, fits = _Part(v, f), None, 0
    todo = _candidates(v, joint, np.asarray(pivot, float))
    # a part is mostly taken at its first candidate or at none: one alone, then the rest of them together
    for size in (1, 4, None):
        grasps = [g for g in _tries(part, list(itertools.islice(todo, size))) if g is not None]
        if blocked is None:
            if grasps:
                return grasps[:1]
            continue
        many = getattr(blocked, "many", None)
        ways = many(grasps[:TRIES - fits]) if many is not None else map(blocked, grasps)
        for g, way in zip(grasps, ways):
            if not way:
                return [g]
            first, fits = first or g, fits + 1
            if fits >= TRIES:
                return [first]
    return [first] if first is not None else []


class Neighbours:
    """The other links of an object at rest, in one link's frame: which of them a grasp's hand would meet
    (two finger boxes ``FINGER`` thick beside the pinched width, from 4 cm before the surface to ``depth``
    past it, a pad wide, and the hand's body behind them (:data:`PALM`), which may not meet the operated part
    itself either: it is then named among them; ``press``: the hand pushes with its fingers shut, so only the
    way in to the surface counts (one box two fingers wide)). ``meshes``: each link's ``_soup``, by name,
    where the caller has them already."""

    def __init__(self, obj, carrier, own: set[str], mesh=None, press: bool = False, meshes=None):
        self.press, self.own, self._seen = press, carrier.name, {}
        self._soups: list[tuple] = []  # (name, _soup in its link's frame, offset into the carrier's frame)
        if mesh is not None and len(mesh[1]):  # the part itself: only the hand's body may not meet it
            tri = mesh[0][mesh[1]]
            self._soups.append((carrier.name, (mesh[0], mesh[1], tri, tri.min(1), tri.max(1), mesh[0].min(0),
                                               mesh[0].max(0)), None))
        for link in obj.links:
            if link.dummy or link.name in own or not link.pieces:
                continue
            soup = meshes[link.name] if meshes is not None else _soup(link.pieces)
            self._soups.append((link.name, soup, link.origin - carrier.origin))
        # each link's bounds in the carrier's frame (a sum keeps the order of floats: bounds move with them)
        self.bounds = [(s[5], s[6]) if off is None else (s[5] + off, s[6] + off) for _, s, off in self._soups]
        self._moved: dict[int, tuple] = {}

    def mesh(self, m: int) -> tuple:
        """Link ``m``'s ``_soup`` moved into the carrier's frame (moved once, when a box first reaches it)."""
        if m not in self._moved:
            _, (lv, lf, tri, tlo, thi, lo, hi), off = self._soups[m]
            self._moved[m] = (lv, lf, tri, tlo, thi) if off is None else (lv + off, lf, tri + off, tlo + off,
                                                                         thi + off)
        return self._moved[m]

    def _boxes(self, g: Grasp, press: bool) -> list:
        """``(centre, half, axes, reach, own)`` of each box the hand fills (``own``: the part itself counts)."""
        p, d, k = (np.asarray(x) for x in (g.position, g.approach, g.closing))
        w = _cross(d, k)
        out = []
        for side in ((0.0,) if press else (1.0, -1.0, 0.0)):
            if press:
                centre, half = p - d * 0.0205, np.array([0.0195, FINGER, PAD])
            elif side == 0.0:  # the hand's body behind the fingers
                centre, half = p + d * (g.depth - (PALM[2] + PALM[3]) / 2), np.array([(PALM[3] - PALM[2]) / 2,
                                                                                      PALM[0] / 2, PALM[1] / 2])
            else:
                centre = p + d * (g.depth - 0.04) / 2 + k * side * (g.width / 2 + FINGER / 2)
                half = np.array([(g.depth + 0.04) / 2, FINGER / 2 - 1e-4, PAD])
            axes = np.stack([d, k, w])
            # the part itself counts for the hand's body and for the fingers beside the pinched stretch (the
            # stretch is free of the part by construction; in front of the surface a lid's rim, a seat's back
            # or the part's own overhang may stand in the fingers' way in)
            out.append((centre, half, axes, np.abs(axes).T @ half, not press))
        return out

    def _one(self, g: Grasp, press: bool) -> list[str]:
        hit = set()
        for centre, half, axes, reach, own in self._boxes(g, press):
            for m, ((name, _, _), (lo, hi)) in enumerate(zip(self._soups, self.bounds)):
                if (name == self.own and not own) or name in hit:  # fingers close on the part
                    continue
                if (lo > centre + reach).any() or (hi < centre - reach).any():
                    continue
                lv, lf, _, tlo, thi = self.mesh(m)
                near = ((tlo <= centre + reach) & (thi >= centre - reach)).all(1)  # triangles whose box meets it
                if not near.any():
                    continue
                planes = [(s * e, h) for e, h in zip(axes, half) for s in (1.0, -1.0)]
                if len(_crop(lv, lf[near], centre, planes)[1]):
                    hit.add(name)
        return sorted(hit)

    def many(self, grasps: list[Grasp], press: bool | None = None) -> list[list[str]]:
        """The links in the hand's way, per grasp: :meth:`__call__` of each, all cut at once."""
        press = self.press if press is None else press
        todo = [g for g in dict.fromkeys(grasps) if (g, press) not in self._seen]
        if not EXACT or not self._soups:
            self._seen.update({(g, press): self._one(g, press) for g in todo})
        elif todo:
            self._seen.update(zip(((g, press) for g in todo), self._cut(todo, press)))
        return [self._seen[g, press] for g in grasps]

    def _cut(self, grasps: list[Grasp], press: bool) -> list[list[str]]:
        boxes = [(gi, b) for gi, g in enumerate(grasps) for b in self._boxes(g, press)]
        centre, half, axes, reach = (np.array([b[i] for _, b in boxes]) for i in range(4))
        top, bottom = centre + reach, centre - reach
        own = np.array([b[4] for _, b in boxes])
        pid, tri, count = [], [], len(self._soups)
        for m, ((name, _, _), (lo, hi)) in enumerate(zip(self._soups, self.bounds)):  # links a box reaches
            meet = ~((lo > top).any(1) | (hi < bottom).any(1)) & (own | (name != self.own))
            if meet.any():
                which = np.flatnonzero(meet)
                _, _, mt, tlo, thi = self.mesh(m)
                b, f = np.nonzero(((tlo <= top[which, None]) & (thi >= bottom[which, None])).all(2))
                pid.append(which[b] * count + m)
                tri.append(mt[f])
        if not pid:
            return [[] for _ in grasps]
        normals = np.stack([s * axes[:, i] for i in range(3) for s in (1.0, -1.0)], 1)
        origins = centre[:, None, :] - normals * np.repeat(half, 2, axis=1)[:, :, None]
        _, pid = clip(np.concatenate(tri), np.concatenate(pid), np.repeat(normals, count, axis=0),
                      np.repeat(origins, count, axis=0))
        hit: list[set] = [set() for _ in grasps]
        for p in np.unique(pid).tolist():
            hit[boxes[p // count][0]].add(self._soups[p % count][0])
        return [sorted(h) for h in hit]

    def __call__(self, g: Grasp, press: bool | None = None) -> list[str]:
        """The links in the hand's way (``press``: as the hand presses; default: as made)."""
        return self.many([g], press)[0]


def rim_grasp(pieces, axis) -> Grasp | None:
    """A lid's edge grasp, for the part that knows it is a lid (``categories/parts/lids.py``): its outer edge
    pinched along ``axis`` (the way it lifts) from each side in turn, else its rim pinched across from above;
    ``None`` if no pinch there needs at most :data:`GRIP`."""
    v, f = _mesh(pieces)
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    for u in _perps(a):
        for o in _rays(v, -u, a):
            g = _try(v, f, o, -u, [a])
            if g is not None:
                return g
    for u in _perps(a):
        for o in _rays(v, -a, u)[1:]:
            g = _try(v, f, o, -a, [u])
            if g is not None:
                return g
    return None


def part_class(joint, label: str, v: np.ndarray, pivot, handle: bool) -> str:
    """The GAPartNet class of the moving part: from the joint's type and role, the part's label
    ``handle``, and its shape (a part thinnest along z at rest is a lid, else a door or drawer)."""
    a = np.asarray(joint.axis, float)
    thin_z = int(np.argmin(np.ptp(v, axis=0))) == 2
    if joint.type == "prismatic":
        if action(joint) == "press":
            return "slider_button"
        vertical = abs(a[2]) > 0.7
        return "slider_lid" if vertical and (thin_z or joint.role in ("lid", "lift_off")) else "slider_drawer"
    if label == "handle":
        return "hinge_handle"
    rel = v - np.asarray(pivot, float)
    reach = np.linalg.norm(rel - np.outer(rel @ a, a), axis=1).max()
    if joint.role in ("knob", "button", "lever", "toggle") or reach < KNOB_REACH:
        return "hinge_knob"
    return "hinge_lid" if thin_z else "hinge_door"


def quat_wxyz(rot) -> list[float]:
    """The unit quaternion (w, x, y, z) of a rotation matrix, w >= 0."""
    m = np.asarray(rot, float)
    w = math.sqrt(max(0.0, 1.0 + m[0, 0] + m[1, 1] + m[2, 2])) / 2
    x = math.copysign(math.sqrt(max(0.0, 1.0 + m[0, 0] - m[1, 1] - m[2, 2])) / 2, m[2, 1] - m[1, 2])
    y = math.copysign(math.sqrt(max(0.0, 1.0 - m[0, 0] + m[1, 1] - m[2, 2])) / 2, m[0, 2] - m[2, 0])
    z = math.copysign(math.sqrt(max(0.0, 1.0 - m[0, 0] - m[1, 1] + m[2, 2])) / 2, m[1, 0] - m[0, 1])
    q = np.array([w, x, y, z])
    return (q / np.linalg.norm(q)).tolist()


def grasp_rotation(g: Grasp) -> np.ndarray:
    """A grasp frame's axes as matrix columns: z along the approach, y along the closing axis (the
    Panda hand's own frame: it closes its fingers along its y and reaches along its z)."""
    z, y = np.asarray(g.approach), np.asarray(g.closing)
    return np.column_stack([_cross(y, z), y, z])


def _fixed_under(obj, names) -> set[str]:
    """``names`` and every link fixed under them."""
    out, stack = set(names), list(names)
    while stack:
        n = stack.pop()
        for j in obj.joints:
            if j.parent == n and j.type == "fixed" and j.child not in out:
                out.add(j.child)
                stack.append(j.child)
    return out


def _carried(obj, carrier) -> tuple[np.ndarray, np.ndarray, list[Grasp], set[str]]:
    """The mesh and the declared grasps of a link and of every link fixed to it, in its frame, and the names
    of those links."""
    links = {link.name: link for link in obj.links}
    names, stack = [carrier.name], [carrier.name]
    while stack:
        n = stack.pop()
        for j in obj.joints:
            if j.parent == n and j.type == "fixed":
                names.append(j.child)
                stack.append(j.child)
    pieces = [p.translated(links[n].origin - carrier.origin) if n != carrier.name else p
              for n in names for p in links[n].pieces]
    v, f = _mesh(pieces) if pieces else (np.zeros((0, 3)), np.zeros((0, 3), int))
    # a handle first: it is what the part is made to be taken by (a lid's knob before its rim)
    return v, f, sorted((g for p in pieces for g in p.grasps), key=lambda g: g.handle_class is None), set(names)


def _range(joint) -> tuple[float, float]:
    """``(rest, open)``: rest is 0 (the closed state where the joint has one); open the far limit that way."""
    if joint.type == "continuous":
        return 0.0, TURN
    return 0.0, float(joint.upper if joint.upper > 0 else joint.lower)


def _path(obj, joint, carrier: str, point) -> list[list[float]]:
    rest, opened = _range(joint)
    p = np.append(np.asarray(point, float), 1.0)
    # obj.poses()'s products for the carrier alone: along its chain from the root, in the same order
    parent = {j.child: j for j in obj.joints}
    chain, name = [], carrier
    while name in parent:
        chain.append(parent[name])
        name = parent[name].parent
    chain.reverse()
    origin = {link.name: link.origin for link in obj.links}
    first = next((i for i, j in enumerate(chain) if j.name == joint.name), len(chain))
    fixed = _steps(_move(origin[obj.links[0].name]), chain[:first], origin, joint.name, 0.0)
    out = []
    for i in range(PATH_STEPS + 1):
        pose = _steps(fixed, chain[first:], origin, joint.name, float(rest + (opened - rest) * i / PATH_STEPS))
        out.append((pose @ p)[:3].tolist())
    return out


def _move(t) -> np.ndarray:
    m = np.eye(4)
    m[:3, 3] = t
    return m


def _steps(pose: np.ndarray, chain, origin: dict, name: str, value: float) -> np.ndarray:
    """``pose`` carried down ``chain`` (joints, parent first) with joint ``name`` at ``value``, the rest at 0."""
    for j in chain:
        pose = pose @ _move(origin[j.child] - origin[j.parent]) @ motion(j.type, j.axis, value if j.name == name
                                                                            else 0.0)
    return pose


def _direction(joint, g: Grasp, pivot) -> list[float]:
    """Unit, link frame: which way the grasp point moves as the joint leaves rest towards open."""
    rest, opened = _range(joint)
    a = np.asarray(joint.axis, float) * math.copysign(1.0, opened - rest)
    if joint.type == "prismatic":
        return a.tolist()
    t = _cross(a, np.asarray(g.position) - np.asarray(pivot, float))
    if np.linalg.norm(t) < 1e-6:  # on the axis: a finger's way round
        t = _cross(a, g.closing)
    return (t / np.linalg.norm(t)).tolist()


def _grasp_json(g: Grasp, blocked) -> dict:
    return {"position": list(g.position), "approach": list(g.approach), "closing": list(g.closing),
            "width": g.width, "depth": g.depth, "blocked_by": blocked(g)}


def _gates(obj, joint) -> list[str]:
    """The parts that must be open before ``joint`` moves, nearest first (:func:`~.joints.gate_chain`: tines
    on a rack that needs the dishwasher's door open)."""
    return gate_chain(joint.requires_open, [(j.group, j.requires_open) for j in obj.joints])


def target(obj, joint, groups: dict[str, list[str]], meshes=None) -> dict:
    """The annotation of one operated joint (the fields of ``infmob-annotations/1``, docs/format.md);
    ``meshes``: every link's ``_soup`` by name, where the caller has them already."""
    carrier = obj.link(joint.group)
    v, f, declared, own = _carried(obj, carrier)
    pivot = np.asarray(joint.origin, float) - carrier.origin
    # the gate parts (a door before the rack behind it, the rack before the tines on it) are open when this
    # joint is operated: not in the way
    gates = _gates(obj, joint)
    gate = [j.child for j in obj.joints if j.group in gates]
    blocked = Neighbours(obj, carrier, own | _fixed_under(obj, gate), (v, f), action(joint) == "press", meshes)
    grasps = declared or (derived_grasps(v, f, joint, pivot, blocked) if len(f) else [])
    if declared and len(f) and all(blocked(g) for g in declared):
        # the part's own holds all meet a neighbour (a cap's side pinch reaching below it onto the bottle's
        # shoulder): a hold from the geometry that the neighbours leave free comes after them
        grasps = declared + [g for g in derived_grasps(v, f, joint, pivot, blocked) if not blocked(g)]
    handle = next((g for g in grasps if g.handle_class is not None), None)
    if handle is not None and handle.box is not None:
        centre, size, rot = handle.box
        box = {"center": list(centre), "size": list(size), "quat_wxyz": quat_wxyz(rot)}
    else:
        lo, hi = (v.min(0), v.max(0)) if len(v) else (np.zeros(3), np.zeros(3))
        box = {"center": ((lo + hi) / 2).tolist(), "size": (hi - lo).tolist(), "quat_wxyz": [1.0, 0.0, 0.0, 0.0]}
    rest, opened = _range(joint)
    return {
        "joint": joint.name, "joint_type": joint.type, "link": carrier.name,
        "part_class": part_class(joint, carrier.label, v, pivot, handle is not None) if len(v) else "hinge_knob",
        "handle_class": None if handle is None else handle.handle_class,
        "box": box,
        "grasps": [_grasp_json(g, blocked) for g in grasps],
        "grasp_source": "part" if declared else "geometry",
        "action": action(joint),
        "direction": _direction(joint, grasps[0], pivot) if grasps else None,
        "rest": rest, "open": opened,
        "open_threshold": OPEN_THRESHOLD, "closed_threshold": CLOSED_THRESHOLD,
        "path": _path(obj, joint, carrier.name, grasps[0].position) if grasps else [],
        "requires_open": [n for g in gates for n in groups.get(g, []) if n != joint.name],
        "requires_closed": [n for g in joint.requires_closed for n in groups.get(g, [])],
    }


def annotate(obj) -> list[dict]:
    """Every operated joint's target (:func:`target`), in joint order; pure function of the object."""
    groups: dict[str, list[str]] = {}
    for j in obj.joints:
        if j.movable:
            groups.setdefault(j.group, []).append(j.name)
    meshes = {link.name: _soup(link.pieces) for link in obj.links if not link.dummy and link.pieces}
    return [target(obj, j, groups, meshes) for j in obj.joints if operated(j, obj.joints)]


def document(targets: list[dict]) -> dict:
    """The ``annotations.json`` document of an object's targets."""
    return {"format": FORMAT, "units": UNITS,
            "conventions": {"open_threshold": "ManiSkill OpenCabinetDrawer: open when"
                                              " (q - rest) / (open - rest) >= open_threshold",
                            "closed_threshold": "RoboCasa fixture is_closed: closed when"
                                                " (q - rest) / (open - rest) <= closed_threshold",
                            "grasp_frame": "z along approach, y along closing (the Panda hand's frame)"},
            "targets": targets}
