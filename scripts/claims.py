#!/usr/bin/env python3
"""The claims ledger: every figure README.md and docs/ state, re-measured on this machine.

  claims.py run [--only STEP ...] [--mtcs PATH]   measure, keep experiments/claims/last.json, render
  claims.py render                                 experiments/CLAIMS.md from claims.toml + last.json
  claims.py check                                  every claim's words stand in its file, every
                                                   measured one within its noise of the last run, and
                                                   README.md states no figure the ledger lacks

experiments/claims/claims.toml lists the claims (the phrase as the file words it, the figure it
states, which measure re-measures it and how far it may be off) and the README's inputs that look
like figures but are not claims. The steps below run the project's own commands; a step's measures
are named STEP.NAME. Standard library only: it runs wherever the test command runs.
"""
import argparse
import csv
import datetime
import io
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import tomllib
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LEDGER = ROOT / "experiments/claims/claims.toml"
LAST = ROOT / "experiments/claims/last.json"
RAW = ROOT / "experiments/claims/raw"
CLAIMS_MD = ROOT / "experiments/CLAIMS.md"


def sh(args, **kw):
    """Runs a command from the checkout; its stdout, or a clear failure naming the command."""
    r = subprocess.run([str(a) for a in args], cwd=ROOT, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, args))}: exit {r.returncode}\n{r.stderr[-2000:]}")
    return r.stdout


def keep(name, text):
    RAW.mkdir(parents=True, exist_ok=True)
    (RAW / name).write_text(text)


# ---- steps: each returns {measure: value} and names the commands it ran -------------------------

class Step:
    def __init__(self, mtcs, work):
        self.mtcs, self.work = mtcs, work


def step_counts(s):
    """Tests CTest runs and the sanitizers' share of them; the certified data's sizes."""
    names = ("modules", "slow", "heavy")  # bash reads the selection as sanitize.sh does
    values = sh(["bash", "-c", 'source scripts/sanitize_selection.sh && printf "%s\\0" "$modules" "$slow" "$heavy"'])
    sel = dict(zip(names, values.split("\0")))

    def count(*args):
        out = sh(["ctest", "--test-dir", "build", "-N", *args])
        return int(re.search(r"Total Tests: (\d+)", out)[1])

    total = count()
    sanitized = count("-L", sel["modules"], "-E", sel["slow"]) + \
        count("-LE", sel["modules"], "-E", sel["heavy"])
    pairs = sum(1 for _ in open(ROOT / "tests/data/cylinder_pairs_public.csv")) - 1 + \
        sum(1 for _ in open(ROOT / "tests/data/cylinder_pairs_exact.csv")) - 1
    return {
        "ctest_cases": total,
        "sanitized_cases": sanitized,
        "sanitized_share": sanitized / total,
        "certified_cylinder_pairs": pairs,
        "certified_access_maps": len(list((ROOT / "tests/data/access_maps").glob("*.txt"))),
        "certified_hv_fronts": len(list((ROOT / "tests/data/hv_fronts").glob("*.txt"))),
    }


def step_interfere(s):
    """The interference counts the README shows (the serve demo's pair, the certified one)."""
    def pairs(a, b, t):
        j = json.loads(sh([s.mtcs, "interfere", a, b, "--translate", t, "--json"]))
        return len(j["pairs"])
    return {
        "gear_cup_pairs": pairs("molds/meshes/mcad_herringbone_gear.off", "molds/meshes/cup.off", "-15,-90,-45"),
        "homer_gear_pairs": pairs("tests/data/meshes/homer.off", "tests/data/meshes/mcad_herringbone_gear.off",
                                  "29.132630030337086,0.029399999999998983,-1.0000930000000001"),
    }


def step_distance(s):
    """The cylinder kernel against FCL on the certified pairs, in one run (bench distance)."""
    pairs = "tests/data/cylinder_pairs_public.csv"
    out = sh([s.mtcs, "bench", "distance", "--pairs", pairs, "--repeat", "16"])
    keep("distance.csv", out)
    rows = {(r["variant"], r["category"]): r for r in csv.DictReader(io.StringIO(out))}
    ns = lambda v, c: float(rows[(v, c)]["median_ns"])
    stiff = sh([s.mtcs, "bench", "stiff", "--pairs", pairs, "--repeat", "4"])
    keep("stiff.csv", stiff)
    worst = max(float(r["max_rel_err"]) for r in csv.DictReader(io.StringIO(stiff)))
    return {
        "full_application_ns": ns("full", "application"),
        "fcl_application_ns": ns("fcl", "application"),
        "fcl_over_full_application": ns("fcl", "application") / ns("full", "application"),
        "full_max_error": max(float(r["max_abs_err"]) for (v, c), r in rows.items() if v == "full"),
        "fcl_max_error_application": float(rows[("fcl", "application")]["max_abs_err"]),
        "stiff_p99_ns": float(rows[("full", "stiff")]["p99_ns"]),
        "worst_relative_error": worst,
    }


