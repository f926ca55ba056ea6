"""Fill rules, union_all, intersection_all and make_valid from Python: the same results as the
command (--fill-rule, union-all, intersection-all, make-valid), exact areas derived here by
hand from winding numbers, every input form, and clear errors for what is not allowed."""

import fractions
import json
import subprocess

import numpy as np
import pytest
import shapely.geometry as sg
import shapely.ops

import mkbool

F = fractions.Fraction
OPS = ["intersection", "union", "difference", "xor"]

# A bow-tie: the path crosses itself at (2, 2); its left triangle runs counterclockwise
# (winding +1, area 4), its right one clockwise (winding -1, area 4). Signed area 0, so
# "union" leaves it as given (nonzero).
BOWTIE = "POLYGON((0 0,4 4,4 0,0 4,0 0))"
# A square traced twice counterclockwise: winding 2 inside.
TWICE = "POLYGON((0 0,2 0,2 2,0 2,0 0,2 0,2 2,0 2,0 0))"
# Two unit-overlapping 2x2 squares, both counterclockwise (winding 2 in [1,2]^2) ...
SAME_WAY = "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))"
# ... and with the second clockwise (winding 0 in the overlap, -1 in the rest of it).
OPPOSITE = "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,1 3,3 3,3 1,1 1)))"

# The region's area under each rule, from the winding numbers above.
HAND = {
    BOWTIE: {"evenodd": 8, "nonzero": 8, "positive": 4, "negative": 4, "union": 8},
    TWICE: {"evenodd": 0, "nonzero": 4, "positive": 4, "negative": 0, "union": 4},
    SAME_WAY: {"evenodd": 6, "nonzero": 7, "positive": 7, "negative": 0, "union": 7},
    OPPOSITE: {"evenodd": 6, "nonzero": 6, "positive": 3, "negative": 3, "union": 7},
}


@pytest.mark.parametrize("geometry", list(HAND))
def test_make_valid_areas_by_hand(geometry):
    for rule, area in HAND[geometry].items():
        r = mkbool.make_valid(geometry, fill_rule=rule)
        assert r.area_exact == area, (geometry, rule)
        assert r.op == "make_valid" and r.fill_rule == rule
        if area:
            assert r.to_shapely().is_valid and r.to_shapely().area == area
    assert mkbool.make_valid(BOWTIE).fill_rule == "evenodd"  # the default, as the command's


@pytest.mark.parametrize("geometry", list(HAND))
def test_binary_operations_read_each_input_by_the_rule(geometry):
    window = "POLYGON((-10 -10,10 -10,10 10,-10 10,-10 -10))"  # counterclockwise: winding 1
    for rule, area in HAND[geometry].items():
        if rule == "negative":  # the window itself is empty under "negative"
            assert mkbool.union(geometry, window, fill_rule=rule).area_exact == area
            continue
        assert mkbool.intersection(geometry, window, fill_rule=rule).area_exact == area
        assert mkbool.difference(window, geometry, fill_rule=rule).area_exact == 400 - area
        assert mkbool.union(geometry, "POLYGON EMPTY", fill_rule=rule).area_exact == area


def test_every_rule_and_operation_as_the_command(cli):
    a, b = OPPOSITE, "POLYGON((0 1,4 1,0 3,4 3,0 1))"  # B: a bow-tie lying across A
    for rule in mkbool.FILL_RULES:
        for op in OPS:
            r = mkbool.compute(op, a, b, fill_rule=rule)
            run = subprocess.run([cli, op, a, b, "--fill-rule", rule, "--stats"], capture_output=True, text=True)
            assert run.returncode == 0, run.stderr
            stats = json.loads(run.stderr)
            assert r.wkt == run.stdout.strip(), (rule, op)
            assert r.area_exact == F(stats["area_exact"]), (rule, op)
            assert r.stats["crossings"] == stats["crossings"], (rule, op)
            assert {k: r.rounding[k] for k in stats["rounding"]} == stats["rounding"], (rule, op)


def test_n_ary_operations_as_the_command(cli):
    squares = [sg.box(i, j, i + 2, j + 2) for i in range(3) for j in range(2)]
    multi = sg.MultiPolygon(squares).wkt  # overlapping parts: refused without a rule, read here as parts
    for name, verb in (("union_all", "union-all"), ("intersection_all", "intersection-all"),
                       ("make_valid", "make-valid")):
        for rule in (None,) + mkbool.FILL_RULES:
            r = getattr(mkbool, name)(multi, fill_rule=rule)
            args = [cli, verb, multi, "--stats"] + (["--fill-rule", rule] if rule else [])
            run = subprocess.run(args, capture_output=True, text=True)
            assert run.returncode == 0, run.stderr
            assert r.wkt == run.stdout.strip(), (name, rule)
            assert r.area_exact == F(json.loads(run.stderr)["area_exact"]), (name, rule)


def test_union_all_forms_agree_and_match_shapely():
    squares = [sg.box(i, j, i + 2, j + 2) for i in range(3) for j in range(2)]
    expected = shapely.ops.unary_union(squares).area  # 4 x 3 = 12, exactly in doubles
    assert expected == 12
    forms = [
        squares,                                              # shapely geometries
        [s.wkt for s in squares],                             # WKT
        [s.wkb for s in squares],                             # WKB
        [s.__geo_interface__ for s in squares],               # GeoJSON mappings
        [np.array(s.exterior.coords) for s in squares],       # numpy rings
        (list(s.exterior.coords) for s in squares),           # a generator of sequences of pairs
        sg.MultiPolygon(squares),                             # one geometry: its parts
        "\n".join(s.wkt for s in squares),                    # one WKT per line, as the command reads files
        {"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry": s.__geo_interface__}
                                                   for s in squares]},
    ]
    results = [mkbool.union_all(f) for f in forms]
    for r in results:
        assert r.area_exact == 12 and r.wkt == results[0].wkt
    assert mkbool.union_all([]).is_empty
    # a coverage: a 10 x 10 grid of unit squares sharing every edge
    grid = [sg.box(i, j, i + 1, j + 1) for i in range(10) for j in range(10)]
    cover = mkbool.union_all(grid)
    assert cover.area_exact == 100 and len(cover.polygons) == 1 and len(cover.polygons[0]) == 1


