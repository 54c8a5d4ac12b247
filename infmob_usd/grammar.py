"""The growth grammar: a category's articulation tree grown from rules, then built node by node.

A :class:`Grammar` maps node kinds to :class:`Node` rules: children a node
always has (``required``), branches it may grow (``optional``, with a chance:
object-wide, each also a ``has_<branch>`` parameter the user can force),
alternatives it picks between (``one_of``, with weights: per instance, or
object-wide through a named choice parameter), and counted repeats
(``repeat``: a fixed count, a parameter, a ``(lo, hi)`` range drawn per
instance, or a function of the parameters and the structure stream). A kind may appear among its own
descendants (a bay that splits into bays); :attr:`Grammar.max_nesting` bounds the
recursion: a kind nests in itself at most that many times, and at the bound its
recursive alternatives are dropped (optional ones not grown, repeats zero, one_of
weights renormalised over the rest).

:meth:`Grammar.grow` draws a tree of :class:`Grown` nodes from the structure
stream. A :class:`Layout` (one method per node kind) then builds it: the root's
method places its parts and calls :meth:`Layout.grow` on each child with
whatever the child needs (a frame, a cell). Every part a method adds is tagged
with its node; afterwards the engine checks that every grown node was built
once, every node with a label made a part with that label, and no part exists
that the grammar did not grow.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from . import joints as J
from . import lift_off
from .errors import ModelError
from .params import Choice, Flag

Count = int | str | tuple[int, int] | Callable[[dict, np.random.Generator], int]


@dataclass(frozen=True)
class Node:
    """The growth rule of one node kind.

    ``label``: the semantic label of the part this node builds, or a tuple of the
    labels it may build one of (a table top that is a ``lid`` when it lifts off a
    storage box); ``None`` for a node that only groups its children or adds pieces
    to its parent's part.
    ``choice``: the name of an object-wide choice parameter for ``one_of``
    (drawn by the schema with the same weights; the user can force it); empty:
    drawn per instance from the structure stream.
    ``auto``: for an object-wide choice, how its default value ``"auto"`` is
    resolved from the other parameters (a bottle's usual closure follows its
    profile); the parameter then draws ``"auto"`` and the user may force any
    alternative.
    """

    label: str | tuple[str, ...] | None = None
    required: tuple[str, ...] = ()
    optional: Mapping[str, float] = field(default_factory=dict)
    one_of: Mapping[str, float] = field(default_factory=dict)
    repeat: Mapping[str, Count] = field(default_factory=dict)
    choice: str = ""
    auto: Callable[[dict], str] | None = None
    doc: str = ""


@dataclass
class Grown:
    """One node of a grown tree."""

    kind: str
    path: str
    depth: int
    children: list[Grown] = field(default_factory=list)
    choice: str | None = None

    def of(self, kind: str) -> list[Grown]:
        """The children of one kind, in order."""
        return [c for c in self.children if c.kind == kind]

    def one(self, kind: str) -> Grown | None:
        """The child of one kind, or ``None`` if it was not grown."""
        found = self.of(kind)
        if len(found) > 1:
            raise ModelError(f"{self.path} grew {len(found)} {kind!r} children, expected at most one")
        return found[0] if found else None

    def walk(self) -> Iterable[Grown]:
        yield self
        for c in self.children:
            yield from c.walk()

    def signature(self) -> str:
        """A canonical text of the tree (kinds and structure), for comparing trees."""
        inner = ",".join(sorted(c.signature() for c in self.children))
        return f"{self.kind}({inner})" if inner else self.kind


class Grammar:
    """A category's growth rules: node kinds and their :class:`Node` rules, grown from ``root``."""

    def __init__(self, root: str, nodes: Mapping[str, Node], max_nesting: int = 3,
                 accept: Callable[[Grown], bool] | None = None, tries: int = 50) -> None:
        """``accept``: a rule every grown tree must satisfy (an all-shelf cabinet would not move); a tree
        that fails it is drawn again from the same stream, at most ``tries`` times."""
        self.root, self.nodes, self.max_nesting = root, dict(nodes), int(max_nesting)
        self.accept, self.tries = accept, int(tries)
        known = set(self.nodes)
        if root not in known:
            raise ModelError(f"grammar root {root!r} has no rule")
        for kind, n in self.nodes.items():
            for child in (*n.required, *n.optional, *n.one_of, *n.repeat):
                if child not in known:
                    raise ModelError(f"grammar node {kind!r} names child {child!r}, which has no rule")
            for k, w in n.one_of.items():
                if not w > 0:
                    raise ModelError(f"grammar node {kind!r}: one_of weight of {k!r} must be positive")
            if n.choice and not n.one_of:
                raise ModelError(f"grammar node {kind!r} names a choice parameter but has no one_of")
            if n.auto is not None and not n.choice:
                raise ModelError(f"grammar node {kind!r}: auto needs an object-wide choice parameter")

    # -- parameters the grammar owns -------------------------------------------------------------------
    def flags(self) -> tuple[Flag, ...]:
        """One ``has_<branch>`` flag per optional branch (the same branch under two nodes shares one)."""
        seen: dict[str, Flag] = {}
        for kind, n in self.nodes.items():
            for branch, p in n.optional.items():
                seen.setdefault(branch, Flag(f"has_{branch}", doc=f"optional branch of {kind}", p=p))
        return tuple(seen.values())

    def choices(self) -> tuple[Choice, ...]:
        """One choice parameter per node whose ``one_of`` is object-wide (``auto`` first where it has one)."""
        out = []
        for kind, n in self.nodes.items():
            if not n.choice:
                continue
            if n.auto is not None:
                out.append(Choice(n.choice, f"one of the alternatives of {kind}; auto follows the other parameters",
                                  choices=("auto", *n.one_of), weights=(1.0,) + (0.0,) * len(n.one_of)))
            else:
                out.append(Choice(n.choice, f"one of the alternatives of {kind}", choices=tuple(n.one_of),
                                  weights=tuple(n.one_of.values())))
        return tuple(out)

    def resolve(self, params: dict) -> dict:
        """The parameters with every ``"auto"`` choice replaced by what its node's ``auto`` picks."""
        out = dict(params)
        for kind, n in self.nodes.items():
            if n.auto is not None and out.get(n.choice) == "auto":
                pick = n.auto(out)
                if pick not in n.one_of:
                    raise ModelError(f"grammar node {kind!r}: auto picked {pick!r}, not one of {list(n.one_of)}")
                out[n.choice] = pick
        return out

    def params(self) -> tuple:
        """Every parameter the grammar owns: choice parameters and ``has_<branch>`` flags."""
        return (*self.choices(), *self.flags())

    # -- growing ------------------------------------------------------------------------------------------
    def grow(self, params: dict, rng: np.random.Generator) -> Grown:
        """Draw the tree: required children, flagged branches, choices and repeats, depth-bounded;
        again while ``accept`` rejects it. ``"auto"`` choices are resolved first (:meth:`resolve`)."""
        params = self.resolve(params)
        for _ in range(self.tries):
            tree = self._grow(self.root, self.root, 0, (), params, rng)
            if self.accept is None or self.accept(tree):
                return tree
        raise ModelError(f"{self.root}: no tree the rules accept in {self.tries} draws with these parameters;"
                         " force a branch that moves (see `infmob params`)")

    def _count(self, kind: str, child: str, c: Count, params: dict, rng: np.random.Generator) -> int:
        if isinstance(c, bool):
            raise ModelError(f"repeat count of {kind}.{child} must be a count, got {c!r}")
        if isinstance(c, int):
            n = c
        elif isinstance(c, str):
            n = params[c]
        elif isinstance(c, tuple):
            n = int(rng.integers(c[0], c[1] + 1))
        else:
            n = c(params, rng)
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
            raise ModelError(f"repeat count of {kind}.{child} must be a non-negative int, got {n!r}")
        return int(n)

    def _grow(self, kind: str, path: str, depth: int, ancestors: tuple[str, ...], params: dict,
              rng: np.random.Generator) -> Grown:
        n = self.nodes[kind]
        node = Grown(kind, path, depth)
        line = (*ancestors, kind)

        def blocked(child: str) -> bool:  # growing it would nest it in itself more than allowed
            return line.count(child) >= self.max_nesting

        order: list[str] = list(n.required)
        order += [b for b in n.optional if params.get(f"has_{b}", False) and not blocked(b)]
        if n.one_of:
            alts = {k: w for k, w in n.one_of.items() if not blocked(k)}
            if not alts:
                raise ModelError(f"{path}: every alternative of {kind!r} nests past the bound")
            if n.choice:
                pick = params[n.choice]
                if pick not in alts:  # the forced choice recurses past the bound: take the first that does not
                    pick = next(iter(alts))
            else:
                names = list(alts)
                w = np.array([alts[k] for k in names], float)
                pick = names[int(rng.choice(len(names), p=w / w.sum()))]
            node.choice = pick
            order.append(pick)
        counts = {}
        for child, c in n.repeat.items():
            counts[child] = 0 if blocked(child) else self._count(kind, child, c, params, rng)
        for child in order:
            if blocked(child):
                raise ModelError(f"{path}: required child {child!r} nests past the bound")
            node.children.append(self._grow(child, f"{path}/{child}", depth + 1, line, params, rng))
        for child, k in counts.items():
            for i in range(k):
                node.children.append(self._grow(child, f"{path}/{child}[{i}]", depth + 1, line, params, rng))
        return node

    # -- reading ------------------------------------------------------------------------------------------
    def children(self, kind: str) -> tuple[str, ...]:
        n = self.nodes[kind]
        return (*n.required, *n.optional, *n.one_of, *n.repeat)

    def recursive(self) -> list[str]:
        """Node kinds that can appear below themselves."""
        out = []
        for kind in self.nodes:
            seen, stack = set(), list(self.children(kind))
            while stack:
                k = stack.pop()
                if k == kind:
                    out.append(kind)
                    break
                if k not in seen:
                    seen.add(k)
                    stack.extend(self.children(k))
        return out

    def table(self) -> str:
        """The rules as text, one node per line (``infmob params`` prints it)."""
        lines = []
        for kind, r in self.nodes.items():
            parts = []
            if r.label:
                parts.append("builds " + (r.label if isinstance(r.label, str) else " or ".join(r.label)))
            if r.required:
                parts.append("requires " + ", ".join(r.required))
            if r.optional:
                parts.append("may grow " + ", ".join(f"{b} ({p:g})" for b, p in r.optional.items()))
            if r.one_of:
                total = sum(r.one_of.values())
                how = (f" [{r.choice}, auto: {_describe(r.auto)}]" if r.auto else f" [{r.choice}]") \
                    if r.choice else " (each)"
                parts.append("one of " + " / ".join(f"{b} ({w / total:.2f})" for b, w in r.one_of.items()) + how)
            if r.repeat:
                parts.append("repeats " + ", ".join(f"{c} x {_describe(n)}" for c, n in r.repeat.items()))
            lines.append(f"{kind}: " + ("; ".join(parts) or "leaf"))
        if self.recursive():
            lines.append(f"(recursive: {', '.join(self.recursive())}; each nests at most {self.max_nesting} times)")
        return "\n".join(lines)


