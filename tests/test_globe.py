"""A globe's printed map is the Earth's: its land lies where the continents are (Natural Earth's 1:110m land), about
29 % of the surface, the right way round (not mirrored), turned about its polar axis so a chosen longitude faces
the front at rest."""

from __future__ import annotations

import numpy as np

from infmob_usd.categories.parts import globes as G


def _lat_lon(piece, gl, facing):
    turn = G.Frame.at(gl.centre, z=gl.axis, x=(1, 0, 0)).matrix
    local = (piece.vertices - np.asarray(gl.centre)) @ turn[:3, :3]
    r = np.linalg.norm(local, axis=1)
    lat = np.degrees(np.arcsin(local[:, 2] / r))
    lon = (np.degrees(np.arctan2(local[:, 1], local[:, 0])) + facing + 180.0) % 360.0 - 180.0
    return lat, lon


def _near(lat, lon, at, within):
    d = np.hypot(lat - at[0], ((lon - at[1] + 180.0) % 360.0 - 180.0) * np.cos(np.radians(at[0])))
    return bool((d < within).any())


def test_the_printed_land_is_the_earths():
    gl = G.make("desk", 0.5, 0.5)
    facing = G.FACING[int(np.random.default_rng(3).integers(len(G.FACING)))]
    land = G._continents(gl, "land", np.random.default_rng(3))
    lat, lon = _lat_lon(land, gl, facing)
    for place in ((23.0, 10.0), (-25.0, 134.0), (-10.0, -55.0), (45.0, -100.0), (60.0, 100.0), (-80.0, 0.0)):
        assert _near(lat, lon, place, 1.5), f"no land printed at {place} (Sahara, Australia, Amazon, ...)"
    for place in ((0.0, -150.0), (-30.0, 80.0), (30.0, -40.0), (-50.0, -120.0)):
        assert not _near(lat, lon, place, 5.0), f"land printed in the open ocean at {place}"
    tri = land.vertices[land.faces]
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1).sum()
    share = area / (4 * np.pi * (gl.radius + G.RAISE) ** 2)
    assert 0.26 < share < 0.33, f"land covers {share:.2f} of the globe (the Earth's: 0.29)"
