"""The robustness harness from Python (experiments/README.md): run the built-in generators'
sweeps or your own cases through every kernel against the exact reference, and get one row
per run (the CSV schema of mkbool-experiment) as dicts or a pandas DataFrame.

A generator written in Python is a function from a seed to two polygons (any input form
of :func:`mkbool.as_polygon`); :func:`register_generator` adds it by name, and sweeps
then run it beside the built-in ones.
"""

import numbers

from . import _mkbool
from ._inputs import as_polygon

__all__ = [
    "generators", "register_generator", "unregister_generator", "plan", "sweep", "run_case",
    "to_frame", "columns", "verdicts", "peer_names", "make_case",
]

_h = _mkbool.harness

# Seeds per Python generator when a sweep does not say: the level's count of random
# instances per configuration in the built-in plan (experiments/generators.cpp).
_LEVEL_SEEDS = {"quick": 3, "normal": 40, "default": 40, "full": 200}

_python_generators = {}


def columns():
    """The row keys, in the CSV schema's order."""
    return _h.csv_columns()


def verdicts():
    return _h.verdict_names()


def peer_names():
    """Peer libraries built in as back ends (GEOS, Boost.Geometry, Clipper, CGAL Epeck)."""
    return _h.peer_names()


def generators():
    """Every generator: name, what it stresses, variants; Python ones have python=True."""
    out = [dict(g, python=False) for g in _h.generators()]
    for name, (fn, stresses) in _python_generators.items():
        out.append({"name": name, "stresses": stresses, "variants": [""], "python": True})
    return out


def register_generator(name, fn=None, *, stresses=""):
    """Adds a generator written in Python: ``fn(seed) -> (a, b)``. Usable as a decorator
    (``@register_generator("my_family")``). The name must not be a built-in generator's."""
    if fn is None:
        return lambda f: register_generator(name, f, stresses=stresses) or f
    if not isinstance(name, str) or not name or any(c in name for c in ",;\n\""):
        raise _mkbool.UsageError(f"generator name {name!r} must be a non-empty string without , ; \" or newlines")
    if any(g["name"] == name for g in _h.generators()):
        raise _mkbool.UsageError(f"'{name}' is a built-in generator; choose another name")
    if not callable(fn):
        raise _mkbool.UsageError("a generator is a function from a seed to two polygons")
    _python_generators[name] = (fn, stresses)
    return fn


def unregister_generator(name):
    _python_generators.pop(name, None)


def _seeds(seeds):
    """Seeds per configuration as mkbool-experiment's --seeds takes them (0 or None: the
    level's default)."""
    if seeds is None or (isinstance(seeds, numbers.Integral) and not isinstance(seeds, bool) and seeds == 0):
        return 0
    if not isinstance(seeds, numbers.Integral) or isinstance(seeds, bool) or not 1 <= seeds <= 1_000_000:
        raise _mkbool.UsageError(f"seeds={seeds!r}: a whole number of seeds from 1 to 1000000")
    return int(seeds)


def _base_seed(base_seed):
    if not isinstance(base_seed, numbers.Integral) or isinstance(base_seed, bool) or not 0 <= base_seed < 2**64:
        raise _mkbool.UsageError(f"base_seed={base_seed!r}: a whole number from 0 to 2**64 - 1")
    return int(base_seed)


def plan(generators=None, level="quick", seeds=0, base_seed=1):
    """The built-in cases a sweep runs (specs: index, generator, variant, params, seed)."""
    return _h.plan(list(generators or []), level, _seeds(seeds), _base_seed(base_seed))


def _backends(kernels, peers):
    names = list(kernels) if kernels is not None else list(_mkbool.kernel_names())
    if peers:
        names += [p for p in _h.peer_names() if p not in names]
    return names


def _ops(ops):
    return list(ops) if ops is not None else ["intersection", "union", "difference", "xor"]


def _regular(regular):
    if isinstance(regular, bool):
        return [regular]
    return [bool(r) for r in regular]


