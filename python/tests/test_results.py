"""The result object: every form agrees with the command's output, exact values are exact
(checked against an area computed here from the exact vertices and against set identities),
what is computed lazily equals what is computed eagerly, and unbounded results say so."""

import fractions
import json
import random
import subprocess

import numpy as np
import pytest
import shapely.geometry as sg
import shapely.wkb
import shapely.wkt

import mkbool
from conftest import shoelace, typed_area

A = "POLYGON((0 0,10 0,10 10,0 10,0 0),(3 3,3 7,7 7,7 3,3 3))"
B = "POLYGON((5 -2,14 5,5 12,5 -2))"
OPS = ["intersection", "union", "difference", "xor"]


def test_forms_agree_with_the_command(cli):
    for op in OPS:
        r = mkbool.compute(op, A, B)
        for fmt, value in (("wkt", r.wkt), ("geojson", r.geojson)):
            run = subprocess.run([cli, op, A, B, "--format", fmt], capture_output=True, text=True, check=True)
            assert run.stdout.strip() == value, (op, fmt)
        run = subprocess.run([cli, op, A, B, "--stats"], capture_output=True, text=True, check=True)
        stats = json.loads(run.stderr)
        mine = r.stats
        for key in ("kernel", "vertices_in", "crossings", "vertices_out", "rounded_valid", "area"):
            assert mine[key] == stats[key], (op, key)
        assert r.area_exact == fractions.Fraction(stats["area_exact"])
        assert shapely.wkb.loads(r.wkb).equals(shapely.wkt.loads(r.wkt))
        assert r.to_shapely().wkb == r.wkb or r.to_shapely().equals(shapely.wkt.loads(r.wkt))
        assert sg.shape(r.__geo_interface__).equals(r.to_shapely())


def test_exact_area_from_exact_vertices():
    r = mkbool.xor(A, B)
    assert r.area_exact == fractions.Fraction(4547, 63)  # docs/images/example_xor.svg's case
    assert typed_area(r) == r.area_exact
    assert r.area == float(r.area_exact)
    # crossing points are exact rationals, not doubles
    assert any(x.denominator != 1 and (x.denominator & (x.denominator - 1)) for ring in r.exact_rings for p in ring
               for x in p)


def test_lazy_values_equal_eager_ones():
    lazy = mkbool.union(A, B)
    eager = mkbool.union(A, B, area_exact=True, exact=True)
    assert lazy.stats["area_exact"] is None and eager.stats["area_exact"] is not None
    assert lazy.area_exact == eager.area_exact
    assert lazy.exact_rings == eager.exact_rings
    assert lazy.json == eager.json


def test_polygons_are_oriented_and_closed():
    r = mkbool.difference(A, "POLYGON((1 1,9 1,9 9,1 9,1 1))")
    assert sorted(r.types) == ["hole", "island"]  # the frame between the two squares
    for polygon in r.polygons:
        shell, *holes = polygon
        assert (shell[0] == shell[-1]).all() and shoelace([tuple(p) for p in shell[:-1]]) > 0
        for h in holes:
            assert (h[0] == h[-1]).all() and shoelace([tuple(p) for p in h[:-1]]) < 0
    for ring in r.rings:
        assert ring.dtype == np.float64 and ring.shape[1] == 2 and not (ring[0] == ring[-1]).all()


def test_non_regular_parts():
    a, b = "POLYGON((0 0,2 0,2 2,0 2,0 0))", "POLYGON((2 0,4 0,4 2,2 2,2 0))"
    r = mkbool.intersection(a, b, regular=False)
    assert r.dangling_edges.tolist() == [[[2, 0], [2, 2]]] or r.dangling_edges.tolist() == [[[2, 2], [2, 0]]]
    assert r.wkt == "GEOMETRYCOLLECTION (LINESTRING (2 0, 2 2))" or r.wkt == "GEOMETRYCOLLECTION (LINESTRING (2 2, 2 0))"
    assert r.area == 0 and r.area_exact == 0
    assert mkbool.intersection(a, b).is_empty
    corner = mkbool.intersection(a, "POLYGON((2 2,4 2,4 4,2 4,2 2))", regular=False)
    assert corner.isolated_points.tolist() == [[2, 2]]
    assert shapely.wkb.loads(r.wkb).geom_type == "GeometryCollection"


def test_unbounded_results():
    r = mkbool.union(A, B, a_type="hole")
    assert r.unbounded and r.area == float("inf")
    for form in ("wkt", "wkb", "geojson", "__geo_interface__"):
        with pytest.raises(mkbool.OutputError, match="is unbounded"):
            getattr(r, form)
    with pytest.raises(mkbool.OutputError, match="infinite"):
        r.area_exact
    assert "hole" in r.types and json.loads(r.json)["unbounded"] is True
    # As input, the result is itself, exactly (hole type, its cycles' exact coordinates): a
    # bounded window then has the window's area less the area of A - B, which those cycles
    # enclose; their rounded vertices enclose a slightly different area.
    diff = mkbool.difference(A, B).area_exact
    rounded = sum((abs(shoelace([tuple(p) for p in ring])) / 2) * (1 if t == "hole" else -1)
                  for ring, t in zip(r.rings, r.types) if len(ring) >= 3)
    assert rounded != diff and abs(float(rounded) - float(diff)) < 1e-12
    window = "POLYGON((-100 -100,100 -100,100 100,-100 100,-100 -100))"
    assert mkbool.intersection(r, window).area_exact == 200 * 200 - diff
    assert r.exact_polygon().type == "hole" and r.exact_polygon().is_exact