def test_intersection_all_by_hand():
    boxes = [sg.box(0, 0, 4, 4), sg.box(1, 1, 5, 5), sg.box(2, 0, 3, 6)]
    assert mkbool.intersection_all(boxes).area_exact == 3  # [2, 3] x [1, 4]
    assert mkbool.intersection_all(boxes).to_shapely().equals(sg.box(2, 1, 3, 4))
    assert mkbool.intersection_all(boxes + ["POLYGON EMPTY"]).is_empty  # one polygon is empty
    # a self-crossing part read by the rule on its own: the bow-tie's left triangle (positive)
    assert mkbool.intersection_all([BOWTIE, sg.box(0, 0, 4, 4)], fill_rule="positive").area_exact == 4
    with pytest.raises(mkbool.InvalidInput, match=r"geoms\[0\]: 2 parts"):
        mkbool.intersection_all([SAME_WAY, sg.box(0, 0, 4, 4)])
    with pytest.raises(mkbool.InvalidInput, match="intersection-all of no polygons"):
        mkbool.intersection_all([])


def test_results_and_lazy_values_of_n_ary_operations():
    r = mkbool.union_all([BOWTIE, "POLYGON((0 1,4 1,0 3,4 3,0 1))"], fill_rule="evenodd")
    eager = mkbool.union_all([BOWTIE, "POLYGON((0 1,4 1,0 3,4 3,0 1))"], fill_rule="evenodd", area_exact=True,
                             exact=True)
    assert r.area_exact == eager.area_exact and r.exact_rings == eager.exact_rings
    assert r.op == "union_all" and repr(r).startswith("<mkbool.Result union_all (exact): ")
    # a result of a rule is valid input to the next operation, exactly
    assert mkbool.intersection(r, r).area_exact == r.area_exact


def test_threads_with_a_fill_rule():
    pieces = [BOWTIE, TWICE, SAME_WAY, OPPOSITE]
    window = "POLYGON((-10 -10,10 -10,10 10,-10 10,-10 -10))"
    out = mkbool.intersection(pieces, window, fill_rule="nonzero", threads=2)
    assert [r.area_exact for r in out] == [HAND[p]["nonzero"] for p in pieces]


def test_every_kernel_with_a_fill_rule():
    for k in mkbool.kernel_names():
        try:
            r = mkbool.make_valid(OPPOSITE, fill_rule="union", kernel=k)
        except mkbool.KernelFailure:
            continue  # rounded-construction kernels may fail: data for the harness
        assert r.kernel == k and abs(r.area - 7) < 1e-12


def test_fill_rule_errors():
    with pytest.raises(mkbool.UsageError, match="unknown fill rule 'even-odd'"):
        mkbool.union(BOWTIE, BOWTIE, fill_rule="even-odd")
    with pytest.raises(mkbool.UsageError, match="fill_rule must be a string"):
        mkbool.union(BOWTIE, BOWTIE, fill_rule=1)
    with pytest.raises(mkbool.UsageError, match="unknown fill rule"):
        mkbool.union_all([BOWTIE], fill_rule="odd")
    # without a rule a self-crossing ring is outside the paper's domain, as before
    with pytest.raises(mkbool.InvalidInput, match="cross"):
        mkbool.union(BOWTIE, BOWTIE)
    with pytest.raises(mkbool.UsageError, match="fill rules and the N-ary operations read doubles"):
        mkbool.make_valid([(0, 0), (F(1, 3), 0), (0, 1)])
    with pytest.raises(mkbool.InvalidInput, match="native JSON has no parts"):
        mkbool.make_valid('{"type": "island", "rings": [[[0, 0], [1, 0], [0, 1]]]}')
    with pytest.raises(mkbool.InvalidInput, match="not type 'hole'"):
        mkbool.union_all([mkbool.Polygon([[(0, 0), (1, 0), (0, 1)]], type="hole")])
    with pytest.raises(mkbool.InvalidInput, match="unbounded"):
        mkbool.union_all([mkbool.union(BOWTIE, "POLYGON((10 10,11 10,11 11,10 10))", fill_rule="evenodd", a_type="hole")])
    with pytest.raises(mkbool.UsageError, match="read by nesting"):
        mkbool.make_valid(mkbool.as_polygon(sg.box(0, 0, 1, 1)))


def test_non_regular_with_a_fill_rule_keeps_where_regions_only_touch():
    # the bowtie's right triangle (2 2, 4 4, 4 0) and the square beside it share x = 4
    right = [(4, 0), (5, 0), (5, 4), (4, 4)]
    r = mkbool.intersection(BOWTIE, right, fill_rule="evenodd", regular=False, area_exact=True)
    assert r.area_exact == 0 and len(r.dangling_edges) == 1
    assert sorted(r.dangling_edges[0][:, 0].tolist()) == [4.0, 4.0]
    assert sorted(r.dangling_edges[0][:, 1].tolist()) == [0.0, 4.0]
    assert len(mkbool.intersection(BOWTIE, right, fill_rule="evenodd").dangling_edges) == 0
    corner = [(4, 4), (5, 4), (5, 5), (4, 5)]
    p = mkbool.intersection(BOWTIE, corner, fill_rule="nonzero", regular=False)
    assert p.isolated_points.tolist() == [[4.0, 4.0]]
