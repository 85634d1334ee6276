#!/usr/bin/env python3
"""Prints the speed table of docs/performance.md from one run of scripts/bench-table.sh.

Usage: scripts/bench-table.py OUT    (OUT: the folder bench-table.sh filled)

Every figure is a median of the run's repetitions or rounds, and every ratio
divides two figures of the same run. A row whose files are missing says so.
"""
import json
import os
import statistics
import sys

# The paper's Table 2 (ms per step of its C++ cloth): basic / global / atomic.
PAPER_TABLE2 = {
    "quads": (0.37, 0.41, 0.55),
    "triangles": (0.78, 0.95, 1.3),
    "mixed": (0.61, 0.72, 0.97),
}
UNIT_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def gbench_runs(out, name):
    """Every entry of OUT/NAME.json (Google Benchmark's JSON), or None."""
    path = os.path.join(out, name + ".json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)["benchmarks"]


def gbench(out, name):
    """Median of each benchmark of OUT/NAME.json: {run_name: entry}."""
    runs = gbench_runs(out, name)
    if runs is None:
        return None
    medians = {r["run_name"]: r for r in runs if r.get("aggregate_name") == "median"}
    if not medians:  # one repetition: the runs themselves
        medians = {r["run_name"]: r for r in runs if r.get("run_type") == "iteration"}
    return medians


def gbench_fastest(out, name):
    """The fastest repetition of each benchmark of OUT/NAME.json: {run_name: entry}."""
    runs = gbench_runs(out, name)
    if runs is None:
        return None
    fastest = {}
    for r in runs:
        if r.get("run_type") == "iteration":
            best = fastest.get(r["run_name"])
            if best is None or real_ns(r) < real_ns(best):
                fastest[r["run_name"]] = r
    return fastest


def real_ns(entry):
    return entry["real_time"] * UNIT_NS[entry["time_unit"]]


def cpu_ns(entry):
    return entry["cpu_time"] * UNIT_NS[entry["time_unit"]]


def rift_bench(out, name, statistic=statistics.median):
    """Medians (or another statistic, such as min) of each scene's rounds in
    OUT/NAME.jsonl: {scene: {field: statistic}}."""
    path = os.path.join(out, name + ".jsonl")
    if not os.path.exists(path):
        return None
    rounds = {}
    with open(path) as f:
        for line in f:
            if line.strip():
                r = json.loads(line)
                rounds.setdefault(r["scene"], []).append(r)
    return {
        scene: {k: statistic([r[k] for r in rs]) for k in rs[0] if isinstance(rs[0][k], (int, float))}
        for scene, rs in rounds.items()
    }


def find(medians, prefix):
    """The benchmark named prefix, else the first whose name starts with it
    (an exact name first: "…/99" must not find "…/999")."""
    if prefix in medians:
        return medians[prefix]
    for name, entry in medians.items():
        if name.startswith(prefix):
            return entry
    raise KeyError(prefix)


def rows(out):
    """(what, now, goal) for each row of the table."""
    result = []

    def row(what, goal, compute):
        try:
            result.append((what, compute(), goal))
        except (KeyError, TypeError, ZeroDivisionError) as e:
            result.append((what, "not measured (%s)" % e, goal))

    tear = gbench(out, "tear")
    def one_tear():
        big, small = find(tear, "BM_OneTear/quads/1000/"), find(tear, "BM_OneTear/quads/10/")
        text = "%.1f× (%.1f µs / %.1f µs)" % (
            real_ns(big) / real_ns(small), real_ns(big) / 1e3, real_ns(small) / 1e3)
        if "ns_per_touched_dart" in big and "ns_per_touched_dart" in small:
            # The two sizes' tears touch different numbers of darts (tear_bench.cpp).
            text += "; per touched dart %.1f× (%.0f / %.0f darts a tear)" % (
                big["ns_per_touched_dart"] / small["ns_per_touched_dart"],
                big["touched_darts"], small["touched_darts"])
        return text
    row("one tear at 1000×1000 vs 10×10 (rewrite + masses + re-match)", "≤ 2×", one_tear)
    def inner_tear():
        big = find(tear, "BM_OneTear/quads_inner/1000/")
        small = find(tear, "BM_OneTear/quads_inner/10/")
        return "%.1f× (%.1f µs / %.1f µs, %.0f / %.0f darts a tear)" % (
            real_ns(big) / real_ns(small), real_ns(big) / 1e3, real_ns(small) / 1e3,
            big["touched_darts"], small["touched_darts"])
    row("the same tear at both sizes (a spring between inner vertices of an untorn part)",
        "≤ 2×", inner_tear)

    # The 10×10 scenes' steps take 15-45 µs: a process now and then runs
    # about 1.6× slower throughout (on an idle machine too, whatever the
    # scene), so the rows give the median of the rounds and their fastest.
    t2 = rift_bench(out, "table2")
    t2_fastest = rift_bench(out, "table2", min)

    def table2(runs):
        cells = []
        for mesh, paper in PAPER_TABLE2.items():
            faster = [paper[k] * 1e6 / runs["%s-%s" % (mesh, kind)]["ns_per_step"]
                      for k, kind in enumerate(("basic", "global", "atomic"))]
            cells.append("%s %s" % (mesh, " / ".join("%.0f×" % x for x in faster)))
        return "; ".join(cells)
    row("Table 2, paper's ms per step / rift's (basic / global / atomic), median of the rounds; fastest",
        "every cell ≥ 22×", lambda: "%s; fastest: %s" % (table2(t2), table2(t2_fastest)))

    sc = gbench(out, "scaling")
    sc_fastest = gbench_fastest(out, "scaling")

    def scaling(runs):
        cells = []
        for mesh in ("quads", "triangles"):
            for n, label in ((10, "10²"), (99, "10⁴"), (999, "10⁶")):
                rift = find(runs, "BM_ScalingClothRift/%s/%d" % (mesh, n))["s_per_vertex"]
                ref = find(runs, "BM_ScalingClothReference/%s_cumulated/%d" % (mesh, n))["s_per_vertex"]
                atomic = find(runs, "BM_ScalingClothReference/%s_atomic/%d" % (mesh, n))["s_per_vertex"]
                cells.append("%s %s %.2f× (atomic %.2f×)" % (mesh, label, rift / ref, rift / atomic))
        return "; ".join(cells)
    row("generated step / reference cloth, springs cumulated (atomic), medians", "≤ 1.1×",
        lambda: scaling(sc))
    row("the same, fastest repetitions", "≤ 1.1×", lambda: scaling(sc_fastest))

    q = rift_bench(out, "setup_quads")
    h = rift_bench(out, "setup_hex")
    ref_kb = None
    path = os.path.join(out, "reference_rss_kb.txt")
    if os.path.exists(path):
        with open(path) as f:
            ref_kb = float(f.read().split()[-1])
    row("peak memory, 10⁶-vertex quad cloth (reference cumulated)", "≤ 0.9 GB",
        lambda: "%.2f GB (reference %.2f GB)" % (q["quads1m"]["peak_rss_mb"] / 1e3, ref_kb / 1e6))
    row("set-up of 10⁶ vertices, quads / hexahedra (each after an untimed run)", "≤ 1 s / ≤ 4 s",
        lambda: "%.2f s / %.1f s" % (q["quads1m"]["setup_ms"] / 1e3, h["hex1m"]["setup_ms"] / 1e3))

    th = {}
    for name in ("threads", "threads1", "threads2"):  # one process per thread count since 30a6001
        th.update(gbench(out, name) or {})

    def threads():
        one = real_ns(find(th, "BM_ThreadsRk4Cloth/1000/1/"))
        two = real_ns(find(th, "BM_ThreadsRk4Cloth/1000/2/"))
        return one, two
    row("RK4 step at 10⁶ quads, 1 / 2 threads", "≤ 150 ms / ≤ 90 ms",
        lambda: "%.0f ms / %.0f ms" % tuple(x / 1e6 for x in threads()))
    row("2 cores vs 1 at 10⁶ quads (RK4 step)", "≥ 1.7×", lambda: "%.2f×" % (threads()[0] / threads()[1]))

    co = gbench(out, "corotational")
    row("co-rotational tetrahedron, per element (hand-written / generated pack)", "≤ 200 ns",
        lambda: "%.0f ns / %.0f ns" % (find(co, "BM_CorotationalElement/quaternion")["s_per_element"] * 1e9,
                                       find(co, "BM_GeneratedCorotational/")["s_per_element"] * 1e9))

    f13 = rift_bench(out, "fig13")
    row("fig13 with `vertex_stress` / without a criterion", "≤ 1.3×",
        lambda: "%.2f× (%.3f ms / %.3f ms)" % (
            f13["fig13"]["ns_per_step"] / f13["fig13_nocrit"]["ns_per_step"],
            f13["fig13"]["ns_per_step"] / 1e6, f13["fig13_nocrit"]["ns_per_step"] / 1e6))
    row("atomic edge criterion over the basic step (10×10 quads), medians; fastest", "≤ +35 %",
        lambda: "%+.0f %%; %+.0f %%" % tuple(
            100 * (runs["quads-atomic"]["ns_per_step"] / runs["quads-basic"]["ns_per_step"] - 1)
            for runs in (t2, t2_fastest)))

    gm = gbench(out, "gmap")

    def gmap():
        cells = []
        for n in (100, 1000):
            cgal = real_ns(find(gm, "BM_CgalBare_Build/%d/" % n))
            rift = real_ns(find(gm, "BM_Rift_Build/%d/" % n))
            cells.append("%.2f×" % (cgal / rift))
        return " / ".join(cells) + " as fast"
    row("G-map build vs CGAL `Generalized_map` (bare), 100² / 1000²", "≥ 2× faster", gmap)
    return result


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: bench-table.py OUT")
    print("| what | now | goal |")
    print("|---|---|---|")
    for what, now, goal in rows(sys.argv[1]):
        print("| %s | %s | %s |" % (what, now, goal))


if __name__ == "__main__":
    main()
