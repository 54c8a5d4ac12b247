"""Interaction annotations: for every joint a person operates, where and how a gripper opens it.

Parts that know their grasp carry it (:class:`~infmob_usd.grasps.Grasp` on their pieces: a handle, a
knob, a dial, a button, a lever); every other operated part gets a grasp derived here from its link's
geometry (:func:`derived_grasps`): the free edge of a door or lid pinched across its thickness, a drawer
front's top edge, a rim from above, a small turning part across its cap. :func:`annotate` builds the
targets that the writers emit (``annotations.json``, ``metadata.json`` "interaction", grasp Xforms in the
USD); the schema is ``infmob-annotations/1`` (docs/format.md).
"""

from __future__ import annotations

import math

import numpy as np
from trimesh.intersections import slice_faces_plane

from .grasps import Grasp

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


def raycast(v: np.ndarray, f: np.ndarray, origin, direction) -> float | None:
    """Distance along ``direction`` (unit) from ``origin`` to the first triangle hit, or ``None``
    (Moeller-Trumbore over every triangle)."""
    o, d = np.asarray(origin, float), np.asarray(direction, float)
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    e1, e2 = b - a, c - a
    p = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, p)
    ok = np.abs(det) > 1e-12
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = o - a
    u = np.einsum("ij,ij->i", s, p) * inv
    q = np.cross(s, e1)
    w = (q @ d) * inv
    t = np.einsum("ij,ij->i", e2, q) * inv
    hit = ok & (u >= -1e-9) & (w >= -1e-9) & (u + w <= 1 + 1e-9) & (t > 1e-9)
    return float(t[hit].min()) if hit.any() else None


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
        if n > 0.5 and not any(np.allclose(p / n, q, atol=1e-6) for q in out):
            out.append(p / n)
    return out


def _fan(a: np.ndarray, count: int = 12) -> list[np.ndarray]:
    """``count`` unit directions perpendicular to ``a``, half a turn."""
    u = _perps(a)[0]
    w = np.cross(a, u)
    return [math.cos(t) * u + math.sin(t) * w for t in np.arange(count) * math.pi / count]


def _rays(v: np.ndarray, d: np.ndarray, k: np.ndarray) -> list[np.ndarray]:
    """Ray origins for a pinch across ``k`` of the part's edge facing ``-d``: the middle of that edge's
    strip, then its ``+k`` and ``-k`` sides, each at the middle of the strip's width."""
    up, w = -d, np.cross(d, k)
    top = float((v @ up).max())
    strip = v[v @ up >= top - 0.01]
    kc = strip @ k
    out = []
    for sel, kk in ((strip, 0.5 * (kc.min() + kc.max())), (strip[kc >= kc.max() - 0.005], kc.max() - 0.002),
                    (strip[kc <= kc.min() + 0.005], kc.min() + 0.002)):
        wc = sel @ w
        out.append(up * (top + 0.05) + k * kk + w * 0.5 * (wc.min() + wc.max()))
    return out


