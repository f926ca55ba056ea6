"""mkbool: exact Boolean operations on polygons (Margalit & Knott 1989), from Python.

>>> import mkbool
>>> r = mkbool.union("POLYGON((0 0,2 0,2 2,0 2,0 0))", "POLYGON((1 1,3 1,3 3,1 3,1 1))")
>>> r.wkt
'POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))'

Every operation takes two polygons in any form ``as_polygon`` accepts (WKT, WKB, shapely
geometries, GeoJSON-like mappings, numpy rings, exact coordinates as Fractions,
:class:`Polygon`, a previous :class:`Result`, exactly) and keyword options mirroring the
command's flags (``fill_rule=``, ``grid_size=``, ``rounding=`` among them). Given two lists
(or numpy object arrays) of polygons instead, it runs every pair in C++ threads and returns
a list of results. ``union_all``, ``intersection_all`` and ``make_valid`` are the command's
N-ary verbs. See docs/python.md.
"""

import decimal
import fractions
import numbers

from . import _mkbool
from . import harness
from ._inputs import Polygon, _is_pair, as_parts, as_polygon, by_rule, is_geometry
from ._mkbool import Error, InputParts, InputPolygon, InvalidInput, KernelFailure, OutputError, UsageError

__all__ = [
    "intersection", "union", "difference", "symmetric_difference", "xor", "compute",
    "union_all", "intersection_all", "make_valid", "FILL_RULES",
    "Result", "Polygon", "InputPolygon", "InputParts", "as_polygon", "as_parts",
    "kernel_names", "default_kernel", "is_exact_kernel",
    "memory_cache", "set_memory_cache_limit", "release_memory",
    "Error", "InvalidInput", "KernelFailure", "OutputError", "UsageError",
]

__version__ = "0.2.0"

# The command's --fill-rule values (Clipper's meanings; "union": OGC shells counterclockwise,
# holes clockwise, then nonzero).
FILL_RULES = ("evenodd", "nonzero", "positive", "negative", "union")


def kernel_names():
    """The kernels built into this library, fastest exact one first."""
    return _mkbool.kernel_names()


def default_kernel():
    return _mkbool.default_kernel()


def is_exact_kernel(name):
    return _mkbool.is_exact_kernel(name)


def memory_cache():
    """The large blocks (256 KiB and more) the library freed and keeps for its next call:
    ``{"cached_bytes", "blocks", "limit_bytes"}``. Kept blocks spare the next operation
    the page faults of fresh memory (about a quarter of an operation on large inputs)."""
    return _mkbool.memory_cache()


def set_memory_cache_limit(nbytes):
    """Keep at most ``nbytes`` of freed blocks (default 256 MiB; 0 keeps none); kept blocks
    beyond the new limit are freed at once."""
    if nbytes < 0:
        raise ValueError("the memory cache limit is a number of bytes, at least 0")
    _mkbool.set_memory_cache_limit(int(nbytes))


