"""Turning what a Python user holds into the library's polygon model.

Accepted (MK89 section 2.2: a polygon is rings plus a type, island or hole):

* ``str``: WKT, or GeoJSON / native JSON text (starts with ``{``), read by the same readers
  as the command's inline text;
* ``bytes``, ``bytearray``, ``memoryview``: WKB;
* shapely geometries (through their WKB: exact and fast) and any other object with
  ``__geo_interface__``; ``dict``: a GeoJSON-like mapping;
* :class:`mkbool.Result`: a result as the next operation's input, exactly (exact kernels'
  regular results: rationals where its coordinates are not doubles), else its rounded
  polygons;
* :class:`mkbool.Polygon` / ``InputPolygon``: rings with an explicit type;
* a numpy ``float64[n, 2]`` array or a sequence of ``(x, y)`` pairs: one ring;
  a sequence of those: the rings of one polygon (their nesting decides shells and holes);
  a ``float64[k, n, 2]`` array: k rings of n vertices.

Coordinates are taken exactly: a coordinate that is not a double (a ``Fraction``, a
``Decimal``, an integer beyond 2**53, native JSON's "p/q") makes the polygon exact, and
the operation then runs over rationals (exact kernels only); nothing is rounded silently.

Fill rules and the N-ary operations read an input as parts (:func:`as_parts`): OGC forms
without checking their rings (they may cross and overlap), rings as one part whose first
ring is the shell and the others its holes (GeoJSON's order); doubles only.
"""

import decimal
import json
import numbers

import numpy as np

from . import _mkbool

__all__ = ["Polygon", "as_polygon", "as_parts", "is_geometry"]


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
        isinstance(obj, (str, bytes, bytearray, memoryview, dict, Polygon, _mkbool.InputPolygon, _mkbool.InputParts,
                         _mkbool.Result))
        or isinstance(getattr(obj, "_r", None), _mkbool.Result)
        or hasattr(obj, "__geo_interface__")
    )


def _exact_doubles(array, where):
    """The array as float64 when every value is exactly a double; else an object array of
    the exact values (Python numbers), which the caller sends through the exact path."""
    if array.dtype == np.float64:
        return array
    if array.dtype.kind == "f" or array.dtype.kind == "b":
        return array.astype(np.float64)
    if array.dtype.kind in "iu":
        as_float = array.astype(np.float64)
        flat, flat_float = array.ravel(), as_float.ravel()
        # float64 -> int64 is exact below 2**63; compare as Python ints at and above that.
        if (np.abs(flat_float) >= 2.0**63).any():
            exact = any(float(v) != v for v in flat.tolist())
        else:
            exact = bool((flat_float.astype(array.dtype) != flat).any())
        return np.array(array.tolist(), dtype=object) if exact else as_float
    if array.dtype == object:
        flat = array.ravel().tolist()
        out = np.empty(len(flat), dtype=np.float64)
        exact = False
        for i, v in enumerate(flat):
            if not isinstance(v, (numbers.Real, decimal.Decimal)):
                raise _mkbool.InvalidInput(f"{where}: coordinate {v!r} is not a number")
            try:
                f = float(v)
            except OverflowError:  # an integer or fraction beyond the doubles: exact
                exact = True
                continue
            if f != v and f == f:
                exact = True
                continue
            out[i] = f
        return array if exact else out.reshape(array.shape)
    raise _mkbool.InvalidInput(f"{where}: coordinates of type {array.dtype} are not numbers")


def _ring(obj, where):
    try:
        array = np.asarray(obj)
    except (ValueError, TypeError) as e:
        raise _mkbool.InvalidInput(f"{where}: not an array of (x, y) pairs ({e})") from None
    if array.dtype.kind not in "fiub" and array.dtype != object:
        raise _mkbool.InvalidInput(f"{where}: coordinates of type {array.dtype} are not numbers")
    return _exact_doubles(array, where)


def _exact_text(v, where, k):
    """A coordinate exactly, as the extension reads it: "p/q" in hexadecimal (Python's
    decimal int-to-text conversion stops at 4300 digits; hexadecimal has no limit)."""
    if isinstance(v, numbers.Integral):
        return format(int(v), "x")
    if isinstance(v, numbers.Rational):
        n, d = v.numerator, v.denominator
    else:
        try:
            n, d = (v if hasattr(v, "as_integer_ratio") else float(v)).as_integer_ratio()
        except (ValueError, OverflowError):
            raise _mkbool.InvalidInput(f"{where}, vertex {k // 2}: {'xy'[k % 2]} coordinate is not finite") from None
    return f"{n:x}/{d:x}"


def _exact_ring_texts(array, where):
    if array.ndim != 2 or array.shape[1] != 2:
        raise _mkbool.InvalidInput(f"{where}: expected vertices of shape (n, 2), got shape {array.shape}")
    return [_exact_text(v, where, k) for k, v in enumerate(array.ravel().tolist())]


def _is_pair(obj):
    if isinstance(obj, np.ndarray):
        return obj.ndim == 1
    try:
        return len(obj) == 2 and all(isinstance(v, (numbers.Real, decimal.Decimal)) for v in obj)
    except TypeError:
        return False


