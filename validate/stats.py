"""Dataset statistics of written objects, read from their ``metadata.json``.

Articulation tree (the exact definition used by ``infmob stats``)
------------------------------------------------------------------
* Nodes are the object's links, dummy links of compound joints left out (a
  compound joint is one edge).
* A node's label is ``<joint kind>:<semantic label>`` where the joint kind is the
  *declared* kind of the joint into that link (``revolute``, ``prismatic``,
  ``revolute_prismatic`` ..., ``fixed``), and ``root`` for the base link.
* Children are ordered canonically: by the sorted bracket string of their
  subtrees, so two objects with the same tree shape and labels give the same
  ordered tree whatever the order their parts were built in.
* Tree edit distance is Zhang-Shasha's ordered-tree edit distance with unit
  costs: deleting a node, inserting a node, relabelling a node (0 if the labels
  are equal) each cost 1.
* "mean pairwise TED" averages over unordered pairs of distinct objects. With
  more than ``max_pairs`` pairs, a fixed, seeded sample of pairs is used (the
  number used is reported).

Other figures: object count; mean and (population) variance of the declared
movable-joint count (a compound joint counts once); objects with no movable
joint; the distinct-tree share (distinct canonical trees / objects); histogram of
declared joint kinds; mean and max tree depth (root alone = depth 0).

The reference's counting convention (``ref_mean_joints``, ``ref_var_joints``)
------------------------------------------------------------------------------
The Infinite Mobility paper's 12.32 / 659.02 count joints the way its URDF writer
emits them: every URDF joint (fixed ones and the joints into dummy links of
compound joints included), plus one abstract fixed link per revolute or
continuous URDF joint, plus the joint to the world. Per object that is
``len(joints) + #revolute/continuous URDF joints + 1``; our declared count above
is the stricter figure.
"""

from __future__ import annotations

import json
from collections import Counter
from dataclasses import dataclass, field
from itertools import combinations
from pathlib import Path

import numpy as np

# the reference method's figures (Infinite Mobility paper) and PartNet-Mobility, as reported there
REFERENCE = {
    "Infinite Mobility": {"mean_joints": 12.32, "var_joints": 659.02, "mean_ted": 78.62, "convention": "reference"},
    "PartNet-Mobility": {"mean_joints": 5.91, "var_joints": 40.31, "mean_ted": 3.88},
}


@dataclass
class Tree:
    label: str
    children: list[Tree] = field(default_factory=list)

    def bracket(self) -> str:
        """Canonical bracket string; children sorted by theirs."""
        return "{" + self.label + "".join(sorted(c.bracket() for c in self.children)) + "}"

    def canonical(self) -> Tree:
        kids = sorted((c.canonical() for c in self.children), key=lambda t: t.bracket())
        return Tree(self.label, kids)

    def depth(self) -> int:
        return 1 + max((c.depth() for c in self.children), default=-1)

    def size(self) -> int:
        return 1 + sum(c.size() for c in self.children)


def tree_from_metadata(meta: dict) -> Tree:
    """The articulation tree of one object (see the module docstring)."""
    links = {link["name"]: link for link in meta["links"]}
    into = {j["child"]: j for j in meta["joints"]}

    def real_parent(name: str) -> str:
        p = into[name]["parent"]
        while links[p]["dummy"]:
            p = into[p]["parent"]
        return p

    nodes: dict[str, Tree] = {}
    root = None
    for name, link in links.items():
        if link["dummy"]:
            continue
        kind = into[name]["kind"] if name in into else "root"
        nodes[name] = Tree(f"{kind}:{link['label']}")
        if name not in into:
            root = name
    for name in nodes:
        if name != root:
            nodes[real_parent(name)].children.append(nodes[name])
    return nodes[root].canonical()


def _postorder(tree: Tree):
    labels, lmd = [], []

    def walk(t: Tree) -> int:
        first = None
        for c in t.children:
            leftmost = walk(c)
            first = leftmost if first is None else first
        labels.append(t.label)
        me = len(labels) - 1
        lmd.append(me if first is None else first)
        return lmd[me]

    walk(tree)
    return labels, lmd


def ted(a: Tree, b: Tree) -> int:
    """Zhang-Shasha ordered tree edit distance with unit costs."""
    return _ted_cached(a.bracket(), b.bracket(), a, b)


_MEMO: dict[tuple[str, str], int] = {}


def _ted_cached(ka: str, kb: str, a: Tree, b: Tree) -> int:
    if ka == kb:
        return 0
    key = (ka, kb) if ka < kb else (kb, ka)
    if key not in _MEMO:
        _MEMO[key] = _zhang_shasha(a, b)
    return _MEMO[key]


