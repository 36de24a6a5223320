"""Benchmark row (not a test): eccd.static_status_batch through Python, per pair.

N random pairs of ellipsoids (3D) and ellipses (2D) at random rigid poses, as
numpy arrays of shape (N, 3) / (N, 4, 4) (2D (N, 2) / (N, 3, 3)); the median of
REPEAT calls, divided by N, printed in nanoseconds per pair, both wall-clock and
the process's CPU time (on a shared machine the wall clock counts the time the
process waited for a core), beside the same pairs one call at a time through
eccd.static_status (numpy poses), for scale.
    PYTHONPATH=build/python python3 bench/python_batch.py [N] [REPEAT]
"""
import statistics
import sys
import time

import numpy as np

import eccd


def pairs(n, dim, rng):
    def poses():
        q, _ = np.linalg.qr(rng.normal(size=(n, dim, dim)))
        p = np.zeros((n, dim + 1, dim + 1))
        p[:, :dim, :dim] = q
        p[:, :dim, dim] = rng.uniform(-3, 3, (n, dim))
        p[:, dim, dim] = 1
        return p
    return rng.uniform(0.5, 2, (n, dim)), poses(), rng.uniform(0.5, 2, (n, dim)), poses()


def median_seconds(f, repeat, clock=time.perf_counter):
    times = []
    for _ in range(repeat):
        t0 = clock()
        f()
        times.append(clock() - t0)
    return statistics.median(times)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 15
    rng = np.random.default_rng(1)
    print(f"eccd {eccd.__version__}: static_status_batch, N = {n}, median of {repeat} calls")
    for dim in (3, 2):
        aa, pa, ab, pb = pairs(n, dim, rng)
        codes = eccd.static_status_batch(aa, pa, ab, pb)
        counts = {eccd.status_of_code(c).value: int((codes == c).sum()) for c in np.unique(codes)}
        batch = median_seconds(lambda: eccd.static_status_batch(aa, pa, ab, pb), repeat)
        cpu = median_seconds(lambda: eccd.static_status_batch(aa, pa, ab, pb), repeat, time.process_time)
        make = eccd.Ellipsoid if dim == 3 else eccd.Ellipse
        m = min(n, 2000)
        single = median_seconds(lambda: [eccd.static_status(make(aa[i], pa[i]), make(ab[i], pb[i])) for i in range(m)], 3)
        print(f"  {dim}D: batch {batch / n * 1e9:7.1f} ns per pair (CPU {cpu / n * 1e9:7.1f} ns)   "
              f"one call per pair {single / m * 1e9:7.0f} ns   {counts}")


if __name__ == "__main__":
    main()
