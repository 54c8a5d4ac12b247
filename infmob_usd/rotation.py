"""Rotations, in one place: every ``(3, 3)`` rotation matrix of the package is built here.

Built on :class:`scipy.spatial.transform.Rotation` where it fits. Conventions: right-handed,
angles in radians, matrices act on column vectors (``v' = R @ v``), URDF roll-pitch-yaw is
rotation about the fixed X, then Y, then Z axes (``R = Rz(yaw) Ry(pitch) Rx(roll)``, scipy's
extrinsic ``"xyz"``).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Sequence

import numpy as np
from scipy.spatial.transform import Rotation


def axis_angle(axis: Sequence[float], angle: float) -> np.ndarray:
    """The ``(3, 3)`` rotation by ``angle`` radians about the unit ``axis`` (right-hand rule)."""
    a = np.asarray(axis, float)
    angle = float(angle)
    if angle == 0.0 and a.shape == (3,) and np.isfinite(a).all():
        # no turn (every joint at rest in forward kinematics): scipy's identity for this rotation
        # vector, bit for bit (signed zeros included), without the ~30 us of a scipy call
        rv = a * angle
        key = tuple(np.signbit(rv).tolist())
        if key not in _NO_TURN:
            _NO_TURN[key] = Rotation.from_rotvec(rv).as_matrix()
        return _NO_TURN[key].copy()
    # the same turns recur (forward kinematics of the same states, bisections): remember them
    key = (a.shape, a.tobytes(), angle.hex())
    turn = _TURNS.get(key)
    if turn is None:
        turn = Rotation.from_rotvec(a * angle).as_matrix()
        if len(_TURNS) >= 4096:
            _TURNS.clear()
        _TURNS[key] = turn
    return turn.copy()


_NO_TURN: dict[tuple, np.ndarray] = {}
_EYE4 = np.eye(4)
_EYE4.flags.writeable = False
_TURNS: dict[tuple, np.ndarray] = {}  # (axis shape, axis bytes, angle.hex()) -> scipy's matrix


def axis_angles(axis: Sequence[float], angles: Sequence[float]) -> np.ndarray:
    """``(n, 3, 3)``: :func:`axis_angle` for each of ``angles`` (the same bits), in one scipy call."""
    a = np.asarray(axis, float)
    angles = np.asarray(angles, float).reshape(-1)
    return Rotation.from_rotvec(a[None, :] * angles[:, None]).as_matrix().reshape(len(angles), 3, 3)


def rotation_between(a: Sequence[float], b: Sequence[float]) -> np.ndarray:
    """The smallest ``(3, 3)`` rotation taking direction ``a`` onto direction ``b`` (any lengths);
    opposite directions turn by pi about an axis perpendicular to ``a``."""
    a = np.asarray(a, float) / np.linalg.norm(a)
    b = np.asarray(b, float) / np.linalg.norm(b)
    axis = np.cross(a, b)
    s, c = float(np.linalg.norm(axis)), float(np.dot(a, b))
    if s < 1e-12:
        if c > 0:
            return np.eye(3)
        p = np.cross(a, [1.0, 0, 0]) if abs(a[0]) < 0.9 else np.cross(a, [0, 1.0, 0])
        return axis_angle(p / np.linalg.norm(p), math.pi)
    return axis_angle(axis / s, math.atan2(s, c))


def align_z(direction: Sequence[float]) -> np.ndarray:
    """A ``(3, 3)`` rotation taking +Z onto the unit ``direction``: the frame a cylinder along
    ``direction`` is built in (its turn about ``direction`` is fixed by this construction, as
    ``trimesh.geometry.align_vectors`` makes it: changing it moves every tilted cylinder's
    vertices). Cached per direction and read-only (most cylinders run along a few directions)."""
    return _align_z(tuple(float(x) for x in direction))


@functools.lru_cache(maxsize=1024)
def _align_z(direction: tuple[float, float, float]) -> np.ndarray:
    # the left singular vectors of each vector, made proper: their first column is the vector
    au = np.linalg.svd(np.array([[0.0], [0.0], [1.0]]))[0]
    bu = np.linalg.svd(np.array(direction, float).reshape(3, 1))[0]
    if np.linalg.det(au) < 0:
        au[:, -1] *= -1.0
    if np.linalg.det(bu) < 0:
        bu[:, -1] *= -1.0
    rot = bu @ au.T
    rot.flags.writeable = False
    return rot


def rpy_matrix(rpy: Iterable[float]) -> np.ndarray:
    """The ``(3, 3)`` rotation of URDF ``rpy="roll pitch yaw"``: ``Rz(yaw) Ry(pitch) Rx(roll)``."""
    return Rotation.from_euler("xyz", [float(x) for x in rpy]).as_matrix()


def matrix_rpy(rot: np.ndarray) -> tuple[float, float, float]:
    """URDF roll, pitch, yaw of a ``(3, 3)`` rotation (the inverse of :func:`rpy_matrix`); at
    gimbal lock (pitch +-pi/2) the roll is folded into the yaw (roll = 0)."""
    sp = -float(rot[2, 0])
    if abs(sp) > 1 - 1e-12:
        return 0.0, math.copysign(math.pi / 2, sp), math.atan2(-float(rot[0, 1]), float(rot[1, 1]))
    return (math.atan2(float(rot[2, 1]), float(rot[2, 2])), math.asin(sp),
            math.atan2(float(rot[1, 0]), float(rot[0, 0])))


def transform(xyz: Iterable[float] = (0, 0, 0), rpy: Iterable[float] = (0, 0, 0)) -> np.ndarray:
    """The ``(4, 4)`` rigid transform of a URDF ``<origin xyz rpy>``."""
    m = np.eye(4)
    m[:3, :3] = rpy_matrix(rpy)
    m[:3, 3] = [float(x) for x in xyz]
    return m


def motion(kind: str, axis: Sequence[float], value: float) -> np.ndarray:
    """The ``(4, 4)`` motion of a simple joint of type ``kind`` moved to ``value`` about (or along)
    the unit ``axis`` through the frame origin: a rotation (revolute, continuous), a translation
    (prismatic), or the identity (fixed). Every forward kinematics is a product of these."""
    m = _EYE4.copy()  # np.eye(4)
    if kind == "prismatic":
        m[:3, 3] = np.asarray(axis, float) * value
    elif kind in ("revolute", "continuous"):
        m[:3, :3] = axis_angle(axis, value)
    return m
