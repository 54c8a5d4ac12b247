"""Globes: a desk globe on a semi-meridian, a floor globe in a full meridian and horizon ring; the printed map.

The globe turns about its polar axis, tilted 23.4 degrees from vertical (the Earth's obliquity) towards +y, in the
y-z plane through its centre; its meridian holds the axis at the poles. Built standing on z = 0, centred on the z
axis, the stand's front facing +x.

* ``desk``: a round foot and a turned stem; the semi-meridian runs from the north pole round the +y side and under
  the globe to the south pole, and turns on the stem (a swivel about the vertical).
* ``floor``: four legs carry a horizon ring at the globe's equator; the full meridian stands in two notches of the
  horizon ring (at +-y) and on a cradle under the globe, and turns in them about x (the tilt is set by hand).

The map is printed: the Earth's continents (Natural Earth's 1:110m land on a 1-degree grid, :mod:`.world_map`),
raised 0.5 mm as a decoration over the ocean-coloured sphere, turned at rest to face the stand's front with the
Americas, Europe and Africa, or Asia; the equator and the two tropics are printed lines.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from . import world_map

TILT = math.radians(23.4)  # the Earth's axial tilt: every globe mounts its axis at it
# Sizes (m). Desk globes: 20-32 cm spheres (Replogle 12 in "World Classic" 30 cm, 16-18 in tall; Waypoint
# Geographic 10 in), 0.8-2.5 kg. Floor globes: 30-50 cm spheres (Replogle 16 in / 20 in floor globes, 36-42 in
# tall), 7-20 kg; their legs and horizon ring hardwood.
DESK = {"radius": (0.10, 0.16), "stem": (0.06, 0.12), "foot": 1.05}  # foot radius: of the globe's
FLOOR = {"radius": (0.15, 0.25), "height": (0.92, 1.07)}  # floor to top of the globe
SHELL = 0.0025  # m, a globe's wall (a pressed-paper or moulded plastic sphere)
GAP = 0.004  # m, the globe's clearance inside its meridian
BAND = {"desk": (0.004, 0.012), "floor": (0.005, 0.018)}  # meridian's radial thickness, width across
HORIZON = {"width": 0.06, "thick": 0.012, "notch": 0.006}  # a floor globe's horizon ring: band, its notches' play
RAISE = 0.0005  # m, printed land and lines stand off the sphere (ink has no thickness; enough not to z-fight)
MAP_DETAIL = 6  # icosphere subdivisions of the printed land: faces ~1.1 degrees across, as fine as the map
FACING = (-75.0, 15.0, 105.0)  # longitudes (degrees E) at the front at rest: the Americas, Europe-Africa, Asia
STRETCHER = 0.12  # m, a floor stand's stretchers' height from the floor
MERIDIAN_SWING = {"desk": math.pi / 2, "floor": math.radians(30)}  # desk: turns on its stem; floor: tilt set


@dataclass(frozen=True)
class Globe:
    design: str
    radius: float
    centre: tuple[float, float, float]

    @property
    def axis(self) -> np.ndarray:
        """The polar axis (north up, tilted towards +y)."""
        return np.array((0.0, math.sin(TILT), math.cos(TILT)))

    @property
    def meridian_r(self) -> tuple[float, float]:
        """The meridian's inner and outer radius."""
        inner = self.radius + GAP
        return inner, inner + BAND[self.design][0]


def _lerp(lo_hi, f: float) -> float:
    return lo_hi[0] + f * (lo_hi[1] - lo_hi[0])


def make(design: str, size: float, height: float) -> Globe:
    """A globe of ``design`` at ``size`` and ``height`` (0-1 through their ranges)."""
    if design == "desk":
        r = _lerp(DESK["radius"], size)
        zc = 0.02 + _lerp(DESK["stem"], height) + r + GAP + BAND["desk"][0]
        return Globe(design, r, (0.0, 0.0, zc))
    r = _lerp(FLOOR["radius"], size)
    return Globe(design, r, (0.0, 0.0, _lerp(FLOOR["height"], height) - r))


