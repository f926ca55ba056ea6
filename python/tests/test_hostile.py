"""Hostile input from Python: NaN, infinities, huge and tiny coordinates, empty and
malformed inputs, wrong types and absurd options each raise a Python exception (the
mkbool one the command's exit code maps to, or TypeError for a wrong argument type), and
never crash the interpreter: every call runs in a child interpreter whose exit status is
checked, so a crash fails the test instead of killing the run."""

import os
import subprocess
import sys
import textwrap

import pytest

# Each entry: (the call, the exception type's name, a fragment of its message). The calls
# run in one child process (see run_children) with `mkbool`, `np`, `sg` and `SQ` (a unit
# square in WKT) defined.
HOSTILE = [
    # non-finite and out-of-range coordinates, in every input form
    ("mkbool.union(np.array([[0, 0], [1, np.nan], [0, 1]]), SQ)", "InvalidInput", "y coordinate is not finite"),
    ("mkbool.union([(0, 0), (np.inf, 0), (0, 1)], SQ)", "InvalidInput", "x coordinate is not finite"),
    ("mkbool.union([(0, 0), (1e400, 0), (0, 1)], SQ)", "InvalidInput", "not finite"),
    ("mkbool.union([(0, 0), (10**400, 0), (0, 1)], SQ)", "InvalidInput", "vertex 1: coordinate beyond the range of doubles"),
    ("mkbool.union([(0, 0), (fractions.Fraction(1, 3), 0), (0, 10**100000)], SQ)", "InvalidInput",
     "vertex 2: coordinate beyond the range of doubles"),
    ("mkbool.union([(0, 0), (fractions.Fraction(1, 3**20000), 0), (0, 1)], SQ).area_exact == 1 or 1 / 0", "", "returned"),
    ("mkbool.union([(0, 0), (decimal.Decimal('NaN'), 0), (0, 1)], SQ)", "InvalidInput", "x coordinate is not finite"),
    ("mkbool.union([(0, 0), (fractions.Fraction(1, 3), decimal.Decimal('-Infinity')), (0, 1)], SQ)", "InvalidInput",
     "y coordinate is not finite"),
    ("mkbool.union([(0, 0), (fractions.Fraction(1, 3), 0), (0, 1)], SQ, kernel='interval')", "UsageError",
     "takes doubles only"),
    ("mkbool.union('POLYGON((0 0,1 0,nan 1,0 0))', SQ)", "InvalidInput", "A (WKT): WKT line 1"),
    ("mkbool.union('POLYGON((0 0,1 0,1e999 1,0 0))', SQ)", "InvalidInput", "A (WKT): WKT line 1"),
    ("mkbool.union({'type': 'Polygon', 'coordinates': [[[0, 0], [1, 0], [float('nan'), 1], [0, 0]]]}, SQ)",
     "InvalidInput", "A (GeoJSON mapping)"),
    ("mkbool.union(sg.Polygon([(0, 0), (1, 0), (float('inf'), 1)]), SQ)", "InvalidInput", "not finite"),
    ("mkbool.union(sg.Polygon([(0, 0, float('nan')), (1, 0, 0), (0, 1, 0)]), SQ)", "InvalidInput",
     "third coordinate is not finite"),
    # empty and degenerate input
    ("mkbool.union('', SQ)", "InvalidInput", "A (WKT)"),
    ("mkbool.union(b'', SQ)", "InvalidInput", "WKB byte 0: empty input"),
    ("mkbool.union(np.zeros((0, 2)), SQ)", "InvalidInput", "ring 0: ring is empty"),
    ("mkbool.union([np.zeros((3, 2, 2))], SQ)", "InvalidInput", "expected vertices of shape (n, 2)"),
    ("mkbool.union(np.zeros((2, 2, 2, 2)), SQ)", "InvalidInput", "an array of rings has shape"),
    ("mkbool.union('POLYGON((0 0,1 0,1 1))', SQ)", "InvalidInput", "ring has 3 coordinates"),
    ("mkbool.union('{', SQ)", "InvalidInput", "A (JSON)"),
    ("mkbool.union('POLYGON((0 0,1 0,0 1,0 0' + ',0 0' * 5 + '\\x00', SQ)", "InvalidInput", "A (WKT)"),
    # nesting far deeper than any polygon: the readers do not recurse on it
    ("mkbool.union('{\"type\": \"Polygon\", \"coordinates\": ' + '[' * 200000 + ']' * 200000 + '}', SQ)",
     "InvalidInput", "A (JSON)"),
    ("mkbool.union('POLYGON' + '(' * 200000 + ')' * 200000, SQ)", "InvalidInput", "A (WKT)"),
    ("mkbool.union(b'\\x01\\x07\\x00\\x00\\x00\\x01\\x00\\x00\\x00' * 20000, SQ)", "InvalidInput", "A (WKB)"),
    # malformed WKB: counts far beyond the bytes, every type code's neighbours
    ("mkbool.union(b'\\x01\\x03\\x00\\x00\\x00\\xff\\xff\\xff\\xff', SQ)", "InvalidInput", "ring count 4294967295"),
    ("mkbool.union(b'\\x01\\x06\\x00\\x00\\x00\\xff\\xff\\xff\\x7f', SQ)", "InvalidInput", "polygon count"),
    ("mkbool.union(b'\\x07' * 64, SQ)", "InvalidInput", "byte order 7"),
    ("mkbool.union(sg.Point(0, 0), SQ)", "InvalidInput", "Point is not a polygonal geometry"),
    # outside the domain: crossing edges, overlapping parts
    ("mkbool.union([(0, 0), (2, 2), (2, 0), (0, 2)], SQ)", "InvalidInput", "cross"),
    ("mkbool.union('MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))', SQ)", "InvalidInput", "polygon"),
    ("mkbool.union(sg.MultiPolygon([sg.box(0, 0, 3, 3), sg.box(1, 1, 2, 2)]), SQ)", "InvalidInput",
     "polygon 1 lies inside polygon 0"),
    ("mkbool.union('POLYGON((0 0,4 0,4 4,0 4,0 0),(5 5,6 5,6 6,5 5))', SQ)", "InvalidInput", "lies outside its shell"),
    # wrong types
    ("mkbool.union(None, SQ)", "InvalidInput", "cannot read a polygon from NoneType"),
    ("mkbool.union(42, SQ)", "InvalidInput", "cannot read a polygon from int"),
    ("mkbool.union(3.5, SQ)", "InvalidInput", "cannot read a polygon from float"),
    ("mkbool.union(object(), SQ)", "InvalidInput", "cannot read a polygon from object"),
    ("mkbool.union([(0, 0), ('x', 0), (0, 1)], SQ)", "InvalidInput", "are not numbers"),
    ("mkbool.union([(0, 0), (None, 0), (0, 1)], SQ)", "InvalidInput", "not a number"),
    ("mkbool.union([(0, 0), (1j, 0), (0, 1)], SQ)", "InvalidInput", "are not numbers"),
    ("mkbool.union([[(0, 0), (1, 0)], 5], SQ)", "InvalidInput", "ring 1"),
    ("mkbool.union({'type': 'Polygon'}, SQ)", "InvalidInput", "A (GeoJSON mapping)"),
    ("mkbool.union({'type': 'Polygon', 'coordinates': object()}, SQ)", "InvalidInput", "A (GeoJSON mapping)"),
    ("mkbool.union(mkbool.Polygon(None), SQ)", "InvalidInput", "A: the rings of a polygon are a sequence"),
    ("mkbool.union(mkbool.Polygon([[(0, 0), (1, 0), (0, 1)]], type=3), SQ)", "TypeError", ""),
    # absurd options
    ("mkbool.union(SQ, SQ, kernel='fast')", "UsageError", "unknown kernel 'fast'"),
    ("mkbool.union(SQ, SQ, kernel=7)", "TypeError", ""),
    ("mkbool.union(SQ, SQ, a_type='lake')", "UsageError", "unknown polygon type 'lake'"),
    ("mkbool.compute('merge', SQ, SQ)", "UsageError", "unknown operation 'merge'"),
    ("mkbool.compute(None, SQ, SQ)", "TypeError", ""),
    ("mkbool.union([SQ, SQ], [SQ], threads=-3)[1].area == 1 or 1 / 0", "", "returned"),
    ("mkbool.union([SQ, SQ], [SQ, SQ, SQ])", "UsageError", "different lengths"),
    ("mkbool.union([SQ], [SQ], threads=10**30)", "TypeError", ""),
    ("mkbool.union([SQ], [SQ], errors='ignore')", "UsageError", "errors must be"),
    ("mkbool.union(np.array([], dtype=object), SQ) == [] or 1 / 0", "", "returned"),
    ("mkbool.union(np.array([], dtype=object), [SQ, SQ])", "UsageError", "different lengths (0 and 2)"),
    ("mkbool._mkbool.compute_many('union', [], [mkbool.as_polygon(SQ)]) == [] or 1 / 0", "", "returned"),
    ("mkbool.union([SQ, 'POINT(0 0)'], SQ)", "InvalidInput", "A[1] (WKT)"),
    # results asked in a form they do not have
    ("mkbool.union(SQ, SQ, a_type='hole').wkt", "OutputError", "unbounded"),
    ("mkbool.union(SQ, SQ, a_type='hole').area_exact", "OutputError", "unbounded"),
    ("mkbool.union(SQ, SQ, kernel='double').area_exact", "UsageError", "exact kernels only"),
    ("mkbool.union(SQ, SQ, kernel='double').exact_rings", "UsageError", "exact kernels only"),
    # fill rules, the N-ary operations, grids
    ("mkbool.make_valid('POLYGON((0 0,1 0,nan 1,0 0))')", "InvalidInput", "geom (WKT): WKT line 1"),
    ("mkbool.union([[(0, 0)], [(0, 0), (1, 1)]], SQ, fill_rule='nonzero').area == 1 or 1 / 0", "", "returned"),
    ("mkbool.make_valid([(0, 0), (1e300, 0), (0, 1e300), (1e300, 1e300)]).stats['area_beyond_double'] or 1 / 0", "",
     "returned"),
    ("mkbool.make_valid([(0, 0), (1e300, 0), (0, 1e300), (1e300, 1e300)]).area_exact == fractions.Fraction(1e300)**2 / 2 or 1 / 0", "",
     "returned"),
    ("mkbool.union_all(np.zeros((0, 2)))", "InvalidInput", "geoms: ring 0: ring is empty"),
    ("mkbool.union_all(5)", "InvalidInput", "union_all: cannot read polygons from int"),
    ("mkbool.union_all([None])", "InvalidInput", "geoms[0]: cannot read a polygon from NoneType"),
    ("mkbool.make_valid(b'\\x01\\x03\\x00\\x00\\x00\\xff\\xff\\xff\\xff')", "InvalidInput", "ring count 4294967295"),
    ("mkbool.make_valid('POLYGON' + '(' * 200000 + ')' * 200000)", "InvalidInput", "geom (WKT)"),
    ("mkbool.union_all(['MULTIPOLYGON(((0 0,1 0,0 1,0 0)))'] * 200, fill_rule='evenodd').is_empty or 1 / 0", "",
     "returned"),
    ("mkbool.union(SQ, SQ, grid_size=10**400)", "UsageError", "outside the range of doubles"),
    ("mkbool.union(SQ, SQ, grid_size=5e-324)", "UsageError", "grid 2^-1074 is too fine"),
    ("mkbool.union(SQ, SQ, grid_size=float('-inf'))", "UsageError", "not a finite number"),
    ("mkbool.union(SQ, SQ, fill_rule='evenodd', rounding=None)", "UsageError", "unknown rounding None"),
    # the harness
    ("mkbool.harness.plan(['no-such-generator'])", "UsageError", "no-such-generator"),
    ("mkbool.harness.plan(['rotated'], level='huge')", "UsageError", "unknown sweep level 'huge'"),
    ("mkbool.harness.run_case('POINT(0 0)', SQ, kernels=['exact'])", "InvalidInput", "A (WKT)"),
    ("mkbool.harness.run_case(SQ, SQ, kernels=['nope'])", "UsageError", "back end 'nope' is not built"),
    ("mkbool.harness.run_case(SQ, SQ, seed=-1)", "UsageError", "non-negative"),
    ("mkbool.harness.plan(['rotated'], seeds=-1)", "UsageError", "seeds=-1: a whole number of seeds from 1 to"),
    ("mkbool.harness.plan(['rotated'], seeds=2**40)", "UsageError", "from 1 to 1000000"),
    ("mkbool.harness.sweep(['rotated'], seeds=2.5)", "UsageError", "seeds=2.5"),
    ("mkbool.harness.plan(['rotated'], base_seed=-5)", "UsageError", "base_seed=-5"),
    ("mkbool.harness.register_generator('bad', 5)", "UsageError", "a generator is a function"),
    # a Python generator that raises or returns nonsense: a row saying so, not an exception
    ("[r['message'] for r in (mkbool.harness.register_generator('div0', lambda seed: 1 / 0) and "
     "mkbool.harness.sweep(['div0'], seeds=1, kernels=['exact'], ops=['union'], regular=True))]"
     " == ['generator: ZeroDivisionError: division by zero'] or 1 / 0", "", "returned"),
    ("[r['verdict'] for r in (mkbool.harness.register_generator('none', lambda seed: None) and "
     "mkbool.harness.sweep(['none'], seeds=1, kernels=['exact'], ops=['union'], regular=True))]"
     " == ['invalid_input'] or 1 / 0", "", "returned"),
]