def _describe(c: Count) -> str:
    if isinstance(c, int):
        return str(c)
    if isinstance(c, str):
        return c
    if isinstance(c, tuple):
        return f"{c[0]}..{c[1]}"
    return getattr(c, "__doc__", None) or getattr(c, "__name__", "f(params)")


class Layout:
    """Builds a grown tree into a blueprint: one method per node kind, named after it.

    A method ``def drawer(self, node, **slot)`` adds the node's parts with
    :meth:`add` / :meth:`place` (tagged with the node), declares joints with
    :meth:`join`, and builds children with ``self.grow(child, **slot)``.
    ``self.p`` are the parameters, ``self.rng`` the geometry stream.
    """

    def __init__(self, bp, params: dict, rng: np.random.Generator, grammar: Grammar) -> None:
        self.bp, self.p, self.rng, self.grammar = bp, params, rng, grammar
        self._stack: list[Grown] = []
        self.built: dict[str, Grown] = {}
        self.owner: dict[str, str] = {}  # part name -> path of the node that made it
        self.contributed: dict[str, set[str]] = {}  # node path -> labels of parts it made or extended

    # -- what node methods call ----------------------------------------------------------------------
    @property
    def node(self) -> Grown:
        if not self._stack:
            raise ModelError("parts can only be added while a grown node is being built")
        return self._stack[-1]

    def grow(self, node: Grown, **slot: Any) -> Any:
        """Build one grown node (and whatever its method grows below it)."""
        if node.path in self.built:
            raise ModelError(f"node {node.path} was built twice")
        method = getattr(self, node.kind, None)
        if method is None:
            raise ModelError(f"{type(self).__name__} has no method for node kind {node.kind!r}")
        self.built[node.path] = node
        self._stack.append(node)
        try:
            return method(node, **slot)
        finally:
            self._stack.pop()

    def grow_all(self, node: Grown, kind: str, **slot: Any) -> list[Any]:
        """Build every child of ``node`` of one kind, in order."""
        return [self.grow(c, **slot) for c in node.of(kind)]

    def _tag(self, name: str, label: str) -> None:
        self.owner[name] = self.node.path
        self.contributed.setdefault(self.node.path, set()).add(label)

    def add(self, name: str, label: str, pieces) -> str:
        """Add a part made by the node being built."""
        self.bp.add(name, label, pieces)
        self._tag(name, label)
        return name

    def extend(self, name: str, pieces) -> None:
        """Add pieces of the node being built to an existing part (a shelf into its carcass)."""
        self.bp.extend(name, pieces)
        self.contributed.setdefault(self.node.path, set()).add(self.bp.parts[name].label)

    def place(self, assembly, name: str):
        """Add a sub-assembly made by the node being built (see ``Blueprint.place``)."""
        placed = self.bp.place(assembly, name)
        for local, glob in placed.names.items():
            self._tag(glob, assembly.parts[local].label)
        return placed

    def join(self, spec) -> None:
        """Declare a joint spec as it is (see :mod:`infmob_usd.joints` for the compound kinds)."""
        self.bp.join(spec)

    # -- joints declared on frames: the axis is the frame's z, rest is 0 ---------------------------------
    def hinge(self, parent: str, child: str, at, upper: float, lower: float = 0.0, role: str = "hinge",
              requires_open: str | None = None, requires_closed: tuple[str, ...] = ()) -> None:
        """A revolute joint about ``at.z`` through ``at.origin``; ``upper`` is the mechanical maximum
        (the core shortens it to clearance and ground); ``requires_closed``: parts closed while it moves
        (:attr:`~.joints.JointSpec.requires_closed`)."""
        self.bp.join(replace(J.revolute(parent, child, at.origin, at.z, lower, upper, role, requires_open),
                             requires_closed=tuple(requires_closed)))

    def slide(self, parent: str, child: str, at, upper: float, lower: float = 0.0, role: str = "slide",
              requires_open: str | None = None, requires_closed: tuple[str, ...] = ()) -> None:
        """A prismatic joint along ``at.z``; ``requires_closed``: :attr:`~.joints.JointSpec.requires_closed`."""
        self.bp.join(replace(J.prismatic(parent, child, at.origin, at.z, lower, upper, role, requires_open),
                             requires_closed=tuple(requires_closed)))

    def lift(self, parent: str, child: str, at, engagement: float | None = None,
             requires_open: str | None = None) -> None:
        """A lift-off part lifted along ``at.z`` (role ``lift_off``): free, and its joint's end, once lifted
        past its seat's ``engagement`` (m) by :data:`~infmob_usd.lift_off.FREE`; without one, a hand's lift
        (:data:`~infmob_usd.lift_off.LIFT_OFF`: :func:`~infmob_usd.lift_off.lift`). ``requires_open``: the
        joint that must be open first (a bin's lid over its bucket)."""
        self.bp.join(J.prismatic(parent, child, at.origin, at.z, 0.0, lift_off.lift(engagement), "lift_off",
                                 requires_open, engagement=engagement))

    def spin(self, parent: str, child: str, at, role: str = "knob", requires_open: str | None = None) -> None:
        """A continuous joint about ``at.z``."""
        self.bp.join(J.continuous(parent, child, at.origin, at.z, role, requires_open))

    def fix(self, parent: str, child: str) -> None:
        self.bp.join(J.fixed(parent, child))

    def couple(self, follower: str, leader: str, ratio: float = 1.0, offset: float = 0.0) -> None:
        """Make the joint that moves part ``follower`` follow the joint that moves part ``leader``:
        ``q_follower = ratio * q_leader + offset`` (a pedal lifting a lid: one DoF for a hand or a
        foot, two bodies moving). Both joints are revolute or prismatic and declared already; the core
        keeps the follower's limits the image of the leader's (:func:`infmob_usd.springs.couple_limits`)."""
        specs = [i for i, s in enumerate(self.bp.joints) if s.child == follower]
        if not specs:
            raise ModelError(f"couple: no joint moves part {follower!r}; declare it before coupling it")
        if not any(s.child == leader for s in self.bp.joints):
            raise ModelError(f"couple: no joint moves part {leader!r}; declare it before coupling to it")
        i = specs[0]
        self.bp.joints[i] = replace(self.bp.joints[i], mimic=J.Mimic(leader, float(ratio), float(offset)))

    # -- the run ---------------------------------------------------------------------------------------
    def run(self, tree: Grown) -> None:
        """Build the tree from its root, then check grammar and parts agree."""
        self.grow(tree)
        self.check(tree)

    def check(self, tree: Grown) -> None:
        missing = [n.path for n in tree.walk() if n.path not in self.built]
        if missing:
            raise ModelError(f"grown nodes never built: {missing[:5]}")
        stray = [name for name in self.bp.parts if name not in self.owner]
        if stray:
            raise ModelError(f"parts the grammar did not grow: {stray[:5]}")
        for n in tree.walk():
            label = self.grammar.nodes[n.kind].label
            wanted = (label,) if isinstance(label, str) else label
            if wanted and not set(wanted) & self.contributed.get(n.path, set()):
                raise ModelError(f"grown node {n.path} made no {' or '.join(map(repr, wanted))} part")
            if label is None and not any(m.path in self.contributed for m in n.walk()):
                raise ModelError(f"grown node {n.path} and its subtree made no part")
