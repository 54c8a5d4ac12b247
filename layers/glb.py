"""``<name>.glb``: the object at rest as one binary glTF 2.0 file, for web viewers.

* one node per link, nested as the joint tree (translation = link origin - parent origin), under
  a root node that turns our Z-up into glTF's Y-up; each joint's type, axis and limits ride in the
  child node's ``extras`` (glTF has no joints of its own);
* one mesh per link with a primitive per visual group: positions, normals, texture coordinates
  (``v`` flipped: glTF's origin is the top left), 32-bit indices; a corner's (position, normal,
  uv) is shared by every face that has the same one;
* one PBR material per slot: base colour texture (sRGB), normal texture, and a
  metallic-roughness texture (glTF's layout: roughness in G, metallic in B) made from our
  roughness map and the look's metallic; glass is ``alphaMode BLEND``; a brushed finish carries
  ``KHR_materials_anisotropy`` (strength from its family, direction along U: the part's long axis);
* images are embedded PNGs; the container (12-byte header, a JSON and a BIN chunk, 4-byte
  aligned) is written by hand, so no glTF package is needed.

Collision hulls are not written (a viewer format).
"""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np

from .common import visual_meshes, write_file

FLOAT, UINT = 5126, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
ANISOTROPY = "KHR_materials_anisotropy"
Z_UP_TO_Y_UP = [-0.7071067811865476, 0.0, 0.0, 0.7071067811865476]  # x y z w: -90 degrees about X


class _Bin:
    """The BIN chunk and its buffer views / accessors."""

    def __init__(self) -> None:
        self.data = bytearray()
        self.views: list[dict] = []
        self.accessors: list[dict] = []

    def view(self, raw: bytes, target: int | None = None) -> int:
        self.data += b"\0" * (-len(self.data) % 4)
        v = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if target:
            v["target"] = target
        self.data += raw
        self.views.append(v)
        return len(self.views) - 1

    def accessor(self, a: np.ndarray, kind: str, target: int, bounds: bool = False) -> int:
        comp = UINT if a.dtype == np.uint32 else FLOAT
        acc = {"bufferView": self.view(np.ascontiguousarray(a).tobytes(), target), "componentType": comp,
               "count": int(len(a)), "type": kind}
        if bounds:
            acc["min"] = [float(x) for x in a.min(0)]
            acc["max"] = [float(x) for x in a.max(0)]
        self.accessors.append(acc)
        return len(self.accessors) - 1


def _metallic_roughness(roughness_png: bytes, metallic: float) -> bytes:
    """glTF's metallic-roughness image: G = roughness, B = metallic, R unused (255)."""
    import cv2

    img = cv2.imdecode(np.frombuffer(roughness_png, np.uint8), cv2.IMREAD_GRAYSCALE)
    out = np.empty(img.shape + (3,), np.uint8)  # OpenCV order: B, G, R
    out[..., 0] = int(round(np.clip(metallic, 0.0, 1.0) * 255))
    out[..., 1] = img
    out[..., 2] = 255
    ok, buf = cv2.imencode(".png", out)
    if not ok:  # pragma: no cover - OpenCV failure
        raise ValueError("could not encode the metallic-roughness texture")
    return buf.tobytes()


def _material(slot: str, look, maps: dict, binary: _Bin, images: list, textures: list) -> dict:
    def texture(png: bytes) -> int:
        images.append({"bufferView": binary.view(png), "mimeType": "image/png"})
        textures.append({"sampler": 0, "source": len(images) - 1})
        return len(textures) - 1

    pbr: dict = {}
    if "basecolor" in maps:
        pbr["baseColorFactor"] = [1.0, 1.0, 1.0, float(look.opacity)]
        pbr["baseColorTexture"] = {"index": texture(maps["basecolor"])}
    else:
        pbr["baseColorFactor"] = [float(c) for c in look.base_color] + [float(look.opacity)]
    if "roughness" in maps:
        pbr["metallicFactor"] = 1.0
        pbr["roughnessFactor"] = 1.0
        pbr["metallicRoughnessTexture"] = {"index": texture(_metallic_roughness(maps["roughness"], look.metallic))}
    else:
        pbr["metallicFactor"] = float(look.metallic)
        pbr["roughnessFactor"] = float(look.roughness)
    mat = {"name": slot, "pbrMetallicRoughness": pbr, "doubleSided": False}
    if "normal" in maps:
        mat["normalTexture"] = {"index": texture(maps["normal"])}
    if look.opacity < 1.0:
        mat["alphaMode"] = "BLEND"
    strength = _specular_anisotropy(look)
    if strength > 0.0:  # brushing along U, which runs along the part: rotation 0 is the UV tangent
        mat["extensions"] = {ANISOTROPY: {"anisotropyStrength": strength, "anisotropyRotation": 0.0}}
    return mat


