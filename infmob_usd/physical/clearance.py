"""Joint limits from clearance: each joint's sweep alone, then every joint at once."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..blueprint import descendants
from ..joints import closed_excludes, one_mode
from .gates import gate_names
from .hulls import CLEARANCE, _boxes_meet, _hits, _Obstacles, _solid_hulls
from .sweep import _Moving, _parent_limit, _sweep_limit

KEEP = 0.75
"""The least share of its range a part keeps when it gives way to another part's sweep from the
all-open state (:func:`clearance_limits`, step 3); below it the two are ordered instead
(``requires_closed``)."""

ALL_FRACTIONS = (0.5, 1.0)
"""The combined states the validators sample: every joint at once at 50 % and 100 % of its
range (continuous joints at f pi), prerequisites fully open."""


class _Clearance:
    """What the passes of :func:`clearance_limits` share: the solid hulls, the movable joints and
    their current limits, the subtree each moves, the ``requires_open`` gates, and caches of
    posed links, scenes and pair contacts (the search revisits states)."""

    def __init__(self, obj):
        self.obj = obj
        self.hulls = _solid_hulls(obj)
        self.movable = [j for j in obj.joints if j.movable]
        self.limits = {j.name: (float(j.lower), float(j.upper)) for j in self.movable}
        self.groups = groups = {}
        for j in self.movable:
            groups.setdefault(j.group, []).append(j)
        # joint -> the parts (groups) that must be closed before it moves (step 3)
        self.closed: dict[str, set[str]] = {j.name: set(getattr(j, "requires_closed", ()))
                                            for j in self.movable}
        self.gates = {j.name: gate_names(j, groups) for j in self.movable if j.requires_open}
        self.gate_of_someone = {name for names in self.gates.values() for name in names}
        # joint -> the other modes of its part that are at rest while it is open (JointSpec.exclusive)
        self.excludes = {j.name: tuple(getattr(j, "excludes", ())) for j in self.movable}
        for name, held in closed_excludes([(j.name, j.group, j.requires_closed) for j in self.movable]).items():
            self.excludes[name] += tuple(held)  # parts that require each other closed: never open together
        self.order = [j.name for j in self.movable]
        self.by_name = {link.name: link for link in obj.links}
        self.into = {j.child: j for j in obj.joints}
        self.subtree = {j.name: descendants(obj.joints, j.child) for j in self.movable}
        self.by_joint = {j.name: j for j in self.movable}
        self.cache: dict = {}
        self.scenes: dict = {}
        self.posed: dict = {}
        self.hull_counts = [len(hs) for hs in self.hulls.values()]
        self.hull_world: dict = {}  # (hull, exact pose) -> world points
        # link pair at exact poses, margin -> whether they meet: the search revisits states in which
        # most links have not moved (a result depends on the two links' posed hulls alone; an exact
        # repeat reads the same cached points, normals and solids as the first time)
        self.met: dict[tuple, bool] = {}

    def poses_at(self, q):
        """``obj.poses(q)``, computed once per state (the search revisits states; callers only read)."""
        key = tuple((k, float(v).hex()) for k, v in sorted(q.items()))
        if key not in self.posed:
            self.posed[key] = self.obj.poses(q)
        return self.posed[key]

    def real_parent(self, j):
        p = j.parent
        while self.by_name[p].dummy:
            p = self.into[p].parent
        return p

    def scene(self, q):
        """Every link posed at ``q``, and all their hulls as obstacles (shared by the joints that
        sweep in this state)."""
        key = tuple(sorted(q.items()))
        if key not in self.scenes:
            poses = self.poses_at(q)
            self.scenes[key] = (poses, _Obstacles(list(self.hulls), self.hulls, poses, self.cache))
        return self.scenes[key]

    def _setup(self, j, q, only: set | None):
        """What a sweep of ``j`` from its value in ``q`` (default 0) needs: the hulls it moves, the
        obstacles, which of them it may not enter (every link but its parent, only the links
        ``only`` if given) and its parent (none if ``only`` is given); None if it moves nothing."""
        hulls = self.hulls
        moving = [h for n in sorted(self.subtree[j.name]) for h in hulls.get(n, [])]
        if not moving:
            return None
        parent = self.real_parent(j)
        poses, obstacles = self.scene(q)
        if self.limits[j.name] == (0.0, 0.0):
            return None
        # per obstacle hull (the links' hulls in ``hulls`` order): not moved by j, not its parent
        allowed = np.repeat([n not in self.subtree[j.name] and n != parent and (only is None or n in only)
                             for n in hulls], self.hull_counts)
        below = _Obstacles([parent] if parent in hulls and only is None else [], hulls, poses, self.cache)
        return _Moving(j, moving, poses, self.hull_world), obstacles, allowed, below

    def blocks(self, j, q, only: set | None = None) -> list[tuple[int, float, str]]:
        """Where each side of ``j``'s range stops when swept from 0 with the other joints at ``q``
        (which leaves ``j`` at 0): :func:`_sweep_limit` against every link but its parent (only
        the links ``only`` if given), :func:`_parent_limit` against the parent (unless ``only``
        is given). ``[(side, value, link hit)]`` for each side (1 upper, 0 lower) that stops
        short of its limit."""
        setup = self._setup(j, q, only)
        if setup is None:
            return []
        moving, obstacles, allowed, below = setup  # the moving hulls shared by both sides
        out = []
        for side in (1, 0):
            limit = self.limits[j.name][side]
            if limit == 0:
                continue
            value, hit = _sweep_limit(moving, limit, obstacles, allowed)
            value, hit = min((value, hit), _parent_limit(moving, value, below), key=lambda t: abs(t[0]))
            if value != limit:
                out.append((side, value, hit))
        return out

    def closing(self, j, q, only: set | None = None) -> tuple[float, str] | None:
        """Where ``j`` stops when driven from its value in ``q`` to its lower limit, the other
        joints at ``q`` (as :meth:`blocks`, the sweep starting there): ``(value, link hit)``, or
        None if it gets there."""
        start = q.get(j.name, 0.0)
        travel = self.limits[j.name][0] - start
        setup = self._setup(j, q, only) if travel != 0 else None
        if setup is None:
            return None
        hit = self.start_hit(j, q, only)
        if hit:
            return start, hit
        moving, obstacles, allowed, below = setup
        value, hit = _sweep_limit(moving, travel, obstacles, allowed)
        value, hit = min((value, hit), _parent_limit(moving, value, below), key=lambda t: abs(t[0]))
        return (start + value, hit) if value != travel else None

    def start_hit(self, j, q, only: set | None = None) -> str:
        """A link (not its parent; among ``only`` if given) that the subtree ``j`` moves overlaps
        at ``q`` although the two are apart at rest; "" if none. The sweeps leave out hull pairs
        that overlap where they start, so a closing sweep that starts inside a part open next
        to it (a sash tilted into its open neighbour) would pass unseen."""
        moved = self.subtree[j.name]
        parent = self.real_parent(j)
        pairs = {tuple(sorted((a, b))) for a in moved if a in self.hulls for b in self.hulls
                 if b not in moved and b != parent and (only is None or b in only)}
        if not pairs:
            return ""
        met = self.contacts(self.poses_at(q), pairs) - self.contacts(self.poses_at({}), pairs)
        return min((b if a in moved else a) for a, b in met) if met else ""

    def shorten(self, j, side: int, value: float, hit: str) -> None:
        from ..errors import ModelError

        if abs(value) < 1e-6:
            raise ModelError(f"joint {j.name} cannot move {j.child!r} at all without meeting"
                             f" {hit!r} (parent {self.real_parent(j)!r}); leave a gap between them")
        lo, hi = self.limits[j.name]
        self.limits[j.name] = (lo, value) if side == 1 else (value, hi)

    def sweep(self, j, q) -> None:
        """Shorten each side of ``j``'s range to what it sweeps from 0 with the other joints at
        ``q`` (:meth:`blocks`)."""
        for side, value, hit in self.blocks(j, q):
            self.shorten(j, side, value, hit)

    def sweep_alone(self) -> None:
        """Step 1: each joint alone, swept from rest (its gates open), in tree order."""
        for j in self.movable:
            if j.type in ("revolute", "prismatic"):
                self.sweep(j, {g: self.limits[g][1] for g in self.gates.get(j.name, [])})

    def pairs(self) -> dict[tuple[str, str], list]:
        """Link pairs that some joint moves apart from each other (not parent and child): the
        joints between them."""
        solid = list(self.hulls)
        chain = {frozenset((self.real_parent(j), j.child)) for j in self.movable if not self.by_name[j.child].dummy}
        path = {}
        for i, a in enumerate(solid):
            for b in solid[i + 1:]:
                between = [j for j in self.movable if (a in self.subtree[j.name]) != (b in self.subtree[j.name])]
                if between and frozenset((a, b)) not in chain:
                    path[tuple(sorted((a, b)))] = between
        return path

    def _meet(self, obstacles: _Obstacles, ka: int, kb: int, starts: list, d: float) -> bool:
        """Whether the hulls of links ``ka`` and ``kb`` (their hulls' rows ``starts[k]`` on in
        ``obstacles``), one grown by ``d``, overlap."""
        lo, hi = obstacles.lo, obstacles.hi
        a0, a1, b0, b1 = starts[ka], starts[ka + 1], starts[kb], starts[kb + 1]
        near = _boxes_meet(lo[a0:a1, None], hi[None, b0:b1] + CLEARANCE, lo[None, b0:b1], hi[a0:a1, None] + CLEARANCE)
        for u, v in zip(*np.nonzero(near)):
            # the exact hull of the first link's hull is the one obstacles.solid(a0 + u) keeps
            if _hits(obstacles.world[a0 + u], obstacles.normals(a0 + u), d, obstacles, b0 + v,
                     self.cache, ("solid", 0.0) + obstacles.keys[a0 + u]):
                return True
        return False

    def contacts(self, poses, pairs, margin=0.0) -> set:
        """Link pairs among ``pairs`` whose hulls, one grown by ``margin`` (a number, or a dict
        pair -> margin), overlap at ``poses``."""
        out = set()
        todo = []
        exact = {}  # link -> its exact pose's bytes
        for pair in sorted(tuple(sorted(p)) for p in pairs):
            d = margin if not isinstance(margin, dict) else margin[pair]
            for n in pair:
                if n not in exact:
                    exact[n] = poses[n].tobytes()
            seen = self.met.get((pair, exact[pair[0]], exact[pair[1]], d))
            if seen is None:
                todo.append((pair, d))
            elif seen:
                out.add(pair)
        if not todo:
            return out
        names = sorted({n for pair, _ in todo for n in pair})
        obstacles = _Obstacles(names, self.hulls, poses, self.cache)
        index = {n: k for k, n in enumerate(names)}
        starts = np.cumsum([0] + [len(self.hulls[n]) for n in names]).tolist()
        # link boxes first: hull boxes of two links whose boxes are not near are not near
        # either (the same comparisons, monotone), so only near link pairs compare hull boxes
        link_lo = np.minimum.reduceat(obstacles.lo, starts[:-1], axis=0)
        link_hi = np.maximum.reduceat(obstacles.hi, starts[:-1], axis=0)
        link_near = _boxes_meet(link_lo[:, None], link_hi[None] + CLEARANCE, link_lo[None],
                                link_hi[:, None] + CLEARANCE)
        for pair, d in todo:
            ka, kb = index[pair[0]], index[pair[1]]  # ka < kb: the hulls of pair[0] come first
            hit = bool(link_near[ka, kb]) and self._meet(obstacles, ka, kb, starts, d)
            self.met[pair, exact[pair[0]], exact[pair[1]], d] = hit
            if hit:
                out.add(pair)
        return out

    def state(self, f, scale=None):
        """Link poses with every joint at ``f`` of its range (the joints ``scale[0]`` with limits
        scaled by ``scale[1]``), an exclusive joint's first mode only (:func:`~..joints.one_mode`:
        a tilt-and-turn sash is never tilted and turned at once), gates of moved joints fully open."""
        limits = self.limits
        lim = dict(limits)
        if scale is not None:
            lim.update({name: (lo * scale[1], hi * scale[1]) for name, (lo, hi) in limits.items()
                        if name in scale[0]})
        q = {j.name: (f * math.pi if j.type == "continuous" else lim[j.name][0] + f * (lim[j.name][1]
             - lim[j.name][0])) for j in self.movable}
        q = one_mode(q, self.order, self.excludes)
        for name in [n for n in q if q[n] != 0.0]:
            for g in self.gates.get(name, []):
                q[g] = lim[g][1]
        return self.poses_at(q)

    def _separate(self, f, a, b, path, margins) -> bool:
        """Scale the limits of the joints between links ``a`` and ``b`` (:func:`clearance_limits`,
        step 2) by the largest factor that separates them in state ``f``; False if none can be
        scaled."""
        from ..errors import ModelError

        names = {j.name for j in path[(a, b)] if j.type != "continuous" and j.name not in self.gate_of_someone}
        turns = {n for n in names if self.by_joint[n].type == "revolute"}
        names = turns or names  # a hinge stops before a slide gives up travel
        if not names:
            return False
        good, bad = 0.0, 1.0
        for _ in range(8):
            mid = 0.5 * (good + bad)
            if (a, b) in self.contacts(self.state(f, (names, mid)), {(a, b)}, margins[(a, b)]):
                bad = mid
            else:
                good = mid
        if good < 1e-6:
            raise ModelError(f"links {a!r} and {b!r} meet whenever their joints move together")
        for name in sorted(names):
            lo, hi = self.limits[name]
            self.limits[name] = (lo * good, hi * good)
        return True

    def together(self, path) -> None:
        """Step 2: every joint at once, in the states :data:`ALL_FRACTIONS`."""
        # pairs apart by the clearance at rest keep it; closer ones keep apart; overlapping ones are
        # left out (not a joint's doing)
        rest = self.poses_at({})
        touching = self.contacts(rest, set(path))
        checked = set(path) - touching
        near_rest = self.contacts(rest, checked, CLEARANCE)  # (only the pairs checked need a margin)
        margins = {pair: 0.0 if pair in near_rest else CLEARANCE for pair in checked}
        for _ in range(8):
            changed = False
            for f in ALL_FRACTIONS:
                for a, b in sorted(self.contacts(self.state(f), checked, margins)):
                    if self._separate(f, a, b, path, margins):
                        changed = True
                        break  # the state changed: look again
            if not changed:
                break


    # -- step 3: each joint closed from the all-open state

    def held_closed(self, j) -> set[str]:
        """Joints at rest while ``j`` moves from the all-open state: the other DoFs of its own
        part (a compound joint's modes are tried one at a time, as a tilt-and-turn sash works),
        those of the parts ``j`` ``requires_closed``, and those that ``requires_open`` a part
        held closed (recursively)."""
        names = {g.name for group in sorted(self.closed[j.name] | {j.group}) for g in self.groups.get(group, [])}
        names |= set(self.excludes[j.name])
        names.discard(j.name)
        while True:
            more = {n for n, gates in self.gates.items() if n not in names and names.intersection(gates)}
            if not more:
                return names
            names |= more

    def open_state(self, j) -> dict[str, float]:
        """Every limited joint at its upper (open) limit, :meth:`held_closed` at 0, an exclusive
        joint's first mode only (:func:`~..joints.one_mode`)."""
        rest = self.held_closed(j)
        q = {n: self.limits[n][1] for n, k in self.by_joint.items() if k.type != "continuous" and n not in rest}
        return one_mode(q, self.order, self.excludes)

    def blocker(self, j, hit: str, q: dict[str, float]):
        """The open joint (not one that moves ``j``) whose subtree holds link ``hit``, the one
        nearest to it; None if no open joint put it there."""
        found = [k for k in self.movable if k is not j and q.get(k.name, 0.0) != 0.0
                 and hit in self.subtree[k.name] and j.child not in self.subtree[k.name]]
        return min(found, key=lambda k: len(self.subtree[k.name])) if found else None

    def spare(self, j, k, q: dict[str, float]) -> float:
        """The largest share of ``k``'s upper limit (bisected, 8 steps) at which ``j`` closes from
        ``q`` clear of ``k``'s subtree."""
        only = self.subtree[k.name]
        if self.closing(j, {**q, k.name: 0.0}, only):
            return 0.0
        good, bad = 0.0, 1.0
        for _ in range(8):
            mid = 0.5 * (good + bad)
            if self.closing(j, {**q, k.name: mid * self.limits[k.name][1]}, only):
                bad = mid
            else:
                good = mid
        return good

    def own_share(self, j, q: dict[str, float]) -> float:
        """The largest share of ``j``'s upper limit from which it closes with the others at ``q``:
        the first contact of its opening sweep from rest, if it then closes from there; else 0."""
        lo, hi = self.limits[j.name]
        if hi <= 0:
            return 0.0
        found = [value for side, value, _ in self.blocks(j, {**q, j.name: 0.0}) if side == 1]
        if not found or found[0] < 1e-6:
            return 0.0
        self.limits[j.name] = (lo, found[0])
        try:
            clear = self.closing(j, {**q, j.name: found[0]}) is None
        finally:
            self.limits[j.name] = (lo, hi)
        return found[0] / hi if clear else 0.0

    def give_way(self, j, value: float, hit: str, q: dict[str, float]) -> bool:
        """Make ``j``'s closing from the all-open state ``q``, stopped at ``value`` by link
        ``hit``, pass: a part inside ``j`` (it ``requires_open`` ``j``) is closed first
        (``requires_closed``); a gate of ``j`` (in its ``requires_open`` chain) is neither closed
        first nor shortened, ``j``'s own upper limit is; otherwise the blocking joint's upper limit
        or ``j``'s own is shortened, whichever keeps the larger share of its range, if that share is
        at least :data:`KEEP` (a gate only as far as the parts behind it still pass:
        :meth:`riders_pass`); otherwise ``j`` ``requires_closed`` the blocking part. Where no open joint
        put ``hit`` there, ``j``'s upper limit is shortened if that helps. Returns whether
        anything changed (False: nothing in the core's reach resolves it)."""
        k = self.blocker(j, hit, q)
        inner = self.inner_open(j, q) if k is None else None
        if inner is not None:
            return self.give_way_inner(j, inner, q)
        if k is not None and k.requires_open == j.group:
            self.closed[j.name].add(k.group)
            return True
        own = self.own_share(j, q)
        if k is not None and k.name in self.gates.get(j.name, ()):
            # j moves only with k open: k can neither be closed first nor give up what j needs
            if own <= 0:
                return False
            self.shorten(j, 1, own * self.limits[j.name][1], hit)
            return True
        other = self.spare(j, k, q) if k is not None else 0.0
        if other > 0 and k.name in self.gate_of_someone and not self.riders_pass(k, other):
            other = 0.0  # a gate keeps the opening the parts behind it pass through
        if k is not None and max(own, other) < KEEP:
            self.closed[j.name].add(k.group)
        elif k is not None and other >= own:
            lo, hi = self.limits[k.name]
            self.limits[k.name] = (lo, hi * other)
        elif own > 0:
            self.shorten(j, 1, own * self.limits[j.name][1], hit)
        else:
            return False
        return True

    def riders_pass(self, k, share: float) -> bool:
        """Whether every joint that ``requires_open`` ``k`` (through its gate chain) still sweeps its whole
        range from rest, its gates open, with ``k`` open only ``share`` of its upper limit: an inner
        drawer behind a door stopped short of its full swing must still clear the door."""
        hi = self.limits[k.name][1]
        for name, gates in self.gates.items():
            if k.name not in gates:
                continue
            q = {g: self.limits[g][1] for g in gates}
            q[k.name] = share * hi
            if any(side == 1 for side, _, _ in self.blocks(self.by_joint[name], q)):
                return False
        return True

    def inner_open(self, j, q: dict[str, float]):
        """An open joint that ``j`` carries (a tote's lid) without which ``j`` closes from ``q``: the part of
        ``j``'s load that its own opening put in the way (a lid opened in a rack fits under the shelf above
        but meets the shelf's front rail as the tote slides out); None if there is none."""
        inner = [d for d in self.movable if d is not j and q.get(d.name, 0.0) != 0.0 and d.type != "continuous"
                 and d.child in self.subtree[j.name]]
        for d in sorted(inner, key=lambda d: -len(self.subtree[d.name])):  # the nearest to j first
            if self.closing(j, {**q, d.name: 0.0}) is None:
                return d
        return None

    def give_way_inner(self, j, d, q: dict[str, float]) -> bool:
        """Make ``j`` close from ``q`` carrying its open part ``d`` (:meth:`inner_open`): ``d``'s upper limit
        is shortened to the largest share (bisected, 8 steps) at which ``j`` closes, if that share is at least
        :data:`KEEP`; otherwise ``d`` is closed before ``j`` moves (``requires_closed``: a lid shut before
        its tote slides). Returns True (something changed)."""
        good, bad = 0.0, 1.0
        for _ in range(8):
            mid = 0.5 * (good + bad)
            if self.closing(j, {**q, d.name: mid * self.limits[d.name][1]}) is None:
                good = mid
            else:
                bad = mid
        if good >= KEEP:
            lo, hi = self.limits[d.name]
            self.limits[d.name] = (lo, hi * good)
        else:
            self.closed[j.name].add(d.group)
        return True

    def from_open(self) -> bool:
        """Step 3: each joint closed from its :meth:`open_state`, made to pass by
        :meth:`give_way`; whether any limit or relation changed."""
        changed = False
        for j in self.movable:
            if j.type not in ("revolute", "prismatic"):
                continue
            for attempt in range(32):
                q = self.open_state(j)
                found = self.closing(j, q)
                if not found:
                    break
                k = self.blocker(j, found[1], q)
                if attempt < 16 or k is None:
                    if not self.give_way(j, *found, q):
                        break  # left as it is: the validators' reach reports it
                elif k.name in self.gates.get(j.name, ()):
                    break  # never its own gate closed first: the validators' reach reports it
                else:  # (never seen) an order that does not settle: the parts in the way close first
                    self.closed[j.name].add(k.group)
                changed = True
        return changed


def clearance_limits(obj) -> dict[str, tuple[float, float]]:
    """Joint limits shortened so no moving part meets a link it may not touch.

    1. *Each joint alone* (in tree order, parents first): each side of the range of every
       revolute and prismatic joint (compound chains DoF by DoF) is swept from rest with the
       other joints at rest. The collision hulls of the subtree it moves, swept (hull of two
       consecutive poses; turns sampled so arcs bulge at most :data:`SWEEP_SAGITTA` past the
       chords), keep :data:`CLEARANCE` from every hull of every link but its parent, and its
       overlap with the parent grows by at most :data:`PARENT_GROWTH` over rest at quarters of
       the range (a door may not swing into its own carcass; a polygonal pin may turn in its
       polygonal bore). A hull pair that already overlaps, or is
       closer than the clearance, at rest keeps only what it has (it is not this joint's
       doing). A joint that ``requires_open`` a part sweeps with that part fully open. The limit
       becomes the last contact-free value, bisected (14 steps) within the first sample
       interval that meets something.
    2. *Joints together*: in the states :data:`ALL_FRACTIONS` (every joint at 50 % and 100 % of
       its range, as the validators sample them; of an exclusive joint's modes, the first: a
       tilt-and-turn sash turned, its tilt swept in step 3), two links that may touch neither by design
       (welded, or parent and child) nor at rest must keep the clearance (or, if closer at rest,
       must not overlap); where they do not, the limits of
       the movable joints between them (not those others require open; only the revolute ones
       if there are any: a door stops before a drawer gives up travel) are scaled by the same
       factor, the largest that separates them (bisection to 0.4 %), until no state changes.
    3. *Each joint from the all-open state*: each joint is swept from its upper limit to its
       lower one with every other limited joint at its upper (open) limit, except the other
       DoFs of its own part, the parts it ``requires_closed`` and the parts that
       ``requires_open`` those, which are at rest (and of another part's exclusive modes, the
       first open): a robot that opened every part can close
       any one and open it again. A start overlapping a link the moving part is apart from at rest
       stops the sweep where it starts (:meth:`_Clearance.start_hit`). Where the sweep is stopped by a part that an
       open joint moved there (:meth:`_Clearance.give_way`): a part that ``requires_open`` the
       moving one (a rack in a door) must be closed first (``requires_closed``); a part is never
       made to require its own gate closed (an inner drawer closing past its door gives up travel
       instead); otherwise whichever of the blocking joint's upper limit and the moving joint's own
       limit keeps the larger share of its range (at least :data:`KEEP`) is shortened (a
       wall-cabinet door that opens past 90 degrees in front of its neighbour's swing stops before
       it; a gate only as far as the parts that require it open still sweep their whole range past
       it); otherwise the moving joint ``requires_closed`` the blocking part. Where what stops it is a part the moving
       joint carries, opened (a tote's lid meeting the rail of the shelf above as the tote slides),
       that part's upper limit is shortened if it keeps :data:`KEEP` of it, else it is closed
       first (``requires_closed``: a lid shut before its tote slides). Steps 2 and 3 repeat (up to 4
       rounds) while step 3 changes something.

    Returns ``{joint name: (lower, upper)}`` for every movable joint (continuous joints keep
    theirs: see :func:`limit_to_ground`); :func:`limit_to_clearance` also sets each joint's
    ``requires_closed``.
    """
    return _clearance(obj).limits


def _clearance(obj) -> _Clearance:
    """The three steps of :func:`clearance_limits` run on ``obj``; steps 2 and 3 again (up to 4
    rounds) while step 3 changes something."""
    c = _Clearance(obj)
    c.sweep_alone()
    path = c.pairs()
    for _ in range(4):
        if path:
            c.together(path)
        if not c.from_open():
            break
    return c


def _share_coupled(joints, closed: dict[str, set[str]]) -> None:
    """A coupled joint and its leader move together (one hand or foot drives both): what either must have
    closed first, both must (a pedal whose lid would meet an open part needs that part closed as the lid does)."""
    for j in joints:
        lead = j.mimic[0] if getattr(j, "mimic", None) else None
        if lead in closed and j.name in closed:
            both = closed[lead] | closed[j.name]
            closed[lead], closed[j.name] = set(both), set(both)


MIN_TRAVEL = {"prismatic": 1e-3, "revolute": math.radians(1.0)}
"""The least range (m, rad) a joint keeps after the clearance pass: a slide with less than 1 mm of travel or
a hinge with less than 1 degree of swing is no mechanism a hand can work (and one the validators' 5 %
tolerance cannot tell from a jammed one); such a joint is made fixed and the object's ``notes`` say so."""


def _too_short(j, limits: dict[str, tuple[float, float]], declared: dict[str, tuple[float, float]]) -> str:
    """Why joint ``j`` is made fixed (its clearance range shorter than :data:`MIN_TRAVEL` where its declared
    range was not), "" if it keeps moving."""
    least = MIN_TRAVEL.get(j.type)
    if least is None or j.name not in limits:
        return ""
    lo, hi = limits[j.name]
    if hi - lo >= least or declared[j.name][1] - declared[j.name][0] < least:
        return ""
    unit, scale = ("mm", 1000.0) if j.type == "prismatic" else ("degrees", math.degrees(1.0))
    return (f"{j.name}: the clearance pass left {(hi - lo) * scale:.3g} {unit} of its "
            f"{(declared[j.name][1] - declared[j.name][0]) * scale:.3g} {unit} range (less than "
            f"{least * scale:.3g} {unit}): made fixed at rest")


def _fix_short(joints, limits: dict[str, tuple[float, float]]) -> tuple[set[str], list[str]]:
    """The joints to make fixed (:func:`_too_short`, and the joints coupled to one that is: a follower moves
    only with its leader) and a note for each."""
    declared = {j.name: (float(j.lower), float(j.upper)) for j in joints if j.movable}
    notes = {j.name: why for j in joints if (why := _too_short(j, limits, declared))}
    for j in joints:
        lead = j.mimic[0] if getattr(j, "mimic", None) else None
        if lead in notes and j.name not in notes and j.movable:
            notes[j.name] = f"{j.name}: follows {lead}, made fixed: fixed at rest too"
    return set(notes), [notes[j.name] for j in joints if j.name in notes]


def limit_to_clearance(obj):
    """A copy of ``obj`` whose joints have the limits of :func:`clearance_limits` and the
    ``requires_closed`` parts its step 3 found (the object and its joints are not modified;
    unchanged joints are shared). A joint left less than :data:`MIN_TRAVEL` becomes a fixed joint at rest,
    noted in ``obj.notes``."""
    c = _clearance(obj)
    _share_coupled(obj.joints, c.closed)
    fixed, notes = _fix_short(obj.joints, c.limits)
    joints = []
    for j in obj.joints:
        if j.name in fixed:
            j = replace(j, type="fixed", lower=0.0, upper=0.0, requires_open=None, requires_closed=(),
                        excludes=(), mimic=None, stiffness=0.0, spring_ref=0.0)
        elif j.name in c.limits:
            closed = tuple(sorted(c.closed[j.name]))
            if c.limits[j.name] != (j.lower, j.upper) or closed != tuple(j.requires_closed):
                j = replace(j, lower=c.limits[j.name][0], upper=c.limits[j.name][1], requires_closed=closed)
        joints.append(j)
    return replace(obj, joints=_forget(joints, fixed) if fixed else joints, notes=[*obj.notes, *notes])


def _forget(joints, fixed: set[str]) -> list:
    """``joints`` with the relations to parts that no longer move taken out: a fixed joint among another's
    ``excludes``, a part with no movable joint left among ``requires_open`` and ``requires_closed``."""
    moving = {j.group for j in joints if j.movable}
    out = []
    for j in joints:
        if j.movable:
            excludes = tuple(n for n in j.excludes if n not in fixed)
            closed = tuple(g for g in j.requires_closed if g in moving)
            opened = j.requires_open if j.requires_open in moving else None
            if (excludes, closed, opened) != (tuple(j.excludes), tuple(j.requires_closed), j.requires_open):
                j = replace(j, excludes=excludes, requires_closed=closed, requires_open=opened)
        out.append(j)
    return out