# -- the sphere and its map ------------------------------------------------------------------------------------------
def sphere(gl: Globe, ocean: str, land: str, lines: str, rng: np.random.Generator) -> list[g.Piece]:
    """The globe: a hollow sphere in ``ocean``, its continents and printed lines, and the axis stubs that meet the
    meridian at the poles."""
    c, r, a = np.asarray(gl.centre), gl.radius, gl.axis
    ball = g.sphere(c, r, ocean).replace(wall=SHELL)
    inner, _ = gl.meridian_r
    stubs = [g.cylinder(c + s * (r - 0.003) * a, c + s * (inner - 0.0012) * a, 0.003, lines, 12) for s in (-1, 1)]
    grasp = Grasp.make(c + r * np.array((1.0, 0.0, 0.0)), (-1, 0, 0), (0, 0, 1), 0.06, 0.01)
    return [ball.with_grasps(grasp), _continents(gl, land, rng), *_graticule(gl, lines), *stubs]


def _continents(gl: Globe, slot: str, rng: np.random.Generator) -> g.Piece:
    """Land: the faces of a fine sphere whose centres fall on land in the world map (Natural Earth's 1:110m land,
    :mod:`.world_map`), raised ``RAISE`` over the sphere, turned so that its poles are the globe's and, at rest, one
    of :data:`FACING` faces the stand's front (drawn from ``rng``)."""
    ico = trimesh.creation.icosphere(subdivisions=MAP_DETAIL, radius=1.0)
    v, f = np.asarray(ico.vertices), np.asarray(ico.faces)
    centre = v[f].mean(1)
    lat = np.degrees(np.arcsin(np.clip(centre[:, 2] / np.linalg.norm(centre, axis=1), -1.0, 1.0)))
    lon = np.degrees(np.arctan2(centre[:, 1], centre[:, 0])) + FACING[int(rng.integers(len(FACING)))]
    land = _manifold(f, _land()[_cell(90.0 - lat, 180), _cell((lon + 180.0) % 360.0, 360)])
    used, faces = np.unique(f[land], return_inverse=True)
    turn = Frame.at(gl.centre, z=gl.axis, x=(1, 0, 0))
    verts = v[used] * (gl.radius + RAISE)
    return g.Piece(verts, faces.reshape(-1, 3), slot).transformed(turn.matrix)


def _manifold(f: np.ndarray, land: np.ndarray) -> np.ndarray:
    """``land`` grown until no vertex joins two patches by a corner alone (four or more coast edges meet
    there): each such vertex's faces all become land, so the printed land is a manifold surface."""
    for _ in range(20):
        tri = f[land]
        edges = np.sort(np.r_[tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]], axis=1)
        uniq, count = np.unique(edges, axis=0, return_counts=True)
        coast = np.bincount(uniq[count == 1].ravel(), minlength=f.max() + 1)
        pinched = coast > 2
        if not pinched.any():
            break
        land = land | pinched[f].any(axis=1)
    return land


def _cell(deg: np.ndarray, n: int) -> np.ndarray:
    return np.clip((deg / world_map.RES).astype(int), 0, n - 1)


@functools.cache
def _land() -> np.ndarray:
    """The world map as (180, 360) booleans, row 0 at 90 N, column 0 at 180 W."""
    rows = []
    for line in world_map.ROWS:
        runs = [int(n) for n in line.split()]
        rows.append(np.repeat(np.arange(len(runs)) % 2 == 1, runs))
    return np.array(rows)


def _graticule(gl: Globe, slot: str) -> list[g.Piece]:
    """The equator and the tropics (23.4 degrees north and south): thin printed rings on the sphere."""
    out = []
    turn = Frame.at(gl.centre, z=gl.axis, x=(1, 0, 0))
    for lat in (0.0, TILT, -TILT):
        rr, zz = (gl.radius + RAISE) * math.cos(lat), (gl.radius + RAISE) * math.sin(lat)
        w = 0.0012 if lat == 0.0 else 0.0007
        ring = g.shell([(rr + 0.0002, zz - w / 2), (rr + 0.0002, zz + w / 2)], 0.0004, slot)
        out.append(ring.replace(convex=()).transformed(turn.matrix))
    return out


