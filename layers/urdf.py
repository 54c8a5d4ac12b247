"""URDF beside the USD, with OBJ meshes: for SAPIEN, ManiSkill and MuJoCo.

* one visual OBJ (+ MTL with PBR texture maps) per link and material slot,
  named ``handle_*`` where the pieces are handles (ManiSkill looks for that);
  no ``<material>`` elements: colours live in the MTL, and SAPIEN's loader would
  need a render device to build URDF materials;
* one ``<collision>`` per convex piece (SAPIEN and MuJoCo hull each collision file), its OBJ
  centred on its own origin and placed by ``<collision><origin>`` (PhysX's contacts misbehave
  otherwise); the wedges of a shell band are turned copies of one wedge, so they share its
  OBJ and differ by their origin's ``xyz rpy`` (a pot writes ~30 collision files, not ~180),
  and identical hulls of a link (a keypad's buttons) share one file;
* ``<inertial>`` with the full tensor about the centre of mass;
* ``<limit>`` with effort and velocity, ``<dynamics damping friction>``; ``<mimic>`` on a coupled joint
  (a return spring has no URDF element: ``metadata.json`` carries it, :mod:`infmob_usd.springs`; a
  sprung joint's ``friction`` here holds its part against its weight anywhere in its range, so a reader
  without the spring leaves it where it is: with the spring set, use ``metadata.json``'s ``friction``);
* a ``<mujoco>`` hint: ``<compiler strippath="false" discardvisual="false"/>``, so MuJoCo finds
  the meshes (3.x strips folders from mesh paths by default) and keeps the visual meshes, and
  ``<option noslip_iterations>`` (:data:`URDF_NOSLIP`), so joint friction holds what it should.

All mesh and texture paths are relative to the URDF file.
"""

from __future__ import annotations

import os
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from infmob_usd.rotation import matrix_rpy as rotation_rpy

from .common import collision_placements, visual_meshes, write_file

MESHES = "meshes"


def _f(x: float) -> str:
    """``x`` to 9 significant digits, ``0`` for minus zero (``-0.0 + 0.0`` is ``0.0``; any other value is unchanged)."""
    return "%.9g" % (float(x) + 0.0)


def _v(a) -> str:
    """The numbers of ``a`` as :func:`_f` writes them, space-separated."""
    return " ".join(["%.9g" % (x + 0.0) for x in (a.tolist() if isinstance(a, np.ndarray) else a)])


def _rows(prefix: str, fmt: str, a: np.ndarray) -> str:
    """One line ``prefix fmt...`` per row of ``a`` (one %-format over the whole array: ~3x an f-string loop)."""
    if not len(a):
        return ""
    return (f"{prefix} {fmt}\n" * len(a)) % tuple(a.ravel().tolist())


# Line layouts of an OBJ: literal text and column numbers of the row, and the decimals of the columns
# (None: whole numbers >= 0)
_V = (("v ", 0, " ", 1, " ", 2, "\n"), 6)
_VT = (("vt ", 0, " ", 1, "\n"), 6)
_VN = (("vn ", 0, " ", 1, " ", 2, "\n"), 5)
_F3 = (("f ", 0, " ", 1, " ", 2, "\n"), None)
_F9 = (("f ", 0, "/", 1, "/", 2, " ", 3, "/", 4, "/", 5, " ", 6, "/", 7, "/", 8, "\n"), None)
_FT = (("f ", 0, "/", 0, "/", 0, " ", 1, "/", 1, "/", 1, " ", 2, "/", 2, "/", 2, "\n"), None)  # an index per corner
_VECTOR_MIN = 256  # fewer numbers than this: one %-format is faster than the vectorised formatter


