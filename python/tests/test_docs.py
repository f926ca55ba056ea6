"""docs/python.md runs as written: its examples are doctests, run in a scratch folder
(the plotting example writes a PNG there)."""

import doctest
import os

from conftest import ROOT


def test_docs_python_md(tmp_path):
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        failures, tried = doctest.testfile(str(ROOT / "docs" / "python.md"), module_relative=False,
                                           optionflags=doctest.ELLIPSIS, report=True)
    finally:
        os.chdir(cwd)
    assert tried > 40 and failures == 0
    assert (tmp_path / "python_experiment.png").stat().st_size > 1000
