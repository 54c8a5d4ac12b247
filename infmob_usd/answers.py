"""Which category of the datasets and benchmarks each of ours answers, and the category lists themselves.

A user coming from PartNet-Mobility, Infinigen-Sim, RoboCasa or the Infinite Mobility paper looks for their
category by its own name; docs/categories.md's table prints :func:`answers` beside each of ours, and
``tests/test_answers.py`` holds that every category of the four lists is answered by one we generate.

Sources of the lists:

* PartNet-Mobility: the 46 categories of the SAPIEN dataset browser (sapien.ucsd.edu/browse; Xiang et al.,
  "SAPIEN", CVPR 2020), names as the dataset's ``meta.json`` ``model_cat`` gives them.
* Infinigen-Sim: ``OBJECT_CLASS_MAP`` of princeton-vl/infinigen ``src/infinigen/assets/sim_objects/mapping.py``
  (the 18 classes of Infinigen-Articulated, arXiv 2505.10755).
* RoboCasa: the articulated ``FixtureType`` members of robocasa/robocasa ``robocasa/models/fixtures/fixture.py``
  (fixtures a robot operates: counters and islands, which have no moving part, left out).
* Infinite Mobility: the 22 categories of arXiv 2503.13424 (the method this project rebuilds), by our ids,
  which are theirs.
"""

from __future__ import annotations

PARTNET_MOBILITY = (
    "Bottle", "Box", "Bucket", "Camera", "Cart", "Chair", "Clock", "CoffeeMachine", "Dishwasher", "Dispenser",
    "Display", "Door", "Eyeglasses", "Fan", "Faucet", "FoldingChair", "Globe", "Kettle", "Keyboard", "KitchenPot",
    "Knife", "Lamp", "Laptop", "Lighter", "Microwave", "Mouse", "Oven", "Pen", "Phone", "Pliers", "Printer",
    "Refrigerator", "Remote", "Safe", "Scissors", "Stapler", "StorageFurniture", "Suitcase", "Switch", "Table",
    "Toaster", "Toilet", "TrashCan", "USB", "WashingMachine", "Window",
)
INFINIGEN_SIM = (
    "door", "toaster", "dishwasher", "lamp", "cabinet", "drawer", "refrigerator", "oven", "microwave",
    "soap_dispenser", "faucet", "plier", "window", "box", "pepper_grinder", "trash", "door_handle", "stovetop",
)
ROBOCASA = (
    "microwave", "stove", "oven", "sink", "coffee_machine", "toaster", "toaster_oven", "fridge", "dishwasher",
    "blender", "stand_mixer", "electric_kettle", "stool", "cabinet", "drawer", "shelf", "window", "dish_rack",
)
INFINITE_MOBILITY = (
    "kitchen_cabinet", "microwave", "lamp", "beverage_fridge", "dishwasher", "oven", "tv", "tap", "toilet", "door",
    "window", "office_chair", "bar_chair", "cocktail_table", "dining_table", "plate_rack", "vase", "bottle", "jar",
    "pot", "pan", "storage_rack",
)

