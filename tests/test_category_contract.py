"""The category contract, once for every registered category: determinism, bad overrides rejected
up front, schema extremes give an object or a ParameterError (never a crash), rules printable."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import infmob_usd
from infmob_usd.api import assemble
from infmob_usd.errors import ParameterError
from infmob_usd.params import Choice, Flag, Float, Int
from infmob_usd.seeding import streams

CATEGORIES = infmob_usd.list_categories()


def blueprint(name, seed, **overrides):
    cat = infmob_usd.get_category(name)
    r = streams(name, seed)
    p = cat.schema.sample(r["params"], overrides)
    return p, cat.build(p, r["structure"], r["geometry"]), r


@pytest.mark.parametrize("name", CATEGORIES)
def test_same_seed_same_object(name):
    p1, a, _ = blueprint(name, 4)
    p2, b, _ = blueprint(name, 4)
    assert p1 == p2 and a.joints == b.joints and list(a.parts) == list(b.parts)
    for part in a.parts:
        for x, y in zip(a.parts[part].pieces, b.parts[part].pieces, strict=True):
            assert np.array_equal(x.vertices, y.vertices) and x.material == y.material
    assert blueprint(name, 5)[0] != p1


@pytest.mark.parametrize("name", CATEGORIES)
def test_bad_overrides_are_rejected_with_the_parameter_named(name):
    schema = infmob_usd.get_category(name).schema
    with pytest.raises(ParameterError, match="unknown parameter 'no_such_thing'"):
        blueprint(name, 0, no_such_thing=1)
    for prm in schema.params:
        if isinstance(prm, Float):
            bad = [prm.high + abs(prm.high) + 1.0, prm.low - abs(prm.low) - 1.0, "wide", float("nan")]
        elif isinstance(prm, Int):
            bad = [prm.high + 1, prm.low - 1, 1.5]
        elif isinstance(prm, Choice):
            bad = ["no_such_choice"]
        else:
            bad = ["maybe"]
        for value in bad:
            with pytest.raises(ParameterError, match=prm.name):
                schema.validate({prm.name: value})


@pytest.mark.parametrize("name", CATEGORIES)
def test_schema_extremes_build_or_are_rejected_up_front(name):
    """Each numeric parameter at one of its bounds (low and high in turn down the schema), one at a time: an
    object, or a ParameterError before any geometry (never another exception). Both bounds of every parameter,
    and combinations of them, are drawn by ``infmob fuzz N`` (30 % low, 30 % high)."""
    schema = infmob_usd.get_category(name).schema
    numeric = [prm for prm in schema.params if isinstance(prm, (Float, Int))]
    for i, prm in enumerate(numeric):
        for value in ((prm.low, prm.high)[i % 2],):
            try:
                p, bp, r = blueprint(name, 1, **{prm.name: value})
            except ParameterError:
                continue
            obj = assemble(bp, 1, r["materials"], 16, p, {prm.name: value})
            assert obj.links, (prm.name, value)


@pytest.mark.parametrize("name", CATEGORIES)
def test_rules_are_printable_and_name_the_flags(name):
    cat = infmob_usd.get_category(name)
    rules = cat.rules()
    assert rules.strip()
    for prm in cat.grammar.flags():
        assert prm.name in cat.schema.names and prm.name[4:] in rules, prm.name




def test_every_category_is_expressed_through_parts_and_the_grammar():
    """Discovery registers every category module (no list to keep), each a Category."""
    from infmob_usd import categories
    from infmob_usd.category import Category

    modules = sorted(f.stem for f in Path(categories.__file__).parent.glob("*.py")
                     if not f.stem.startswith("_") and f.stem not in categories.NOT_CATEGORIES)
    assert CATEGORIES and CATEGORIES == modules
    assert all(isinstance(infmob_usd.get_category(n), Category) for n in CATEGORIES)


@pytest.mark.parametrize("name", CATEGORIES)
def test_grown_tree_and_parts_agree(name):
    """Every grown node made its labelled part and every part was grown (Layout.check), and the parts
    of a node kind carry the labels its rule names."""
    cat = infmob_usd.get_category(name)
    for seed in range(3):
        r = streams(name, seed)
        p = cat.schema.sample(r["params"])
        tree = cat.grammar.grow(dict(p), np.random.default_rng(0))
        assert tree.kind == cat.grammar.root
        bp = cat.build(p, r["structure"], r["geometry"])
        labels = {part.label for part in bp.parts.values()}
        wanted = set()
        for node in cat.grammar.nodes.values():
            if node.label:
                wanted |= {node.label} if isinstance(node.label, str) else set(node.label)
        assert labels <= wanted, f"{name} seed {seed}: labels {labels - wanted} no rule builds"


# -- overrides drive the growth ------------------------------------------------------------------------------
GROWTH_SEEDS = range(4)


def grown(name, seed, **overrides):
    """``(params, tree)``: the parameters as :meth:`Category.build` leaves them (``derive``, then the grammar's
    ``auto`` choices) and the tree it grows from the structure stream, without building geometry."""
    cat = infmob_usd.get_category(name)
    r = streams(name, seed)
    p = cat.schema.sample(r["params"], overrides)
    if cat.derive is not None:
        p.update(cat.derive(dict(p)))
    p.update(cat.grammar.resolve(p))
    return p, cat.grammar.grow(p, r["structure"])


def _line(node):
    """The node kinds from the root to ``node`` (its path without repeat indices)."""
    return [seg.split("[")[0] for seg in node.path.split("/")]


def _forced(name, overrides):
    """``(params, tree)`` per growth seed where the override is used as given; asserts an override is only ever
    changed by the category's ``derive`` rule. A forced value no tree accepts (ModelError) or that the schema
    refuses (ParameterError) is left out: the contract test above covers refusals."""
    from infmob_usd.errors import ModelError

    cat, out = infmob_usd.get_category(name), []
    for seed in GROWTH_SEEDS:
        try:
            p, tree = grown(name, seed, **overrides)
        except (ModelError, ParameterError):
            continue
        changed = {k: (v, p[k]) for k, v in overrides.items() if p[k] != v}
        assert not changed or cat.derive is not None, f"{name} seed {seed}: overrides changed {changed} by no rule"
        if not changed:
            out.append((p, tree))
    return out


def _values(prm):
    if isinstance(prm, Flag):
        return (True, False)
    if isinstance(prm, Choice):
        return tuple(c for c in prm.choices if c != "auto")
    if isinstance(prm, (Float, Int)):
        return (prm.low, prm.high)
    return ()


@pytest.mark.parametrize("name", CATEGORIES)
def test_overrides_drive_the_growth(name):
    """Every parameter forced to each choice, flag value or bound is used as given (unless the category's
    ``derive`` rule says otherwise), and the grown tree follows the grammar's parameters: a forced branch flag
    grows (or leaves out) that branch under every node that may hold it, a forced choice is the alternative
    every choosing node takes, a count parameter is the number of children grown. Each flag and each choice
    alternative is honoured for at least one seed."""
    cat = infmob_usd.get_category(name)
    g = cat.grammar
    for prm in cat.schema.params:
        for value in _values(prm):
            cases = _forced(name, {prm.name: value})
            if isinstance(prm, (Flag, Choice)) and prm.name in {q.name for q in g.params()}:
                assert cases, f"{name}: {prm.name}={value!r} is never used as given in seeds {list(GROWTH_SEEDS)}"
            for p, tree in cases:
                for node in tree.walk():
                    rule, line = g.nodes[node.kind], _line(node)
                    kinds = [c.kind for c in node.children]
                    for branch in rule.optional:
                        other = branch in (*rule.required, *rule.one_of, *rule.repeat)
                        if line.count(branch) < g.max_nesting and not other:
                            assert (branch in kinds) == p[f"has_{branch}"], (name, node.path, branch, p)
                    if rule.choice and p[rule.choice] in rule.one_of and line.count(p[rule.choice]) < g.max_nesting:
                        assert node.choice == p[rule.choice], (name, node.path, rule.choice)
                    for child, count in rule.repeat.items():
                        if isinstance(count, str) and line.count(child) < g.max_nesting:
                            assert kinds.count(child) == p[count], (name, node.path, child, count)
