"""The large blocks the library frees are kept for the next call (python/src/memory.cpp):
within the limit, released on request, and the results the same with or without them,
in one thread and in many."""

import concurrent.futures
import multiprocessing
import threading

import numpy as np
import pytest

import mkbool


def disc(n, dx=0.0, dy=0.0, r=1.0):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.column_stack([dx + r * np.cos(t), dy + r * np.sin(t)])


def fingerprint(r):
    return [x.tobytes() for x in r.rings], r.area_exact, r.types


def area_of_pair(pair):
    return mkbool.intersection(*pair).area


@pytest.fixture(autouse=True)
def default_limit():
    yield
    mkbool.set_memory_cache_limit(256 << 20)


def test_blocks_are_kept_within_the_limit_and_released():
    a, b = disc(40000), disc(40000, 0.5, 0.2)
    mkbool.release_memory()
    assert mkbool.memory_cache()["cached_bytes"] == 0
    mkbool.intersection(a, b)
    kept = mkbool.memory_cache()
    # 80,000 input vertices: the library's arrays of 256 KiB and more come back to the cache.
    assert kept["cached_bytes"] >= 1 << 20 and kept["blocks"] >= 2
    assert kept["limit_bytes"] == 256 << 20

    mkbool.set_memory_cache_limit(1 << 20)
    assert mkbool.memory_cache()["cached_bytes"] <= 1 << 20
    mkbool.union(a, b)
    assert mkbool.memory_cache()["cached_bytes"] <= 1 << 20

    mkbool.set_memory_cache_limit(0)
    assert mkbool.memory_cache()["cached_bytes"] == 0
    mkbool.difference(a, b)
    assert mkbool.memory_cache() == {"cached_bytes": 0, "blocks": 0, "limit_bytes": 0}

    mkbool.set_memory_cache_limit(256 << 20)
    mkbool.intersection(a, b)
    assert mkbool.memory_cache()["cached_bytes"] > 0
    mkbool.release_memory()
    assert mkbool.memory_cache()["cached_bytes"] == 0
    with pytest.raises(ValueError):
        mkbool.set_memory_cache_limit(-1)


def test_results_are_the_same_with_kept_blocks_without_them_and_in_threads():
    pairs = [(disc(n, 0, 0), disc(n, 0.3 + 0.01 * k, 0.1, 0.9)) for k, n in enumerate([3000, 20000, 70000, 5000])]
    ops = [mkbool.intersection, mkbool.union, mkbool.difference, mkbool.symmetric_difference]
    mkbool.set_memory_cache_limit(0)
    want = [fingerprint(op(a, b)) for a, b in pairs for op in ops]
    mkbool.set_memory_cache_limit(256 << 20)
    # Twice with the cache: the second round runs on blocks the first one freed.
    for _ in range(2):
        assert [fingerprint(op(a, b)) for a, b in pairs for op in ops] == want
    # Many Python threads and the vectorized form share the cache.
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        got = list(pool.map(lambda i: fingerprint(ops[i % 4](*pairs[i // 4])), range(len(want))))
    assert got == want
    vec = mkbool.intersection([mkbool.as_polygon(a) for a, _ in pairs], [mkbool.as_polygon(b) for _, b in pairs],
                              threads=3)
    assert [fingerprint(r) for r in vec] == want[0::4]
    # The result's arrays own their memory (from the extension's allocator): they outlive
    # the result and a release of the kept blocks.
    r = mkbool.intersection(*pairs[2])
    rings = r.rings
    del r
    mkbool.release_memory()
    assert [x.tobytes() for x in rings] == want[8][0]


def test_a_forked_child_computes_while_a_thread_of_the_parent_does():
    # The fork may come while the parent's other thread is inside the cache (its lock
    # taken): the child must find it unlocked, not wait forever.
    a, b = disc(30000), disc(30000, 0.4)
    want = mkbool.intersection(a, b).area
    stop = threading.Event()

    def busy():
        while not stop.is_set():
            mkbool.intersection(a, b, threads=2)

    worker = threading.Thread(target=busy)
    worker.start()
    try:
        with multiprocessing.get_context("fork").Pool(2) as pool:
            got = pool.map_async(area_of_pair, [(a, b)] * 8, chunksize=1).get(timeout=120)
    finally:
        stop.set()
        worker.join()
    assert got == [want] * 8