def _from_rings(rings, polygon_type):
    arrays = _ring_arrays(rings)
    if any(a.dtype == object for a in arrays):
        return _mkbool.from_exact([_exact_ring_texts(a, f"ring {i}") for i, a in enumerate(arrays)], polygon_type)
    return _mkbool.from_arrays(arrays, polygon_type)


def _ring_arrays(rings):
    """The rings of one polygon (any accepted array form) as a list of arrays, float64 or,
    for rings with coordinates that are not doubles, object arrays of the exact values."""
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
    return [_ring(r, f"ring {i}") for i, r in enumerate(rings)]


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
    if isinstance(obj, _mkbool.InputParts):
        raise _mkbool.UsageError(f"{role}: parts read for a fill rule (InputParts) are read by one: give fill_rule=")
    return _read(obj, role, _mkbool.from_text, _mkbool.from_wkb, _mkbool.from_result,
                 lambda rings, polygon_type, role: _from_rings(rings, polygon_type))


def as_parts(obj, role="A"):
    """The parts of any accepted input, unchecked (``InputParts``), for fill rules and the
    N-ary operations: WKT (also one geometry per line), GeoJSON, WKB and shapely geometries
    as their parts; rings (arrays, sequences, :class:`Polygon`) as one part, the first ring
    its shell and the others its holes; a :class:`mkbool.Result` as its polygons when those
    are the result exactly. Coordinates must be doubles (the library's fill rules read
    doubles): others raise :class:`mkbool.UsageError`."""
    if isinstance(obj, _mkbool.InputParts):
        return obj
    if isinstance(obj, _mkbool.InputPolygon):
        raise _mkbool.UsageError(
            f"{role}: an InputPolygon's rings are read by nesting, not by a fill rule: give the geometry itself "
            "(WKT, WKB, shapely, GeoJSON or rings)")
    return _read(obj, role, _mkbool.parts_from_text, _mkbool.parts_from_wkb, _mkbool.parts_from_result,
                 _parts_from_rings)


def _read(obj, role, text, wkb, result, rings):
    """obj read by the reader of its form: text (WKT or JSON), wkb, result (a Result) or
    rings(rings, type, role) (arrays, sequences, Polygon)."""
    if isinstance(obj, str):
        form = "JSON" if obj.lstrip().startswith("{") else "WKT"
        return _with_role(f"{role} ({form})", text, obj)
    if isinstance(obj, (bytes, bytearray, memoryview)):
        return _with_role(f"{role} (WKB)", wkb, obj)
    core = getattr(obj, "_r", obj)
    if isinstance(core, _mkbool.Result):
        return _with_role(role, result, core)
    if isinstance(obj, Polygon):
        return _with_role(role, rings, obj.rings, obj.type, role)
    if _shapely_geometry(obj):
        if obj.is_empty:
            polygonal = obj.geom_type in ("Polygon", "MultiPolygon", "GeometryCollection")
            return _with_role(f"{role} (shapely)", text, "POLYGON EMPTY" if polygonal else obj.wkt)
        return _with_role(f"{role} (shapely WKB)", wkb, obj.wkb)
    if hasattr(obj, "__geo_interface__") and not isinstance(obj, dict):
        obj = obj.__geo_interface__
    if isinstance(obj, dict):
        try:
            mapping = json.dumps(obj, default=_json_default)
        except (TypeError, ValueError) as e:
            raise _mkbool.InvalidInput(f"{role} (GeoJSON mapping): {e}") from None
        return _with_role(f"{role} (GeoJSON mapping)", text, mapping)
    if isinstance(obj, (list, tuple, np.ndarray)) or hasattr(obj, "__len__"):
        return _with_role(role, rings, obj, "island", role)
    raise _mkbool.InvalidInput(
        f"{role}: cannot read a polygon from {type(obj).__name__}; give WKT, WKB, a shapely geometry, a GeoJSON-like "
        "mapping, an mkbool.Polygon or a sequence of (n, 2) rings")


def _parts_from_rings(rings, polygon_type, role):
    """Rings as one part (the polygon type is the caller's: by_rule)."""
    arrays = _ring_arrays(rings)
    for i, a in enumerate(arrays):
        if a.dtype == object:
            raise _mkbool.UsageError(
                f"{role}: ring {i} has coordinates that are not doubles; fill rules and the N-ary operations read "
                "doubles (without a fill rule the binary operations take them exactly)")
    return _mkbool.parts_from_arrays(arrays)


def by_rule(obj, role, rule):
    """The polygon of any accepted input as fill rule ``rule`` reads it (``InputPolygon``)."""
    if isinstance(obj, _mkbool.InputPolygon):
        return obj  # made by the caller: its rings as they are
    polygon_type = obj.type if isinstance(obj, Polygon) else "island"
    return _with_role(role, _mkbool.by_rule, as_parts(obj, role), rule, polygon_type)


def _json_default(v):
    # shapely's __geo_interface__ holds tuples (fine) and sometimes numpy scalars.
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    raise TypeError(f"{type(v).__name__} is not a coordinate")