def step_freefem(s):
    """The finite volumes against FreeFem++ P2 at the reference block's 720 patch samples."""
    ref = [float(r["T"]) for r in csv.DictReader(open(ROOT / "tests/data/thermal/patch_samples.csv"))]
    result = {}
    for cell in (1, 2):
        out = s.work / f"fd{cell}.csv"
        t0 = time.perf_counter()
        sh([s.mtcs, "thermal", "molds/thermal_block.yaml", "--layout", "molds/thermal_block.layout.yaml",
            "--tier", "fd", "--cell", cell, "--samples", "tests/data/thermal/patch_samples.csv", "--out", out])
        result[f"fd{cell}_seconds"] = time.perf_counter() - t0
        got = [float(r["T"]) for r in csv.DictReader(open(out))]
        d = [a - b for a, b in zip(got, ref, strict=True)]
        result[f"fd{cell}_rms_K"] = math.sqrt(sum(x * x for x in d) / len(d))
        result[f"fd{cell}_max_K"] = max(abs(x) for x in d)
    return result


def step_tiers(s):
    """Every tier on the reference block's 60 random layouts against T3 at 1 mm (bench thermal)."""
    out = sh([s.mtcs, "bench", "thermal", "--case", "block", "--layouts", "60", "--reference-cell", "1", "--json"])
    keep("tiers.json", out)
    j = json.loads(out)
    result = {}
    for t in j["tiers"]:
        name = re.sub(r"[^a-z0-9]+", "_", t["tier"].lower()).strip("_")
        result[f"{name}_ms"] = t["ms_full"]
        result[f"{name}_ms_one_bore"] = t["ms_incremental"]
        if t["rms_k"] is not None:
            result[f"{name}_rms_K"] = t["rms_k"]
            result[f"{name}_tau_std"] = t["tau_std"]
    return result


def es_rate(s, mold, seeds, evaluations, config=None):
    """The ES run's own evaluations a second on one thread (after the model's build)."""
    rates = []
    for seed in seeds:
        out = s.work / f"rate_{Path(mold).stem}_{Path(config or 'default').stem}_{seed}"
        shutil.rmtree(out, ignore_errors=True)
        sh([s.mtcs, "optimize", mold, "--out", out, "--seed", seed, "--threads", 1, "--evaluations", evaluations,
            "--quiet", *(["--config", config] if config else [])])
        j = json.loads((out / "summary.json").read_text())
        rates.append(j["evaluations"] / j["seconds"])
        shutil.rmtree(out)
    return statistics.median(rates)


def step_rates(s):
    """Plate layouts a second: wall distance, the cavity's temperature, and screened (one run)."""
    wall = es_rate(s, "molds/plate_wall_distance.yaml", (1, 2, 3), 100000)
    plain = es_rate(s, "molds/plate.yaml", (1, 2, 3), 10000)
    screened = es_rate(s, "molds/plate.yaml", (1, 2, 3), 10000, "configs/es_screened.yaml")
    return {"wall_distance_per_s": wall, "temperature_per_s": plain, "screened_per_s": screened,
            "screened_over_plain": screened / plain, "wall_over_temperature": wall / plain}


def step_part(s):
    """What a designer waits for on each bundled mesh part and the held-out one (bench part)."""
    result = {}
    text = ""
    molds = {m: f"molds/{m}.yaml" for m in ("cup", "gear", "l_bracket", "ribbed_box")}
    molds["fandisk"] = "experiments/part_speed/held_out/fandisk.yaml"  # a part the project had not seen
    for mold, spec in molds.items():
        out = sh([s.mtcs, "bench", "part", spec, "--repeat", "3"])
        text += out if not text else out.split("\n", 1)[1]
        for r in csv.DictReader(io.StringIO(out)):
            result[f"{mold}_{r['measure']}"] = float(r["value"])
    keep("part.csv", text)
    for mold in ("cup", "gear", "l_bracket", "ribbed_box"):
        result[f"{mold}_evaluate_cold_over_warm"] = result[f"{mold}_evaluate_cold"] / result[f"{mold}_evaluate_warm"]
    return result


