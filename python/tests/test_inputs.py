"""Every input form reaches the library as the same polygon, exactly, and every bad input
is refused with mkbool.InvalidInput and the message the command gives."""

import fractions
import json
import subprocess

import numpy as np
import pytest
import shapely.geometry as sg
import shapely.wkb
import shapely.wkt

import mkbool

SQUARE_WKT = "POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,1 2,2 2,2 1,1 1))"


def rings_of(obj):
    return [r.tolist() for r in mkbool.as_polygon(obj).rings]


def test_every_form_gives_the_same_rings():
    shell = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]
    hole = [(1.0, 1.0), (1.0, 2.0), (2.0, 2.0), (2.0, 1.0)]
    expected = [[list(p) for p in shell], [list(p) for p in hole]]
    shapely_polygon = sg.Polygon(shell, [hole])
    forms = {
        "wkt": SQUARE_WKT,
        "wkb": shapely_polygon.wkb,
        "bytearray": bytearray(shapely_polygon.wkb),
        "shapely": shapely_polygon,
        "geo_interface dict": shapely_polygon.__geo_interface__,
        "geojson text": json.dumps(shapely_polygon.__geo_interface__),
        "native json": json.dumps({"type": "island", "rings": [shell, hole]}),
        "numpy rings": [np.array(shell), np.array(hole)],
        "closed lists": [shell + [shell[0]], hole + [hole[0]]],
        "int lists": [[(int(x), int(y)) for x, y in shell], [(int(x), int(y)) for x, y in hole]],
        "mkbool.Polygon": mkbool.Polygon([shell, hole]),
        "k x n x 2 array": np.array([shell, hole]),
    }
    for name, form in forms.items():
        assert rings_of(form) == expected, name


def test_one_ring_forms():
    ring = [(0, 0), (3, 0), (0, 3)]
    for form in (ring, np.array(ring, dtype=np.float64), np.array(ring, dtype=np.int32), tuple(ring)):
        assert rings_of(form) == [[[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]]]


def test_coordinates_are_taken_bit_for_bit():
    tiny = np.nextafter(0.0, 1.0)  # the smallest subnormal
    ring = np.array([[0.1, 1e-300], [1e300, tiny], [1.0 / 3.0, 2.0**53 + 2]])
    # (not shapely's WKT: shapely 1.8 prints it with limited precision, which is why
    # shapely geometries are read through WKB)
    for form in (ring, sg.Polygon(ring).wkb, sg.Polygon(ring), sg.Polygon(ring).__geo_interface__):
        got = mkbool.as_polygon(form).rings[0]
        # the ring may start elsewhere only if the form reorders; none of these does
        assert got.tobytes() == ring.tobytes(), type(form)


def test_multipolygons_and_collections():
    mp = sg.MultiPolygon([sg.box(0, 0, 1, 1), sg.box(2, 0, 3, 1)])
    assert len(mkbool.as_polygon(mp).rings) == 2
    gc = shapely.wkt.loads("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)), POLYGON ((5 5, 6 5, 5 6, 5 5)))")
    assert len(mkbool.as_polygon(gc).rings) == 2
    assert mkbool.as_polygon(sg.Polygon()).rings == []
    assert mkbool.as_polygon("POLYGON EMPTY").rings == []
    assert mkbool.as_polygon([]).rings == []


def test_hole_type_and_paper_rings():
    p = mkbool.as_polygon(mkbool.Polygon([[(0, 0), (1, 0), (0, 1)]], type="hole"))
    assert p.type == "hole"
    # one- and two-sided rings of the paper's model (MK89 section 2.2)
    p = mkbool.as_polygon([[(5, 5)], [(0, 0), (1, 1)]])
    assert [len(r) for r in p.rings] == [1, 2]
    # the closing vertex and repeated vertices go, as native JSON's reader does
    p = mkbool.as_polygon([(0, 0), (0, 0), (2, 0), (2, 0), (0, 2), (0, 0)])
    assert p.rings[0].tolist() == [[0, 0], [2, 0], [0, 2]]


def test_results_feed_the_next_operation():
    a, b, c = sg.box(0, 0, 2, 2), sg.box(1, 1, 3, 3), sg.box(0, 1.5, 3, 2.5)
    # (A ∪ B) ∩ C: width 3 for y in [1.5, 2], width 2 for y in [2, 2.5]
    assert mkbool.intersection(mkbool.union(a, b), c).area_exact == fractions.Fraction(5, 2)


def test_unbounded_result_as_input():
    a, b = sg.box(0, 0, 4, 4), sg.box(1, 1, 5, 5)
    outside = mkbool.union(a, b, a_type="hole", b_type="hole")  # the outside of A ∩ B... closure
    assert outside.unbounded
    # (outside of A) ∪ (outside of B) = outside of (A ∩ B): intersecting it with A leaves A − int(B)
    chained = mkbool.intersection(outside, a)
    assert chained.area_exact == mkbool.difference(a, b).area_exact == 16 - 9


def assert_invalid(obj, fragment):
    with pytest.raises(mkbool.InvalidInput) as e:
        mkbool.intersection(obj, "POLYGON((0 0,1 0,0 1,0 0))")
    assert fragment in str(e.value), str(e.value)
    return str(e.value)


