"""mkbool: exact Boolean operations on polygons (Margalit & Knott 1989), from Python.

>>> import mkbool
>>> r = mkbool.union("POLYGON((0 0,2 0,2 2,0 2,0 0))", "POLYGON((1 1,3 1,3 3,1 3,1 1))")
>>> r.wkt
'POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))'

Every operation takes two polygons in any form ``as_polygon`` accepts (WKT, WKB, shapely
geometries, GeoJSON-like mappings, numpy rings, :class:`Polygon`, a previous
:class:`Result`) and keyword options mirroring the command's flags. Given two lists (or
numpy object arrays) of polygons instead, it runs every pair in C++ threads and returns a
list of results. See docs/python.md.
"""

import fractions
import math

from . import _mkbool
from . import harness
from ._inputs import Polygon, as_polygon, is_geometry
from ._mkbool import Error, InputPolygon, InvalidInput, KernelFailure, OutputError, UsageError

__all__ = [
    "intersection", "union", "difference", "symmetric_difference", "xor", "compute",
    "Result", "Polygon", "InputPolygon", "as_polygon",
    "kernel_names", "default_kernel", "is_exact_kernel",
    "Error", "InvalidInput", "KernelFailure", "OutputError", "UsageError",
]

__version__ = "0.1.0"

# Options of the command that the library does not have yet, and the issue that adds them.
# Each becomes a keyword of make_options (python/src/module.cpp) when its issue lands.
_PENDING_OPTIONS = {
    "fill_rule": "fill rules (issue 13)",
    "grid_size": "certified rounding onto a grid (issue 12)",
}


def kernel_names():
    """The kernels built into this library, fastest exact one first."""
    return _mkbool.kernel_names()


def default_kernel():
    return _mkbool.default_kernel()


def is_exact_kernel(name):
    return _mkbool.is_exact_kernel(name)


class Result:
    """The result of one operation.

    Forms: ``.wkt``, ``.wkb``, ``.geojson``, ``__geo_interface__``, ``.to_shapely()``,
    ``.json`` (native JSON, exact coordinates for exact kernels), ``.svg``.
    Geometry: ``.polygons`` (OGC polygons-with-holes: per polygon a list of closed float64
    ``(n + 1, 2)`` arrays, shell counterclockwise then holes clockwise), ``.rings`` and
    ``.types`` (the paper's irreducible result polygons, float64 ``(n, 2)`` without the
    closing vertex, each "island" or "hole"), ``.dangling_edges`` ``(k, 2, 2)`` and
    ``.isolated_points`` ``(k, 2)`` (non-regular results), ``.unbounded``.
    Exact values: ``.area`` (the exact area correctly rounded to a double), ``.area_exact``
    (a ``fractions.Fraction``), ``.exact_rings`` (per irreducible polygon a list of
    ``(Fraction, Fraction)``), ``.rounded_valid`` (whether the rounded vertices still form a
    valid output, checked exactly). Statistics: ``.stats`` (the command's ``--stats``).
    ``area_exact`` and the exact coordinates cost more than the operation on results with
    many crossings: unless the call asked for them (``area_exact=True``, ``exact=True``)
    they are computed on first use, by running the operation again once.
    """

    __slots__ = ("_r", "_area_exact", "_exact_rings")

    def __init__(self, core):
        self._r = core
        self._area_exact = None
        self._exact_rings = None

    op = property(lambda self: self._r.op)
    kernel = property(lambda self: self._r.kernel)
    regular = property(lambda self: self._r.regular)
    unbounded = property(lambda self: self._r.unbounded)
    is_empty = property(lambda self: self._r.is_empty)
    wkt = property(lambda self: self._r.wkt)
    wkb = property(lambda self: self._r.wkb)
    geojson = property(lambda self: self._r.geojson)
    json = property(lambda self: self._r.json)
    svg = property(lambda self: self._r.svg)
    area = property(lambda self: self._r.area)
    rounded_valid = property(lambda self: self._r.rounded_valid)
    polygons = property(lambda self: self._r.polygons)
    rings = property(lambda self: self._r.rings)
    types = property(lambda self: self._r.types)
    dangling_edges = property(lambda self: self._r.dangling_edges)
    isolated_points = property(lambda self: self._r.isolated_points)
    stats = property(lambda self: self._r.stats)

    @property
    def __geo_interface__(self):
        import json
        return json.loads(self._r.geojson)

    @property
    def area_exact(self):
        if self._area_exact is None:
            self._area_exact = fractions.Fraction(*self._r._area_exact_ratio)
        return self._area_exact

    @property
    def exact_rings(self):
        if self._exact_rings is None:
            F = fractions.Fraction
            self._exact_rings = [
                [(F(*c[i]), F(*c[i + 1])) for i in range(0, len(c), 2)] for c in self._r._exact_ratios
            ]
        return self._exact_rings

    def to_shapely(self):
        """The result as a shapely geometry (through WKB: the rounded vertices, bit for bit)."""
        import shapely.wkb
        return shapely.wkb.loads(self._r.wkb)

    def _repr_svg_(self):
        return self._r.svg

    def __repr__(self):
        kinds = {}
        for t in self._r.types:
            kinds[t] = kinds.get(t, 0) + 1
        parts = ", ".join(f"{n} {t}{'s' if n > 1 else ''}" for t, n in kinds.items()) or "empty"
        area = "unbounded" if self.unbounded else f"area {self.area!r}"
        return f"<mkbool.Result {self.op} ({self.kernel}): {parts}, {area}>"


