"""The scenes' VTU files (fields-<instant>.vtu, frames/step-<n>.vtu) and their index fields.pvd,
read with the standard library and numpy.

What FreeFEM's iovtk writes (docs/outputs.md): a VTK XML UnstructuredGrid, one Piece, each array
inline as `format="binary"`: base64 of a UInt32 byte count followed by the little-endian values,
uncompressed; points in Float32 with 3 components (z = 0); the cells triangles only (VTK type 5).
`format="ascii"` arrays are read too. Anything else (appended or compressed data, other cell
types, a big-endian file) is refused, naming the file and the array, rather than misread.
"""
import base64
import os
import xml.etree.ElementTree as ET

import numpy as np

from .errors import SceneError

TRIANGLE = 5  # VTK's cell type of a linear triangle
DTYPES = {"Float32": "<f4", "Float64": "<f8", "Int8": "<i1", "UInt8": "<u1", "Int16": "<i2", "UInt16": "<u2",
          "Int32": "<i4", "UInt32": "<u4", "Int64": "<i8", "UInt64": "<u8"}


class Fields:
    """One VTU state: `points` (n x 2, m: the mesh's nodes, z dropped, in the file's single precision
    widened to float64), `triangles` (m x 3 node indices from 0), `point_data` and `cell_data`
    ({name: array}, one row per node or triangle; vectors n x 3), `path` (absolute), `time` (s, from
    fields.pvd when read through Results.fields or states; else None)."""

    def __init__(self, path, points, triangles, point_data, cell_data, time=None):
        self.path, self.points, self.triangles = path, points, triangles
        self.point_data, self.cell_data, self.time = point_data, cell_data, time

    def __repr__(self):
        return (f"Fields({self.path!r}: {len(self.points)} nodes, {len(self.triangles)} triangles; "
                f"point data {sorted(self.point_data)}, cell data {sorted(self.cell_data)}"
                + (f", t = {self.time} s" if self.time is not None else "") + ")")


