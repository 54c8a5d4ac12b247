"""Parts: reusable parametric components, the vocabulary categories are written in.

Each builder returns an :class:`~infmob_usd.assembly.Assembly` in its own local
frame: pieces, internal joints, named anchors (frames where things attach) and
support points (where it touches what carries it). Conventions of the local
frame, unless a builder says otherwise: the part stands on (or is mounted to)
the plane z = 0 and grows along +z; anchor ``"mount"`` is that mounting frame,
so ``part.attached("mount", to=frame)`` puts the part on a surface whose
outward normal is ``frame.z``.

Sizes are in metres and come from real products; where a default is a
product dimension its source is named beside it.
"""

from . import hardware, panels, vessel

__all__ = ["hardware", "panels", "vessel"]
