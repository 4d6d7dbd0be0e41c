"""Merge FE sweep CSVs (each with its sidecar) into one dataset whose sidecar names every source.

Usage: python -P tools/merge_fe_datasets.py OUT.csv WHAT BOX_SOURCE.csv SOURCE.csv [SOURCE ...]

``BOX_SOURCE``: the source whose sidecar box (and draw) the merged set claims. A source that
is itself a merge keeps its own sources (nested), so a set grown step by step names them all.
The solver's diagnostics columns are dropped (the shipped sets stay small); muscle ids are
offset so each source's muscles stay apart. Builds the shipped ``muscle-gp-range`` sets
(``surrogate/data/mkm_range_*.csv``; their sidecars record the command).
"""

import json
import sys
from pathlib import Path

import pandas as pd

from mkm.core.records import file_sha256, provenance

KEEP = ("muscle", "pressure_bar", "D0_mm", "t0_mm", "eps", "force_N", "converged", "valid",
        "model", "mesh", "theta0_deg", "L0_mm", "C10_MPa", "C01_MPa", "failure",
        "threshold_pressure_bar", "origin")


def seeds_of(parts) -> list:
    """The draw seeds of ``parts`` and of the sources they merged, in order, once each."""
    seeds = []
    for part in parts:
        for seed in (*seeds_of(part.get("sources", ())), part["seed"]):
            if seed not in seeds:
                seeds.append(seed)
    return seeds


def main() -> None:
    if len(sys.argv) < 5:
        sys.exit("usage: merge_fe_datasets.py OUT.csv WHAT BOX_SOURCE.csv SOURCE.csv [...]")
    out, what, box_source, *sources = sys.argv[1:]
    frames, parts, offset = [], [], 0
    for source in map(Path, sources):
        frame = pd.read_csv(source, comment="#")
        frame["muscle"] = frame["muscle"] + offset
        offset = int(frame["muscle"].max()) + 1
        frames.append(frame[[c for c in KEEP if c in frame.columns]])
        side = json.loads(source.with_suffix(".json").read_text(encoding="utf-8"))
        parts.append({"file": source.name, "sha256": file_sha256(source),
                      "command": side.get("command"), "seed": side.get("draw", {}).get("seed"),
                      "muscles": int(frame["muscle"].nunique()), "date_utc": side.get("date_utc"),
                      **({"adaptive": side["adaptive"]} if side.get("adaptive") else {}),
                      **({"sources": side["sources"]} if side.get("sources") else {})})
    merged = pd.concat(frames, ignore_index=True)
    merged.to_csv(out, index=False, float_format="%.10g")
    box = json.loads(Path(box_source).with_suffix(".json").read_text(encoding="utf-8"))
    meta = {**provenance(), "what": what, "box": box["box"], "draw": box.get("draw", {}),
            "pressure_bar": box.get("pressure_bar"), "model": "axisym", "mesh": "fine",
            "seeds": seeds_of(parts), "sources": parts}
    Path(out).with_suffix(".json").write_text(json.dumps(meta, indent=2), encoding="utf-8")
    print(f"{out}: {len(merged)} rows, {merged['muscle'].nunique()} muscles")


if __name__ == "__main__":
    main()
