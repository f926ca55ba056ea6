"""Shared fixtures of the Python tests: the repository, the command line tool to compare
messages with, an independent exact area, and a check that the package under test is the
one the run meant (the build tree's or the installed one)."""

import fractions
import os
import pathlib

import pytest

import mkbool

ROOT = pathlib.Path(__file__).resolve().parents[2]


def pytest_report_header(config):
    return f"mkbool from {mkbool.__file__}; kernels {mkbool.kernel_names()}"


@pytest.fixture(scope="session", autouse=True)
def expected_package():
    expected = os.environ.get("MKBOOL_EXPECTED_PACKAGE")
    if expected:
        here = pathlib.Path(mkbool.__file__).resolve().parent
        assert here == pathlib.Path(expected).resolve(), f"testing {here}, expected {expected}"


@pytest.fixture(scope="session")
def cli():
    """The mkbool command of the same build (MKBOOL_CLI, else build/bin/mkbool)."""
    path = pathlib.Path(os.environ.get("MKBOOL_CLI", ROOT / "build" / "bin" / "mkbool"))
    assert path.exists(), f"{path} is not built: build the command first (cmake --build build)"
    return str(path)


def shoelace(ring):
    """Twice the signed area of a ring of exact points, as a Fraction (written here, not
    taken from the library)."""
    s = fractions.Fraction(0)
    n = len(ring)
    for i in range(n):
        x0, y0 = ring[i]
        x1, y1 = ring[(i + 1) % n]
        s += fractions.Fraction(x0) * fractions.Fraction(y1) - fractions.Fraction(x1) * fractions.Fraction(y0)
    return s


def typed_area(result):
    """The result's exact area from its exact irreducible cycles: |area| of islands minus
    |area| of holes (cycles of fewer than 3 vertices add nothing)."""
    total = fractions.Fraction(0)
    for ring, t in zip(result.exact_rings, result.types):
        if len(ring) < 3:
            continue
        a = abs(shoelace(ring)) / 2
        total += a if t == "island" else -a
    return total
