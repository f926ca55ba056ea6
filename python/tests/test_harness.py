"""The harness from Python: built-in sweeps, single cases and generators written in Python,
with rows in the CSV schema and as a DataFrame; exact kernels match the exact reference."""

import collections
import math

import pandas as pd
import pytest

import mkbool
import mkbool.harness as h


def test_generators_and_plan():
    names = [g["name"] for g in h.generators()]
    assert {"shared_edge", "rotated", "kettner_grid", "paper_figures"} <= set(names)
    specs = h.plan(["shared_edge"], "quick")
    assert specs and all(s["generator"] == "shared_edge" for s in specs)
    assert h.plan(["shared_edge"], "quick") == specs  # reproducible from the base seed
    a, b = h.make_case(specs[0])
    assert a.vertex_count > 0 and b.vertex_count > 0
    with pytest.raises(mkbool.UsageError):
        h.plan(["no_such_generator"])


def test_builtin_sweep_rows():
    rows = h.sweep(["shared_edge", "rotated"], kernels=["exact", "double"], jobs=2, level="quick")
    assert rows and set(rows[0]) == set(h.columns())
    verdicts = collections.Counter((r["kernel"], r["verdict"]) for r in rows)
    exact_runs = sum(n for (k, _), n in verdicts.items() if k == "exact")
    assert verdicts[("exact", "exact_match")] == exact_runs
    # the double kernel's failures on rotated configurations are the data the harness exists for
    assert any(k == "double" and v != "exact_match" for k, v in verdicts)
    # issue 12: the exact kernel's written output is valid for GEOS too (where GEOS is built)
    written = [r for r in rows if r["kernel"] == "exact" and r["certified_valid"] is not None]
    assert written and all(r["certified_valid"] for r in written)
    if "geos" in h.peer_names():
        assert all(r["geos_valid"] is True for r in written), [r for r in written if r["geos_valid"] is not True][:1]
    assert all(r["geos_valid"] is None for r in rows if r["kernel"] == "double")
    frame = h.sweep(["shared_edge"], kernels=["exact"], ops=["union"], regular=True, as_frame=True)
    assert isinstance(frame, pd.DataFrame) and list(frame.columns) == h.columns()
    assert (frame["verdict"] == "exact_match").all() and (frame["op"] == "union").all()


def test_python_generator():
    calls = []

    def needle(seed):
        calls.append(seed)
        k = seed % 7 + 1
        # a triangle and a needle through its vertex: vertex_on_edge and shared vertices
        return [(0, 0), (8, 0), (0, 8)], [(0, 0), (k, 8 - k), (k + 1, 9 - k)]

    h.register_generator("needle_py", needle, stresses="a needle through a vertex")
    try:
        assert any(g["name"] == "needle_py" and g["python"] for g in h.generators())
        rows = h.sweep(["needle_py"], seeds=5, kernels=["exact", "rational", "adaptive"], base_seed=7)
        assert len(calls) == 5 and len(set(calls)) == 5
        assert {r["generator"] for r in rows} == {"needle_py"}
        assert {r["seed"] for r in rows} == set(calls)
        assert all(r["verdict"] == "exact_match" for r in rows if r["kernel"] in ("exact", "rational"))
        assert all(r["exact_area"] is not None and r["exact_area"] >= 0 for r in rows)
        again = h.sweep(["needle_py"], seeds=5, kernels=["exact", "rational", "adaptive"], base_seed=7)
        assert [r["seed"] for r in again] == [r["seed"] for r in rows]
    finally:
        h.unregister_generator("needle_py")


def test_python_generator_errors_become_rows():
    def broken(seed):
        if seed % 2:
            raise ValueError("odd seed")
        return "POLYGON((0 0,2 2,2 0,0 2,0 0))", "POLYGON((0 0,1 0,0 1,0 0))"

    h.register_generator("broken_py", broken)
    try:
        rows = h.sweep(["broken_py"], seeds=6, kernels=["exact"])
        refused = [r for r in rows if r["verdict"] == "invalid_input"]
        assert refused == rows and {r["case"] for r in rows} == set(range(6))
        assert any("generator: ValueError: odd seed" in r["message"] for r in refused)
        assert any("cross" in r["message"] for r in refused)
    finally:
        h.unregister_generator("broken_py")
    with pytest.raises(mkbool.UsageError, match="built-in"):
        h.register_generator("rotated", broken)


def test_run_case_with_peers():
    rows = h.run_case("POLYGON((0 0,3 0,3 3,0 3,0 0))", "POLYGON((1 -1,2 -1,2 4,1 4,1 -1))",
                      ops=["difference"], regular=True, peers=True)
    by_kernel = {r["kernel"]: r for r in rows}
    assert set(mkbool.kernel_names()) <= set(by_kernel)
    assert all(by_kernel[k]["verdict"] == "exact_match" for k in mkbool.kernel_names())
    assert all(math.isclose(r["exact_area"], 6) for r in rows)
    for peer in h.peer_names():
        assert by_kernel[peer]["verdict"] in ("exact_area", "rounding_only"), by_kernel[peer]


def test_kernel_failure_reproduced_from_a_sweep_row():
    # A run where the naive kernel fails in the sweep fails the same way from Python.
    rows = h.sweep(["rotated", "ulp_perturbed"], kernels=["double"], regular=True, jobs=2)
    failed = [r for r in rows if r["verdict"] == "error" and r["message"].startswith("KernelFailure")]
    assert failed, "the quick sweep has kernel failures of the double kernel"
    r = failed[0]
    a, b = h.make_case(r)
    with pytest.raises(mkbool.KernelFailure) as e:
        mkbool.compute(r["op"], a, b, kernel="double", regular=r["regular"])
    assert r["message"].removeprefix("KernelFailure: ") in str(e.value)
    assert "kernel='exact'" in str(e.value)
    assert mkbool.compute(r["op"], a, b, regular=r["regular"]).area >= 0
