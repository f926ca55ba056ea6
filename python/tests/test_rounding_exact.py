"""Rounding and exact input from Python: grid_size= and rounding= as the command's --grid and
--rounding (the same output and the same "rounding" statistics), grid sizes taken exactly in
every numeric form, exact coordinates (Fractions, Decimals, integers beyond 2**53, native
JSON's "p/q") and exact results fed into the next operation, checked against exact answers
derived by hand."""

import decimal
import fractions
import json
import subprocess

import numpy as np
import pytest
import shapely.geometry as sg

import mkbool

F = fractions.Fraction
D = decimal.Decimal

T1, T2 = "POLYGON((0 0,3 0,0 3,0 0))", "POLYGON((1 1,4 1,1 4,1 1))"  # union 9/2 + 9/2 - 1/2 = 17/2

# Two triangles whose intersection's nearest doubles are not a valid polygon (B's vertices a
# few ulps off A's edges): the command's tests/cli/rounding_test.cpp.
SLIVER_A = ("POLYGON ((0.96537237542267185 0.22739579952077785, 0.46786665351848666 0.14712530555449221, "
            "0.64551903878599848 0.038874529127181534, 0.96537237542267185 0.22739579952077785))")
SLIVER_B = ("POLYGON ((0.79810829600868205 0.20040843096150171, 0.68449956803149792 0.061849618182837497, "
            "0.53908903038851086 0.10372663357173791, 0.79810829600868205 0.20040843096150171))")


def run_cli(cli, *args):
    run = subprocess.run([cli, *args, "--stats"], capture_output=True, text=True)
    return run.returncode, run.stdout.strip(), json.loads(run.stderr.splitlines()[0])


def test_grid_as_the_command(cli):
    code, wkt, stats = run_cli(cli, "union", T1, T2, "--grid", "0.5")
    assert code == 0
    for g in ("0.5", "1/2", 0.5, F(1, 2), D("0.5"), " 5e-1 "):
        r = mkbool.union(T1, T2, grid_size=g)
        assert r.wkt == wkt == "POLYGON ((0 0, 3 0, 2 1, 4 1, 1 4, 1 2, 0 3, 0 0))", g
        assert {k: r.rounding[k] for k in stats["rounding"]} == stats["rounding"]
        assert r.rounding["snapped"] and r.rounding["user_grid"] and r.rounding["grid"] == "2^-1"
        assert r.area_exact == F(17, 2)


def test_grid_points_and_the_exact_result_beside_them():
    # x + y <= 3 and y <= 2x/3 cross at (9/5, 6/5), which the grid of thirds moves to
    # (5/3, 4/3): 2/5 of a cell along each axis. Union area 9/2 + 3 - 9/5 = 57/10.
    r = mkbool.union("POLYGON((0 0,3 0,0 3,0 0))", "POLYGON((0 0,3 0,3 2,0 0))", grid_size=F(1, 3))
    assert r.grid == "1/3" and r.rounding["grid"] == "1/3"
    snapped = [tuple(p) for polygon in r.polygons for ring in polygon for p in ring.tolist()]
    for x in (v for p in snapped for v in p):
        assert float(F(round(F(x) * 3), 3)) == x  # the nearest double of a multiple of 1/3
    assert (float(F(5, 3)), float(F(4, 3))) in snapped
    assert 0.4 <= r.rounding["max_displacement"] <= 0.7072  # at most half a cell's diagonal
    assert r.area_exact == F(57, 10)  # .area and .area_exact describe the exact result
    assert (F(9, 5), F(6, 5)) in r.exact_rings[0]
    assert r.to_shapely().is_valid


def test_a_float_grid_is_its_binary_value():
    binary = mkbool.union(T1, T2, grid_size=0.1)
    decimal_grid = mkbool.union(T1, T2, grid_size="0.1")
    assert F(0.1) != F(1, 10)
    assert binary.grid == f"{F(0.1).numerator}/{F(0.1).denominator}" == binary.rounding["grid"]
    assert decimal_grid.grid == "0.1" and decimal_grid.rounding["grid"] == "1/10"
    assert mkbool.union(T1, T2, grid_size=D("0.1")).rounding["grid"] == "1/10"


