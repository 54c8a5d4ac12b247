"""MJCF beside the USD and URDF: ``<name>.xml`` for MuJoCo (checked with MuJoCo 4.0.0).

* **bodies nested** as the joint tree: each body at its link frame (world-aligned at rest, so
  ``pos`` = child origin - parent origin, no rotation); fixed joints weld (no ``<joint>``); the
  base is welded to the world, or free (``free_base=True``: a ``<freejoint>``);
* **joints** ``hinge`` / ``slide`` at the body origin with ``range`` (continuous: unlimited),
  ``damping``, ``frictionloss``, ``armature`` and ``actuatorfrcrange`` = +-effort (what MuJoCo's
  URDF reader makes of ``<limit effort>``), ``solreflimit`` (:data:`LIMIT_SOLREF`), and a return
  spring as ``stiffness`` + ``springref`` (:mod:`infmob_usd.springs`); ``solimpfriction`` of a ``holding``
  joint (:data:`HOLD_SOLIMP`);
* **coupled joints** as ``<equality><joint joint1 joint2 polycoef>``;
* **visual geoms** (class ``visual``: no contacts, no mass, group 2) from the URDF's OBJ meshes, with
  one MuJoCo ``<material>`` per slot whose ``<layer>`` s are our PNG maps (base colour, normal,
  roughness; metallic and roughness also as constants);
* **collision geoms** (class ``collision``: group 3, no mass), one per convex hull, placed as in
  the URDF (MuJoCo hulls every collision mesh; ours are hulls already);
* **inertials** with the full tensor (``fullinertia``) about the centre of mass; geoms carry no mass;
* ``<contact><exclude>`` for the real parent and child of every compound chain (two or more bodies
  apart through massless-geometry dummies, so MuJoCo's parent-child filter misses them).

Paths are relative to the file (``meshdir="meshes"``, ``texturedir="textures"``), and the bytes are
a pure function of the object.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from .common import write_file
from .urdf import MESHES, _f, _v, write_meshes  # numbers as the URDF writes them

TEXTURE_ROLES = {"basecolor": "rgb", "normal": "normal", "roughness": "roughness", "metallic": "metallic"}
"""Our texture maps and the MuJoCo material ``<layer role>`` each becomes."""


def _quat(rot: np.ndarray) -> np.ndarray:
    """MuJoCo quaternion ``w x y z`` (``w >= 0``) of a rotation matrix (Shepperd's method: from the
    largest of the four squared components; scipy's ``Rotation`` costs ~40x more per call here)."""
    r = np.asarray(rot, float)
    t = np.trace(r)
    k = int(np.argmax([t, r[0, 0], r[1, 1], r[2, 2]]))
    if k == 0:
        w = np.sqrt(1.0 + t) / 2
        q = np.array([w, (r[2, 1] - r[1, 2]) / (4 * w), (r[0, 2] - r[2, 0]) / (4 * w), (r[1, 0] - r[0, 1]) / (4 * w)])
    else:
        i, j, m = k - 1, k % 3, (k + 1) % 3
        v = np.sqrt(1.0 + r[i, i] - r[j, j] - r[m, m]) / 2
        q = np.empty(4)
        q[0] = (r[m, j] - r[j, m]) / (4 * v)
        q[1 + i] = v
        q[1 + j] = (r[j, i] + r[i, j]) / (4 * v)
        q[1 + m] = (r[m, i] + r[i, m]) / (4 * v)
    q /= np.linalg.norm(q)
    return -q if q[0] < 0 else q


LIMIT_SOLREF = (0.004, 1.0)
"""MuJoCo ``solreflimit`` (time constant s, damping ratio) of every limited joint. MuJoCo's default
(0.02 s) lets a part pushed across its range with its own effort arrive at its stop and go 7-23 % of
the range past it for a moment (chair lifts, lids, caps, buttons pushed from their far stop); past a
stop the overshoot grows with the time constant (measured: 3.8 % at 4 ms, 8.2 % at 8 ms for the
worst, a 0.78 mN pump head), and 4 ms is the stiffest MuJoCo's default 2 ms step keeps (it raises
any time constant below two steps to two steps). The efforts (:mod:`infmob_usd.effort`) are sized on
the default's softness, so every joint's stop budget needs it: one value, not one per joint."""


def _limit_softness(joint) -> str:
    """``solreflimit`` of ``joint`` (:data:`LIMIT_SOLREF`); none for continuous joints."""
    if joint.type == "continuous":
        return ""
    return f' solreflimit="{_f(LIMIT_SOLREF[0])} {_f(LIMIT_SOLREF[1])}"'


HOLD_SOLIMP = (0.99, 0.999, 0.001)
"""MuJoCo ``solimpfriction`` of a ``holding`` joint (a laptop lid's friction hinge, a monitor's tilt). MuJoCo's
dry friction is a soft constraint that lets a loaded joint creep: with the default impedance (0.9 0.95) a 1.2 kg
laptop lid held by 2.2 N m of friction under 0.5 N m of gravity creeps 1 degree a second; at 0.99 0.999 it creeps
0.1 degree a second (measured), as near a real friction hinge's stillness as MuJoCo's default step keeps."""


def _friction_softness(joint) -> str:
    """``solimpfriction`` of a ``holding`` joint (:data:`HOLD_SOLIMP`); none for any other."""
    if joint.role != "holding":
        return ""
    return f' solimpfriction="{" ".join(_f(x) for x in HOLD_SOLIMP)}"'


def _joint(joint) -> str:
    """The ``<joint>`` element of a movable joint: range (none for continuous), damping, friction,
    armature, effort, its return spring (``stiffness`` about ``springref``) and limit softness."""
    kind = "slide" if joint.type == "prismatic" else "hinge"
    lim = ' limited="false"' if joint.type == "continuous" else f' range="{_f(joint.lower)} {_f(joint.upper)}"'
    spring = (f' stiffness="{_f(joint.stiffness)}" springref="{_f(joint.spring_ref)}"'
              if joint.stiffness > 0 else "")
    return (f'<joint name="{joint.name}" type="{kind}" axis="{_v(joint.axis)}"{lim}'
            f' damping="{_f(joint.damping)}" frictionloss="{_f(joint.friction)}"'
            f' armature="{_f(joint.armature)}" actuatorfrcrange="{_f(-joint.effort)} {_f(joint.effort)}"'
            f'{spring}{_limit_softness(joint)}{_friction_softness(joint)}/>')


def _equality(obj) -> list[str]:
    """``<equality>`` lines for the coupled joints: ``joint1 = polycoef(joint2)`` = offset + ratio * leader,
    as stiff as the limits (MuJoCo's default lets a lid lag its pedal by 8 % under its own weight)."""
    coupled = [j for j in obj.joints if j.mimic is not None]
    if not coupled:
        return []
    return ["  <equality>", *(f'    <joint name="mimic_{j.name}" joint1="{j.name}" joint2="{j.mimic[0]}"'
                               f' polycoef="{_f(j.mimic[2])} {_f(j.mimic[1])} 0 0 0"'
                               f' solref="{_f(LIMIT_SOLREF[0])} {_f(LIMIT_SOLREF[1])}"/>' for j in coupled),
            "  </equality>"]


def _real_parent(obj, name: str) -> str:
    into = {j.child: j for j in obj.joints}
    dummy = {link.name for link in obj.links if link.dummy}
    p = into[name].parent
    while p in dummy:
        p = into[p].parent
    return p


def write_mjcf(obj, folder: Path, free_base: bool = False) -> Path:
    """Write ``<name>.xml`` (and ``meshes/``, unless written already) into ``folder``; return its path."""
    files = write_meshes(obj, folder)
    out = [f'<mujoco model={quoteattr(obj.name)}>',
           f'  <compiler angle="radian" meshdir="{MESHES}" texturedir="textures" autolimits="true"'
           ' inertiafromgeom="false" balanceinertia="true"/>',
           "  <default>",
           '    <default class="visual"><geom type="mesh" contype="0" conaffinity="0" group="2"'
           ' density="0" mass="0"/></default>',
           '    <default class="collision"><geom type="mesh" group="3" density="0" mass="0"'
           ' rgba="0.5 0.5 0.5 1"/></default>',
           "  </default>",
           "  <asset>"]
    for slot, look in obj.materials.items():
        maps = obj.textures.get(slot, {})
        for name in TEXTURE_ROLES:
            if name in maps:
                colorspace = ' colorspace="sRGB"' if name == "basecolor" else ' colorspace="linear"'
                out.append(f'    <texture name="{slot}_{name}" type="2d" file="{slot}_{name}.png"{colorspace}/>')
        r, g, b = (1.0, 1.0, 1.0) if "basecolor" in maps else look.base_color
        layers = [f'<layer texture="{slot}_{name}" role="{role}"/>'
                  for name, role in TEXTURE_ROLES.items() if name in maps]
        out.append(f'    <material name="{slot}" rgba="{_v((r, g, b, look.opacity))}"'
                   f' metallic="{_f(look.metallic)}" roughness="{_f(look.roughness)}"'
                   f' specular="0.5" shininess="{_f(1.0 - look.roughness)}">' + "".join(layers) + "</material>")
    meshes_seen: set[str] = set()
    for link in obj.links:
        visuals, collisions = files[link.name]
        for fname in [f for _, _, f in visuals] + [f for f, _, _ in collisions]:
            if fname not in meshes_seen:
                meshes_seen.add(fname)
                out.append(f'    <mesh name="{fname[:-4]}" file="{fname}"/>')
    out.append("  </asset>")

    children: dict[str, list] = {}
    for j in obj.joints:
        children.setdefault(j.parent, []).append(j)
    links = {link.name: link for link in obj.links}
    out.append("  <worldbody>")

    def body(name: str, pos, joint, depth: int) -> None:
        pad = "  " * depth
        link = links[name]
        out.append(f'{pad}<body name="{name}" pos="{_v(pos)}">')
        if joint is None and free_base:
            out.append(f'{pad}  <freejoint name="root"/>')
        elif joint is not None and joint.movable:
            out.append(f"{pad}  {_joint(joint)}")
        I = link.inertia
        out.append(f'{pad}  <inertial pos="{_v(link.com)}" mass="{_f(link.mass)}" fullinertia="'
                   f'{_v((I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]))}"/>')
        visuals, collisions = files[name]
        for vname, slot, fname in visuals:
            out.append(f'{pad}  <geom name="{name}__{vname}" class="visual" mesh="{fname[:-4]}" material="{slot}"/>')
        for i, (fname, p, rot) in enumerate(collisions):
            quat = "" if rot is None else f' quat="{_v(_quat(rot))}"'
            out.append(f'{pad}  <geom name="{name}__collision_{i:03d}" class="collision" mesh="{fname[:-4]}"'
                       f' pos="{_v(p)}"{quat}/>')
        for j in children.get(name, []):
            body(j.child, np.asarray(links[j.child].origin) - np.asarray(link.origin), j, depth + 1)
        out.append(f"{pad}</body>")

    root = obj.links[0]
    body(root.name, root.origin, None, 2)
    out.append("  </worldbody>")
    pairs = sorted({(_real_parent(obj, j.child), j.child) for j in obj.joints
                    if not links[j.child].dummy and links[j.parent].dummy})
    if pairs:
        out.append("  <contact>")
        out += [f'    <exclude body1="{a}" body2="{b}"/>' for a, b in pairs]
        out.append("  </contact>")
    out += _equality(obj)
    out.append("</mujoco>\n")
    path = folder / f"{obj.name}.xml"
    write_file(path, "\n".join(out))
    return path


__all__ = ["TEXTURE_ROLES", "write_mjcf"]
