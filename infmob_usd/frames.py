"""Poses and placement patterns: how categories and parts say *where* without matrices.

A :class:`Frame` is a rigid pose (an origin and three orthonormal axes) in
world coordinates, or in the local frame of a part. Categories and part
builders compose frames (``a @ b``), move them along their own axes
(:meth:`Frame.moved`), turn them about their own axes (:meth:`Frame.turned`)
and ask for patterns of them (:func:`row`, :func:`grid`, :func:`polar`,
:func:`cells`); the core turns frames into matrices. Nothing outside this
module and the geometry kernel builds a rotation matrix.

Conventions: metres, Z up, fronts face +X; angles in radians, right-handed.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .errors import GeometryError

V3 = Sequence[float]
_AXES = {"x": 0, "y": 1, "z": 2}


_EYE3 = np.eye(3)
_ORTHONORMAL_TOL = 1e-8 + 1e-5 * np.abs(_EYE3)  # np.allclose's bound against the identity, atol=1e-8


def _triple(r: list) -> float:
    """``det`` of a ``(3, 3)`` matrix given as rows, as the triple product ``r0 . (r1 x r2)``."""
    (a, b, c), (d, e, f), (g, h, i) = r
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)


def _unit(v: V3, what: str) -> np.ndarray:
    a = np.asarray(v, float)
    n = float(np.linalg.norm(a))
    if a.shape != (3,) or not np.isfinite(a).all() or n < 1e-12:
        raise GeometryError(f"{what} must be a finite non-zero 3-vector, got {v!r}")
    return a / n


def _rotation(axis: V3, angle: float) -> np.ndarray:
    """``(3, 3)`` rotation by ``angle`` about the unit ``axis`` (Rodrigues, as the kernel's)."""
    from .rotation import axis_angle

    return axis_angle(_unit(axis, "rotation axis"), float(angle))


@dataclass(frozen=True, eq=False)
class Frame:
    """A rigid pose: ``origin`` ``(3,)`` and ``rotation`` ``(3, 3)`` whose columns are the x, y, z axes.

    Build one with :meth:`at` (an origin and one or two axis directions), then
    derive others with :meth:`moved`, :meth:`turned`, :meth:`facing` and
    composition ``parent @ local``. Frames are immutable values.
    """

    origin: np.ndarray
    rotation: np.ndarray

    def __post_init__(self) -> None:
        o = np.array(self.origin, dtype=float).reshape(3)
        r = np.array(self.rotation, dtype=float).reshape(3, 3)
        if not (np.isfinite(o).all() and np.isfinite(r).all()):
            raise GeometryError("a frame needs a finite origin and rotation")
        # np.allclose(r.T @ r, np.eye(3), atol=1e-8) for finite r, then the sign of det(r) (near +-1
        # once orthonormal: the triple product's sign is the determinant's), without their overhead
        if not (np.abs(r.T @ r - _EYE3) <= _ORTHONORMAL_TOL).all() or _triple(r.tolist()) < 0:
            raise GeometryError("a frame's axes must be orthonormal and right-handed")
        o.setflags(write=False)
        r.setflags(write=False)
        object.__setattr__(self, "origin", o)
        object.__setattr__(self, "rotation", r)

    # -- construction ----------------------------------------------------------------------------
    @classmethod
    def at(cls, origin: V3 = (0.0, 0.0, 0.0), x: V3 | None = None, z: V3 | None = None,
           y: V3 | None = None) -> Frame:
        """A frame at ``origin`` whose axes point along the given directions.

        Give at most two of ``x``, ``y``, ``z`` (the first named in the order
        z, x, y is kept exactly, the second is made perpendicular to it); the
        rest default to the world axes.
        """
        given = {k: _unit(v, f"{k} axis") for k, v in (("z", z), ("x", x), ("y", y)) if v is not None}
        if len(given) > 2:
            raise GeometryError("Frame.at takes at most two axis directions")
        if not given:
            return cls(origin, np.eye(3))
        (k1, a1), *rest = given.items()
        if rest:
            k2, a2 = rest[0]
        else:  # the world axis least parallel to a1, among the two others of k1
            k2 = next(k for k in ("z", "x", "y") if k != k1 and abs(a1[_AXES[k]]) < 0.9)
            a2 = np.eye(3)[_AXES[k2]]
        a2 = a2 - a1 * float(a1 @ a2)
        if np.linalg.norm(a2) < 1e-9:
            raise GeometryError(f"Frame.at: {k1} and {k2} axes are parallel")
        a2 = a2 / np.linalg.norm(a2)
        cols: dict[str, np.ndarray] = {k1: a1, k2: a2}
        (k3,) = {"x", "y", "z"} - set(cols)
        # right-handed: x = y * z, y = z * x, z = x * y
        nxt = {"x": ("y", "z"), "y": ("z", "x"), "z": ("x", "y")}[k3]
        cols[k3] = np.cross(cols[nxt[0]], cols[nxt[1]])
        return cls(origin, np.column_stack([cols["x"], cols["y"], cols["z"]]))

    @classmethod
    def from_matrix(cls, m: np.ndarray) -> Frame:
        m = np.asarray(m, float)
        return cls(m[:3, 3], m[:3, :3])

    # -- reading -------------------------------------------------------------------------------
    @property
    def x(self) -> np.ndarray:
        return self.rotation[:, 0]

    @property
    def y(self) -> np.ndarray:
        return self.rotation[:, 1]

    @property
    def z(self) -> np.ndarray:
        return self.rotation[:, 2]

    def axis(self, name: str) -> np.ndarray:
        """The world direction of a local axis: ``"x"``, ``"-y"`` ..."""
        sign = -1.0 if name.startswith("-") else 1.0
        return sign * self.rotation[:, _AXES[name.lstrip("+-")]]

    @property
    def matrix(self) -> np.ndarray:
        """``(4, 4)`` homogeneous matrix local -> parent."""
        m = np.eye(4)
        m[:3, :3], m[:3, 3] = self.rotation, self.origin
        return m

    def point(self, p: V3) -> np.ndarray:
        """A local point (or ``(n, 3)`` points) in the parent frame."""
        return np.asarray(p, float) @ self.rotation.T + self.origin

    def vector(self, v: V3) -> np.ndarray:
        """A local direction (or ``(n, 3)`` directions) in the parent frame."""
        return np.asarray(v, float) @ self.rotation.T

    def local(self, p: V3) -> np.ndarray:
        """A parent-frame point expressed in this frame."""
        return (np.asarray(p, float) - self.origin) @ self.rotation

    # -- deriving ------------------------------------------------------------------------------
    def __matmul__(self, other: Frame) -> Frame:
        """``self @ other``: ``other`` is given in this frame; the result is in this frame's parent."""
        return Frame(self.point(other.origin), self.rotation @ other.rotation)

    def inverse(self) -> Frame:
        r = self.rotation.T
        return Frame(-r @ self.origin, r)

    def moved(self, dx: float = 0.0, dy: float = 0.0, dz: float = 0.0) -> Frame:
        """The same axes, origin moved along this frame's own axes."""
        return Frame(self.point((dx, dy, dz)), self.rotation)

    def shifted(self, offset: V3) -> Frame:
        """The same axes, origin moved by a parent-frame vector."""
        return Frame(self.origin + np.asarray(offset, float), self.rotation)

    def placed_at(self, origin: V3) -> Frame:
        """The same axes at another origin (parent frame)."""
        return Frame(origin, self.rotation)

    def turned(self, axis: str | V3, angle: float) -> Frame:
        """Turned by ``angle`` about one of its own axes (``"x"``, ``"-z"`` ...) or a local direction."""
        local = np.eye(3)[_AXES[axis.lstrip("+-")]] * (-1 if axis.startswith("-") else 1) \
            if isinstance(axis, str) else _unit(axis, "turn axis")
        return Frame(self.origin, self.rotation @ _rotation(local, angle))

    def facing(self, x: V3) -> Frame:
        """Turned about its own z so that its x axis points as close to ``x`` as z allows."""
        return Frame.at(self.origin, z=self.z, x=np.asarray(x, float) - self.z * float(self.z @ np.asarray(x)))


IDENTITY = Frame(np.zeros(3), np.eye(3))


# -- patterns ---------------------------------------------------------------------------------------
def row(start: Frame, count: int, step: V3) -> list[Frame]:
    """``count`` frames from ``start``, each moved by ``step`` (in ``start``'s axes) from the last."""
    s = np.asarray(step, float)
    return [start.moved(*(s * i)) for i in range(int(count))]


def grid(start: Frame, counts: tuple[int, int], steps: tuple[V3, V3]) -> list[list[Frame]]:
    """Rows of frames: ``grid[i][j]`` is ``start`` moved by ``i * steps[0] + j * steps[1]``."""
    a, b = (np.asarray(s, float) for s in steps)
    return [[start.moved(*(a * i + b * j)) for j in range(int(counts[1]))] for i in range(int(counts[0]))]


def polar(center: Frame, count: int, radius: float, phase: float = 0.0) -> list[Frame]:
    """``count`` frames evenly around ``center``'s z axis at ``radius``, each with x pointing outward.

    Frame ``i`` sits at angle ``phase + 2 pi i / count`` from ``center``'s x axis.
    """
    out = []
    for i in range(int(count)):
        f = center.turned("z", phase + 2 * np.pi * i / count)
        out.append(f.moved(radius))
    return out


def cells(lo: float, hi: float, count: int, gap: float = 0.0) -> list[tuple[float, float]]:
    """``count`` equal intervals filling ``[lo, hi]`` with ``gap`` between neighbours."""
    n = int(count)
    if n < 1 or hi - lo <= gap * (n - 1):
        raise GeometryError(f"cannot fit {n} cells with gap {gap:g} in [{lo:g}, {hi:g}]")
    w = (hi - lo - gap * (n - 1)) / n
    return [(lo + i * (w + gap), lo + i * (w + gap) + w) for i in range(n)]


def spans(lo: float, hi: float, sizes: Sequence[float], gap: float = 0.0) -> list[tuple[float, float]]:
    """Intervals of ``[lo, hi]`` in proportion to ``sizes``, with ``gap`` between neighbours."""
    s = np.asarray(sizes, float)
    if len(s) < 1 or (s <= 0).any():
        raise GeometryError(f"spans need positive sizes, got {list(sizes)}")
    room = hi - lo - gap * (len(s) - 1)
    if room <= 0:
        raise GeometryError(f"no room for {len(s)} spans with gap {gap:g} in [{lo:g}, {hi:g}]")
    edges = lo + np.concatenate([[0.0], np.cumsum(s / s.sum() * room)])
    return [(float(edges[i] + gap * i), float(edges[i + 1] + gap * i)) for i in range(len(s))]