_RAISE = {
    "InvalidInput": InvalidInput, "KernelFailure": KernelFailure, "UsageError": UsageError,
    "MemoryError": MemoryError, "Error": Error,
}


def _check_pending(options):
    for name, value in options.items():
        if name in _PENDING_OPTIONS:
            if value is not None:
                raise UsageError(f"{name}= needs {_PENDING_OPTIONS[name]}, which this build of mkbool does not have yet")
        else:
            raise TypeError(f"unknown option {name}=")


def _is_batch(obj):
    if isinstance(obj, (str, bytes, bytearray, memoryview, dict)) or is_geometry(obj):
        return False
    try:
        import numpy as np
        if isinstance(obj, np.ndarray):
            return obj.dtype == object
    except ImportError:  # pragma: no cover - numpy is a dependency
        pass
    if isinstance(obj, (list, tuple)) and obj:
        return is_geometry(obj[0])
    return False


def compute(op, a, b, *, kernel=None, regular=True, a_type=None, b_type=None, area_exact=False, exact=False,
            threads=None, errors="raise", **pending):
    """A op B, op one of "intersection", "union", "difference", "symmetric_difference" (or
    "xor"). Options as the command's: ``kernel`` (a name from :func:`kernel_names`; default
    the fastest exact one), ``regular`` (False: closed-set operations with dangling edges and
    isolated points), ``a_type``/``b_type`` ("island" or "hole": override the input's
    type). ``area_exact`` and ``exact`` compute the exact area and exact coordinates with the
    operation (otherwise on first use). With sequences of polygons for ``a`` and/or ``b``
    (equal lengths, or one polygon against many), every pair runs in C++ threads
    (``threads``: how many, default one per core) and a list comes back; ``errors="raise"``
    raises the first pair's error (its message starts with "pair i"), ``errors="return"``
    puts the exception in that pair's place.
    """
    _check_pending(pending)
    kernel = "" if kernel is None else kernel
    batch_a, batch_b = _is_batch(a), _is_batch(b)
    if not (batch_a or batch_b):
        pa, pb = as_polygon(a, "A"), as_polygon(b, "B")
        return Result(_mkbool.compute(op, pa, pb, kernel, bool(regular), a_type, b_type, bool(area_exact),
                                      bool(exact)))
    if errors not in ("raise", "return"):
        raise UsageError(f"errors must be 'raise' or 'return', not {errors!r}")
    for t in (a_type, b_type):
        if t is not None and t not in ("island", "hole"):
            raise UsageError(f"unknown polygon type '{t}' (island or hole)")
    if batch_a and batch_b and len(a) != len(b) and 1 not in (len(a), len(b)):
        raise UsageError(f"the sequences of A and B have different lengths ({len(a)} and {len(b)}); give equal "
                         "lengths or one polygon")
    # Inputs that cannot be read are that pair's error, as the operation's own errors are.
    la, ea = _convert_many(a, "A", a_type, batch_a)
    lb, eb = _convert_many(b, "B", b_type, batch_b)
    n = 0 if not la or not lb else max(len(la), len(lb))
    pick = (lambda v, i: v[i] if len(v) > 1 else v[0])
    errors_in = [pick(ea, i) or pick(eb, i) for i in range(n)]
    todo = [i for i in range(n) if errors_in[i] is None]
    out = _mkbool.compute_many(op, [pick(la, i) for i in todo], [pick(lb, i) for i in todo], kernel, bool(regular),
                               bool(area_exact), bool(exact), 0 if threads is None else int(threads))
    results = [None] * n
    for i, r in zip(todo, out):
        results[i] = _RAISE[r[0]](r[1]) if isinstance(r, tuple) else Result(r)
    for i in range(n):
        if errors_in[i] is not None:
            results[i] = errors_in[i]
        if isinstance(results[i], BaseException):
            results[i] = type(results[i])(f"pair {i}: {results[i]}")
            if errors == "raise":
                raise results[i]
    return results


def _convert_many(objs, role, polygon_type, batch):
    """The polygons of one side of a batch, and per polygon the error that refused it."""
    if not batch:
        p = _typed(as_polygon(objs, role), polygon_type)  # one polygon for every pair: raise now
        return [p], [None]
    polygons, errors = [], []
    for i, x in enumerate(objs):
        try:
            polygons.append(_typed(as_polygon(x, f"{role}[{i}]"), polygon_type))
            errors.append(None)
        except Error as e:
            polygons.append(None)
            errors.append(e)
    return polygons, errors


def _typed(polygon, polygon_type):
    return polygon if polygon_type is None else _mkbool.with_type(polygon, polygon_type)


def intersection(a, b, **options):
    """A ∩ B (regular by default: clos(int(A ∩ B))). Options: see :func:`compute`."""
    return compute("intersection", a, b, **options)


def union(a, b, **options):
    """A ∪ B. Options: see :func:`compute`."""
    return compute("union", a, b, **options)


def difference(a, b, **options):
    """A − B (A minus the interior of B). Options: see :func:`compute`."""
    return compute("difference", a, b, **options)


def symmetric_difference(a, b, **options):
    """(A − B) ∪ (B − A). Options: see :func:`compute`."""
    return compute("symmetric_difference", a, b, **options)


xor = symmetric_difference
