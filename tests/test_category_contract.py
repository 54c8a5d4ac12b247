"""The category contract, once for every registered category: determinism, bad overrides rejected
up front, schema extremes give an object or a ParameterError (never a crash), rules printable."""

from __future__ import annotations

import numpy as np
import pytest

import infmob_usd
from infmob_usd.api import assemble
from infmob_usd.errors import ParameterError
from infmob_usd.params import Choice, Float, Int
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
    """Each numeric parameter at its bounds, one at a time: an object, or a ParameterError before
    any geometry (never another exception)."""
    schema = infmob_usd.get_category(name).schema
    for prm in schema.params:
        if not isinstance(prm, (Float, Int)):
            continue
        for value in (prm.low, prm.high):
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
    from infmob_usd.category import Category

    assert len(CATEGORIES) == 22
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