def _doubles(obj, role):
    """The polygon of a case: every kernel of the harness reads doubles."""
    p = as_polygon(obj, role)
    if p.is_exact:
        raise _mkbool.InvalidInput(f"{role}: coordinates that are not doubles (Fractions, an exact result); the "
                                   "harness runs every kernel, which read doubles")
    return p


def _jobs(jobs):
    import os
    return int(jobs) if jobs else (os.cpu_count() or 1)


def _python_cases(names, count, base_seed, first_index):
    """(index, generator, variant, params, seed, A, B) per case, and rows for generators that
    failed (a generator that cannot build its case gives one row, as in the harness)."""
    built, failed = [], []
    index = first_index
    for name in names:
        fn, _ = _python_generators[name]
        for i in range(count):
            seed = _h.mix_seed(base_seed, name, i)
            try:
                pair = fn(seed)
                a, b = pair
                built.append((index, name, "", "", seed, _doubles(a, "A"), _doubles(b, "B")))
            except Exception as e:  # the harness records it and goes on
                row = {c: None for c in columns()}
                row.update(case=index, generator=name, variant="", params="", seed=seed, size=0,
                           op="", regular=True, kernel="reference", verdict="invalid_input",
                           message=f"generator: {type(e).__name__}: {e}")
                failed.append(row)
            index += 1
    return built, failed


def sweep(generators=None, *, level="quick", seeds=None, base_seed=1, kernels=None, ops=None,
          regular=(True, False), jobs=None, isolate=True, timeout=60.0, peers=False, peer_every=4,
          as_frame=False):
    """Runs generators (names: built-in and registered Python ones; default every one) x
    kernels x operations x regularity against the exact reference. Built-in generators run
    in forked worker processes with a time limit per run (``isolate``), as mkbool-experiment
    does; Python generators are called here, in order of their seeds, and their cases run in
    C++ threads. Rows are dicts keyed by :func:`columns` (a DataFrame with ``as_frame``)."""
    seeds, base_seed = _seeds(seeds), _base_seed(base_seed)
    names = list(generators) if generators is not None else [g["name"] for g in _h.generators()] + \
        list(_python_generators)
    builtin = [n for n in names if n not in _python_generators]
    python = [n for n in names if n in _python_generators]
    backends, op_list, reg = _backends(kernels, peers), _ops(ops), _regular(regular)
    rows = []
    if builtin:
        specs = _h.plan(builtin, level, int(seeds or 0), int(base_seed))
        rows += _h.run_specs(specs, backends, op_list, reg, _jobs(jobs), bool(isolate), float(timeout),
                             int(peer_every))
        first = len(_h.plan([], level, int(seeds or 0), int(base_seed)))
    else:
        first = 0
    if python:
        count = int(seeds) if seeds else _LEVEL_SEEDS.get(level, 3)
        built, failed = _python_cases(python, count, int(base_seed), first)
        rows += failed
        rows += _h.run_built(built, backends, op_list, reg, _jobs(jobs))
    return to_frame(rows) if as_frame else rows


def run_case(a, b, *, kernels=None, ops=None, regular=(True, False), peers=False, name="case", seed=0,
             as_frame=False):
    """One case (two polygons in any accepted form) through every kernel (and the peers with
    ``peers=True``), each operation and regularity, against the exact reference."""
    if not isinstance(seed, numbers.Integral) or seed < 0:
        raise _mkbool.UsageError("seed must be a non-negative integer")
    built = [(0, str(name), "", "", int(seed), _doubles(a, "A"), _doubles(b, "B"))]
    rows = _h.run_built(built, _backends(kernels, peers), _ops(ops), _regular(regular), 1)
    return to_frame(rows) if as_frame else rows


def to_frame(rows):
    """Rows as a pandas DataFrame (columns in the schema's order)."""
    import pandas as pd
    return pd.DataFrame(list(rows), columns=columns())


def make_case(spec):
    """A built-in case's two input polygons, from a spec of :func:`plan` (or a row)."""
    return _h.make_case({k: spec[k] for k in ("generator", "variant", "params", "seed")})