def _values(path, array, header_type):
    """The values of one DataArray element, flat, in its declared type."""
    name = array.get("Name", "(points)")
    kind = array.get("type")
    if kind not in DTYPES:
        raise SceneError(f"{path}: the array {name} has the type {kind!r}, not one of {sorted(DTYPES)}")
    fmt = array.get("format", "ascii")
    text = (array.text or "").strip()
    if fmt == "ascii":
        return np.array(text.split(), dtype=DTYPES[kind])
    if fmt != "binary":
        raise SceneError(f"{path}: the array {name} is stored as {fmt!r}; only inline binary and ascii arrays are read")
    size = np.dtype(DTYPES[header_type]).itemsize
    try:
        raw = base64.b64decode(text, validate=False)
        count = int(np.frombuffer(raw[:size], DTYPES[header_type])[0])
        if len(raw) != size + count:  # the header and the values encoded as two base64 blocks
            head_chars = 4 * ((size + 2) // 3)
            count = int(np.frombuffer(base64.b64decode(text[:head_chars]), DTYPES[header_type])[0])
            raw = base64.b64decode(text[:head_chars])[:size] + base64.b64decode(text[head_chars:])
    except (ValueError, IndexError) as e:
        raise SceneError(f"{path}: the array {name} is not valid base64 ({e}): a cut or damaged file") from None
    if len(raw) != size + count or count % np.dtype(DTYPES[kind]).itemsize:
        raise SceneError(f"{path}: the array {name} holds {len(raw) - size} bytes, its header says {count}: "
                         "a cut or damaged file")
    return np.frombuffer(raw[size:], DTYPES[kind]).copy()


def _shaped(path, array, header_type, rows):
    values = _values(path, array, header_type)
    components = int(array.get("NumberOfComponents", "1"))
    if values.size != rows * components:
        raise SceneError(f"{path}: the array {array.get('Name', '(points)')} has {values.size} values, "
                         f"not {rows} x {components}")
    return values.reshape(rows, components) if components > 1 else values


def _xml_root(path, why_missing, why_damaged):
    """(absolute path, root element) of an XML file; SceneError naming it when it is missing or
    does not parse (the reasons given complete the message)."""
    path = os.path.abspath(os.fspath(path))
    if not os.path.isfile(path):
        raise SceneError(f"{path} is missing ({why_missing})")
    try:
        return path, ET.parse(path).getroot()
    except ET.ParseError as e:
        raise SceneError(f"{path} is not a readable XML file ({e}): {why_damaged}") from None


def read_vtu(path):
    """The mesh and fields of one VTU file written by a scene (a Fields): nodes, triangles, point
    and cell data as numpy arrays. Fails (SceneError) naming the file when it is missing, not such a
    VTU, damaged, or holds cells other than triangles."""
    path, root = _xml_root(path, "no such VTU: the run did not write it, or -vtkevery 0 skipped it", "a cut or damaged VTU")
    if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
        raise SceneError(f"{path} is not a VTK UnstructuredGrid file (root {root.tag} {root.get('type')!r})")
    if root.get("byte_order", "LittleEndian") != "LittleEndian" or root.get("compressor"):
        raise SceneError(f"{path}: big-endian or compressed VTU files are not read here "
                         f"(byte_order {root.get('byte_order')!r}, compressor {root.get('compressor')!r})")
    header_type = root.get("header_type", "UInt32")
    if header_type not in ("UInt32", "UInt64"):
        raise SceneError(f"{path}: header_type {header_type!r} is neither UInt32 nor UInt64")
    pieces = root.findall("UnstructuredGrid/Piece")
    if len(pieces) != 1:
        raise SceneError(f"{path} has {len(pieces)} pieces; a scene writes one")
    piece = pieces[0]
    n_points, n_cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))

    def arrays(section):
        return piece.findall(f"{section}/DataArray")

    points = arrays("Points")
    if len(points) != 1:
        raise SceneError(f"{path}: no Points array")
    xyz = _shaped(path, points[0], header_type, n_points).astype(np.float64)
    cells = {a.get("Name"): a for a in arrays("Cells")}
    missing = [k for k in ("connectivity", "offsets", "types") if k not in cells]
    if missing:
        raise SceneError(f"{path}: the Cells section lacks {', '.join(missing)}")
    types = _shaped(path, cells["types"], header_type, n_cells)
    if not np.all(types == TRIANGLE):
        raise SceneError(f"{path}: cells of VTK types {sorted(set(types.tolist()) - {TRIANGLE})} besides triangles; "
                         "only triangle meshes are read")
    offsets = _shaped(path, cells["offsets"], header_type, n_cells).astype(np.int64)
    connectivity = _values(path, cells["connectivity"], header_type).astype(np.int64)
    if not np.array_equal(offsets, 3 * np.arange(1, n_cells + 1)) or connectivity.size != 3 * n_cells:
        raise SceneError(f"{path}: the connectivity is not 3 nodes per triangle")
    triangles = connectivity.reshape(n_cells, 3)
    if n_cells and (triangles.min() < 0 or triangles.max() >= n_points):
        raise SceneError(f"{path}: a triangle names a node outside 0..{n_points - 1}")
    point_data = {a.get("Name"): _shaped(path, a, header_type, n_points) for a in arrays("PointData")}
    cell_data = {a.get("Name"): _shaped(path, a, header_type, n_cells) for a in arrays("CellData")}
    return Fields(path, xyz[:, :2].copy(), triangles, point_data, cell_data)


def read_pvd(path):
    """[(time in s, absolute path of the VTU)] of a fields.pvd, in its order. Fails (SceneError)
    naming the file when it is missing or damaged."""
    path, root = _xml_root(path, "a 2D sleeve scene writes it with its VTU files", "a cut or damaged file")
    states = []
    for entry in root.iter("DataSet"):
        try:
            states.append((float(entry.get("timestep")), os.path.join(os.path.dirname(path), entry.get("file"))))
        except (TypeError, ValueError):
            raise SceneError(f"{path}: a DataSet without a numeric timestep or a file: {entry.attrib}") from None
    return states