def optimize_demo(s, out, seed, start=None, threads=None, env=None):
    args = [s.mtcs, "optimize", "molds/plate.yaml", "--evaluations", 10000, "--seed", seed, "--polish", 500,
            "--out", out, "--quiet"]
    args += ["--start", start] if start else ["--config", "configs/es_explore.yaml"]
    args += ["--threads", threads] if threads else []
    sh(args, env=env)
    return json.loads((out / "summary.json").read_text())["best_objective"]


def step_demo(s):
    """The demo's first run as a new user waits for it (no kept model), its report's size."""
    out = s.work / "demo"
    shutil.rmtree(out, ignore_errors=True)
    cold = dict(os.environ, MTCS_CACHE_DIR=str(s.work / "demo_cache"))  # a first run keeps nothing yet
    t0 = time.perf_counter()
    optimize_demo(s, out, 1, env=cold)
    seconds = time.perf_counter() - t0
    sh([s.mtcs, "report", out, "--out", out / "report.html"])
    size = (out / "report.html").stat().st_size / 1e6
    shutil.rmtree(out)
    return {"optimize_seconds": seconds, "report_MB": size}


def step_demo_seeds(s):
    """The demo's two arms over seeds 1-11 against the hand-made layout (one thread a run)."""
    ref = json.loads(sh([s.mtcs, "evaluate", "molds/plate.yaml", "--layout", "molds/plate.layout.yaml", "--json"]))
    hand = ref["scalarised"]

    def arm(job):
        start, seed = job
        out = s.work / f"seeds_{'start' if start else 'random'}_{seed}"
        shutil.rmtree(out, ignore_errors=True)
        v = optimize_demo(s, out, seed, start, threads=1)
        shutil.rmtree(out)
        return start, v

    jobs = [(start, seed) for seed in range(1, 12) for start in (None, "molds/plate.layout.yaml")]
    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(arm, jobs))
    random_arm = [v for start, v in results if not start]
    start_arm = [v for start, v in results if start]
    return {"hand_made": hand,
            "random_beats_hand_made": sum(v < hand for v in random_arm),
            "start_beats_hand_made": sum(v < hand for v in start_arm),
            "random_median": statistics.median(random_arm), "start_median": statistics.median(start_arm),
            "start_median_below_hand_made": 1 - statistics.median(start_arm) / hand}


STEPS = {
    "counts": step_counts, "interfere": step_interfere, "distance": step_distance, "freefem": step_freefem,
    "tiers": step_tiers, "rates": step_rates, "part": step_part, "demo": step_demo, "demo_seeds": step_demo_seeds,
}


# ---- the ledger -------------------------------------------------------------------------------

def load_ledger():
    with open(LEDGER, "rb") as f:
        return tomllib.load(f)


def load_last():
    return json.loads(LAST.read_text()) if LAST.exists() else {"steps": {}}


def measured(last, name):
    step, _, key = name.partition(".")
    if step == "run":  # the whole run's own figures (its minutes)
        return last.get("run", {}).get(key)
    return last["steps"].get(step, {}).get("measures", {}).get(key)


def claim_value(claim, last):
    """The figure the claim states, as the last run measured it: a number or (low, high)."""
    names = claim.get("measure")
    if names is None:
        return None
    values = [measured(last, n) for n in ([names] if isinstance(names, str) else names)]
    if any(v is None for v in values):
        return None
    scale = claim.get("scale", 1)
    values = [v * scale for v in values]
    if claim.get("range"):  # the lowest and the highest of the measures against [low, high]
        return (min(values), max(values))
    return tuple(values) if len(values) > 1 else values[0]


def holds(claim, value):
    stated, noise = claim["stated"], claim.get("noise", 0)
    near = lambda a, b: abs(a - b) <= noise * abs(b) + 1e-12
    if claim.get("bound") == "at_most":
        return value <= stated * (1 + noise)
    if claim.get("bound") == "at_least":
        return value >= stated * (1 - noise)
    if claim.get("bound") == "within":  # one measure inside the stated range
        return stated[0] * (1 - noise) <= value <= stated[1] * (1 + noise)
    if isinstance(stated, list):  # figure by figure
        return len(value) == len(stated) and all(near(v, s) for v, s in zip(value, stated))
    return near(value, stated)


def normalised(text):
    return re.sub(r"\s+", " ", text)


def git(*args):
    return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True).stdout.strip()


def head():
    dirty = " (with uncommitted changes)" if git("status", "--porcelain", "--untracked-files=no") else ""
    return git("rev-parse", "--short", "HEAD") + dirty


