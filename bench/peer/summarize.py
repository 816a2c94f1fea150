#!/usr/bin/env python3
"""Builds results.md from results/raw (written by run.sh)."""
import glob
import os
import re
import statistics as st

HERE = os.environ.get("PEER_DIR", os.path.expanduser("~/pagor-peer"))
RAW = os.path.join(HERE, "results", "raw")


def parse_ours(path):
    txt = open(path).read()
    r = {"file": path}
    m = re.search(r"^times \[ms\]: (.*?) \| total ([\d.]+)", txt, re.M)
    if not m:
        r["error"] = txt.strip().splitlines()[-1] if txt.strip() else "no output"
        return r
    kv = m.group(1).split()
    stages = {kv[i]: float(kv[i + 1]) for i in range(0, len(kv), 2)}
    r["stages"] = stages
    r["cli_total"] = float(m.group(2))
    r["backend"] = stages["graph"] + stages["clique"] + stages["gnc"]
    m = re.search(r"^correspondences: (\d+)$", txt, re.M)
    r["n"] = int(m.group(1)) if m else None
    m = re.search(r"translation error ([\d.]+) m, rotation error ([\d.]+) deg -> (\w+)", txt)
    r["t_err"], r["r_err"], r["verdict"] = float(m.group(1)), float(m.group(2)), m.group(3)
    r["ok"] = r["t_err"] < 2.0 and r["r_err"] < 5.0
    m = re.search(r"^\*\s+(\d+)\s+([\d.]+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)", txt, re.M)
    r["level"], r["eps"], r["clique"], r["clique_true"] = (
        int(m.group(1)), float(m.group(2)), int(m.group(5)), int(m.group(6)))
    js = path[:-4] + ".json"
    if os.path.exists(js):
        import json
        d = json.load(open(js))
        r["lvl_ms"] = [l.get("clique_time_ms") for l in d["levels"]]
        r["lvl_proven"] = [l.get("clique_proven") for l in d["levels"]]
        r["lvl_budget"] = [l.get("clique_budget_hit") for l in d["levels"]]
        r["lvl_ub"] = [l.get("clique_upper_bound") for l in d["levels"]]
        r["pair_budget_hit"] = d.get("pair_time_budget_hit")
    levels = re.findall(r"^[ *]\s+(\d+)\s+([\d.]+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)", txt, re.M)
    r["edges"] = [int(l[3]) for l in levels]
    r["cliques"] = [int(l[4]) for l in levels]
    return r


def parse_peer(path):
    txt = open(path).read().strip()
    if "=" not in txt:
        return {"error": txt}
    return {k: (float(v) if re.fullmatch(r"-?[\d.]+", v) else v)
            for k, v in (t.split("=", 1) for t in txt.split())}


def parse_bench(path):
    out = {}
    if not os.path.exists(path):
        return out
    for line in open(path):
        m = re.match(r"gedi (\d+)\s+(\d+)\s+cascaded\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)", line)
        if m:
            out["gedi-" + m.group(1)] = dict(graph=float(m.group(3)), clique=float(m.group(4)),
                                             gnc=float(m.group(5)), total=float(m.group(6)))
    return out


def names():
    ns = sorted({os.path.basename(p).split(".")[0] for p in glob.glob(os.path.join(RAW, "*.ours.*.txt"))})
    return [n for n in ns if n.startswith("gedi")] + [n for n in ns if n.startswith("gen")]


def lvl_ms(o):
    if "lvl_ms" not in o:
        return "—"
    return ", ".join(f"{t:.1f}" + ("*" if b not in (None, "none") else "") for t, b in zip(o["lvl_ms"], o["lvl_budget"]))


def sizes_str(o):
    ub = o.get("lvl_ub") or [None] * len(o["cliques"])
    return ", ".join(str(c) if u in (None, c) else f"{c} (ub {u})" for c, u in zip(o["cliques"], ub))


def f(x, d=2):
    return "—" if x is None else f"{x:.{d}f}"


rows = []
bench = parse_bench(os.path.join(RAW, "pagor_bench_dense.txt"))
for name in names():
    ours = [parse_ours(p) for p in sorted(glob.glob(os.path.join(RAW, f"{name}.ours.*.txt")))]
    peers = [parse_peer(p) for p in sorted(glob.glob(os.path.join(RAW, f"{name}.peer.*.txt")))]
    clique_p = os.path.join(RAW, f"{name}.peerclique.txt")
    pc = parse_peer(clique_p) if os.path.exists(clique_p) else None
    good = [o for o in ours if "backend" in o]
    ob = min(good, key=lambda o: o["backend"]) if good else None
    pcold = min(p["cold_total_ms"] for p in peers)
    pwarm = min(p["warm_total_ms"] for p in peers)
    p0 = peers[0]
    rows.append(dict(name=name, set=name.split("-")[0], ours=ob, ours_all=ours, peer=p0,
                     pcold=pcold, pwarm=pwarm, pcold_best=min(peers, key=lambda p: p["cold_total_ms"]),
                     pc=pc, bench=bench.get(name),
                     ratio=(ob["backend"] / pcold) if ob else None))