def _zhang_shasha(a: Tree, b: Tree) -> int:
    la, ra = _postorder(a)
    lb, rb = _postorder(b)
    na, nb = len(la), len(lb)
    keys_a = [i for i in range(na) if all(ra[j] != ra[i] for j in range(i + 1, na))]
    keys_b = [j for j in range(nb) if all(rb[k] != rb[j] for k in range(j + 1, nb))]
    td = np.zeros((na, nb), dtype=np.int64)
    for i in keys_a:
        for j in keys_b:
            li, lj = ra[i], rb[j]
            m, n = i - li + 2, j - lj + 2
            fd = np.zeros((m, n), dtype=np.int64)
            fd[:, 0] = np.arange(m)
            fd[0, :] = np.arange(n)
            for x in range(1, m):
                ix = li + x - 1
                for y in range(1, n):
                    jy = lj + y - 1
                    if ra[ix] == li and rb[jy] == lj:
                        fd[x, y] = min(fd[x - 1, y] + 1, fd[x, y - 1] + 1,
                                       fd[x - 1, y - 1] + (la[ix] != lb[jy]))
                        td[ix, jy] = fd[x, y]
                    else:
                        fd[x, y] = min(fd[x - 1, y] + 1, fd[x, y - 1] + 1,
                                       fd[ra[ix] - li, rb[jy] - lj] + td[ix, jy])
    return int(td[na - 1, nb - 1])


@dataclass
class Group:
    name: str
    joints: list[int] = field(default_factory=list)
    ref_joints: list[int] = field(default_factory=list)
    kinds: Counter = field(default_factory=Counter)
    trees: list[Tree] = field(default_factory=list)

    def summary(self, max_pairs: int, seed: int = 0) -> dict:
        n = len(self.joints)
        total = n * (n - 1) // 2
        if total > max_pairs:
            # the k-th pair of combinations(range(n), 2), without listing all n^2/2 of them (10,000 objects:
            # 50 M pairs, gigabytes); row i starts at i * (2n - i - 1) / 2
            rng = np.random.default_rng(seed)
            ks = np.sort(rng.choice(total, max_pairs, replace=False))
            starts = np.arange(n) * (2 * n - np.arange(n) - 1) // 2
            rows = np.searchsorted(starts, ks, side="right") - 1
            pairs = [(int(i), int(i + 1 + k - starts[i])) for i, k in zip(rows, ks)]
        else:
            pairs = list(combinations(range(n), 2))
        teds = [ted(self.trees[i], self.trees[j]) for i, j in pairs]
        depths = [t.depth() for t in self.trees]
        distinct = len({t.bracket() for t in self.trees})
        return {
            "objects": n,
            "mean_joints": float(np.mean(self.joints)) if n else 0.0,
            "var_joints": float(np.var(self.joints)) if n else 0.0,
            "no_movable_joint": sum(1 for j in self.joints if j == 0),
            "distinct_trees": distinct,
            "distinct_share": distinct / n if n else 0.0,
            "ref_mean_joints": float(np.mean(self.ref_joints)) if self.ref_joints else 0.0,
            "ref_var_joints": float(np.var(self.ref_joints)) if self.ref_joints else 0.0,
            "joint_kinds": dict(sorted(self.kinds.items())),
            "mean_depth": float(np.mean(depths)) if n else 0.0,
            "max_depth": int(max(depths, default=0)),
            "mean_ted": float(np.mean(teds)) if teds else 0.0,
            "ted_pairs": len(teds),
        }


def reference_count(meta: dict) -> int:
    """Joints of one object counted the reference's way (see the module docstring)."""
    joints = meta["joints"]
    turning = sum(1 for j in joints if j["type"] in ("revolute", "continuous"))
    return len(joints) + turning + 1


def blueprint_figures(bp) -> tuple[Tree, int, int, Counter]:
    """Tree, movable-joint count, reference count and movable kinds of one blueprint (the grown parts
    and declared joints of :func:`infmob_usd.api.blueprint`): the figures ``infmob stats`` reads
    from the object's files, before the core builds and writes it. A declared joint is one URDF
    joint per degree of freedom (a fixed one: one), its revolute and continuous ones turning."""
    into = {j.child: j for j in bp.joints}
    nodes = {name: Tree(f"{into[name].kind if name in into else 'root'}:{part.label}")
             for name, part in bp.parts.items()}
    for j in bp.joints:
        nodes[j.parent].children.append(nodes[j.child])
    movable = [j for j in bp.joints if j.kind != "fixed"]
    urdf = sum(max(1, len(j.dofs)) for j in bp.joints)
    turning = sum(1 for j in bp.joints for d in j.dofs if d.type in ("revolute", "continuous"))
    return nodes[bp.root].canonical(), len(movable), urdf + turning + 1, Counter(j.kind for j in movable)