def _specular_anisotropy(look) -> float:
    from infmob_usd.materials import FAMILIES

    return float(FAMILIES[look.family].specular_anisotropy)


def _primitive(v, f, n, uv, binary: _Bin) -> dict:
    corners = np.hstack([v[f.reshape(-1)], n, np.column_stack([uv[:, 0], 1.0 - uv[:, 1]])]).astype(np.float32)
    uniq, inverse = np.unique(corners, axis=0, return_inverse=True)
    return {"attributes": {"POSITION": binary.accessor(uniq[:, 0:3], "VEC3", ARRAY_BUFFER, bounds=True),
                           "NORMAL": binary.accessor(uniq[:, 3:6], "VEC3", ARRAY_BUFFER),
                           "TEXCOORD_0": binary.accessor(uniq[:, 6:8], "VEC2", ARRAY_BUFFER)},
            "indices": binary.accessor(inverse.reshape(-1).astype(np.uint32), "SCALAR", ELEMENT_ARRAY_BUFFER)}


def glb_bytes(obj) -> bytes:
    """The GLB file of ``obj`` (module docstring)."""
    binary = _Bin()
    images: list[dict] = []
    textures: list[dict] = []
    slots = list(obj.materials)
    materials = [_material(s, obj.materials[s], obj.textures.get(s, {}), binary, images, textures) for s in slots]
    visuals = visual_meshes(obj)
    into = {j.child: j for j in obj.joints}
    index = {link.name: i + 1 for i, link in enumerate(obj.links)}
    nodes: list[dict] = [{"name": obj.name, "rotation": Z_UP_TO_Y_UP, "children": [index[obj.links[0].name]]}]
    meshes: list[dict] = []
    for link in obj.links:
        node: dict = {"name": link.name}
        j = into.get(link.name)
        parent_origin = obj.link(j.parent).origin if j else np.zeros(3)
        t = np.asarray(link.origin, float) - np.asarray(parent_origin, float)
        if np.any(t != 0):
            node["translation"] = [float(x) for x in t]
        prims = [dict(_primitive(v, f, n, uv, binary), material=slots.index(slot))
                 for _vname, slot, _role, v, f, n, uv in visuals[link.name] if len(f)]
        if prims:
            meshes.append({"name": link.name, "primitives": prims})
            node["mesh"] = len(meshes) - 1
        kids = [index[k.child] for k in obj.joints if k.parent == link.name]
        if kids:
            node["children"] = kids
        extras: dict = {"label": link.label}
        if j is not None:
            extras["joint"] = {"name": j.name, "type": j.type, "kind": j.kind, "axis": [float(x) for x in j.axis],
                               "lower": float(j.lower), "upper": float(j.upper)}
        node["extras"] = extras
        nodes.append(node)
    doc = {
        "asset": {"version": "2.0", "generator": f"infmob-usd {obj.version}"},
        "scene": 0,
        "scenes": [{"name": obj.name, "nodes": [0]}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "accessors": binary.accessors,
        "bufferViews": binary.views,
        "buffers": [{"byteLength": len(binary.data)}],
    }
    if any(ANISOTROPY in m.get("extensions", {}) for m in materials):
        doc["extensionsUsed"] = [ANISOTROPY]
    if textures:
        doc["textures"] = textures
        doc["images"] = images
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    data = bytes(binary.data) + b"\0" * (-len(binary.data) % 4)
    total = 12 + 8 + len(js) + 8 + len(data)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(js), b"JSON") + js
            + struct.pack("<I4s", len(data), b"BIN\0") + data)


def write_glb(obj, folder: Path) -> Path:
    """Write ``<name>.glb`` into ``folder``; return its path."""
    path = folder / f"{obj.name}.glb"
    write_file(path, glb_bytes(obj))
    return path


__all__ = ["glb_bytes", "write_glb"]