# ours -> (PartNet-Mobility, Infinigen-Sim, RoboCasa) categories it answers; the paper's from INFINITE_MOBILITY
_MAP: dict[str, tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]] = {
    "bar_chair": (("Chair",), (), ("stool",)),
    "beverage_fridge": (("Refrigerator",), (), ()),
    "blender": ((), (), ("blender",)),
    "bottle": (("Bottle",), (), ()),
    "box": (("Box",), ("box",), ()),
    "bucket": (("Bucket",), (), ()),
    "camera": (("Camera",), (), ()),
    "cart": (("Cart",), (), ()),
    "clock": (("Clock",), (), ()),
    "cocktail_table": (("Table",), (), ()),
    "coffee_machine": (("CoffeeMachine",), (), ("coffee_machine",)),
    "dining_table": (("Table",), (), ()),
    "dishwasher": (("Dishwasher",), ("dishwasher",), ("dishwasher",)),
    "dispenser": (("Dispenser",), ("soap_dispenser",), ()),
    "door": (("Door",), ("door", "door_handle"), ()),
    "eyeglasses": (("Eyeglasses",), (), ()),
    "fan": (("Fan",), (), ()),
    "folding_chair": (("FoldingChair",), (), ()),
    "globe": (("Globe",), (), ()),
    "jar": ((), (), ()),
    "kettle": (("Kettle",), (), ("electric_kettle",)),
    "keyboard": (("Keyboard",), (), ()),
    "kitchen_cabinet": (("StorageFurniture",), ("cabinet", "drawer"), ("cabinet", "drawer")),
    "knife": (("Knife",), (), ()),
    "lamp": (("Lamp",), ("lamp",), ()),
    "laptop": (("Laptop",), (), ()),
    "lighter": (("Lighter",), (), ()),
    "microwave": (("Microwave",), ("microwave",), ("microwave",)),
    "monitor": (("Display",), (), ()),
    "mouse": (("Mouse",), (), ()),
    "office_chair": (("Chair",), (), ()),
    "oven": (("Oven",), ("oven",), ("oven",)),
    "pan": (("KitchenPot",), (), ()),
    "pen": (("Pen",), (), ()),
    "pepper_grinder": ((), ("pepper_grinder",), ()),
    "phone": (("Phone",), (), ()),
    "plate_rack": ((), (), ("dish_rack",)),
    "pliers": (("Pliers",), ("plier",), ()),
    "pot": (("KitchenPot",), (), ()),
    "printer": (("Printer",), (), ()),
    "refrigerator": (("Refrigerator",), ("refrigerator",), ("fridge",)),
    "remote": (("Remote",), (), ()),
    "safe": (("Safe",), (), ()),
    "scissors": (("Scissors",), (), ()),
    "stand_mixer": ((), (), ("stand_mixer",)),
    "stapler": (("Stapler",), (), ()),
    "storage_rack": (("StorageFurniture",), (), ("shelf",)),
    "stovetop": ((), ("stovetop",), ("stove",)),
    "suitcase": (("Suitcase",), (), ()),
    "switch": (("Switch",), (), ()),
    "tap": (("Faucet",), ("faucet",), ("sink",)),
    "toaster": (("Toaster",), ("toaster",), ("toaster",)),
    "toaster_oven": (("Oven",), (), ("toaster_oven",)),
    "toilet": (("Toilet",), (), ()),
    "trash_can": (("TrashCan",), ("trash",), ()),
    "tv": (("Display",), (), ()),
    "usb": (("USB",), (), ()),
    "vase": ((), (), ()),
    "washing_machine": (("WashingMachine",), (), ()),
    "window": (("Window",), ("window",), ("window",)),
}


def answers(category: str) -> str:
    """What ``category`` answers, as the README prints it, e.g. ``PartNet-Mobility Microwave; Infinigen-Sim
    microwave; RoboCasa microwave; Infinite Mobility``; ``""`` for a category none of the four lists has."""
    pm, ig, rc = _MAP.get(category, ((), (), ()))
    parts = [f"PartNet-Mobility {', '.join(pm)}" if pm else "", f"Infinigen-Sim {', '.join(ig)}" if ig else "",
             f"RoboCasa {', '.join(rc)}" if rc else "", "Infinite Mobility" if category in INFINITE_MOBILITY else ""]
    return "; ".join(p for p in parts if p)


def unanswered(categories) -> dict[str, list[str]]:
    """Per list, the categories of it that none of ``categories`` answers."""
    got = [_MAP.get(c, ((), (), ())) for c in categories]
    return {"PartNet-Mobility": [c for c in PARTNET_MOBILITY if not any(c in g[0] for g in got)],
            "Infinigen-Sim": [c for c in INFINIGEN_SIM if not any(c in g[1] for g in got)],
            "RoboCasa": [c for c in ROBOCASA if not any(c in g[2] for g in got)],
            "Infinite Mobility": [c for c in INFINITE_MOBILITY if c not in set(categories)]}