def grammar_stats(categories, count: int, seed: int = 0, max_pairs: int = 2000) -> dict:
    """:func:`dataset_stats` of seeds ``seed .. seed + count - 1`` of each category, computed from the
    blueprints alone (no passes, no files: about 100x faster than generating). The files' figures
    are the same: the core adds only dummy links, which the tree leaves out and the reference count
    takes from the joints' degrees of freedom (``tests/test_stats.py`` checks the two agree)."""
    from infmob_usd.api import blueprint

    return _summarise(((category, *blueprint_figures(blueprint(category, s)))
                       for category in categories for s in range(seed, seed + count)), max_pairs)


def _summarise(objects, max_pairs: int) -> dict:
    """Per-category and overall :class:`Group` summaries of ``(category, tree, movable joints,
    reference count, movable kinds)`` records."""
    groups: dict[str, Group] = {}
    overall = Group("overall")
    for category, tree, joints, ref, kinds in objects:
        for g in (groups.setdefault(category, Group(category)), overall):
            g.joints.append(joints)
            g.ref_joints.append(ref)
            g.kinds.update(kinds)
            g.trees.append(tree)
    return {
        "categories": {name: g.summary(max_pairs) for name, g in sorted(groups.items())},
        "overall": overall.summary(max_pairs),
        "reference": REFERENCE,
    }


def dataset_stats(folder: str | Path, max_pairs: int = 2000, skipped: list | None = None) -> dict:
    """Statistics per category and overall of every object folder under ``folder``.

    A folder whose ``metadata.json`` cannot be read as an object's is left out and, when
    ``skipped`` is a list, appended to it as ``(folder, reason)``.
    """
    from .files import find_objects

    if isinstance(max_pairs, bool) or not isinstance(max_pairs, int) or max_pairs < 1:
        raise ValueError(f"max_pairs must be a positive integer, got {max_pairs!r}")

    def records():
        for obj in find_objects([folder]):
            try:
                meta = json.loads((obj / "metadata.json").read_text())
                tree = tree_from_metadata(meta)
                kinds = meta["joint_kinds"]
                record = (str(meta["category"]), tree, sum(kinds.values()), reference_count(meta), kinds)
            except Exception as e:  # noqa: BLE001 - a damaged metadata.json is one object left out
                if skipped is not None:
                    skipped.append((obj, f"{type(e).__name__}: {' '.join(str(e).split())[:200]}"))
                continue
            yield record

    return _summarise(records(), max_pairs)


def format_stats(stats: dict) -> str:
    """A table for the terminal, ours beside the reference figures."""
    head = (f"{'category':<22}{'objects':>8}{'mean joints':>13}{'var joints':>12}{'no joint':>9}{'distinct':>9}"
            f"{'ref mean':>10}{'ref var':>10}{'depth':>7}{'mean TED':>10}  kinds")
    lines = [head, "-" * len(head)]

    def row(name, s):
        kinds = ", ".join(f"{k} {v}" for k, v in s["joint_kinds"].items())
        return (f"{name:<22}{s['objects']:>8}{s['mean_joints']:>13.2f}{s['var_joints']:>12.2f}"
                f"{s['no_movable_joint']:>9}{s['distinct_share']:>8.0%} {s['ref_mean_joints']:>10.2f}"
                f"{s['ref_var_joints']:>10.2f}{s['mean_depth']:>7.2f}{s['mean_ted']:>10.2f}  {kinds}")

    for name, s in stats["categories"].items():
        lines.append(row(name, s))
    lines.append("-" * len(head))
    lines.append(row("overall (ours)", stats["overall"]))
    for name, ref in stats["reference"].items():
        # the paper's figures for its own method come from its URDF writer (the "ref" convention); those
        # for PartNet-Mobility count that dataset's declared joints
        own = ref.get("convention") == "reference"
        cols = (f"{'':>13}{'':>12}{'':>18}{ref['mean_joints']:>10.2f}{ref['var_joints']:>10.2f}" if own else
                f"{ref['mean_joints']:>13.2f}{ref['var_joints']:>12.2f}{'':>18}{'':>20}")
        lines.append(f"{name:<22}{'':>8}{cols}{'':>7}{ref['mean_ted']:>10.2f}"
                     "  (as reported by the Infinite Mobility paper)")
    lines.append("distinct: distinct articulation trees / objects;  ref mean/var: joints counted the reference's way"
                 " (URDF joints + a fixed link per revolute/continuous joint + the world joint)")
    return "\n".join(lines)