out = []
P = out.append
P("# Back-end timing: Pagor vs KISS-Matcher back end (ROBIN max-core + GNC-TLS)\n")
P(open(os.path.join(HERE, "results_header.md")).read() if os.path.exists(os.path.join(HERE, "results_header.md")) else "")
mach = os.path.join(HERE, "results", "machine.txt")
if os.path.exists(mach):
    P("## Machine state during the run\n")
    P("```")
    P("\n".join(l for l in open(mach).read().splitlines()
                if l.startswith(("start", "end", "uptime", "nproc", "cpu", "taskset"))))
    la = os.path.join(RAW, "loadavg.txt")
    if os.path.exists(la):
        loads = [float(l.split()[2]) for l in open(la) if len(l.split()) >= 3]
        P(f"1-min load average after each problem: min {min(loads):.2f}, median {st.median(loads):.2f}, max {max(loads):.2f}")
    P("```\n")

for s, title in (("gedi", "(a) gedi-dev (real GeDi correspondences, ../shared/data/gedi-dev)"),
                 ("gen", "(b) generated dense problems (harness/gen_problems, seeds 1-20; problems/gen/manifest.txt)")):
    rs = [r for r in rows if r["set"] == s]
    if not rs:
        continue
    P(f"## {title}\n")
    P("Times in ms. ours = best of 3 CLI processes by graph+clique+gnc (stage times of that run); "
      "peer = KISS-Matcher back end (max-core, res 0.3), best of 3 processes' first call (cold) / best in-process "
      "repeat (warm); ratio = ours / peer cold. inl = correspondences flagged inlier in the file. "
      "sel = our selected level: clique size/flagged-inlier members. pruned = ROBIN max-core size/flagged inliers in it. "
      "errors: t [m] / r [deg]; ok = < 2 m and < 5 deg.\n")
    P("| problem | n | inl | our graph | our clique | our gnc | **ours** | sel | peer graph | peer core | peer gnc | **peer cold** | peer warm | **ratio** | ours err | ok | peer pruned | peer err | ok | peer max-clique (warm) / ok | our clique ms per level L0..L3 (* budget hit) |")
    P("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rs:
        o, p, pb = r["ours"], r["peer"], r["pcold_best"]
        pc = r["pc"]
        pcs = f"{pc['warm_total_ms']:.2f} / {'yes' if pc['ok'] else 'NO'}" if pc and "ok" in pc else "—"
        if o is None:
            P(f"| {r['name']} | {int(p['n'])} | {int(p['n_true'])} | ours failed: {r['ours_all'][0].get('error')} |")
            continue
        P(f"| {r['name']} | {o['n']} | {int(p['n_true'])} | {f(o['stages']['graph'],1)} | {f(o['stages']['clique'],1)} | "
          f"{f(o['stages']['gnc'],1)} | **{f(o['backend'],1)}** | L{o['level']}: {o['clique']}/{o['clique_true']} | "
          f"{f(pb['cold_graph_ms'])} | {f(pb['cold_prune_ms'])} | {f(pb['cold_solve_ms'])} | **{f(r['pcold'])}** | {f(r['pwarm'])} | "
          f"**{r['ratio']:.2f}** | {o['t_err']:.2f} / {o['r_err']:.2f} | {'yes' if o['ok'] else 'NO'} | "
          f"{int(p['pruned'])}/{int(p['pruned_true'])} | {p['t_err']:.2f} / {p['r_err']:.2f} | {'yes' if p['ok'] else 'NO'} | {pcs} | {lvl_ms(o)} |")
    ratios = [r["ratio"] for r in rs if r["ratio"] is not None]
    P("")
    P(f"**{s}: ratio ours/peer-cold: median {st.median(ratios):.2f}, worst (largest) {max(ratios):.2f} "
      f"({max(rs, key=lambda r: r['ratio'] or 0)['name']}), best {min(ratios):.2f}; "
      f"success ours {sum(1 for r in rs if r['ours'] and r['ours']['ok'])}/{len(rs)}, "
      f"peer (max-core) {sum(1 for r in rs if r['peer']['ok'])}/{len(rs)}, "
      f"peer (max-clique) {sum(1 for r in rs if r['pc'] and r['pc'].get('ok'))}/{len(rs)}.**  ")
    P(f"Median back-end ms: ours {st.median(r['ours']['backend'] for r in rs if r['ours']):.2f}, "
      f"peer cold {st.median(r['pcold'] for r in rs):.2f}, peer warm {st.median(r['pwarm'] for r in rs):.2f}.  ")
    wr = [r["ours"]["backend"] / r["pwarm"] for r in rs if r["ours"]]
    P(f"Ratio ours(CLI) / peer warm: median {st.median(wr):.2f}, worst {max(wr):.2f}.")
    bs = [r for r in rs if r["bench"]]
    if bs:
        P("")
        P("Warm comparison with our own benchmark (`pagor_bench --only dense`, cascaded = default solver, median of 15 in-process runs) "
          "vs the peer's warm best-of-3:\n")
        P("| problem | bench graph | bench clique | bench gnc | **bench total** | peer warm | **ratio warm** | our CLI best (cold process) |")
        P("|---|---|---|---|---|---|---|---|")
        for r in bs:
            b = r["bench"]
            P(f"| {r['name']} | {b['graph']:.2f} | {b['clique']:.2f} | {b['gnc']:.2f} | **{b['total']:.2f}** | {r['pwarm']:.2f} | "
              f"**{b['total']/r['pwarm']:.2f}** | {r['ours']['backend']:.1f} |")
        bw = [r["bench"]["total"] / r["pwarm"] for r in bs]
        P(f"\nwarm ratio (bench / peer warm): median {st.median(bw):.2f}, worst {max(bw):.2f}.")
    P("")

thp = []
for r in rows:
    ot = [parse_ours(p) for p in sorted(glob.glob(os.path.join(RAW, f"{r['name']}.ours_thp.*.txt")))]
    pt = [parse_peer(p) for p in sorted(glob.glob(os.path.join(RAW, f"{r['name']}.peer_thp.*.txt")))]
    ot = [o for o in ot if "backend" in o]
    if ot and pt:
        thp.append((r, min(ot, key=lambda o: o["backend"]), min(p["cold_total_ms"] for p in pt)))
if thp:
    P("## Cold-process experiment: malloc on transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1)\n")
    P("Same protocol (3 interleaved fresh processes each, best of 3), gedi-dev only. Fewer first-touch page "
      "faults; in this VM guest each fault is expensive. Not used for the main ratios.\n")
    P("| problem | ours default (graph/clique/gnc = total) | ours THP (graph/clique/gnc = total) | peer cold default | peer cold THP | ratio default | ratio THP |")
    P("|---|---|---|---|---|---|---|")
    for r, o, pc in thp:
        d = r["ours"]
        P(f"| {r['name']} | {d['stages']['graph']:.1f}/{d['stages']['clique']:.1f}/{d['stages']['gnc']:.1f} = {d['backend']:.1f} | "
          f"{o['stages']['graph']:.1f}/{o['stages']['clique']:.1f}/{o['stages']['gnc']:.1f} = {o['backend']:.1f} | "
          f"{r['pcold']:.2f} | {pc:.2f} | {r['ratio']:.2f} | {o['backend']/pc:.2f} |")
    P(f"\nmedian ratio: default {st.median(r['ratio'] for r, _, _ in thp):.2f}, THP {st.median(o['backend']/pc for _, o, pc in thp):.2f}\n")

P("## The 5 problems where we are slowest relative to the peer\n")
P("| problem | n | ours graph / clique / gnc = total [ms] | per-level clique ms (L0..L3; * = budget hit, not proven) | per-level edges | per-level clique sizes (upper bound) | selected | peer cold (graph / core / gnc) [ms] | ratio |")
P("|---|---|---|---|---|---|---|---|---|")
for r in sorted([r for r in rows if r["ratio"]], key=lambda r: -r["ratio"])[:5]:
    o, pb = r["ours"], r["pcold_best"]
    P(f"| {r['name']} | {o['n']} | {o['stages']['graph']:.1f} / {o['stages']['clique']:.1f} / {o['stages']['gnc']:.1f} = {o['backend']:.1f} | "
      f"{lvl_ms(o)} | {', '.join(str(e) for e in o['edges'])} | "
      f"{sizes_str(o)} | L{o['level']} | "
      f"{r['pcold']:.2f} ({pb['cold_graph_ms']:.2f} / {pb['cold_prune_ms']:.2f} / {pb['cold_solve_ms']:.2f}); ROBIN edges {int(r['peer']['edges'])} | {r['ratio']:.1f} |")
P("")
P("## Run-to-run spread of our back end (3 CLI processes, graph+clique+gnc ms)\n")
P("| problem | run 1 | run 2 | run 3 |")
P("|---|---|---|---|")
for r in rows:
    P(f"| {r['name']} | " + " | ".join(f(o.get('backend'), 1) for o in r["ours_all"]) + " |")
P("")
tail = os.path.join(HERE, "results_footer.md")
if os.path.exists(tail):
    P(open(tail).read())
print("\n".join(out))