def machine():
    model = platform.machine()
    try:
        model = next(l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{os.cpu_count()} cores, {model}"


def fmt(v):
    if v is None:
        return "—"
    if isinstance(v, tuple):
        return ", ".join(fmt(x) for x in v)
    if isinstance(v, int) or float(v).is_integer():
        return f"{int(v):,}".replace(",", " ")
    return f"{v:.3g}" if abs(v) < 1000 else f"{v:,.0f}".replace(",", " ")


def cell(text):
    """Text inside a Markdown table cell."""
    return str(text).replace("|", "\\|")


def render(ledger, last):
    lines = [
        "# Claims ledger",
        "",
        "Every figure README.md states, and the docs' figures, with what it measures, the command that",
        "re-measures it and the last run's value. Generated by `scripts/claims.sh` from",
        "`experiments/claims/claims.toml` (the claims) and `experiments/claims/last.json` (the last run);",
        "do not edit by hand. `python3 scripts/claims.py check` (a CTest case) fails when a claim's words",
        "leave its file, when a re-measured figure is off by more than its noise, or when README.md",
        "states a figure that is not here.",
        "",
    ]
    meta = last.get("run")
    if meta:
        lines += [f"Last run: {meta['date']}, commit {meta['commit']}, {meta['machine']} "
                  f"(`{meta['command']}`); every step, as last run: {meta['minutes']:.1f} min.", ""]
    lines += ["## Re-measured by `scripts/claims.sh`", "",
              "| claim | where | stated | last run | noise | holds | what it measures | step |",
              "|---|---|---:|---:|---:|:---:|---|---|"]
    for c in ledger["claim"]:
        if "measure" not in c:
            continue
        v = claim_value(c, last)
        ok = "—" if v is None else ("yes" if holds(c, v) else "**no**")
        stated = c["stated"]
        stated = fmt(tuple(stated)) if isinstance(stated, list) else fmt(stated)
        stated = stated.replace(", ", "-") if c.get("range") or c.get("bound") == "within" else stated
        bound = {"at_most": "≤ ", "at_least": "≥ "}.get(c.get("bound"), "")
        noise = f"{c.get('noise', 0) * 100:.0f} %" if c.get("noise") else "exact"
        step = c["measure"] if isinstance(c["measure"], str) else c["measure"][0]
        lines.append(f"| {c['id']}: “{cell(c['text'])}” | {c['file']} | {bound}{stated} | {fmt(v)} | {noise} | {ok} | "
                     f"{cell(c['measures'])} | {step.split('.')[0]} |")
    lines += ["", "## Recorded, not re-measured by `scripts/claims.sh`", "",
              "Figures of the docs whose measurement is a study of its own (minutes to hours, a bare machine, root),",
              "with the data that holds them. `stale` counts the commits to the measured code since the data's.",
              "",
              "| claim | where | what it measures | data | data's commit, date | stale | to re-measure |",
              "|---|---|---|---|---|---:|---|"]
    for c in ledger["claim"]:
        if "measure" in c:
            continue
        data = c.get("data", "")
        commit = git("log", "-1", "--format=%h %ad", "--date=short", "--", data) if data else ""
        stale = ""
        if commit and c.get("code"):
            stale = str(len(git("log", "--oneline", f"{commit.split()[0]}..HEAD", "--", *c["code"]).splitlines()))
        lines.append(f"| {c['id']}: “{cell(c['text'])}” | {c['file']} | {cell(c['measures'])} | {data or 'none'} | "
                     f"{commit or '—'} | {stale or '—'} | {cell(c.get('rerun', ''))} |")
    lines += ["", "## Steps, as last run", "",
              "Each step's measures were taken at the commit and date shown (`--only STEP` re-runs one).", "",
              "| step | what | commit | date | load | seconds |", "|---|---|---|---|---:|---:|"]
    for name, fn in STEPS.items():
        st = last["steps"].get(name)
        if st:
            lines.append(f"| {name} | {fn.__doc__} | {st['commit']} | {st['date']} | {st.get('load', 0):.1f} | "
                         f"{st['seconds']:.0f} |")
        else:
            lines.append(f"| {name} | {fn.__doc__} | — | — | — | — |")
    lines += ["", "Raw outputs of the last run: `experiments/claims/raw/`.", ""]
    CLAIMS_MD.write_text("\n".join(lines))


# A figure: a number (a range, a thousands space, "~") then, within two words, a unit or a count.
# A figure: a number (a range, a thousands space, "~") and a unit right after it, or within four
# words a count's noun.
FIGURE = re.compile(r"(?<![\w.\-/])~?\d[\d  ,.]*(?:-\d[\d  ,.]*)?(?:\s?(?:%|×|x\b|K\b|°C|s\b|ms\b|µs|ns\b|"
                    r"min\b|MB\b|GB\b|/s)|(?:\s[A-Za-z\-']+){0,4}?\s(?:a second|evaluations|layouts|pairs|cases|"
                    r"seeds|maps|of (?:\d+|them)))")


def numbers_in(text):
    """The numbers a sentence shows: "43 020" is one, "110-220" two, "7.0e-14" one."""
    found = re.findall(r"\d{1,3}(?:[  ]\d{3})+(?![\d.])|\d+(?:\.\d+)?(?:e-?\d+)?", text)
    return [float(re.sub(r"[  ]", "", n)) for n in found]


def check(ledger, last, readme_path=ROOT / "README.md"):
    problems = []
    texts = {}
    for c in ledger["claim"]:
        path = readme_path if c["file"] == "README.md" else ROOT / c["file"]
        texts.setdefault(c["file"], normalised(path.read_text()))
        if normalised(c["text"]) not in texts[c["file"]]:
            problems.append(f"{c['id']}: not in {c['file']} as worded: “{c['text']}”")
        stated = c["stated"] if isinstance(c["stated"], list) else [c["stated"]]
        shown = numbers_in(c["text"])
        for figure in stated:
            if not any(math.isclose(figure, n, rel_tol=1e-9) for n in shown):
                problems.append(f"{c['id']}: its text does not show the stated {figure}")
        if "measure" in c:
            v = claim_value(c, last)
            if v is None:
                problems.append(f"{c['id']}: no measure {c['measure']} in {LAST.relative_to(ROOT)} (run scripts/claims.sh)")
            elif not holds(c, v):
                problems.append(f"{c['id']}: states {c['stated']}, the last run measured {fmt(v)} "
                                f"(noise {c.get('noise', 0)})")
    # Every figure in README.md lies inside a claim's words or an input the ledger names.
    readme = normalised(Path(readme_path).read_text())
    covered = [normalised(c["text"]) for c in ledger["claim"] if c["file"] == "README.md"]
    covered += [normalised(t) for t in ledger.get("inputs", {}).get("readme", [])]
    spans = []
    for t in covered:
        for m in re.finditer(re.escape(t), readme):
            spans.append((m.start(), m.end()))
    for m in FIGURE.finditer(readme):
        if not any(a <= m.start() and m.end() <= b for a, b in spans):
            around = readme[max(0, m.start() - 50):m.end() + 20]
            problems.append(f"README.md states “{m.group(0)}” outside the ledger: …{around}…")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("action", choices=["run", "render", "check"])
    ap.add_argument("--only", nargs="+", choices=list(STEPS), help="the steps to run (default: all)")
    ap.add_argument("--mtcs", default=str(ROOT / "build/mtcs"), help="the mtcs binary (mtcs-bench beside it)")
    ap.add_argument("--readme", default=str(ROOT / "README.md"), help="check this file as README.md (tests)")
    a = ap.parse_args()
    ledger, last = load_ledger(), load_last()
    if a.action == "check":
        problems = check(ledger, last, Path(a.readme))
        for p in problems:
            print("claims:", p, file=sys.stderr)
        print(f"claims: {len(ledger['claim'])} claims, {len(problems)} problems")
        return 1 if problems else 0
    if a.action == "run":
        mtcs = Path(a.mtcs).resolve()
        with tempfile.TemporaryDirectory(prefix="mtcs-claims-") as work:
            s = Step(mtcs, Path(work))
            for name in a.only or STEPS:
                print(f"claims: {name}: {STEPS[name].__doc__}", flush=True)
                t0 = time.perf_counter()
                m = STEPS[name](s)
                last["steps"][name] = {"measures": m, "seconds": time.perf_counter() - t0,
                                       "commit": head(), "load": os.getloadavg()[0],
                                       "date": datetime.date.today().isoformat()}
                LAST.write_text(json.dumps(last, indent=1, sort_keys=True) + "\n")
                print(f"claims: {name}: {time.perf_counter() - t0:.0f} s", flush=True)
        last["run"] = {"date": datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), "commit": head(),
                       "machine": f"{machine()}, load {os.getloadavg()[0]:.1f} at the end",
                       # every step's last time summed: a run of all steps, however it was split
                       "minutes": sum(st["seconds"] for st in last["steps"].values()) / 60,
                       "command": "bash scripts/claims.sh" + (" --only " + " ".join(a.only) if a.only else "")}
        LAST.write_text(json.dumps(last, indent=1, sort_keys=True) + "\n")
    render(ledger, last)
    problems = check(ledger, last)
    for p in problems:
        print("claims:", p, file=sys.stderr)
    return 1 if problems else 0  # a figure the run no longer supports: the words must change


if __name__ == "__main__":
    sys.exit(main())
