"""The content core: frames and patterns, assemblies placed by anchors, the executed grammar,
the category contract, and the worked example of docs/ADDING_A_CATEGORY.md end to end."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from infmob_usd.assembly import Assembly
from infmob_usd.blueprint import Blueprint
from infmob_usd.categories.parts import hardware, panels
from infmob_usd.category import Category
from infmob_usd.errors import GeometryError, ModelError
from infmob_usd.frames import Frame, cells, grid, polar, row, spans
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Float
from infmob_usd.seeding import streams

EXAMPLE = Path(__file__).resolve().parents[1] / "docs" / "examples" / "latch_box.py"


def load_example():
    spec = importlib.util.spec_from_file_location("latch_box_example", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.CATEGORY


# -- frames ----------------------------------------------------------------------------------------------
def test_frame_at_keeps_the_first_axis_and_is_right_handed():
    f = Frame.at((1, 2, 3), z=(1, 0, 0), x=(0, 0, 2))
    assert np.allclose(f.z, (1, 0, 0)) and np.allclose(f.x, (0, 0, 1))
    assert np.allclose(np.cross(f.x, f.y), f.z)
    assert np.allclose(f.point((0, 0, 1)), (2, 2, 3))


def test_frame_compose_inverse_and_turn():
    f = Frame.at((0.3, -0.2, 0.5), z=(0, 1, 0), x=(1, 0, 0))
    g = Frame.at((0.1, 0.0, 0.0)).turned("z", 0.7)
    h = f @ g
    assert np.allclose((h @ h.inverse()).matrix, np.eye(4))
    assert np.allclose(h.matrix, f.matrix @ g.matrix)
    q = Frame.at().turned("z", math.pi / 2)
    assert np.allclose(q.x, (0, 1, 0))
    assert np.allclose(f.local(f.point((0.4, 0.5, 0.6))), (0.4, 0.5, 0.6))


def test_frame_rejects_bad_input():
    with pytest.raises(GeometryError):
        Frame.at(z=(0, 0, 0))
    with pytest.raises(GeometryError):
        Frame.at(z=(0, 0, 1), x=(0, 0, 3))
    with pytest.raises(GeometryError):
        Frame((0, 0, 0), np.diag([1.0, 1.0, -1.0]))


def test_patterns():
    r = row(Frame.at(), 3, (0.5, 0, 0))
    assert [float(f.origin[0]) for f in r] == [0.0, 0.5, 1.0]
    gr = grid(Frame.at(), (2, 3), ((1, 0, 0), (0, 1, 0)))
    assert np.allclose(gr[1][2].origin, (1, 2, 0))
    ring = polar(Frame.at((0, 0, 1)), 5, 0.3)
    assert len(ring) == 5
    assert np.allclose([np.linalg.norm(f.origin[:2]) for f in ring], 0.3)
    assert all(np.allclose(f.x[:2] / np.linalg.norm(f.x[:2]), f.origin[:2] / 0.3) for f in ring)
    c = cells(0.0, 1.0, 4, gap=0.02)
    assert len(c) == 4 and math.isclose(c[-1][1], 1.0) and math.isclose(c[1][0] - c[0][1], 0.02)
    s = spans(0.0, 1.0, (1, 3))
    assert math.isclose(s[1][1] - s[1][0], 0.75)
    with pytest.raises(GeometryError):
        cells(0.0, 0.01, 3, gap=0.01)


# -- assemblies --------------------------------------------------------------------------------------------
def test_attached_anchor_lands_on_the_target_frame_and_supports_follow():
    handle = hardware.bar_handle(0.16, "handle")
    target = Frame.at((0.3, 0.1, 0.7), z=(1, 0, 0), x=(0, 0, 1))
    placed = handle.attached("mount", to=target)
    assert np.allclose(placed.anchor("mount").matrix, target.matrix)
    # the posts' feet touch the face x = 0.3, one above the other along z
    a, b = placed.support("mount_a"), placed.support("mount_b")
    assert np.isclose(a[0], 0.3) and np.isclose(b[0], 0.3) and np.isclose(abs(a[2] - b[2]), 0.16 - 2 * 0.02)
    lo, hi = placed.bounds()
    assert np.isclose(lo[0], 0.3) and hi[0] > 0.3  # stands out of the face, not into it
    with pytest.raises(ModelError, match="no anchor"):
        handle.anchor("hinge")


def test_lid_on_box_hinges_upward():
    box = panels.open_box(0.4, 0.3, 0.2, 0.012, "body")
    lid = panels.leaf(0.4, 0.3, 0.012, "body").attached("hinge", to=box.anchor("rim_back"))
    lo, hi = lid.bounds()
    assert np.allclose(lo, (-0.15, -0.2, 0.2)) and np.allclose(hi, (0.15, 0.2, 0.212))
    # a positive turn about the hinge's z lifts the free edge
    h = box.anchor("rim_back")
    opened = lid.placed(h @ Frame.at().turned("z", 0.5) @ h.inverse())
    assert opened.bounds()[1][2] > 0.3


def test_blueprint_place_names_parts_and_keeps_internal_joints():
    a = Assembly.single("body", [panels.open_box(0.3, 0.3, 0.2, 0.01, "b").parts["main"].pieces[0]])
    knob = hardware.knob_handle(0.015, 0.02, "k")
    both = a.merged(knob, prefix="knob_")
    bp = Blueprint("t", {"b": "wood", "k": "chrome"})
    placed = bp.place(both, "front")
    assert placed.root == "front" and placed["knob_main"] == "front_knob_main"
    assert set(bp.parts) == {"front", "front_knob_main"}


# -- grammar ------------------------------------------------------------------------------------------------
def _grammar(nesting=2):
    return Grammar("cab", {
        "cab": Node(label="body", required=("top",), optional={"plinth": 0.5},
                    repeat={"bay": "bays"}),
        "top": Node(label="top"),
        "plinth": Node(label="plinth"),
        "bay": Node(one_of={"drawer": 1.0, "split": 1.0}),
        "split": Node(label="divider", repeat={"bay": 2}),
        "drawer": Node(label="drawer", one_of={"bar": 1, "knob": 1}, choice="handle_style"),
        "bar": Node(label="handle"),
        "knob": Node(label="handle"),
    }, max_nesting=nesting)


def test_grammar_owns_its_parameters_and_grows_what_they_say():
    gr = _grammar()
    names = [p.name for p in gr.params()]
    assert names == ["handle_style", "has_plinth"]
    rng = np.random.default_rng(1)
    tree = gr.grow({"has_plinth": False, "bays": 3, "handle_style": "knob"}, rng)
    kinds = [c.kind for c in tree.children]
    assert kinds == ["top", "bay", "bay", "bay"]
    assert all(d.choice == "knob" for d in tree.walk() if d.kind == "drawer")
    assert gr.grow({"has_plinth": True, "bays": 0, "handle_style": "bar"}, rng).one("plinth") is not None


def test_grammar_recursion_is_bounded():
    gr = _grammar(nesting=2)
    assert gr.recursive() == ["bay", "split"]
    deepest = 0
    for seed in range(30):
        tree = gr.grow({"has_plinth": False, "bays": 2, "handle_style": "bar"}, np.random.default_rng(seed))
        bays = [n.path.count("bay") for n in tree.walk() if n.kind == "bay"]
        deepest = max(deepest, *bays)
        assert max(bays) <= 2
        assert all(n.children for n in tree.walk() if n.kind == "bay")  # a bay always became something
    assert deepest == 2  # the bound is reached, not just respected
    assert "each nests at most 2 times" in gr.table()


def test_grammar_rejects_unknown_children():
    with pytest.raises(ModelError, match="no rule"):
        Grammar("a", {"a": Node(required=("b",))})


class _Tiny(Layout):
    def root(self, node):
        self.add("base", "body", hardware.knob_handle(0.02, 0.02, "m").parts["main"].pieces)
        for c in node.of("leaf"):
            self.grow(c)

    def leaf(self, node):
        if self.p.get("skip"):
            return
        name = f"leaf{len(self.bp.parts)}"
        self.add(name, "handle" if not self.p.get("mislabel") else "door",
                 hardware.knob_handle(0.01, 0.02, "m").placed(Frame.at((0.1 * len(self.bp.parts), 0, 0)))
                 .parts["main"].pieces)
        self.fix("base", name)


TINY = Grammar("root", {"root": Node(label="body", repeat={"leaf": 2}), "leaf": Node(label="handle")})


def _run(params):
    bp = Blueprint("t", {"m": "chrome"})
    layout = _Tiny(bp, params, np.random.default_rng(0), TINY)
    layout.run(TINY.grow(params, np.random.default_rng(0)))
    return bp


def test_layout_checks_that_grammar_and_parts_agree():
    assert len(_run({}).parts) == 3
    with pytest.raises(ModelError, match="made no 'handle' part"):
        _run({"mislabel": True})
    with pytest.raises(ModelError, match="made no 'handle' part"):
        _run({"skip": True})

    class Stray(_Tiny):
        def root(self, node):
            super().root(node)
            self.bp.add("stray", "body", hardware.knob_handle(0.01, 0.01, "m").parts["main"].pieces)

    bp = Blueprint("t", {"m": "chrome"})
    with pytest.raises(ModelError, match="did not grow"):
        Stray(bp, {}, np.random.default_rng(0), TINY).run(TINY.grow({}, np.random.default_rng(0)))


def test_category_checks_layout_against_grammar():
    class NoLeaf(Layout):
        def root(self, node):
            pass

    with pytest.raises(ModelError, match="no method for grammar node 'leaf'"):
        Category("tiny", "tiny", (Float("w", "w", "m", 0.1, 0.2),), TINY, NoLeaf)


def test_unknown_joint_role_is_an_error():
    from infmob_usd import joints as J

    with pytest.raises(ModelError, match="unknown role 'hinje'"):
        J.revolute("a", "b", (0, 0, 0), (0, 0, 1), 0, 1, role="hinje")


# -- the worked example ----------------------------------------------------------------------------------
def test_worked_example_builds_the_tree_its_grammar_grew():
    cat = load_example()
    assert "lid: builds lid; may grow handle (0.5)" in cat.rules()
    for seed in range(6):
        r = streams("latch_box", seed)
        p = cat.schema.sample(r["params"])
        bp = cat.build(p, r["structure"], r["geometry"])
        assert ("latch" in bp.parts) == p["has_latch"]
        assert ("handle" in bp.parts) == p["has_handle"]
        lid = next(j for j in bp.joints if j.child == "lid")
        assert lid.kind == "revolute" and np.allclose(lid.dofs[0].axis, (0, -1, 0))


@pytest.mark.sim
def test_worked_example_passes_validate_sim(tmp_path):
    pytest.importorskip("sapien")
    from infmob_usd.api import assemble
    from infmob_usd.validate import validate_object

    cat = load_example()
    r = streams("latch_box", 3)
    p = cat.schema.sample(r["params"], {"has_latch": True, "has_handle": True})
    obj = assemble(cat.build(p, r["structure"], r["geometry"]), 3, r["materials"], 16, p, {})
    result = validate_object(obj.save(tmp_path), sim=True, physics=True)
    assert result.ok, result