def test_rounding_modes_as_the_command(cli):
    certified = mkbool.intersection(SLIVER_A, SLIVER_B)
    nearest = mkbool.intersection(SLIVER_A, SLIVER_B, rounding="nearest")
    assert not certified.rounded_valid and certified.rounding["snapped"] and certified.rounding["valid"]
    assert certified.rounding["max_displacement"] <= 0.7072 and certified.to_shapely().is_valid
    assert nearest.rounding["mode"] == "nearest" and not nearest.rounding["snapped"]
    assert not nearest.rounding["valid"]
    assert certified.area_exact == nearest.area_exact  # one exact result, two roundings
    code, wkt, stats = run_cli(cli, "intersection", SLIVER_A, SLIVER_B)
    assert code == 0 and certified.wkt == wkt and certified.stats["rounding"] == {
        **stats["rounding"], "rounds": certified.rounding["rounds"], "failure": None}
    code, wkt, stats = run_cli(cli, "intersection", SLIVER_A, SLIVER_B, "--rounding", "nearest")
    assert code == 4 and nearest.wkt == wkt and not stats["rounding"]["valid"]


@pytest.mark.parametrize("bad, fragment", [
    (0, "is not positive"), (-1, "is not positive"), (-0.5, "is not positive"), (F(-1, 3), "is not positive"),
    (float("nan"), "is not a finite number"), (float("inf"), "is not a finite number"),
    (D("NaN"), "is not a finite number"), (True, "not bool"), ([1], "not list"),
    ("abc", "grid 'abc' is not a positive decimal"), ("1/0", "grid '1/0'"), ("-2", "grid '-2'"), ("", "is empty"),
    (F(1, 2**1100), "outside the range of doubles"),
])
def test_bad_grids(bad, fragment):
    with pytest.raises(mkbool.UsageError, match=fragment.replace("(", r"\(")):
        mkbool.union(T1, T2, grid_size=bad)


def test_bad_rounding():
    with pytest.raises(mkbool.UsageError, match="unknown rounding 'round'"):
        mkbool.union(T1, T2, rounding="round")
    with pytest.raises(mkbool.UsageError, match="which rounding='nearest' does not"):
        mkbool.union(T1, T2, rounding="nearest", grid_size=1)
    with pytest.raises(mkbool.UsageError, match="which rounding='nearest' does not"):
        mkbool.union_all([T1, T2], rounding="nearest", grid_size=1)


def test_grid_with_the_n_ary_operations():
    r = mkbool.union_all([T1, T2], grid_size="0.5")
    assert r.wkt == mkbool.union(T1, T2, grid_size="0.5").wkt and r.rounding["user_grid"]


# Exact input

SQUARE = "POLYGON((0 0,1 0,1 1,0 1,0 0))"


def test_fractions_and_decimals_are_exact(cli):
    # the triangle (0, 0), (1/3, 0), (1/10, 2/3) inside the unit square: area (1/2)(1/3)(2/3) = 1/9
    forms = [
        [(0, 0), (F(1, 3), 0), (F(1, 10), F(2, 3))],
        [(0, 0), (F(1, 3), 0), (D("0.1"), F(2, 3)), (0, 0)],
        np.array([[0, 0], [F(1, 3), 0], [F(1, 10), F(2, 3)]], dtype=object),
        '{"type": "island", "rings": [[["0", "0"], ["1/3", "0"], ["0.1", "2/3"]]]}',  # native JSON, as the command's
    ]
    for f in forms:
        r = mkbool.intersection(f, SQUARE)
        assert r.area_exact == F(1, 9) and r.kernel == "rational"
        assert mkbool.as_polygon(f).is_exact
        assert (F(1, 10), F(2, 3)) in r.exact_rings[0]
    code, _, stats = run_cli(cli, "intersection", forms[3], SQUARE)
    assert code == 0 and F(stats["area_exact"]) == F(1, 9)
    big = 2**53 + 1  # not a double
    r = mkbool.intersection([(0, 0), (big, 0), (0, 1)], [(0, 0), (2**54, 0), (2**54, 2**54), (0, 2**54)])
    assert r.area_exact == F(big, 2)
    r = mkbool.intersection(np.array([[0, 0], [big, 0], [0, 1]], dtype=np.int64), [(0, 0), (2**54, 0), (0, 2**54)])
    assert r.area_exact == F(big, 2)


