"""Turning what a Python user holds into the library's polygon model.

Accepted (MK89 section 2.2: a polygon is rings plus a type, island or hole):

* ``str``: WKT, or GeoJSON / native JSON text (starts with ``{``), read by the same readers
  as the command's inline text;
* ``bytes``, ``bytearray``, ``memoryview``: WKB;
* shapely geometries (through their WKB: exact and fast) and any other object with
  ``__geo_interface__``; ``dict``: a GeoJSON-like mapping;
* :class:`mkbool.Result`: a result as the next operation's input (its rounded vertices);
* :class:`mkbool.Polygon` / ``InputPolygon``: rings with an explicit type;
* a numpy ``float64[n, 2]`` array or a sequence of ``(x, y)`` pairs: one ring;
  a sequence of those: the rings of one polygon (their nesting decides shells and holes);
  a ``float64[k, n, 2]`` array: k rings of n vertices.

Coordinates must be exactly doubles: integers beyond 2**53 or fractions that no double
equals are refused, never rounded silently.
"""

import json
import numbers

import numpy as np

from . import _mkbool

__all__ = ["Polygon", "as_polygon", "is_geometry"]


class Polygon:
    """A polygon in the paper's model: rings (numpy ``(n, 2)`` arrays or sequences of pairs,
    closing vertex optional) and a type, ``"island"`` (the region the rings enclose, their
    nesting deciding shells and holes) or ``"hole"`` (the closure of the outside)."""

    __slots__ = ("rings", "type")

    def __init__(self, rings, type="island"):
        self.rings = rings
        self.type = type

    def __repr__(self):
        return f"mkbool.Polygon({len(self.rings)} rings, type={self.type!r})"


def _shapely_geometry(obj):
    module = type(obj).__module__ or ""
    return module.startswith("shapely.") and hasattr(obj, "wkb")


def is_geometry(obj):
    """Whether obj is one geometry (not a batch of them, not a bare coordinate)."""
    return (
        isinstance(obj, (str, bytes, bytearray, memoryview, dict, Polygon, _mkbool.InputPolygon, _mkbool.Result))
        or isinstance(getattr(obj, "_r", None), _mkbool.Result)
        or hasattr(obj, "__geo_interface__")
    )


def _exact_doubles(array, where):
    """The array as float64, refusing values that no double equals."""
    if array.dtype == np.float64:
        return array
    if array.dtype.kind == "f" or array.dtype.kind == "b":
        return array.astype(np.float64)
    if array.dtype.kind in "iu":
        as_float = array.astype(np.float64)
        flat, flat_float = array.ravel(), as_float.ravel()
        # float64 -> int64 is exact below 2**63; compare as Python ints at and above that.
        if (np.abs(flat_float) >= 2.0**63).any():
            bad = [v for v in flat.tolist() if float(v) != v]
        else:
            bad = flat[flat_float.astype(array.dtype) != flat].tolist()
        if bad:
            raise _mkbool.InvalidInput(f"{where}: coordinate {bad[0]} is not exactly a double")
        return as_float
    if array.dtype == object:
        flat = array.ravel().tolist()
        out = np.empty(len(flat), dtype=np.float64)
        for i, v in enumerate(flat):
            if not isinstance(v, numbers.Real):
                raise _mkbool.InvalidInput(f"{where}: coordinate {v!r} is not a number")
            try:
                f = float(v)
            except OverflowError:
                raise _mkbool.InvalidInput(f"{where}: coordinate {v} is not exactly a double") from None
            if f != v and f == f:
                raise _mkbool.InvalidInput(f"{where}: coordinate {v} is not exactly a double")
            out[i] = f
        return out.reshape(array.shape)
    raise _mkbool.InvalidInput(f"{where}: coordinates of type {array.dtype} are not numbers")