def test_bad_inputs_are_refused_with_where():
    assert_invalid("POLYGON((0 0,1 0,1 1))", "A (WKT): WKT line 1, column 9 (polygon 0, ring 0): ring has 3 coordinates")
    assert_invalid("LINESTRING(0 0,1 1)", "LINESTRING is not a polygonal geometry")
    assert_invalid(b"\x01\x03\x00\x00", "A (WKB): WKB byte 1: unexpected end of input")
    assert_invalid(sg.LineString([(0, 0), (1, 1)]), "A (shapely WKB): WKB byte 0: LineString is not a polygonal")
    # multi-part input read as OGC means it, or refused (never reinterpreted by nesting)
    assert_invalid(sg.MultiPolygon([sg.box(0, 0, 3, 3), sg.box(1, 1, 2, 2)]),
                   "A (shapely WKB): polygon 1 lies inside polygon 0; the parts of a multi-part polygon must not overlap")
    assert_invalid({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}, "A (GeoJSON mapping): GeoJSON at")
    assert_invalid(np.array([[0, 0], [1, np.nan], [0, 1]]), "A: ring 0, vertex 1: y coordinate is not finite")
    assert_invalid([np.array([[0, 0], [1, 0], [0, 1]]), np.zeros((3, 3))], "A: ring 1: expected vertices of shape (n, 2)")
    # coordinates that are not doubles are exact input (test_rounding_exact.py), never rounded
    assert_invalid([[(0, 0), (2**53 + 1, 0), (0, 2**1024)]], "A: ring 0, vertex 2: coordinate beyond the range of doubles")
    assert_invalid([(0, 0), (fractions.Fraction(1, 3), float("inf")), (0, 1)], "A: ring 0, vertex 1: y coordinate is not finite")
    assert_invalid([(0, 0), ("x", 0), (0, 1)], "are not numbers")
    assert_invalid(object(), "cannot read a polygon from object")
    # a polygon whose own edges cross is outside the domain: the library's message
    assert_invalid([(0, 0), (2, 2), (2, 0), (0, 2)], "cross")


def test_messages_are_the_commands(cli):
    cases = [
        "POLYGON((0 0,1 0,1 1))",
        "POLYGON((0 0,1 0,1 1,0 0),(5 5))",
        "POLYGON((0 0,2 2,2 0,0 2,0 0))",
        "MULTIPOLYGON(((0 0,1 0,0 1,0 0)),((0 0,1 0)))",
        "POINT(1 2)",
        "POLYGON Z((0 0 0,1 0 0,0 1 0,0 0))",
        "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)),((1 1,3 1,3 3,1 3,1 1)))",
        "POLYGON((0 0,4 0,4 4,0 4,0 0),(5 5,6 5,6 6,5 5))",
    ]
    other = "POLYGON((0 0,1 0,0 1,0 0))"
    for text in cases:
        run = subprocess.run([cli, "intersection", text, other], capture_output=True, text=True)
        assert run.returncode == 3, (text, run.stderr)
        command = run.stderr.strip().removeprefix("mkbool: error: ")
        with pytest.raises(mkbool.InvalidInput) as e:
            mkbool.intersection(text, other)
        # the command names the argument "A (inline WKT)", the module "A (WKT)"; the rest is the same
        assert command.split(": ", 1)[1] == str(e.value).split(": ", 1)[1], text


def test_unknown_options_and_kernels():
    with pytest.raises(mkbool.UsageError, match="unknown kernel 'fast'"):
        mkbool.union(SQUARE_WKT, SQUARE_WKT, kernel="fast")
    with pytest.raises(mkbool.UsageError, match="unknown polygon type 'lake'"):
        mkbool.union(SQUARE_WKT, SQUARE_WKT, a_type="lake")
    with pytest.raises(mkbool.UsageError, match="unknown operation"):
        mkbool.compute("merge", SQUARE_WKT, SQUARE_WKT)
    with pytest.raises(TypeError, match="colour"):
        mkbool.union(SQUARE_WKT, SQUARE_WKT, colour="red")
    # the command's later options, None meaning what the command does without them
    plain = mkbool.union(SQUARE_WKT, SQUARE_WKT, fill_rule=None, grid_size=None)
    assert plain.area == 15 and plain.fill_rule is None and plain.grid is None
    assert mkbool.union(SQUARE_WKT, SQUARE_WKT, fill_rule="evenodd", grid_size=0.5).area == 15


def test_z_and_m_are_dropped_as_the_command_drops_them(cli):
    flat = sg.Polygon([(0, 0), (4, 0), (0, 4)])
    with_z = sg.Polygon([(0, 0, 1), (4, 0, 2), (0, 4, 3)])
    for form in (with_z, with_z.wkb, shapely.wkb.dumps(with_z, srid=4326), with_z.wkt):
        assert rings_of(form) == rings_of(flat), type(form)
    text = "POLYGON ZM((0 0 1 2,4 0 1 2,0 4 1 2,0 0 1 2))"
    run = subprocess.run([cli, "union", text, "POLYGON((1 1,5 1,1 5,1 1))"], capture_output=True, text=True, check=True)
    assert mkbool.union(text, "POLYGON((1 1,5 1,1 5,1 1))").wkt == run.stdout.strip()


def test_shapely_wkb_variants():
    p = sg.box(0, 0, 1, 1)
    big_endian = shapely.wkb.dumps(p, big_endian=True)
    with_srid = shapely.wkb.dumps(p, srid=4326)
    for form in (big_endian, with_srid, memoryview(p.wkb)):
        assert mkbool.as_polygon(form).rings[0].tolist() == mkbool.as_polygon(p).rings[0].tolist()
