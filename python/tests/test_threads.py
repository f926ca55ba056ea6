"""Many operations at once: the vectorized form runs pairs in C++ threads and gives exactly
what one call at a time gives, Python threads may call the module concurrently, and the
GIL is released while the library works."""

import concurrent.futures
import threading

import numpy as np
import pytest

import mkbool
import mkbool.harness as h


def near_degenerate_pairs():
    """Cases of the built-in generators that stress the arithmetic (rotated, ulp-perturbed,
    Kettner grids, shared edges): the filters' exact stages and MPFR run in every thread."""
    specs = h.plan(["rotated", "ulp_perturbed", "kettner_grid", "shared_edge", "collinear_overlap"], "quick")
    return [h.make_case(s) for s in specs[:160]]


def fingerprint(r):
    return (r.types, [x.tobytes() for x in r.rings], r._r._exact_text, r.unbounded or r.area_exact,
            r.rounded_valid)


@pytest.mark.parametrize("kernel", ["exact", "rational", "double"])
def test_threads_give_what_one_thread_gives(kernel):
    pairs = near_degenerate_pairs()
    a = [p[0] for p in pairs]
    b = [p[1] for p in pairs]
    for op in ("intersection", "xor"):
        threaded = mkbool.compute(op, a, b, kernel=kernel, threads=4, errors="return", exact=True, area_exact=True)
        for i, (x, y) in enumerate(pairs):
            try:
                one = mkbool.compute(op, x, y, kernel=kernel, exact=True, area_exact=True)
            except mkbool.Error as e:
                assert isinstance(threaded[i], type(e)) and str(threaded[i]) == f"pair {i}: {e}"
                continue
            if not mkbool.is_exact_kernel(kernel):
                assert threaded[i].json == one.json
                continue
            assert fingerprint(threaded[i]) == fingerprint(one), (op, i)


def test_python_threads_call_concurrently():
    pairs = near_degenerate_pairs()[:60]
    expected = [mkbool.xor(a, b, exact=True)._r._exact_text for a, b in pairs]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        got = list(pool.map(lambda p: mkbool.xor(p[0], p[1], exact=True)._r._exact_text, pairs * 3))
    assert got == expected * 3


def test_broadcast_and_errors():
    square = "POLYGON((0 0,4 0,4 4,0 4,0 0))"
    others = [f"POLYGON(({i} 0,{i + 2} 0,{i + 2} 2,{i} 2,{i} 0))" for i in range(6)]
    areas = [r.area_exact for r in mkbool.intersection(square, others)]
    assert areas == [4, 4, 4, 2, 0, 0]
    assert [r.area_exact for r in mkbool.intersection(np.array(others, dtype=object), square)] == areas
    bad = others[:2] + ["POLYGON((0 0,2 2,2 0,0 2,0 0))"] + others[2:]
    with pytest.raises(mkbool.InvalidInput, match=r"^pair 2: A\[2\] \(WKT\): polygon 0, ring 0: its edge from \(2 0\) to \(0 2\) crosses its edge from \(0 0\) to \(2 2\)"):
        mkbool.intersection(bad, square)
    mixed = mkbool.intersection(bad, square, errors="return")
    assert isinstance(mixed[2], mkbool.InvalidInput) and mixed[3].area_exact == 4
    with pytest.raises(mkbool.UsageError, match="different lengths"):
        mkbool.intersection(others[:2], others[:3])
    # inputs that cannot be read are their pair's error too, the other pairs run
    with pytest.raises(mkbool.InvalidInput, match=r"^pair 1: A\[1\] \(WKT\)"):
        mkbool.intersection([square, "POLYGON((0 0))"], square)
    mixed = mkbool.intersection([square, "POLYGON((0 0))", 42], [others[0], others[1], None], errors="return")
    assert mixed[0].area_exact == 4
    assert str(mixed[1]).startswith("pair 1: A[1] (WKT)") and str(mixed[2]).startswith("pair 2: A[2]: cannot read")
    # one polygon against many that cannot be read: refused at once, not once per pair
    with pytest.raises(mkbool.InvalidInput, match=r"^B \(WKT\)"):
        mkbool.intersection(others, "POLYGON((0 0))", errors="return")


def test_the_gil_is_released_during_the_operation():
    # Two blobs of 2e5 vertices: tens of milliseconds in C++. While they run in another
    # thread, this thread must get the interpreter again and again; with the GIL held
    # through the operation it could not run at all until it ends.
    t = np.linspace(0, 2 * np.pi, 200000, endpoint=False)
    r = 100 * (1 + 0.1 * np.sin(5 * t))
    a = np.column_stack([r * np.cos(t), r * np.sin(t)])
    b = a + [30.0, 10.0]
    pa, pb = mkbool.as_polygon(a), mkbool.as_polygon(b)
    done = threading.Event()
    ticks = 0

    def work():
        mkbool.intersection(pa, pb)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    while not done.is_set():
        ticks += 1
    worker.join()
    assert ticks > 1000, ticks