def spin_axis(gl: Globe) -> Frame:
    """The globe's polar axis through its centre (z north: a positive turn is the Earth's, eastward)."""
    return Frame.at(gl.centre, z=gl.axis, x=(1, 0, 0))


# -- meridians and stands ----------------------------------------------------------------------------------------------
def _arc(frame: Frame, r_in: float, r_out: float, half_w: float, a0: float, a1: float, slot: str) -> g.Piece:
    """A flat band bent round ``frame``'s z axis from angle ``a0`` to ``a1`` (about z, from x), ``half_w`` either
    side of the x-y plane; one convex block per segment."""
    n = max(4, int(math.ceil(abs(a1 - a0) / math.radians(6))))
    ang = np.linspace(a0, a1, n + 1)
    ring = []
    for a in ang:
        ca, sa = math.cos(a), math.sin(a)
        ring.append([(r * ca, r * sa, z) for r in (r_in, r_out) for z in (-half_w, half_w)])
    ring = np.asarray(ring)  # (n+1, 4, 3): inner-low, inner-high, outer-low, outer-high
    verts = ring.reshape(-1, 3)
    faces = []
    for k in range(n):
        o, p = 4 * k, 4 * (k + 1)
        idx = [o, o + 1, o + 2, o + 3, p, p + 1, p + 2, p + 3]
        for q in ((0, 2, 6, 4), (1, 5, 7, 3), (0, 4, 5, 1), (2, 3, 7, 6)):  # low, high, inner, outer faces
            a, b, c_, d = (idx[i] for i in q)
            faces += [(a, b, c_), (a, c_, d)]
    for i0, (a, b, c_, d) in ((0, (0, 1, 3, 2)), (4 * n, (2, 3, 1, 0))):  # the two end caps
        faces += [(i0 + a, i0 + b, i0 + c_), (i0 + a, i0 + c_, i0 + d)]
    mesh = trimesh.Trimesh(verts, np.asarray(faces), process=False)
    mesh.fix_normals()
    convex = [ring[k:k + 2].reshape(-1, 3) for k in range(n)]
    return g.Piece(mesh.vertices, mesh.faces, slot, convex).transformed(frame.matrix)