def test_every_kernel_runs_and_the_exact_ones_agree():
    results = {k: mkbool.xor(A, B, kernel=k) for k in mkbool.kernel_names()}
    exact = [k for k in results if mkbool.is_exact_kernel(k)]
    assert "exact" in exact and "rational" in exact
    for k in exact:
        assert results[k].exact_rings == results[exact[0]].exact_rings
        assert results[k].stats["kernel"] == k
    for k, r in results.items():
        assert abs(r.area - results["exact"].area) <= 1e-9 * results["exact"].area, k
        if not mkbool.is_exact_kernel(k):
            with pytest.raises(mkbool.UsageError, match="exact kernels only"):
                r.area_exact
            assert isinstance(r.rounded_valid, bool)


def random_polygon(rng, cx, cy, n):
    """A star-shaped polygon around (cx, cy) with integer vertices (shared vertices and
    collinear edges between two such polygons are common)."""
    import math
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    ring = []
    for t in angles:
        r = rng.randint(2, 8)
        p = (cx + round(r * math.cos(t)), cy + round(r * math.sin(t)))
        if not ring or p != ring[-1]:
            ring.append(p)
    if len(ring) > 1 and ring[0] == ring[-1]:
        ring.pop()
    return ring


def test_exact_identities_on_random_polygons():
    seed = 20261124
    print("seed", seed)
    rng = random.Random(seed)
    checked = 0
    for _ in range(60):
        a = random_polygon(rng, 0, 0, rng.randint(3, 12))
        b = random_polygon(rng, rng.randint(-4, 4), rng.randint(-4, 4), rng.randint(3, 12))
        try:
            inter = mkbool.intersection(a, b)
        except mkbool.InvalidInput:
            continue  # a random star may cross itself after rounding to integers
        union, diff, sym = mkbool.union(a, b), mkbool.difference(a, b), mkbool.xor(a, b)
        area_a, area_b = mkbool.union(a, a).area_exact, mkbool.union(b, b).area_exact
        assert union.area_exact == area_a + area_b - inter.area_exact, (a, b)
        assert diff.area_exact == area_a - inter.area_exact, (a, b)
        assert sym.area_exact == union.area_exact - inter.area_exact, (a, b)
        for r in (inter, union, diff, sym):
            assert typed_area(r) == r.area_exact, (r.op, a, b)
        # shapely (GEOS) on the same doubles: close, and exact whenever GEOS is
        for op, r in (("intersection", inter), ("union", union)):
            geos = getattr(sg.Polygon(a), op)(sg.Polygon(b)).area
            assert abs(geos - r.area) <= 1e-9 * max(1.0, r.area), (op, a, b)
        checked += 1
    assert checked >= 30


def test_repr_and_svg():
    r = mkbool.xor(A, B)
    assert repr(r).startswith("<mkbool.Result xor (exact): ")
    assert r.svg.startswith("<svg") or r.svg.startswith("<?xml")


def star(n, phase):
    t = 2 * np.pi * np.arange(2 * n) / (2 * n) + phase
    r = np.where(np.arange(2 * n) % 2 == 0, 100.0, 50.0)
    return np.column_stack([r * np.cos(t), r * np.sin(t)])


def test_exact_values_beyond_pythons_decimal_digit_limit():
    # Two stars turned by half a spike: about 4n crossing points whose exact coordinates,
    # and the exact area over them, have more digits than Python reads from a decimal
    # string (4300 by default): they reach Python through hexadecimal instead.
    r = mkbool.intersection(star(200, 0.0), star(200, np.pi / 400))
    assert r.area_exact.denominator.bit_length() > 4300 * 3.33
    assert r.area_exact == typed_area(r)  # from the exact vertices, summed here
    assert float(r.area_exact) == r.area  # both correctly rounded
    assert all(float(x) == v for ring, arr in zip(r.exact_rings, r.rings) for p, row in zip(ring, arr)
               for x, v in zip(p, row))  # the rounded vertices are the exact ones rounded to nearest


def test_the_kernels_are_the_commands(cli):
    # the command's list of built kernels (its usage error names them) is the module's, and
    # each gives the same result through both
    run = subprocess.run([cli, "xor", A, B, "--kernel", "no-such-kernel"], capture_output=True, text=True)
    assert run.returncode == 2
    listed = run.stderr.split("(built: ", 1)[1].split(")", 1)[0].split(", ")
    assert listed == mkbool.kernel_names()
    assert {"rational-mp", "rational-cpp"} <= {k for k in listed if mkbool.is_exact_kernel(k)}
    with pytest.raises(mkbool.UsageError) as e:
        mkbool.xor(A, B, kernel="no-such-kernel")
    assert str(e.value) == "unknown kernel 'no-such-kernel' (built: " + ", ".join(listed) + ")"
    for k in listed:
        run = subprocess.run([cli, "xor", A, B, "--kernel", k], capture_output=True, text=True, check=True)
        assert run.stdout.strip() == mkbool.xor(A, B, kernel=k).wkt, k