def test_exact_input_errors():
    with pytest.raises(mkbool.UsageError, match="takes doubles only"):
        mkbool.intersection([(0, 0), (F(1, 3), 0), (0, 1)], SQUARE, kernel="double")
    with pytest.raises(mkbool.InvalidInput, match="A: ring 0, vertex 1: y coordinate is not finite"):
        mkbool.intersection([(0, 0), (F(1, 3), float("nan")), (0, 1)], SQUARE)
    with pytest.raises(mkbool.InvalidInput, match="beyond the range of doubles"):
        mkbool.intersection([(0, 0), (10**400, 0), (0, 1)], SQUARE)
    with pytest.raises(mkbool.UsageError, match="fill rules read coordinates that are doubles"):
        mkbool.intersection(mkbool.as_polygon([(0, 0), (F(1, 3), 0), (0, 1)]), SQUARE, fill_rule="nonzero")
    with pytest.raises(mkbool.InvalidInput, match="the harness runs every kernel"):
        mkbool.harness.run_case([(0, 0), (F(1, 3), 0), (0, 1)], SQUARE, kernels=["exact"])


# A = x + y <= 3, B = y <= 2x/3 (triangles), C = [1, 2] x [0, 2]. A ∪ B has the crossing
# (9/5, 6/5), not a double; (A ∪ B) ∩ C is y <= 3 - x on [1, 9/5] and y <= 2x/3 on [9/5, 2]:
# area 32/25 + 19/75 = 23/15 (integrated by hand; the command's rounding_test.cpp).
A, B, C = "POLYGON((0 0,3 0,0 3,0 0))", "POLYGON((0 0,3 0,3 2,0 0))", "POLYGON((1 0,2 0,2 2,1 2,1 0))"


def test_chained_results_are_exact(cli):
    ab = mkbool.union(A, B)
    assert (F(9, 5), F(6, 5)) in ab.exact_rings[0]
    assert ab.exact_polygon().is_exact and not mkbool.as_polygon(A).is_exact
    for operand in (ab, ab.exact_polygon()):
        abc = mkbool.intersection(operand, C)
        assert abc.area_exact == F(23, 15) and abc.kernel == "rational"
        assert (F(9, 5), F(6, 5)) in abc.exact_rings[0]
    # one more step: C less (A ∪ B) ∩ C, by hand 2 - 23/15
    assert mkbool.xor(mkbool.intersection(ab, C), C).area_exact == F(7, 15)
    # the module's exact JSON read by the command gives the same exact answer
    code, _, stats = run_cli(cli, "intersection", ab.json, C)
    assert code == 0 and F(stats["area_exact"]) == F(23, 15) and stats["kernel"] == "rational"
    # the rounded result (its WKB) is another polygon: the chain through it is not exact
    assert mkbool.intersection(ab.wkb, C).area_exact != F(23, 15)
    # threads take exact operands as well
    assert [r.area_exact for r in mkbool.intersection([ab, ab], C, threads=2)] == [F(23, 15)] * 2


def test_a_result_of_exact_doubles_feeds_a_fill_rule():
    # union of two squares: every exact coordinate is a double, so a fill rule can read it
    u = mkbool.union(sg.box(0, 0, 2, 2), sg.box(1, 1, 3, 3))
    assert mkbool.union_all([u, sg.box(2, 2, 4, 4)]).area_exact == 7 + 4 - 1
    assert mkbool.intersection(u, sg.box(0, 0, 3, 3), fill_rule="nonzero").area_exact == 7
    # an exact result with rational vertices cannot be read by a rule: said, not rounded
    with pytest.raises(mkbool.UsageError, match="give its rounded form"):
        mkbool.union_all([mkbool.union(A, B), C])
    assert mkbool.union_all([mkbool.union(A, B).wkb, C]).area > 0  # its rounded form, asked for