def _ring(obj, where):
    try:
        array = np.asarray(obj)
    except (ValueError, TypeError) as e:
        raise _mkbool.InvalidInput(f"{where}: not an array of (x, y) pairs ({e})") from None
    if array.dtype.kind not in "fiub" and array.dtype != object:
        raise _mkbool.InvalidInput(f"{where}: coordinates of type {array.dtype} are not numbers")
    return _exact_doubles(array, where)


def _is_pair(obj):
    if isinstance(obj, np.ndarray):
        return obj.ndim == 1
    try:
        return len(obj) == 2 and all(isinstance(v, numbers.Real) for v in obj)
    except TypeError:
        return False


def _from_rings(rings, polygon_type):
    if isinstance(rings, np.ndarray):
        if rings.ndim == 2:
            rings = [rings]
        elif rings.ndim == 3:
            rings = list(rings)
        elif rings.size == 0:
            rings = []
        else:
            raise _mkbool.InvalidInput(
                f"an array of rings has shape (n, 2) for one ring or (k, n, 2) for k rings, got {rings.shape}")
    else:
        try:
            rings = list(rings)
        except TypeError:
            raise _mkbool.InvalidInput(f"the rings of a polygon are a sequence, not {type(rings).__name__}") from None
        if rings and _is_pair(rings[0]):
            rings = [rings]
    arrays = [_ring(r, f"ring {i}") for i, r in enumerate(rings)]
    return _mkbool.from_arrays(arrays, polygon_type)


def _with_role(role, fn, *args):
    try:
        return fn(*args)
    except _mkbool.InvalidInput as e:
        raise _mkbool.InvalidInput(f"{role}: {e}") from None


def as_polygon(obj, role="A"):
    """The library's polygon (an ``InputPolygon``) for any accepted input; raises
    :class:`mkbool.InvalidInput` naming the role ("A" or "B") and what is wrong."""
    if isinstance(obj, _mkbool.InputPolygon):
        return obj
    if isinstance(obj, str):
        form = "JSON" if obj.lstrip().startswith("{") else "WKT"
        return _with_role(f"{role} ({form})", _mkbool.from_text, obj)
    if isinstance(obj, (bytes, bytearray, memoryview)):
        return _with_role(f"{role} (WKB)", _mkbool.from_wkb, obj)
    core = getattr(obj, "_r", obj)
    if isinstance(core, _mkbool.Result):
        return _mkbool.from_result(core)
    if isinstance(obj, Polygon):
        return _with_role(role, _from_rings, obj.rings, obj.type)
    if _shapely_geometry(obj):
        if obj.is_empty:
            return _mkbool.from_wkt("POLYGON EMPTY") if obj.geom_type in ("Polygon", "MultiPolygon", "GeometryCollection") \
                else _with_role(f"{role} (shapely)", _mkbool.from_wkt, obj.wkt)
        return _with_role(f"{role} (shapely WKB)", _mkbool.from_wkb, obj.wkb)
    if hasattr(obj, "__geo_interface__") and not isinstance(obj, dict):
        obj = obj.__geo_interface__
    if isinstance(obj, dict):
        try:
            text = json.dumps(obj, default=_json_default)
        except (TypeError, ValueError) as e:
            raise _mkbool.InvalidInput(f"{role} (GeoJSON mapping): {e}") from None
        return _with_role(f"{role} (GeoJSON mapping)", _mkbool.from_text, text)
    if isinstance(obj, (list, tuple, np.ndarray)) or hasattr(obj, "__len__"):
        return _with_role(role, _from_rings, obj, "island")
    raise _mkbool.InvalidInput(
        f"{role}: cannot read a polygon from {type(obj).__name__}; give WKT, WKB, a shapely geometry, a GeoJSON-like "
        "mapping, an mkbool.Polygon or a sequence of (n, 2) rings")


def _json_default(v):
    # shapely's __geo_interface__ holds tuples (fine) and sometimes numpy scalars.
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    raise TypeError(f"{type(v).__name__} is not a coordinate")