def _numbers(x: np.ndarray, decimals: int | None):
    """The decimal form of each number of ``x`` (n,) as printf's ``%.{decimals}f`` (or ``%d``) writes it:
    ``(magnitude digits m (n,) int, negative (n,) bool or None, integer digits of the widest)``, where the
    text is ``-`` if negative, then ``m`` with a point before its last ``decimals`` digits.

    ``m`` is ``|x| * 10**decimals`` rounded half to even: exactly printf's rounding of the binary value
    wherever the scaled float lies farther than two units in its last place from a half (then no
    rounding error of the scaling can cross the half); the few that do not are rounded by Python's own
    ``%``-format. ``None`` when the values are too large, or not finite: then the caller %-formats."""
    if decimals is None:
        m = np.asarray(x, np.int64)
        if len(m) and int(m.min()) < 0:
            return None
        neg = None
    else:
        q = x * 10.0 ** decimals
        if not np.isfinite(q).all() or (len(q) and float(np.abs(q).max()) >= 2.0 ** 52):
            return None
        m = np.abs(np.rint(q)).astype(np.int64)
        near = np.abs(q - np.floor(q) - 0.5) <= 2 * np.spacing(np.abs(q))
        for i in np.flatnonzero(near).tolist():
            m[i] = int(f"{abs(float(x[i])):.{decimals}f}".replace(".", ""))
        neg = np.signbit(x)
    top = int(m.max()) if len(m) else 0
    if top < 2**31:
        m = m.astype(np.int32)  # faster divisions
    return m, neg, len(str(top // 10 ** (decimals or 0)))


def _format(a: np.ndarray, layout: tuple) -> tuple[bytes, np.ndarray] | None:
    """The lines of ``layout`` (:data:`_V` ...) for every row of ``a``, as printf writes them, in one
    vectorised pass: the characters of all lines in a (width, rows) array with a mask of those kept
    (a number's unused leading places, a plus sign), gathered row by row. Returns the text and each
    line's length, or ``None`` where :func:`_numbers` declines."""
    items, decimals = layout
    n = len(a)
    cols = []
    for j in range(a.shape[1]):
        num = _numbers(a[:, j], decimals)
        if num is None:
            return None
        cols.append(num)
    frac = 0 if decimals is None else decimals
    width = [(1 + k + 1 + frac) if decimals is not None else k for _, _, k in cols]
    W = sum(len(it) if isinstance(it, str) else width[it] for it in items)
    chars = np.empty((W, n), np.uint8)
    keep = np.ones((W, n), bool)
    pos, placed = 0, {}
    for it in items:
        if isinstance(it, str):
            for ch in it.encode():
                chars[pos] = ch
                pos += 1
            continue
        w = width[it]
        if it in placed:  # the same number again
            p0 = placed[it]
            chars[pos:pos + w], keep[pos:pos + w] = chars[p0:p0 + w], keep[p0:p0 + w]
            pos += w
            continue
        placed[it] = pos
        m, neg, k = cols[it]
        if decimals is not None:
            chars[pos] = 45  # "-"
            keep[pos] = neg
            unit = 10 ** decimals
            whole = m // unit
            rest = m - whole * unit
            for col in range(pos + w - 1, pos + w - 1 - decimals, -1):
                nxt = rest // 10
                np.add(rest - nxt * 10, 48, out=chars[col], casting="unsafe")
                rest = nxt
            chars[pos + 1 + k] = 46  # "."
            lo = pos + 1
        else:
            whole, lo = m, pos
        for col in range(lo + k - 1, lo - 1, -1):
            nxt = whole // 10
            np.add(whole - nxt * 10, 48, out=chars[col], casting="unsafe")
            if col < lo + k - 1:
                np.greater(whole, 0, out=keep[col])  # no leading zeros
            whole = nxt
        pos += w
    return np.compress(keep.T.ravel(), chars.T.ravel()).tobytes(), keep.sum(0)  # ~2x chars.T[keep.T]


def _printf(a: np.ndarray, layout: tuple) -> str:
    """The lines of ``layout`` for every row of ``a`` by one %-format (what :func:`_format` gives)."""
    items, decimals = layout
    number = "%d" if decimals is None else f"%.{decimals}f"
    line = "".join(it.replace("%", "%%") if isinstance(it, str) else number for it in items)
    cols = [it for it in items if not isinstance(it, str)]
    return (line * len(a)) % tuple(a[:, cols].ravel().tolist())


class _Text:
    """The text of many OBJ files, its number lines formatted together: one vectorised pass per line
    layout for all files (:func:`_format`), not one %-format per block of lines of each file."""

    def __init__(self):
        self.files: list[list] = []
        self.blocks: dict[tuple, list[np.ndarray]] = {}

    def file(self) -> list:
        self.files.append([])
        return self.files[-1]

    def lines(self, parts: list, layout: tuple, a: np.ndarray) -> None:
        if len(a):
            block = self.blocks.setdefault(layout, [])
            parts.append((layout, len(block)))
            block.append(a)

    def render(self) -> list[bytes]:
        text: dict[tuple, list[bytes]] = {}
        for layout, arrays in self.blocks.items():
            a = np.concatenate(arrays) if len(arrays) > 1 else arrays[0]
            done = _format(a, layout) if a.size >= _VECTOR_MIN else None
            if done is None:
                text[layout] = [_printf(b, layout).encode() for b in arrays]
                continue
            blob, lengths = done
            ends = np.cumsum([len(b) for b in arrays])
            cut = np.concatenate([[0], np.cumsum(lengths)[ends - 1]]).tolist()
            text[layout] = [blob[cut[i]:cut[i + 1]] for i in range(len(arrays))]
        return [b"".join(p.encode() if isinstance(p, str) else text[p[0]][p[1]] for p in parts)
                for parts in self.files]


def _unique_inverse(key: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(key, return_inverse=True)`` of a 1-D array, plus where one copy of each value is:
    ``(sorted unique values, inverse, an index of each)`` (any copy: the caller reads equal rows)."""
    perm = key.argsort()
    sorted_ = key[perm]
    new = np.empty(len(key), bool)
    new[:1] = True
    np.not_equal(sorted_[1:], sorted_[:-1], out=new[1:])
    inverse = np.empty(len(key), np.intp)
    inverse[perm] = np.cumsum(new) - 1
    return sorted_[new], inverse, perm[new]


def _unique_rows(a: np.ndarray, decimals: int) -> tuple[np.ndarray, np.ndarray]:
    """Rows of ``a`` rounded to ``decimals`` and deduplicated (in lexicographic order), and each
    row's index among them."""
    q = np.rint(a * 10.0**decimals).astype(np.int64)
    if not len(q):
        return q / 10.0**decimals, np.zeros(0, np.intp)
    flat = q.ravel()
    lo = int(flat.min())  # one shift for every column (a contiguous reduction: no per-column min)
    b = int(flat.max() - lo + 1).bit_length()
    if q.shape[1] * b <= 62:  # pack each row into one integer, in the rows' order: a 1-D sort
        cols = (q - lo).T
        key = cols[0].copy()
        for col in cols[1:]:
            key <<= b
            key |= col
        _, inverse, one = _unique_inverse(key)
        uniq = q[one]
    else:
        uniq, inverse = np.unique(q, axis=0, return_inverse=True)
    return uniq / 10.0**decimals, inverse.reshape(-1)


def _corner_lists(meshes: list[tuple[np.ndarray, np.ndarray, np.ndarray, int]]) -> list[tuple]:
    """The ``vt`` and ``vn`` lists of several OBJ files at once: for each ``(uvs (k, 2), normals (k, 3),
    vertex index per corner (k,), vertex count)``, ``(vt, ti, vn, ni, smooth)`` as :func:`_unique_rows`
    gives them for the UVs (6 decimals) and the normals (5 decimals), and whether the file lists
    (position, uv, normal) triples in step (:func:`_obj`): its distinct triples are at most 1.25 per vertex.

    One sort per list for all the files (the file's number in the key's top bits keeps each file's rows
    apart and in their own order), not three per file: an object's ~20 visual meshes are small, so the
    calls, not the sorting, cost."""
    if not meshes:
        return []
    uv = _unique_rows_of([m[0] for m in meshes], 6)
    nv = _unique_rows_of([m[1] for m in meshes], 5)
    out = []
    check = []
    for k, (_, _, _, count) in enumerate(meshes):
        (vt, ti), (vn, ni) = uv[k], nv[k]
        if max(count, len(vt), len(vn)) < 1 << 21:
            check.append(k)
        out.append([vt, ti, vn, ni, False])
    if check:
        # distinct (vertex, uv, normal) triples per file, counted in one sort
        bits = [max(max(count, len(out[k][0]), len(out[k][2])) - 1, 1).bit_length()
                for k, (_, _, _, count) in ((k, meshes[k]) for k in check)]
        b = max(bits)
        fb = max(len(check) - 1, 1).bit_length()
        if 3 * b + fb <= 63:
            keys = [(np.full(len(meshes[k][2]), i, np.int64) << 3 * b) | (meshes[k][2] << 2 * b)
                    | (out[k][1] << b) | out[k][3] for i, k in enumerate(check)]
            key = np.sort(np.concatenate(keys)) if len(keys) > 1 else np.sort(keys[0])
            new = np.empty(len(key), bool)
            new[:1] = True
            np.not_equal(key[1:], key[:-1], out=new[1:])
            distinct = np.bincount(key[new] >> 3 * b, minlength=len(check)).tolist()
        else:
            distinct = [len(_unique_inverse((meshes[k][2] << 42) | (out[k][1] << 21) | out[k][3])[0])
                        for k in check]
        for k, n in zip(check, distinct):
            out[k][4] = n <= 1.25 * meshes[k][3]
    return [tuple(o) for o in out]


def _unique_rows_of(arrays: list[np.ndarray], decimals: int) -> list[tuple[np.ndarray, np.ndarray]]:
    """:func:`_unique_rows` of each array (rows of equal width), with one sort for them all where
    the rows and the array's number pack into one integer."""
    if len(arrays) == 1:
        return [_unique_rows(arrays[0], decimals)]
    sizes = [len(a) for a in arrays]
    q = np.rint(np.concatenate(arrays) * 10.0**decimals).astype(np.int64)
    if not len(q):
        return [_unique_rows(a, decimals) for a in arrays]
    flat = q.ravel()
    lo = int(flat.min())
    b = int(flat.max() - lo + 1).bit_length()
    width = q.shape[1] * b
    if width + max(len(arrays) - 1, 1).bit_length() > 62:
        return [_unique_rows(a, decimals) for a in arrays]
    cols = (q - lo).T
    key = np.repeat(np.arange(len(arrays), dtype=np.int64), sizes)
    for col in cols:
        key <<= b
        key |= col
    uniq, inverse, one = _unique_inverse(key)
    # each array's distinct rows are a run of the sorted keys: its number is their top bits
    first = np.searchsorted(uniq >> width, np.arange(len(arrays) + 1)).tolist()
    rows = q[one] / 10.0**decimals
    ends = np.cumsum(sizes).tolist()
    out = []
    for k, end in enumerate(ends):
        out.append((rows[first[k]:first[k + 1]], inverse[end - sizes[k]:end] - first[k]))
    return out


def _obj(text: _Text, vertices: np.ndarray, faces: np.ndarray, normals=None, uvs=None,
         mtl: str | None = None, material: str | None = None, lists: tuple | None = None) -> None:
    """Lay out one OBJ file in ``text`` (see :func:`write_obj`); ``lists``: its :func:`_corner_lists`
    where made already."""
    parts = text.file()
    parts.append("# infmob-usd\n")
    if mtl:
        parts.append(f"mtllib {mtl}\n")
    vertices = np.asarray(vertices, float)
    f1 = np.asarray(faces, np.int64) + 1
    if uvs is not None and normals is not None:
        vi = f1.reshape(-1) - 1
        if lists is None:
            lists = _corner_lists([(np.asarray(uvs, float).reshape(-1, 2), np.asarray(normals, float).reshape(-1, 3),
                                    vi, len(vertices))])[0]
        vt, ti, vn, ni, smooth = lists
        if smooth:
            # a smooth surface: one (position, uv, normal) triple per vertex, almost; then list the
            # triples in step so a face reads "f i/i/i j/j/j k/k/k", one number per corner to format
            key = (vi << 42) | (ti << 21) | ni
            triples, inverse, corner = _unique_inverse(key)
            text.lines(parts, _V, vertices[vi[corner]])
            text.lines(parts, _VT, vt[ti[corner]])
            text.lines(parts, _VN, vn[ni[corner]])
            if material:
                parts.append(f"usemtl {material}\n")
            text.lines(parts, _FT, inverse.reshape(-1, 3) + 1)
            return
        text.lines(parts, _V, vertices)
        text.lines(parts, _VT, vt)
        text.lines(parts, _VN, vn)
        if material:
            parts.append(f"usemtl {material}\n")
        text.lines(parts, _F9, np.stack([f1.reshape(-1), ti + 1, ni + 1], 1).reshape(-1, 9))
    else:
        text.lines(parts, _V, vertices)
        if material:
            parts.append(f"usemtl {material}\n")
        text.lines(parts, _F3, f1)


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray, normals=None, uvs=None,
              mtl: str | None = None, material: str | None = None) -> None:
    """Write an OBJ; ``normals``/``uvs`` are per face corner ``(m, 3, 3)`` / ``(m, 3, 2)``.

    Corner normals and UVs are rounded to the precision written and shared between
    corners that agree, so a smooth surface lists each normal once.  Where nearly every
    vertex has one UV and one normal (smooth surfaces), the lists run in step and faces
    read ``f i/i/i ...``. (:func:`write_meshes` lays out all the OBJ files of an object
    first and formats their numbers together.)
    """
    text = _Text()
    _obj(text, vertices, faces, normals, uvs, mtl, material)
    write_file(path, text.render()[0])


_MTL_MAPS = {"basecolor": "map_Kd", "roughness": "map_Pr", "metallic": "map_Pm", "normal": "norm"}


def _mtl(slot: str, look, maps) -> str:
    """MTL of one slot: constants from the look, a map line for each texture written.

    The object's wear of the look (:class:`~infmob_usd.materials.Wear`): ``Kd`` is the tint,
    which multiplies ``map_Kd`` (as the MTL format defines it; without a map it is the tinted
    colour), the roughness scale is ``map_Pr -mm 0 <scale>`` (base, gain), and the UV rotation
    and offset are baked into the OBJ ``vt`` (:func:`write_urdf`), which every reader honours.
    ``d`` and ``Tr`` (= 1 - d) give the opacity, ``Ni`` the index of refraction.  No ``aniso`` line
    for brushed finishes: Assimp's MTL reader (SAPIEN, URDF importers) fails on it.
    """
    tint = np.asarray(look.wear.tint, float)
    r, g, b = tint if "basecolor" in maps else tint * np.asarray(look.base_color, float)
    rough = look.wear.roughness_scale
    lines = [
        f"newmtl {slot}",
        f"Kd {r:.4f} {g:.4f} {b:.4f}",
        "Ka 0 0 0",
        "Ks 0.04 0.04 0.04",
        f"d {look.opacity:.3f}",
        f"Pr {min(1.0, look.roughness * rough):.3f}",
        f"Pm {look.metallic:.3f}",
    ]
    if look.opacity < 1.0:
        from infmob_usd.materials import FAMILIES

        lines += [f"Tr {1.0 - look.opacity:.3f}", f"Ni {FAMILIES[look.family].ior:.3f}"]
    for name, key in _MTL_MAPS.items():
        if name in maps:
            option = f"-mm 0 {rough:.4f} " if name == "roughness" else ""
            lines.append(f"{key} {option}../textures/{slot}_{name}.png")
    return "\n".join(lines + [""])


def write_meshes(obj, folder: Path) -> dict[str, tuple[list, list]]:
    """Write ``meshes/`` (visual OBJ + MTL per link and slot, collision OBJ per distinct hull) once
    per object folder, for the URDF and the MJCF; return, per link, ``(visuals, collisions)``:
    ``visuals`` ``[(vname, slot, file)]``, ``collisions`` ``[(file, position (3,), rotation or None)]``
    (files relative to ``meshes/``). Kept on the object while :func:`~infmob_usd.layers.write_object`
    runs, so the second writer only reads it."""
    cached = getattr(obj, "_mesh_files", None)
    if cached is not None and cached[0] == folder:
        return cached[1]
    meshes = folder / MESHES
    meshes.mkdir()
    for slot, look in obj.materials.items():
        write_file(meshes / f"{slot}.mtl", _mtl(slot, look, obj.textures.get(slot, {})))
    visuals = visual_meshes(obj)
    text, names = _Text(), []  # every OBJ laid out first, their numbers formatted together
    table = {}
    corners = []
    for link in obj.links:
        for _vname, slot, _role, v, f, n, uv in visuals[link.name]:
            m = obj.materials[slot].wear.uv_matrix()  # this object's placement of the maps, baked in
            corners.append((np.asarray(uv @ m[:, :2].T + m[:, 2], float).reshape(-1, 2),
                            np.asarray(n, float).reshape(-1, 3), np.asarray(f, np.int64).reshape(-1), len(v)))
    lists = iter(_corner_lists(corners))  # the vt and vn lists of every visual OBJ, made together
    corners = iter(corners)
    for link in obj.links:
        vis = []
        for vname, slot, _role, v, f, _n, _uv in visuals[link.name]:
            fname = f"{link.name}__{vname}.obj"
            c = next(corners)
            _obj(text, v, f, c[1], c[0], mtl=f"{slot}.mtl", material=slot, lists=next(lists))
            names.append(fname)
            vis.append((vname, slot, fname))
        col = []
        same_shape: dict[bytes, str] = {}  # identical centred hulls (a keypad's buttons) share a file
        file_of: dict[int, str] = {}  # hull index -> the file holding its mesh
        for mesh, pos, rot, hv, hf in collision_placements(link):
            if rot is None:
                key = np.round(hv, 9).tobytes() + np.asarray(hf, np.int64).tobytes()
                if key not in same_shape:
                    same_shape[key] = f"{link.name}__collision_{mesh:03d}.obj"
                    _obj(text, hv, hf)
                    names.append(same_shape[key])
                file_of[mesh] = same_shape[key]
            col.append((file_of[mesh], pos, rot))  # an instance's prototype comes before it
        table[link.name] = (vis, col)
    into = os.path.join(meshes, "")  # ~70 files: a string join, not a Path each
    for fname, data in zip(names, text.render()):
        write_file(into + fname, data)
    obj._mesh_files = (folder, table)
    return table


URDF_NOSLIP = 5
"""``noslip_iterations`` in the URDF's ``<mujoco><option>``. MuJoCo's dry joint friction is a soft constraint
that lets a loaded joint creep whatever its size: a 5 g key held by a friction of 1.3 times its weight slid its
whole 4.4 mm travel in 2 s. The MJCF hardens friction per joint (``solimpfriction``), which MuJoCo's URDF reader
does not read; it does read ``<option>``, and the no-slip pass removes that creep from joint friction and
contact friction alike: MuJoCo on the URDFs of seeds 0-1 of every category moved nothing at rest over 1 mm or
1 degree in 2 s with 2 iterations (21 of 120 objects did with none); 5 leaves a margin."""


def write_urdf(obj, folder: Path) -> Path:
    """Write ``<name>.urdf`` (and ``meshes/``, unless written already) into ``folder``; return the URDF path."""
    files = write_meshes(obj, folder)
    out = [f'<?xml version="1.0"?>\n<robot name={quoteattr(obj.name)}>']
    # MuJoCo reads this: keep the meshes/ folder in mesh paths (3.x strips it by default) and the visuals;
    # its no-slip pass holds joint friction (URDF_NOSLIP)
    out.append('  <mujoco><compiler strippath="false" discardvisual="false"/>'
               f'<option noslip_iterations="{URDF_NOSLIP}"/></mujoco>')
    for link in obj.links:
        out.append(f'  <link name="{link.name}">')
        visuals, collisions = files[link.name]
        for vname, _slot, fname in visuals:
            out.append(f'    <visual name="{link.name}_{vname}"><origin xyz="0 0 0" rpy="0 0 0"/>'
                       f'<geometry><mesh filename="{MESHES}/{fname}"/></geometry></visual>')
        for i, (fname, pos, rot) in enumerate(collisions):
            rpy = "0 0 0" if rot is None else _v(rotation_rpy(rot))
            out.append(f'    <collision name="{link.name}_collision_{i:03d}"><origin xyz="{_v(pos)}" rpy="{rpy}"/>'
                       f'<geometry><mesh filename="{MESHES}/{fname}"/></geometry></collision>')
        I = link.inertia
        out.append(f'    <inertial><origin xyz="{_v(link.com)}" rpy="0 0 0"/><mass value="{_f(link.mass)}"/>'
                   f'<inertia ixx="{_f(I[0, 0])}" ixy="{_f(I[0, 1])}" ixz="{_f(I[0, 2])}" iyy="{_f(I[1, 1])}"'
                   f' iyz="{_f(I[1, 2])}" izz="{_f(I[2, 2])}"/></inertial>')
        out.append("  </link>")
    origins = {link.name: link.origin for link in obj.links}
    for j in obj.joints:
        xyz = np.asarray(origins[j.child]) - np.asarray(origins[j.parent])
        out.append(f'  <joint name="{j.name}" type="{j.type}">')
        out.append(f'    <parent link="{j.parent}"/><child link="{j.child}"/>')
        out.append(f'    <origin xyz="{_v(xyz)}" rpy="0 0 0"/>')
        if j.type != "fixed":
            out.append(f'    <axis xyz="{_v(j.axis)}"/>')
            lim = "" if j.type == "continuous" else f'lower="{_f(j.lower)}" upper="{_f(j.upper)}" '
            out.append(f'    <limit {lim}effort="{_f(j.effort)}" velocity="{_f(j.velocity)}"/>')
            friction = max(j.friction, j.hold_friction)  # no spring element: friction holds a sprung part
            out.append(f'    <dynamics damping="{_f(j.damping)}" friction="{_f(friction)}"/>')
            if j.mimic is not None:
                out.append(f'    <mimic joint="{j.mimic[0]}" multiplier="{_f(j.mimic[1])}" offset="{_f(j.mimic[2])}"/>')
        out.append("  </joint>")
    out.append("</robot>\n")
    path = folder / f"{obj.name}.urdf"
    write_file(path, "\n".join(out))
    return path


__all__ = ["write_meshes", "write_obj", "write_urdf"]