def semi_meridian(gl: Globe, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A desk globe's semi-meridian: a band from the north pole round the +y side and under the globe to the south
    pole, a hub where it sits on the stem; returns its pieces, its swivel (z up through the stem) and its swing."""
    inner, outer = gl.meridian_r
    half = BAND["desk"][1] / 2
    # the meridian's plane is y-z: frame x along +z (angle 0 at the top), y along +y, z along -x
    plane = Frame.at(gl.centre, x=(0, 0, 1), z=(-1, 0, 0))
    band = _arc(plane, inner, outer, half, TILT, math.pi + TILT, slot)
    c = np.asarray(gl.centre)
    bottom = c - (0, 0, outer)
    hub = g.cylinder(bottom - (0, 0, 0.012), bottom + (0, 0, 0.001), 0.012, slot, 24)
    bosses = [g.cylinder(c + s * (outer - 0.001) * gl.axis, c + s * (outer + 0.004) * gl.axis, 0.006, slot, 16)
              for s in (-1, 1)]
    grasp = Grasp.make(c + (0, outer, 0), (0, -1, 0), (1, 0, 0), 2 * half, 0.004)
    pieces = [band.with_grasps(grasp), hub, *bosses]
    return pieces, Frame.at(bottom - (0, 0, 0.012), z=(0, 0, 1), x=(1, 0, 0)), MERIDIAN_SWING["desk"]


def desk_stand(gl: Globe, slot: str) -> list[g.Piece]:
    """A round foot and a turned stem up to just under the meridian's hub."""
    _, outer = gl.meridian_r
    top = gl.centre[2] - outer - 0.012 - 0.0012
    rf = DESK["foot"] * gl.radius * 0.7
    foot = g.revolve([(0.0, 0.0), (rf, 0.0), (rf, 0.006), (0.85 * rf, 0.02), (0.2 * rf, 0.03), (0.0, 0.03)], slot)
    stem = g.revolve([(0.0, 0.028), (0.018, 0.028), (0.011, 0.06), (0.009, top - 0.02), (0.014, top - 0.006),
                      (0.012, top), (0.0, top)], slot)
    return [foot, stem]


def swivel_collar(gl: Globe, slot: str) -> list[g.Piece]:
    """A swivel stand's bearing: a collar round the stem's top, under the meridian's hub."""
    _, outer = gl.meridian_r
    top = gl.centre[2] - outer - 0.012 - 0.0012
    return [g.cylinder((0.0, 0.0, top - 0.012), (0.0, 0.0, top), 0.016, slot, 24)]


def full_meridian(gl: Globe, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A floor globe's full meridian: a ring in the y-z plane; returns it, its axis (z along +x through the centre:
    turning it in its notches sets the tilt) and its swing either side."""
    inner, outer = gl.meridian_r
    half = BAND["floor"][1] / 2
    ring = g.shell([(outer, -half), (outer, half)], outer - inner, slot)
    at = Frame.at(gl.centre, z=(1, 0, 0), x=(0, 0, 1))
    c = np.asarray(gl.centre)
    bosses = [g.cylinder(c + s * (outer - 0.001) * gl.axis, c + s * (outer + 0.005) * gl.axis, 0.008, slot, 16)
              for s in (-1, 1)]
    grasp = Grasp.make(c + (0, 0, outer), (0, 0, -1), (1, 0, 0), 2 * half, 0.004)
    return [ring.transformed(at.matrix).with_grasps(grasp), *bosses], at, MERIDIAN_SWING["floor"]


def floor_stand(gl: Globe, slot: str) -> list[g.Piece]:
    """Four legs to a horizon ring at the equator (notched at +-y for the meridian), stretchers to a central post
    and a cradle under the meridian."""
    _, outer = gl.meridian_r
    c = np.asarray(gl.centre)
    h_in, h_out = outer + 0.004, outer + 0.004 + HORIZON["width"]
    t, half_m = HORIZON["thick"], BAND["floor"][1] / 2
    flat = Frame.at(c, z=(0, 0, 1), x=(1, 0, 0))
    gap = math.asin(min(1.0, (half_m + HORIZON["notch"]) / h_in))  # the notch's half angle at the inner edge
    pieces = [_arc(flat, h_in, h_out, t / 2, math.pi / 2 + gap + 0.02, 3 * math.pi / 2 - gap - 0.02, slot),
              _arc(flat, h_in, h_out, t / 2, -math.pi / 2 + gap + 0.02, math.pi / 2 - gap - 0.02, slot)]
    r_leg = (h_in + h_out) / 2
    zt = c[2] - t / 2
    for k in range(4):
        a = math.pi / 4 + k * math.pi / 2
        top = np.array((r_leg * math.cos(a), r_leg * math.sin(a), zt))
        foot = np.array((1.1 * r_leg * math.cos(a), 1.1 * r_leg * math.sin(a), 0.0))
        on_leg = foot + (top - foot) * (STRETCHER / zt)
        pieces += [g.cylinder(foot, top, 0.016, slot, 16), g.cylinder(on_leg, (0.0, 0.0, STRETCHER), 0.01, slot, 12)]
    cradle_top = c[2] - outer - 0.0015
    pieces.append(g.revolve([(0.0, STRETCHER - 0.02), (0.025, STRETCHER - 0.02), (0.02, STRETCHER + 0.02),
                             (0.012, cradle_top - 0.02),
                             (0.02, cradle_top - 0.005), (0.02, cradle_top), (0.0, cradle_top)], slot))
    return pieces
