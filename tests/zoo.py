"""A hand-built object with one joint of every kind, independent of any category."""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.api import assemble
from infmob_usd.blueprint import Blueprint


def zoo_blueprint() -> Blueprint:
    bp = Blueprint("zoo", materials={"body": "painted", "part": "plastic"})
    bp.add("base", "body", [g.box_between([-0.1, -1.0, 0.0], [0.1, 1.0, 0.05], "body")])
    xs = np.linspace(-0.85, 0.85, 9)
    z = 0.3

    def part(name, k):
        return bp.add(name, "part", [g.box([0.06, 0.06, 0.06], [0.0, xs[k], z], "part")])

    bp.join(J.fixed("base", part("fixed_part", 0)))
    bp.join(J.revolute("base", part("rev_part", 1), (0, xs[1], z), (0, 0, 1), 0.0, math.pi / 2))
    bp.join(J.continuous("base", part("cont_part", 2), (0, xs[2], z), (0, 0, 1)))
    bp.join(J.prismatic("base", part("pris_part", 3), (0, xs[3], z), (1, 0, 0), 0.0, 0.2))
    bp.join(J.revolute_prismatic("base", part("rp_part", 4), (0, xs[4], z), (0, 0, 1), (-1.0, 1.0),
                                 (0, 0, 1), (0.0, 0.1)))
    bp.join(J.continuous_prismatic("base", part("cp_part", 5), (0, xs[5], z), (0, 0, 1), (0.0, 0.05)))
    bp.join(J.limited_planar("base", part("lp_part", 6), (0, xs[6], z), ((0, 1, 0), (0, 0, 1)),
                             ((-0.05, 0.05), (0.0, 0.1)), (1, 0, 0), (-0.3, 0.3)))
    bp.join(J.limited_floating("base", part("lf_part", 7), (0, xs[7], z), ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
                               ((0.0, 0.1), (-0.02, 0.02), (0.0, 0.05))))
    bp.join(J.flip_revolute("base", part("fr_part", 8), (0.03, xs[8], z), (0, 1, 0), (0.0, 1.0),
                            (-0.03, xs[8], z), (0, 1, 0), (0.0, 1.0)))
    return bp


def zoo(seed: int = 0, texture_size: int = 32):
    return assemble(zoo_blueprint(), seed, np.random.default_rng(seed), texture_size)


def make_bp(module, name, seed, **overrides):
    """``(params, blueprint)`` of category module ``module`` (id ``name``) for ``seed``, grounded:
    the blueprint path of :func:`infmob_usd.generate`, for tests of one category."""
    from infmob_usd import get_category, physical
    from infmob_usd.seeding import streams

    cat = get_category(name)
    r = streams(name, seed)
    p = cat.schema.sample(r["params"], overrides)
    bp = cat.build(p, r["structure"], r["geometry"])
    bp = physical.rest_on_ground(bp)
    return p, bp


def movable(bp):
    """The movable joints of a blueprint (or object), in order."""
    return [j for j in bp.joints if j.movable]


def by_child(bp, name):
    """The joint whose child is part ``name``."""
    return next(j for j in bp.joints if j.child == name)


def object_limits(name, seed, bp, **overrides):
    """``bp`` with the joint limits and axes of the generated object (after the core's
    ``rest_on_stops`` and ``limit_to_clearance``); joints with one DoF only."""
    from dataclasses import replace

    from infmob_usd.api import generate

    obj = generate(name, seed, 16, **overrides)
    final = {j.child: j for j in obj.movable_joints}
    fixed = {j.child for j in obj.joints if j.type == "fixed"}  # a joint the passes left too short to move

    def limited(j):
        if not (j.movable and len(j.dofs) == 1):
            return j
        if j.child in final:
            f = final[j.child]
            return replace(j, dofs=(replace(j.dofs[0], lower=f.lower, upper=f.upper, axis=tuple(f.axis)),))
        if j.child in fixed:
            return replace(j, kind="fixed", dofs=())
        return j

    bp.joints = [limited(j) for j in bp.joints]
    return bp


def spring_blueprint() -> Blueprint:
    """One joint of every spring-returned role on a fixed base (a push button, a pen-style plunger
    pressed down, a lever whose weight pulls it off its stop, a self-closing door) and a pedal whose
    lid follows it (``Layout.couple``: the lid turns three times the pedal's angle)."""
    from types import SimpleNamespace

    from infmob_usd.grammar import Layout

    bp = Blueprint("spring_zoo", materials={"body": "painted", "part": "plastic"})
    bp.add("base", "body", [g.box_between([-0.1, -1.0, 0.0], [0.1, 1.0, 0.05], "body")])
    lay = Layout(bp, {}, np.random.default_rng(0), None)
    at = lambda o, z: SimpleNamespace(origin=o, z=z)  # noqa: E731  (a frame: origin and axis)
    bp.add("button", "part", [g.box([0.02, 0.02, 0.02], [0.0, -0.8, 0.3], "part")])
    lay.slide("base", "button", at((0.0, -0.8, 0.3), (-1, 0, 0)), upper=0.004, role="button")
    bp.add("plunger", "part", [g.box([0.01, 0.01, 0.04], [0.0, -0.5, 0.3], "part")])
    lay.slide("base", "plunger", at((0.0, -0.5, 0.3), (0, 0, -1)), upper=0.006, role="plunger")
    bp.add("lever", "part", [g.box([0.08, 0.01, 0.01], [0.04, -0.2, 0.3], "part")])
    lay.hinge("base", "lever", at((0.0, -0.2, 0.3), (0, 1, 0)), upper=0.5, role="lever")
    bp.add("door", "part", [g.box([0.01, 0.3, 0.3], [0.0, 0.25, 0.3], "part")])
    lay.hinge("base", "door", at((0.0, 0.1, 0.3), (0, 0, 1)), upper=1.2, role="self_closing")
    bp.add("pedal", "part", [g.box([0.06, 0.04, 0.01], [0.03, 0.7, 0.3], "part")])
    lay.hinge("base", "pedal", at((0.0, 0.7, 0.3), (0, -1, 0)), upper=0.4, role="hinge")
    bp.add("lid", "part", [g.box([0.15, 0.1, 0.01], [0.0, 0.85, 0.45], "part")])
    lay.hinge("base", "lid", at((-0.075, 0.85, 0.45), (0, -1, 0)), upper=1.2, role="pedal_lid")
    lay.couple("lid", "pedal", ratio=3.0)
    return bp


def spring_zoo(seed: int = 0, texture_size: int = 16):
    return assemble(spring_blueprint(), seed, np.random.default_rng(seed), texture_size)