def _try(v, f, origin, d, closings) -> Grasp | None:
    """The narrowest pinch across one of ``closings`` where a ray from ``origin`` along ``d`` meets the part."""
    t = raycast(v, f, origin, d)
    if t is None:
        return None
    c = origin + t * d
    tri = v[f]
    near = (v, f[((tri.min(1) <= c + 0.2) & (tri.max(1) >= c - 0.2)).all(1)])  # what a hand there can meet
    best = None
    for k in closings:
        got = pinch(*near, c, d, k)
        if got is not None and 0.001 <= got[0] <= GRIP and (best is None or got[0] < best[0]):
            best = (*got, k)
    if best is None:
        return None
    width, depth, middle, k = best
    # the fingers straddle the pinched stretch: the grasp on the surface over its middle
    mid = c + middle * k
    t = raycast(*near, mid - 0.05 * d, d)
    if t is not None and abs(t - 0.05) < REACH / 2:
        c = mid - 0.05 * d + t * d
    return Grasp.make(c, d, k, width, depth)


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
            yield from ((o, -u, [np.cross(a, u)]) for o in _rays(v, -u, np.cross(a, u)))
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
    n = np.cross(a, e)
    for u in (e, n, -n, -e):  # the far edge first: across the leaf, then along the axis
        yield from ((o, -u, [np.cross(a, u)]) for o in _rays(v, -u, np.cross(a, u)))
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
        w = np.cross(a, u)
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
    their way); else the first that fits, blocked."""
    first, fits = None, 0
    for origin, d, closings in _candidates(v, joint, np.asarray(pivot, float)):
        g = _try(v, f, np.asarray(origin, float), np.asarray(d, float), closings)
        if g is None:
            continue
        if blocked is None or not blocked(g):
            return [g]
        first, fits = first or g, fits + 1
        if fits >= TRIES:
            break
    return [first] if first is not None else []


class Neighbours:
    """The other links of an object at rest, in one link's frame: which of them a grasp's hand would meet
    (two finger boxes ``FINGER`` thick beside the pinched width, from 4 cm before the surface to ``depth``
    past it, a pad wide, and the hand's body behind them (:data:`PALM`), which may not meet the operated part
    itself either: it is then named among them; for a press, the shut fingers' way in)."""

    def __init__(self, obj, carrier, own: set[str], mesh=None):
        self.meshes = []
        if mesh is not None and len(mesh[1]):  # the part itself: only the hand's body may not meet it
            tri = mesh[0][mesh[1]]
            self.meshes.append((carrier.name, mesh[0], mesh[1], tri.min(1), tri.max(1), mesh[0].min(0),
                                mesh[0].max(0)))
        self.own = carrier.name
        for link in obj.links:
            if link.dummy or link.name in own or not link.pieces:
                continue
            lv, lf = _mesh(link.pieces)
            lv = lv + (link.origin - carrier.origin)
            tri = lv[lf]
            self.meshes.append((link.name, lv, lf, tri.min(1), tri.max(1), lv.min(0), lv.max(0)))

    def __call__(self, g: Grasp, press: bool = False) -> list[str]:
        """The links in the hand's way; ``press``: the hand pushes with its fingers shut, so only the way
        in to the surface counts (one box two fingers wide)."""
        p, d, k = (np.asarray(x) for x in (g.position, g.approach, g.closing))
        w = np.cross(d, k)
        hit = set()
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
            reach = np.abs(axes).T @ half
            for name, lv, lf, tlo, thi, lo, hi in self.meshes:
                if (name == self.own and (press or side != 0.0)) or name in hit:  # fingers close on the part
                    continue
                if (lo > centre + reach).any() or (hi < centre - reach).any():
                    continue
                near = ((tlo <= centre + reach) & (thi >= centre - reach)).all(1)  # triangles whose box meets it
                if not near.any():
                    continue
                planes = [(s * e, h) for e, h in zip(axes, half) for s in (1.0, -1.0)]
                if len(_crop(lv, lf[near], centre, planes)[1]):
                    hit.add(name)
        return sorted(hit)


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
    return np.column_stack([np.cross(y, z), y, z])


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
    out = []
    for i in range(PATH_STEPS + 1):
        pose = obj.poses({joint.name: rest + (opened - rest) * i / PATH_STEPS})[carrier]
        out.append((pose @ p)[:3].tolist())
    return out


def _direction(joint, g: Grasp, pivot) -> list[float]:
    """Unit, link frame: which way the grasp point moves as the joint leaves rest towards open."""
    rest, opened = _range(joint)
    a = np.asarray(joint.axis, float) * math.copysign(1.0, opened - rest)
    if joint.type == "prismatic":
        return a.tolist()
    t = np.cross(a, np.asarray(g.position) - np.asarray(pivot, float))
    if np.linalg.norm(t) < 1e-6:  # on the axis: a finger's way round
        t = np.cross(a, g.closing)
    return (t / np.linalg.norm(t)).tolist()


def _grasp_json(g: Grasp, blocked) -> dict:
    return {"position": list(g.position), "approach": list(g.approach), "closing": list(g.closing),
            "width": g.width, "depth": g.depth, "blocked_by": blocked(g)}


def target(obj, joint, groups: dict[str, list[str]]) -> dict:
    """The annotation of one operated joint (the fields of ``infmob-annotations/1``, docs/format.md)."""
    carrier = obj.link(joint.group)
    v, f, declared, own = _carried(obj, carrier)
    pivot = np.asarray(joint.origin, float) - carrier.origin
    # the gate part (a door before the rack behind it) is open when this joint is operated: not in the way
    gate = [j.child for j in obj.joints if j.group == joint.requires_open] if joint.requires_open else []
    neighbours, press = Neighbours(obj, carrier, own | _fixed_under(obj, gate), (v, f)), action(joint) == "press"

    def blocked(g: Grasp) -> list[str]:
        return neighbours(g, press)

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
        "requires_open": [n for n in groups.get(joint.requires_open, []) if n != joint.name]
        if joint.requires_open else [],
        "requires_closed": [n for g in joint.requires_closed for n in groups.get(g, [])],
    }


def annotate(obj) -> list[dict]:
    """Every operated joint's target (:func:`target`), in joint order; pure function of the object."""
    groups: dict[str, list[str]] = {}
    for j in obj.joints:
        if j.movable:
            groups.setdefault(j.group, []).append(j.name)
    return [target(obj, j, groups) for j in obj.joints if operated(j, obj.joints)]


def document(targets: list[dict]) -> dict:
    """The ``annotations.json`` document of an object's targets."""
    return {"format": FORMAT, "units": UNITS,
            "conventions": {"open_threshold": "ManiSkill OpenCabinetDrawer: open when"
                                              " (q - rest) / (open - rest) >= open_threshold",
                            "closed_threshold": "RoboCasa fixture is_closed: closed when"
                                                " (q - rest) / (open - rest) <= closed_threshold",
                            "grasp_frame": "z along approach, y along closing (the Panda hand's frame)"},
            "targets": targets}
