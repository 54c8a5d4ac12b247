"""Controls on a face: typed push :class:`Button`, :class:`Dial` and :class:`Lever` specs.

A spec is a frozen size (metres, from real products where a category names one) that knows the hole it
needs in a face (:meth:`cutout`, a :class:`~.casing.Cutout`) and builds its moving part
(:meth:`build`, an :class:`~infmob_usd.assembly.Assembly`). Every control's local frame has its face at
x = 0 and reaches out along +x, with local z "up" on the face; anchor ``mount`` (z out of the face, x up)
attaches it to a face anchor or a casing's cut-out anchor. :class:`ControlFace` (a
:class:`~infmob_usd.grammar.Layout` mixin) places one on a face and joins it to whatever part carries it:
a fascia, a door, a casing (any parent, not one fixed part name).
"""

from __future__ import annotations

from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grammar import Layout
from infmob_usd.grasps import Grasp

from . import appliance as A
from .casing import Cutout

MOUNT = Frame.at((0, 0, 0), z=(1, 0, 0), x=(0, 0, 1))
"""A control's mounting frame in its own local frame: its face is x = 0, it reaches out along +x."""


@dataclass(frozen=True)
class Button:
    """A push button: face ``half`` extents (u, v), ``shape`` ``"rect"`` or ``"round"``, standing ``proud``
    of the face and pressing in ``travel`` (1.5-2.5 mm on appliance keypads, :mod:`.appliance`)."""

    half: tuple[float, float]
    shape: str
    proud: float
    travel: float

    def cutout(self, face: str, at: tuple[float, float]) -> Cutout:
        return Cutout.around(face, at, (2 * self.half[0], 2 * self.half[1]), A.CLEAR)

    def build(self, material: str = "button") -> Assembly:
        """Anchors ``mount`` and ``press`` (on its face, z into the panel: the slide's axis); its piece
        carries a finger's press (:func:`~.appliance.button_grasp`)."""
        piece = A._button(tuple(self.half), self.shape, self.proud)
        if material != piece.material:
            piece = piece.replace(material=material)
        return Assembly.single("button", [piece], {"mount": MOUNT, "press": Frame.at((self.proud, 0, 0),
                                                                                     z=(-1, 0, 0))})


@dataclass(frozen=True)
class Dial:
    """A dial on a stem through the face: cap ``radius``, ``stem`` radius, ``style`` (:data:`~.appliance.DIALS`)
    and the angle it turns from its rest stop (``None``: a continuous encoder)."""

    radius: float
    stem: float
    style: str = "round"
    turns: float | None = None

    def cutout(self, face: str, at: tuple[float, float]) -> Cutout:
        return Cutout.around(face, at, (2 * self.stem, 2 * self.stem), A.CLEAR)

    def build(self) -> Assembly:
        """Anchors ``mount`` and ``axis`` (z along the stem, out of the face)."""
        return Assembly.single("knob", A.dial(0.0, 0.0, 0.0, self.radius, self.stem, self.style),
                               {"mount": MOUNT, "axis": MOUNT})


@dataclass(frozen=True)
class Lever:
    """A lever in a slot: a ``stem`` (u width, v thickness) through the face carrying a ``paddle``
    (u, v, thickness) ``reach`` in front of it; it rests at the top of a slot ``travel`` long and slides
    down it (a toaster's carriage lever)."""

    stem: tuple[float, float]
    paddle: tuple[float, float, float]
    reach: float
    travel: float

    def cutout(self, face: str, at: tuple[float, float]) -> Cutout:
        """The slot: from the stem at rest (``at``, the anchor) down by ``travel``."""
        du, dv = self.stem[0] / 2 + A.CLEAR, self.stem[1] / 2 + A.CLEAR
        return Cutout(face, (at[0] - du, at[1] - self.travel - dv), (at[0] + du, at[1] + dv), tuple(at))

    def build(self, material: str, label: str = "lever") -> Assembly:
        """Anchors ``mount`` and ``slide`` (z down the slot: a slide along it presses the lever down)."""
        (sw, st), (pw, ph, pt), reach = self.stem, self.paddle, self.reach
        # pressed from above, fingers across the paddle's thickness
        grasp = Grasp.make((reach + pt / 2, 0, ph / 2), (0, 0, -1), (1, 0, 0), pt, min(ph / 2, 0.01))
        pieces = [g.box_between((-A.BEHIND, -sw / 2, -st / 2), (reach, sw / 2, st / 2), material),
                  g.box_between((reach, -pw / 2, -ph / 2), (reach + pt, pw / 2, ph / 2), material,
                                bevel=0.25 * min(ph, pt)).with_grasps(grasp)]
        return Assembly.single(label, pieces, {"mount": MOUNT, "slide": Frame.at((0, 0, 0), z=(0, 0, -1), x=(1, 0, 0))})


class ControlFace(Layout):
    """Layout helpers that put a control on a face anchor and join it to any ``parent`` part."""

    def place_button(self, parent: str, name: str, spec: Button, at: Frame, material: str = "button") -> str:
        """A :class:`Button` at ``at`` (a face or cut-out anchor), sliding into ``parent``."""
        placed = self.place(spec.build(material).attached("mount", to=at), name)
        self.slide(parent, placed.root, placed.anchor("press"), upper=spec.travel, role="button")
        return placed.root

    def place_dial(self, parent: str, name: str, spec: Dial, at: Frame) -> str:
        """A :class:`Dial` at ``at``: continuous, or turning ``spec.turns`` from its rest stop."""
        placed = self.place(spec.build().attached("mount", to=at), name)
        axis = placed.anchor("axis")
        if spec.turns is None:
            self.spin(parent, placed.root, axis, role="knob")
        else:
            self.hinge(parent, placed.root, axis, upper=spec.turns, role="knob")
        return placed.root

    def place_lever(self, parent: str, name: str, spec: Lever, at: Frame, material: str) -> str:
        """A :class:`Lever` resting at ``at`` (the top of its slot), sliding down ``spec.travel``."""
        placed = self.place(spec.build(material).attached("mount", to=at), name)
        # a return spring holds it at its top stop and brings it back up when let go (role "lever")
        self.slide(parent, placed.root, placed.anchor("slide"), upper=spec.travel, role="lever")
        return placed.root


