"""Contract parts for casings and controls (categories/parts/casing.py, controls.py) and the Category
material hooks they come with (Same slots, substrates)."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.categories.parts import casing, controls
from infmob_usd.category import Category, Same
from infmob_usd.errors import ModelError
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node

SIZE = casing.CasingSize(width=0.3, depth=0.2, height=0.18, wall=0.003, sheet=0.0006, corner=0.02)


def _inside_any_hull(assembly, point) -> bool:
    for pc in assembly.pieces:
        for v in pc.convex:
            lo, hi = v.min(0), v.max(0)  # every casing piece collides as boxes
            if np.all(point > lo - 1e-9) and np.all(point < hi + 1e-9):
                return True
    return False


def test_cutouts_are_open_and_anchored_on_their_face():
    lever = controls.Lever(stem=(0.006, 0.004), paddle=(0.04, 0.015, 0.012), reach=0.013, travel=0.08)
    cuts = {"slot": lever.cutout("front", SIZE.on("front", 0.6, 0.5)), **SIZE.slots("top", 0.13, 0.03, 0.02)}
    body = casing.sheet_casing(SIZE, "body", cuts)
    at = body.anchor("slot")
    assert np.isclose(at.origin[0], SIZE.depth / 2) and np.allclose(at.z, (1, 0, 0))  # on the front face
    assert np.isclose(at.origin[1], -0.6 * SIZE.width / 2)  # u is to the right seen from the front (-y)
    for k in range(2):
        top = body.anchor(f"slot_{k}")
        assert np.isclose(top.origin[2], SIZE.height) and np.allclose(top.z, (0, 0, 1))
        assert not _inside_any_hull(body, top.point((0, 0, -SIZE.wall / 2)))  # the bread slot is open
    bottom = at.point((-lever.travel, 0, -SIZE.wall / 2))  # the slot runs the lever's travel down
    assert not _inside_any_hull(body, bottom)
    assert _inside_any_hull(body, at.point((-lever.travel - 0.01, 0, -SIZE.wall / 2)))  # and no further
    with pytest.raises(ModelError, match="face must be one of"):
        casing.sheet_casing(SIZE, "body", {"x": casing.Cutout("bottom", (0, 0), (0.01, 0.01))})


def test_liner_and_hinge_bracket_anchors():
    tray = casing.liner(casing.LinerSize(0.2, 0.15, 0.01, 0.003, 0.0006, lip=0.01, front=0.003), "tray")
    lo, hi = tray.bounds()
    assert np.isclose(hi[0], 0) and np.isclose(lo[0], -0.15) and np.isclose(tray.anchor("front").origin[2], 0.01)
    bracket = casing.hinge_bracket(casing.BracketSize(0.05, 0.02, 0.002, 0.004, 0.03), "hinge")
    pin = bracket.attached("mount", to=Frame.at((0, 0, 1.0), z=(1, 0, 0), x=(0, 0, 1))).anchor("pin")
    assert np.isclose(abs(pin.z @ (0, 0, 1)), 0) and np.isclose(pin.origin[0], 0.004)  # radius off the face


def _cat(materials, **kw):
    grammar = Grammar("thing", {"thing": Node(label="body")})

    class L(Layout):
        def thing(self, node):
            pass

    return Category("thing", "a thing", (), grammar, L, materials, **kw)


def test_same_slot_must_name_a_slot_with_a_family():
    assert _cat({"body": "wood", "lid": Same("body")}).resolve_materials({})["lid"] == "wood"
    with pytest.raises(ModelError, match="same as 'shell'"):
        _cat({"body": "wood", "lid": Same("shell")})
    with pytest.raises(ModelError, match="parameter and a value table"):
        _cat({"body": "wood"}, substrates={"body": ("nope", {"painted": 7850.0})})