CHILD = textwrap.dedent("""
    import decimal, fractions, sys, traceback
    import numpy as np
    import shapely.geometry as sg
    import mkbool
    SQ = "POLYGON((0 0,1 0,1 1,0 1,0 0))"
    for line in sys.stdin.read().split("\\n\\x1e\\n"):
        if not line:
            continue
        try:
            eval(line)
            print("returned", flush=True)
        except Exception as e:
            print(type(e).__name__ + "\\x1f" + str(e).replace("\\n", " "), flush=True)
""")


def run_children(calls):
    """Runs the calls in one child interpreter; returns its exit status and one line per
    call that finished (the exception's type and message, or "returned")."""
    env = dict(os.environ)
    run = subprocess.run([sys.executable, "-c", CHILD], input="\n\x1e\n".join(calls), capture_output=True,
                         text=True, env=env, timeout=300)
    return run.returncode, run.stdout.splitlines(), run.stderr


def test_hostile_input_raises_and_never_crashes():
    code, lines, stderr = run_children([c for c, _, _ in HOSTILE])
    assert code == 0, f"the interpreter died (status {code}) after {len(lines)} calls:\n{stderr[-3000:]}"
    assert len(lines) == len(HOSTILE)
    for (call, kind, fragment), line in zip(HOSTILE, lines):
        if not kind:
            assert line == fragment, call  # "returned": the call's own assertion held
            continue
        got_kind, _, message = line.partition("\x1f")
        assert got_kind == kind, f"{call}: {line}"
        assert fragment in message, f"{call}: {message}"


