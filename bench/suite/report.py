#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Turns the Google Benchmark JSON of bench_suite into the markdown tables of
bench/README.md: time per library (median and min of the repetitions) and
ratio to cgogn per suite, the memory table, the dynamic-editing table, and
the agreement of the check values (all libraries must print the same:
counts exactly, real values to 1e-9 relative).

usage: report.py RESULT.json [MORE.json ...] [--check]
       report.py --orders RUN.json [MORE.json ...]
       report.py --same-check RESULT.json
  --check   only verify the check values; exit status 1 on disagreement
  --same-check  every benchmark of the file reports the same "check" counter
            (bench_dart_layout: each layout does the same work); exit status
            1 on disagreement
  --orders  one table per suite comparing runs made on differently ordered
            inputs (bench_suite --permute=SEED [--reorder]): each file is one
            run, its context "order" names the variant ("file",
            "permuted (seed N)", "..., cgogn reordered (morton)"); columns are
            library x order, cells the median (min) time in ms

With --reorder, cgogn's vertices are in Morton order, so the in-place
(Gauss-Seidel) surface smoothing visits them in another order than the peers
and its check value legitimately differs: it is not compared in such runs.
"""
import json
import statistics
import sys

LIBRARIES = ["cgogn", "cgogn_quick", "openmesh", "cgal_sm", "cgal_polyhedron", "cgal_lcc", "flat"]
SUITES = {
    "surface": ["circulator", "barycenter", "normal", "smoothing", "subdivision", "collapse"],
    "volume": ["circulator", "circulator2", "barycenter", "smoothing", "split", "collapse"],
}
REL_TOL = 1e-9
ABS_TOL = 1e-9  # sums that are zero up to rounding (e.g. normals of a symmetric closed mesh)


def load(paths):
    runs = {}  # base name -> list of benchmark entries (one per repetition)
    context = None
    for p in paths:
        with open(p) as f:
            d = json.load(f)
        context = context or d.get("context", {})
        for b in d.get("benchmarks", []):
            if b.get("run_type", "iteration") != "iteration":
                continue
            if "error_occurred" in b and b["error_occurred"]:
                continue
            base = b["name"].split("/iterations:")[0].split("/repeats:")[0]
            runs.setdefault(base, []).append(b)
    return runs, context


def ms(b):
    unit = b.get("time_unit", "ns")
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]
    return b["real_time"] * scale


def fmt_ms(x):
    if x >= 100:
        return f"{x:.0f}"
    if x >= 10:
        return f"{x:.1f}"
    return f"{x:.2f}"


ORDER_DEPENDENT = {("surface", "smoothing")}  # in-place passes: the result depends on the vertex order


def checks_agree(runs, reordered=False):
    """Returns a list of disagreement messages."""
    problems = []
    by_workload = {}
    for base, entries in runs.items():
        parts = base.split("/")
        if len(parts) != 3 or parts[0] not in SUITES:
            continue
        by_workload.setdefault((parts[0], parts[1]), {})[parts[2]] = entries
    for (suite, workload), libs in sorted(by_workload.items()):
        ref_lib, ref = None, None
        for lib in sorted(libs):
            entries = libs[lib]
            checks = {k: v for k, v in entries[-1].items() if k.startswith("check")}
            for e in entries:  # every repetition must agree with the last one
                for k, v in checks.items():
                    if not close(e.get(k), v):
                        problems.append(f"{suite}/{workload}/{lib}: {k} varies across repetitions")
            if workload == "dynamic":
                continue  # the dynamic check is per library (back to the start counts)
            if reordered and (suite, workload) in ORDER_DEPENDENT:
                continue  # cgogn's vertex order differs from the peers' by design
            if ref is None:
                ref_lib, ref = lib, checks
                continue
            for k in set(ref) | set(checks):
                if k not in ref or k not in checks:
                    continue  # a library may report fewer checks (e.g. no naive count)
                if not close(ref[k], checks[k]):
                    problems.append(f"{suite}/{workload}: {k} {lib}={checks[k]!r} != {ref_lib}={ref[k]!r}")
    return problems


def close(a, b):
    if a is None or b is None:
        return False
    return abs(a - b) <= REL_TOL * max(abs(a), abs(b)) + ABS_TOL


def time_tables(runs, suite):
    libs = [l for l in LIBRARIES if any(f"{suite}/{w}/{l}" in runs for w in SUITES[suite])]
    if not libs:
        return ""
    out = [f"### {suite} suite: time per run, median (min) in ms\n"]
    out.append("| workload | " + " | ".join(libs) + " |")
    out.append("|---" * (len(libs) + 1) + "|")
    med = {}
    for w in SUITES[suite]:
        row = [w]
        for l in libs:
            e = runs.get(f"{suite}/{w}/{l}")
            if not e:
                row.append("—")
                continue
            t = [ms(x) for x in e]
            med[(w, l)] = statistics.median(t)
            row.append(f"{fmt_ms(med[(w, l)])} ({fmt_ms(min(t))})")
        out.append("| " + " | ".join(row) + " |")
    out.append("")
    out.append(f"### {suite} suite: ratio of medians to cgogn (< 1: faster than cgogn)\n")
    out.append("| workload | " + " | ".join(libs) + " |")
    out.append("|---" * (len(libs) + 1) + "|")
    for w in SUITES[suite]:
        row = [w]
        base = med.get((w, "cgogn"))
        for l in libs:
            v = med.get((w, l))
            row.append("—" if v is None or base is None else f"{v / base:.2f}")
        out.append("| " + " | ".join(row) + " |")
    out.append("")
    return "\n".join(out)


def cache_table(runs):
    rows = []
    for suite in SUITES:
        e = runs.get(f"{suite}/cache_build/cgogn_quick")
        if not e:
            continue
        t = [ms(x) for x in e]
        rows.append(f"| {suite} | {fmt_ms(statistics.median(t))} ({fmt_ms(min(t))}) | "
                    f"{statistics.median(x.get('wall_ms', 0) for x in e):.0f} | {e[-1].get('cache_MB', 0):.1f} |")
    if not rows:
        return ""
    head = [
        "### cgogn_quick: building the incidence caches (thread pool; process CPU time)\n",
        "| suite | build, median (min) ms of CPU | wall ms | cache MB |",
        "|---|---|---|---|",
    ]
    return "\n".join(head + rows) + "\n"


def memory_table(runs):
    rows = []
    for suite, per in (("surface", "bytes_per_face"), ("volume", "bytes_per_tet")):
        for l in LIBRARIES:
            e = runs.get(f"memory/{suite}/{l}")
            if not e:
                continue
            b = e[-1]
            rows.append(
                f"| {suite} | {l} | {b.get(per, 0):.1f} | {b.get('bytes_per_vertex', 0):.1f} | "
                f"{b.get('bytes', 0) / 1e6:.1f} | {b.get('peak_rss_MB', 0):.0f} |"
            )
    if not rows:
        return ""
    head = [
        "### memory: bytes held by the structure after building (mallinfo2 before/after)\n",
        "| suite | library | bytes per face (tet) | bytes per vertex | MB | peak RSS of the process, MB |",
        "|---|---|---|---|---|---|",
    ]
    return "\n".join(head + rows) + "\n"


def dynamic_table(runs):
    rows = []
    for l in LIBRARIES:
        e = runs.get(f"surface/dynamic/{l}")
        if not e:
            continue
        b = e[-1]
        t = [b[k] for k in sorted(b) if k.startswith("batch") and k.endswith("_ms")]
        r = [b[k] for k in sorted(b) if k.startswith("batch") and k.endswith("_rss_MB")]
        h = [b[k] for k in sorted(b) if k.startswith("batch") and k.endswith("_heap_MB")] or [0.0] * len(t)
        if not t:
            continue
        pick = [0, 9, 24, len(t) - 1]
        rows.append(
            f"| {l} | "
            + " | ".join(f"{t[i]:.1f}" for i in pick)
            + f" | {max(t) / min(t):.2f} | "
            + " | ".join(f"{r[i]:.0f}" for i in pick)
            + f" | {r[-1] - r[0]:+.0f} | {h[0]:.0f} | {h[-1]:.0f} |"
        )
    if not rows:
        return ""
    head = [
        "### dynamic editing: 50 batches (split 10% of the faces, collapse back, garbage collection for peers)\n",
        "| library | batch 1 ms | batch 10 ms | batch 25 ms | batch 50 ms | max/min time | RSS 1 MB | RSS 10 MB | RSS 25 MB | RSS 50 MB | RSS 50 - RSS 1 MB | heap 1 MB | heap 50 MB |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    return "\n".join(head + rows) + "\n"


def short_order(order):
    if "reordered" in order:
        return "permuted + reorder" if order.startswith("permuted") else "file + reorder"
    return "permuted" if order.startswith("permuted") else order


def order_tables(paths):
    # files with the same order variant are merged (a later file's runs replace an earlier one's)
    variants = {}  # order -> runs, in the order of first appearance
    for p in paths:
        runs, context = load([p])
        variants.setdefault(context.get("order", p), {}).update(runs)
    out = ["Orders: " + "; ".join(f"**{short_order(o)}** = {o}" for o in variants) + ".\n"]
    for suite, workloads in SUITES.items():
        cols = []
        for lib in LIBRARIES:
            for order, runs in variants.items():
                if any(f"{suite}/{w}/{lib}" in runs for w in workloads):
                    cols.append((lib, short_order(order), runs))
        if not cols:
            continue
        out.append(f"### {suite} suite by input order: time per run, median (min) in ms\n")
        out.append("| workload | " + " | ".join(f"{l} {o}" for l, o, _ in cols) + " |")
        out.append("|---" * (len(cols) + 1) + "|")
        for w in workloads:
            row = [w]
            for lib, _, runs in cols:
                e = runs.get(f"{suite}/{w}/{lib}")
                if not e:
                    row.append("—")
                    continue
                t = [ms(x) for x in e]
                row.append(f"{fmt_ms(statistics.median(t))} ({fmt_ms(min(t))})")
            if any(c != "—" for c in row[1:]):
                out.append("| " + " | ".join(row) + " |")
        out.append("")
    print("\n".join(out))
    return 0


def same_check(paths):
    """(number of benchmarks, disagreements with the first one's check).
    Aggregates count too: bench_dart_layout reports only those."""
    runs = {}
    for p in paths:
        with open(p) as f:
            for b in json.load(f).get("benchmarks", []):
                runs.setdefault(b["name"].split("/")[0], b)
    ref_name, ref = None, None
    problems = [] if runs else ["no benchmark ran"]
    for name, entry in runs.items():
        value = entry.get("check")
        if value is None:
            problems.append(f"{name}: no check value")
        elif ref is None:
            ref_name, ref = name, value
        elif not close(ref, value):
            problems.append(f"{name}: check {value!r} != {ref_name}={ref!r}")
    return len(runs), problems


def main(argv):
    check_only = "--check" in argv
    paths = [a for a in argv if not a.startswith("--")]
    if not paths:
        print(__doc__)
        return 2
    if "--orders" in argv:
        return order_tables(paths)
    if "--same-check" in argv:
        count, problems = same_check(paths)
        for p in problems:
            print("MISMATCH", p)
        print(f"check values of {count} benchmarks: " + ("all agree" if not problems else "disagree"))
        return 1 if problems else 0
    runs, context = load(paths)
    problems = checks_agree(runs, reordered="reordered" in (context or {}).get("order", ""))
    if check_only:
        for p in problems:
            print("MISMATCH", p)
        print("check values: " + ("all agree" if not problems else f"{len(problems)} disagreements"))
        return 1 if problems else 0
    out = []
    if context:
        out.append(
            f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
            f"run {context.get('date', '?')}; flags {context.get('compiler_flags', '?')}.\n"
        )
        if "input" in context:
            out.append(f"Input: {context['input']}.\n")
    for s in SUITES:
        out.append(time_tables(runs, s))
    out.append(cache_table(runs))
    out.append(memory_table(runs))
    out.append(dynamic_table(runs))
    out.append("### check values\n")
    if problems:
        out.append("Disagreements:\n")
        out.extend(f"- {p}" for p in problems)
    else:
        out.append("All libraries print the same check value for every workload they run "
                   "(counts exactly, real values to 1e-9 relative).")
    print("\n".join(x for x in out if x))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
