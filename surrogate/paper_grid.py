"""The paper's 27-network study (its Table 2), repeated over seeds, and the variant that fixes it.

Each of the 27 nets (1/2/3 layers x 25/50/100 neurons x ReLU/tanh/sigmoid) is trained as
MATLAB's Regression Learner trains ``fitrnet`` (see ``mkm.surrogate.paper_nets.paper_net``) on the
same 80/20 splits (one per seed); on each split: 5-fold cross-validated RMSE on the training
part (Regression Learner's "validation") and the RMSE of the refit on the held-out 20 %. The
variant ``standardised`` also standardises the response: with the force left in N, tanh and
sigmoid nets stall and predict about the mean, which is what the paper's tanh and sigmoid rows
show.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pandas as pd
from joblib import Parallel, delayed

from mkm.core.records import (
    provenance,
    recorded_path,
    save_figure,
    source_version,
    write_csv_with_sidecar,
)
from mkm.fem.paper import TABLE2_CSV
from mkm.surrogate.paper_nets import PAPER_NETS, paper_net
from mkm.surrogate.training_data import PAPER_DATASET, load_training_data
from mkm.surrogate.validation import split_scores

VARIANTS = {"paper": False, "standardised": True}  # name -> standardise the response


def _score(data_X, data_y, layers, size, activation, variant, seed):
    import warnings

    from sklearn.exceptions import ConvergenceWarning
    from threadpoolctl import threadpool_limits

    # One BLAS thread whatever the machine: loky gives each worker cores / jobs threads, and
    # a net's L-BFGS path (so its result) changes with the thread count's summation order.
    with warnings.catch_warnings(), threadpool_limits(limits=1):
        # fitrnet also stops at IterationLimit silently; n_iter records where each fit stopped.
        warnings.simplefilter("ignore", ConvergenceWarning)
        net = paper_net(layers, size, activation, VARIANTS[variant], random_state=seed)
        scores = split_scores(net, data_X, data_y, seed)
    return {"layers": layers, "size": size, "activation": activation, "variant": variant,
            **scores}


def run_paper_grid(dataset=PAPER_DATASET, seeds: int = 10, jobs: int = 2,
                   variants=tuple(VARIANTS), nets=None, progress: bool = False) -> pd.DataFrame:
    """One row per configuration, variant and seed (``seed`` = split = net initialisation).

    ``nets``: Table 2 numbers (1-27) to run; None runs all 27. The paper's protocol: 80/20
    splits by row of the paper-grid dataset (its 27 muscles at one length, angle and rubber).
    ``progress``: a bar on stderr (when it is a terminal).
    """
    nets = list(range(1, len(PAPER_NETS) + 1)) if nets is None else list(nets)
    bad = [n for n in nets if not 1 <= n <= len(PAPER_NETS)]
    if bad:
        raise ValueError(f"net number {bad[0]} is invalid: expected Table 2 numbers 1-27")
    configs = [PAPER_NETS[n - 1] for n in nets]
    unknown = sorted(set(variants) - set(VARIANTS))
    if unknown:
        raise ValueError(f"unknown variant(s) {', '.join(unknown)}: expected some of "
                         f"{', '.join(VARIANTS)}")
    if seeds < 1:
        raise ValueError(f"seeds={seeds} is invalid: expected at least 1 split")
    if jobs < 1:  # joblib's own words for 0 name no option ("n_jobs == 0 in Parallel ...")
        raise ValueError(f"jobs={jobs} is invalid: expected at least 1 parallel worker")
    data = load_training_data(dataset)
    tasks = [(cfg, variant, seed) for seed in range(seeds) for variant in variants
             for cfg in configs]
    # joblib's loky workers limit BLAS to one thread each, so two jobs use two cores cleanly.
    from tqdm import tqdm

    bar = tqdm(total=len(tasks), desc="27-net grid", unit="net", file=sys.stderr,
               disable=not (progress and sys.stderr.isatty()))
    with bar:
        rows = []
        for row in Parallel(n_jobs=jobs, return_as="generator")(
                delayed(_score)(data.X, data.y, *cfg, variant, seed)
                for cfg, variant, seed in tasks):
            rows.append(row)
            bar.update()
    return pd.DataFrame(rows)


def summarise_grid(runs: pd.DataFrame) -> pd.DataFrame:
    """Median and 10-90 % spread of the CV and held-out RMSE per configuration, beside Table 2."""
    paper = pd.read_csv(TABLE2_CSV, comment="#")
    keys = ["layers", "size", "activation"]
    stats = runs.groupby(["variant", *keys], sort=False).agg(
        rmse_cv_median_N=("rmse_cv_N", "median"),
        rmse_cv_p10_N=("rmse_cv_N", lambda v: v.quantile(0.1)),
        rmse_cv_p90_N=("rmse_cv_N", lambda v: v.quantile(0.9)),
        rmse_test_median_N=("rmse_test_N", "median"),
        rmse_test_p10_N=("rmse_test_N", lambda v: v.quantile(0.1)),
        rmse_test_p90_N=("rmse_test_N", lambda v: v.quantile(0.9)),
        rmse_train_median_N=("rmse_train_N", "median"),
        n_iter_median=("n_iter", "median"),
        fit_seconds_median=("fit_seconds", "median"),
        seeds=("seed", "nunique"),
    ).reset_index()
    table = stats.merge(paper, on=keys, how="left").rename(
        columns={"rmse_train_N": "paper_train_N", "rmse_valid_N": "paper_valid_N"})
    return table.sort_values(["variant", "number"], kind="stable").reset_index(drop=True)


def markdown_grid(table: pd.DataFrame) -> str:
    """Markdown table: ours (median [p10-p90]) beside the paper's two columns, per variant."""
    variants = list(dict.fromkeys(table["variant"]))
    head = "| # | layers | size | act | paper train | paper valid | " + " | ".join(
        f"{v}: CV RMSE | {v}: held-out RMSE" for v in variants) + " |"
    lines = [head, "|---" * (6 + 2 * len(variants)) + "|"]
    by_variant = {v: table[table["variant"] == v].set_index("number") for v in variants}
    first = by_variant[variants[0]]
    for number, row in first.iterrows():
        cells = [f"{number}", f"{row['layers']}", f"{row['size']}", row["activation"],
                 f"{row['paper_train_N']:.2f}", f"{row['paper_valid_N']:.2f}"]
        for v in variants:
            r = by_variant[v].loc[number]
            cells.append(f"{r['rmse_cv_median_N']:.1f} [{r['rmse_cv_p10_N']:.1f}-"
                         f"{r['rmse_cv_p90_N']:.1f}]")
            cells.append(f"{r['rmse_test_median_N']:.1f} [{r['rmse_test_p10_N']:.1f}-"
                         f"{r['rmse_test_p90_N']:.1f}]")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def plot_grid(table: pd.DataFrame, path) -> None:
    """Held-out RMSE per configuration (median and 10-90 % bar) per variant, paper's as dots."""
    import matplotlib.pyplot as plt  # the backend is the caller's (mkm.cli.main picks Agg headless)

    fig, ax = plt.subplots(figsize=(10, 4.2))
    offsets = {"paper": -0.15, "standardised": 0.15}
    for variant, group in table.groupby("variant", sort=False):
        x = group["number"] + offsets.get(variant, 0.0)
        med = group["rmse_test_median_N"]
        ax.errorbar(x, med, yerr=[med - group["rmse_test_p10_N"], group["rmse_test_p90_N"] - med],
                    fmt="o", ms=4, capsize=2,
                    label=f"ours, {variant} response: held-out RMSE (median, 10-90 %)")
    paper = table.drop_duplicates("number")
    ax.plot(paper["number"], paper["paper_valid_N"], "kx", label="paper, Table 2 validation")
    ax.set_yscale("log")
    ax.set_xticks(paper["number"])
    ax.set_xticklabels([f"{n}\n{a[:4]}" for n, a in zip(paper["number"], paper["activation"],
                                                         strict=True)], fontsize=6)
    ax.set_xlabel("network # (Table 2 order: 1-9 ReLU, 10-18 tanh, 19-27 sigmoid)")
    ax.set_ylabel("RMSE [N]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, path)
    plt.close(fig)


def paper_grid_study(out_dir, dataset=PAPER_DATASET, seeds: int = 10, jobs: int = 2,
                     variants=tuple(VARIANTS), nets=None, progress: bool = False) -> pd.DataFrame:
    """Run the grid and write ``paper_grid_runs.csv``, ``paper_grid.csv``, ``.md`` and ``.png``."""
    start = time.perf_counter()
    runs = run_paper_grid(dataset, seeds, jobs, variants, nets, progress)
    seconds = time.perf_counter() - start
    table = summarise_grid(runs)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    info = provenance()
    sha256 = load_training_data(dataset).sha256
    header = (f"<!-- dataset {recorded_path(dataset)} ({sha256[:12]}), seeds 0-{seeds - 1}, "
              f"jobs {jobs}, {seconds:.0f} s, {info['date_utc']}, {info['versions']} -->\n")
    # provenance beside each CSV: the dataset, the splits and nets, the code, the command
    record = {"dataset": recorded_path(dataset), "dataset_sha256": sha256,
              "seeds": list(range(seeds)), "jobs": jobs, "variants": list(variants),
              "nets": None if nets is None else list(nets), "seconds": seconds,
              "code_version": source_version("mkm.surrogate.paper_grid"), **info}
    for name, frame in (("paper_grid_runs.csv", runs), ("paper_grid.csv", table)):
        write_csv_with_sidecar(out_dir / name, frame.to_csv(index=False, float_format="%.6g",
                                                             lineterminator="\n"), record)
    (out_dir / "paper_grid.md").write_text(header + markdown_grid(table), encoding="utf-8")
    plot_grid(table, out_dir / "paper_grid.png")
    return table