def test_huge_and_tiny_coordinates_are_exact():
    """Coordinates near the ends of the double range: results exact, area beyond the
    largest double given as infinity with the exact rational still there."""
    import fractions
    import mkbool
    big = 1e300
    r = mkbool.intersection([(0, 0), (big, 0), (0, big)], [(0, 0), (big, big), (0, big)])
    assert r.area == float("inf") and r.stats["area_beyond_double"]
    assert r.area_exact == fractions.Fraction(int(big)) ** 2 / 4
    tiny = 5e-324  # the smallest subnormal
    r = mkbool.union([(0, 0), (2 * tiny, 0), (0, 2 * tiny)], [(0, 0), (tiny, 0), (tiny, tiny), (0, tiny)])
    assert r.area_exact == 2 * fractions.Fraction(tiny) ** 2  # the square lies inside the triangle
    assert r.area == 0.0  # 2 tiny**2 rounds to zero


@pytest.mark.parametrize("n", [1, 3, 200])
def test_many_pairs_with_bad_ones_in_threads(n):
    import mkbool
    good = "POLYGON((0 0,2 0,2 2,0 2,0 0))"
    bad = "POLYGON((0 0,2 2,2 0,0 2,0 0))"  # crossing edges: that pair's error, the others run
    a = [good if i % 3 else bad for i in range(n)]
    out = mkbool.union(a, "POLYGON((1 1,3 1,3 3,1 3,1 1))", errors="return", threads=2)
    for i, r in enumerate(out):
        if i % 3:
            assert r.area == 7
        else:
            assert isinstance(r, mkbool.InvalidInput) and str(r).startswith(f"pair {i}: ") and "cross" in str(r)