def release_memory():
    """Free every kept block (the limit stays): the process's memory as if no operation
    had run."""
    _mkbool.release_memory()


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
    ``(Fraction, Fraction)``), ``.exact_polygon()`` (the result as an exact input; a Result
    given as an operand is read the same way), ``.rounded_valid`` (whether the nearest
    doubles form a valid output, checked exactly). Rounding: ``.rounding`` (the command's
    --stats "rounding": mode, snapped, grid, max_displacement in grid units, valid, ...):
    ``.wkt``, ``.wkb``, ``.polygons`` and the other written forms are the certified (or
    snapped) doubles, while ``.area``, ``.area_exact``, ``.rings`` and ``.exact_rings``
    describe the exact result. Statistics: ``.stats`` (the command's ``--stats``).
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
    rounding = property(lambda self: self._r.rounding)
    fill_rule = property(lambda self: self._r.fill_rule)
    grid = property(lambda self: self._r.grid)

    def exact_polygon(self):
        """The result as an input (``InputPolygon``), exactly: rationals where its coordinates
        are not doubles (exact kernels, regular results; otherwise its rounded polygons)."""
        return self._r.exact_polygon()

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


def _grid_text(grid_size):
    """grid_size as the library's exact text: str as written (a decimal or p/q), int,
    Fraction and Decimal exactly, a float as its exact binary value (0.1 is not 1/10)."""
    if grid_size is None:
        return ""
    if isinstance(grid_size, bool) or not isinstance(grid_size, (str, numbers.Real, decimal.Decimal)):
        raise UsageError(f"grid_size must be a number (int, float, Fraction, Decimal) or decimal text, not "
                         f"{type(grid_size).__name__}")
    if isinstance(grid_size, str):
        if not grid_size.strip():
            raise UsageError("grid_size='' is empty (grid_size=None: no grid)")
        return grid_size.strip()  # the library says what else is wrong with the text
    try:
        v = fractions.Fraction(grid_size if isinstance(grid_size, (numbers.Rational, float, decimal.Decimal))
                               else float(grid_size))
    except (ValueError, OverflowError):
        raise UsageError(f"grid_size={grid_size!r} is not a finite number") from None
    if v <= 0:
        raise UsageError(f"grid_size={grid_size!r} is not positive (grid_size=None: no grid)")
    try:
        return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
    except ValueError:  # beyond Python's 4300-digit conversion limit, and far beyond the doubles
        raise UsageError("grid_size is outside the range of doubles") from None


def _options(fill_rule, grid_size, rounding):
    """(fill rule, grid, rounding) as the extension takes them, checked before any input is
    read (with a fill rule inputs are read differently)."""
    if fill_rule is not None and fill_rule not in FILL_RULES:
        raise UsageError(f"unknown fill rule {fill_rule!r} (evenodd, nonzero, positive, negative or union)"
                         if isinstance(fill_rule, str) else f"fill_rule must be a string, not {type(fill_rule).__name__}")
    if rounding not in ("certified", "nearest"):
        raise UsageError(f"unknown rounding {rounding!r} (certified or nearest)")
    grid = _grid_text(grid_size)
    if grid and rounding == "nearest":
        raise UsageError("grid_size= snaps the result, which rounding='nearest' does not")
    return fill_rule or "", grid, rounding


def _is_batch(obj):
    if isinstance(obj, (str, bytes, bytearray, memoryview, dict)) or is_geometry(obj):
        return False
    try:
        import numpy as np
        if isinstance(obj, np.ndarray):
            return obj.dtype == object and obj.ndim == 1  # (n, 2) of objects: one ring of exact numbers
    except ImportError:  # pragma: no cover - numpy is a dependency
        pass
    if isinstance(obj, (list, tuple)) and obj:
        return is_geometry(obj[0])
    return False


def compute(op, a, b, *, kernel=None, regular=True, a_type=None, b_type=None, fill_rule=None, grid_size=None,
            rounding="certified", area_exact=False, exact=False, threads=None, errors="raise"):
    """A op B, op one of "intersection", "union", "difference", "symmetric_difference" (or
    "xor"). Options as the command's: ``kernel`` (a name from :func:`kernel_names`; default
    the fastest exact one), ``regular`` (False: closed-set operations with dangling edges and
    isolated points), ``a_type``/``b_type`` ("island" or "hole": override the input's
    type), ``fill_rule`` (one of :data:`FILL_RULES`: each input's rings read in their given
    directions, crossing freely, by their winding numbers; inputs are then read by
    :func:`as_parts`), ``grid_size`` (snap-round the result onto multiples of it: str, int,
    Fraction and Decimal exactly, a float as its exact binary value), ``rounding``
    ("certified": the nearest doubles when valid, else snap rounding; "nearest": the nearest
    doubles, valid or not, which ``.rounding["valid"]`` says). ``area_exact`` and ``exact``
    compute the exact area and exact coordinates with the operation (otherwise on first use).
    With sequences of polygons for ``a`` and/or ``b``
    (equal lengths, or one polygon against many), every pair runs in C++ threads
    (``threads``: how many, default one per core) and a list comes back; ``errors="raise"``
    raises the first pair's error (its message starts with "pair i"), ``errors="return"``
    puts the exception in that pair's place.
    """
    rule, grid, rounding = _options(fill_rule, grid_size, rounding)
    convert = as_polygon if not rule else (lambda x, role: by_rule(x, role, rule))
    kernel = "" if kernel is None else kernel
    batch_a, batch_b = _is_batch(a), _is_batch(b)
    if not (batch_a or batch_b):
        pa, pb = convert(a, "A"), convert(b, "B")
        return Result(_mkbool.compute(op, pa, pb, kernel, bool(regular), a_type, b_type, bool(area_exact),
                                      bool(exact), rule, grid, rounding))
    if errors not in ("raise", "return"):
        raise UsageError(f"errors must be 'raise' or 'return', not {errors!r}")
    for t in (a_type, b_type):
        if t is not None and t not in ("island", "hole"):
            raise UsageError(f"unknown polygon type '{t}' (island or hole)")
    if batch_a and batch_b and len(a) != len(b) and 1 not in (len(a), len(b)):
        raise UsageError(f"the sequences of A and B have different lengths ({len(a)} and {len(b)}); give equal "
                         "lengths or one polygon")
    # Inputs that cannot be read are that pair's error, as the operation's own errors are.
    la, ea = _convert_many(a, "A", a_type, batch_a, convert)
    lb, eb = _convert_many(b, "B", b_type, batch_b, convert)
    n = 0 if not la or not lb else max(len(la), len(lb))
    pick = (lambda v, i: v[i] if len(v) > 1 else v[0])
    errors_in = [pick(ea, i) or pick(eb, i) for i in range(n)]
    todo = [i for i in range(n) if errors_in[i] is None]
    out = _mkbool.compute_many(op, [pick(la, i) for i in todo], [pick(lb, i) for i in todo], kernel, bool(regular),
                               bool(area_exact), bool(exact), 0 if threads is None else int(threads), rule, grid,
                               rounding)
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


def _convert_many(objs, role, polygon_type, batch, convert):
    """The polygons of one side of a batch, and per polygon the error that refused it."""
    if not batch:
        p = _typed(convert(objs, role), polygon_type)  # one polygon for every pair: raise now
        return [p], [None]
    polygons, errors = [], []
    for i, x in enumerate(objs):
        try:
            polygons.append(_typed(convert(x, f"{role}[{i}]"), polygon_type))
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


def union_all(geoms, *, fill_rule=None, kernel=None, grid_size=None, rounding="certified", area_exact=False,
              exact=False):
    """The union of every polygon in ``geoms``, in one arrangement of all their rings (the
    command's ``union-all``). ``geoms``: one geometry (its parts: a MULTIPOLYGON, a
    GEOMETRYCOLLECTION, a GeoJSON FeatureCollection, WKT with one geometry per line) or an
    iterable of inputs in any form :func:`as_parts` reads (their parts together). The rings
    may cross and overlap. ``fill_rule``: None or "union" (the default: every part its shell
    less its holes, then their union); the other rules read all rings together, as Clipper's
    union of all paths. Other options as :func:`compute`."""
    return _parts_operation("union_all", geoms, fill_rule, kernel, grid_size, rounding, area_exact, exact)


def intersection_all(geoms, *, fill_rule=None, kernel=None, grid_size=None, rounding="certified", area_exact=False,
                     exact=False):
    """The points in every polygon of ``geoms`` (the command's ``intersection-all``), each
    polygon read by the fill rule on its own (default "union"). One geometry: its parts are
    the polygons; an iterable: its elements are, each of one part (an element of several
    parts is refused: union it first) or none (then the result is empty). No polygon at all
    is refused (the plane has no bounded form)."""
    return _parts_operation("intersection_all", geoms, fill_rule, kernel, grid_size, rounding, area_exact, exact)


def make_valid(geom, *, fill_rule="evenodd", kernel=None, grid_size=None, rounding="certified", area_exact=False,
               exact=False):
    """The valid polygon of ``geom``'s region under ``fill_rule`` (default evenodd: a point
    is inside when an odd number of rings wind around it; "union" gives OGC's union of the
    parts). Any rings: crossing themselves and each other, overlapping, repeated. The
    command's ``make-valid``; docs/usage.md says how it differs from GEOS's MakeValid."""
    if fill_rule is None:
        fill_rule = "evenodd"
    return _parts_operation("make_valid", geom, fill_rule, kernel, grid_size, rounding, area_exact, exact)


def _parts_operation(name, geoms, fill_rule, kernel, grid_size, rounding, area_exact, exact):
    rule, grid, rounding = _options(fill_rule, grid_size, rounding)
    elements = not (name == "make_valid" or _is_one_geometry(geoms))
    if not elements:
        parts = [_island_parts(geoms, "geoms" if name != "make_valid" else "geom")]
    else:
        try:
            items = list(geoms)
        except TypeError:
            raise InvalidInput(f"{name}: cannot read polygons from {type(geoms).__name__}; give a geometry or an "
                               "iterable of them") from None
        parts = [_island_parts(g, f"geoms[{i}]") for i, g in enumerate(items)]
        if name == "intersection_all":
            for i, p in enumerate(parts):
                if p.part_count > 1:
                    raise InvalidInput(f"geoms[{i}]: {p.part_count} parts: intersection_all intersects polygons of one "
                                       "part each (give the parts as elements, or union_all them first)")
    return Result(_mkbool.compute_all(name, parts, "" if kernel is None else kernel, rule, grid, rounding,
                                      bool(area_exact), bool(exact), elements))


def _is_one_geometry(geoms):
    if is_geometry(geoms):
        return True
    try:
        import numpy as np
        if isinstance(geoms, np.ndarray):
            return geoms.dtype != object or geoms.ndim != 1  # (n, 2) or (k, n, 2): rings of one polygon
    except ImportError:  # pragma: no cover - numpy is a dependency
        pass
    if isinstance(geoms, (list, tuple)) and geoms:
        return _is_pair(geoms[0])  # one ring as a list of (x, y) pairs
    return False


def _island_parts(obj, role):
    if isinstance(obj, Polygon) and obj.type != "island":
        raise InvalidInput(f"{role}: the N-ary operations read islands (the parts' regions), not type {obj.type!r}")
    return as_parts(obj, role)
