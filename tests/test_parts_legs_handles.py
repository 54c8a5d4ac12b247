"""Parts added to the leg and handle families: the bow pull, the hairpin leg and the tube leg with its glide.

Each stands where its support points say (a pull's feet on the face it is mounted on, a leg's foot on the
floor and its plate under the top), is a closed solid (so its mass is its volume) and is drawn by the
categories that offer it (dining_table drawer handles, cocktail_table legs)."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd import api, measures, triangles
from infmob_usd.categories.parts import hardware, tables
from infmob_usd.frames import Frame


@pytest.mark.parametrize("length", [0.096, 0.128, 0.16])
def test_bow_handle_stands_on_its_feet(length):
    asm = hardware.bow_handle(length, "handle")
    (piece,) = asm.parts[asm.root].pieces
    assert triangles.is_closed(piece.faces) and measures.solids(piece)[0][0] > 0
    v = piece.vertices
    assert v[:, 2].min() == pytest.approx(0.0, abs=1e-12)  # on the face, not in it
    assert v[:, 2].max() == pytest.approx(hardware.BOW_PROJECTION, abs=1e-4)
    for name in ("mount_a", "mount_b"):
        foot = np.asarray(asm.supports[name])
        near = v[np.linalg.norm(v[:, :2] - foot[:2], axis=1) <= hardware.BOW_WIRE + 1e-9]
        assert len(near) and near[:, 2].min() == pytest.approx(0.0, abs=1e-12)  # the wire's end sits on its hole
    assert abs(asm.supports["mount_b"][0] - asm.supports["mount_a"][0]) == pytest.approx(length)


def test_handles_are_named_handle_and_stand_off_their_face():
    # the one handle family, mounted on a front face (normal +X) with its bar across (+Y)
    face = Frame.at((0.3, 0.1, 0.5), z=(1, 0, 0), x=(0, 1, 0))
    for part in (hardware.bar_handle(0.2, "h"), hardware.knob_handle(0.015, 0.025, "h"),
                 hardware.edge_pull(0.2, "h"), hardware.bow_handle(0.128, "h")):
        pieces = part.attached("mount", to=face).pieces
        assert pieces and all(p.name == "handle" for p in pieces)
        assert min(p.bounds[0, 0] for p in pieces) == pytest.approx(0.3, abs=1e-9)  # on the face, not in it


@pytest.mark.parametrize("radius,height", [(0.015, 0.3), (0.03, 0.45), (0.02, 0.7)])
def test_hairpin_and_tube_legs_reach_floor_and_top(radius, height):
    for pieces in (tables.hairpin_leg(radius, height, "metal"), tables.tube_leg(radius, height, "metal", "foot")):
        v = np.vstack([p.vertices for p in pieces])
        assert v[:, 2].min() == pytest.approx(0.0, abs=1e-9)
        assert v[:, 2].max() == pytest.approx(height, abs=1e-9)
        for p in pieces:
            assert triangles.is_closed(p.faces) and measures.solids(p)[0][0] > 0
    plate, rod = tables.hairpin_leg(radius, height, "metal")
    top = rod.vertices[rod.vertices[:, 2] > height - tables.HAIRPIN_PLATE - 1e-9]
    lo, hi = plate.bounds
    assert (top[:, :2] >= lo[:2] - 1e-9).all() and (top[:, :2] <= hi[:2] + 1e-9).all()  # rods end under the plate
    # the two rods stand HAIRPIN_SPREAD or more apart along the diagonal at the top
    assert np.ptp(rod.vertices[:, 0]) * np.sqrt(2) >= 2 * tables.HAIRPIN_SPREAD


def test_categories_draw_the_new_parts():
    # seed 17 is a lift-top coffee table: its four legs are hairpins in the metal finish
    bp = api.blueprint("cocktail_table", 17, leg_style="hairpin")
    rods = [p for p in bp.parts["body"].pieces if p.material == "metal" and len(p.convex) > 5]
    assert len(rods) == 4
    assert min(p.bounds[0][2] for p in rods) == pytest.approx(0.0, abs=1e-6)
    bp = api.blueprint("cocktail_table", 13, leg_style="tube")
    assert sum(p.material == "foot" for p in bp.parts["body"].pieces) == 4
    # dining_table seed 2 has a drawer; a bow pull is one tube on its front
    bp = api.blueprint("dining_table", 2, handle_style="bow")
    bows = [p for p in bp.parts["drawer_0"].pieces if p.material == "handle"]
    assert len(bows) == 1 and len(bows[0].convex) == 14  # 15 path points: two feet and a 13-point arch


def test_rocker_switch_paddle_rocks_inside_its_bezel():
    from infmob_usd.rotation import axis_angle

    asm = hardware.rocker_switch("switch")
    (joint,) = asm.joints
    (dof,) = joint.dofs
    paddle = asm.parts["rocker"].pieces[0].vertices
    il = hardware.ROCKER["length"] / 2 - hardware.ROCKER["rim"]
    ends = []
    for q in np.linspace(dof.lower, dof.upper, 9):  # from the "off" stop to the "on" stop
        r = axis_angle(np.asarray(dof.axis), q)
        v = (paddle - dof.origin) @ r.T + dof.origin
        assert v[:, 2].min() > 0  # never into the surface it is mounted on
        assert np.abs(v[:, 0]).max() < il  # never through the bezel's ends
        ends.append(v[v[:, 0] > 0, 2].mean() - v[v[:, 0] < 0, 2].mean())
    assert ends[0] < 0 < ends[-1]  # the +x end goes from down to up
    assert dof.upper == pytest.approx(2 * hardware.ROCKER["throw"])


def test_lamp_draws_a_rocker_switch():
    bp = api.blueprint("lamp", 20)
    (joint,) = [j for j in bp.joints if j.child == "switch"]
    assert joint.kind == "revolute" and joint.role == "button"
