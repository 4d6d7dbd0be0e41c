"""What ``mkm design`` says of a measured muscle's own uncertainty: the Festo DMSP-20-300's
published map imported, identified with the FE model and designed for, by the commands the
design guide shows (:data:`COMMANDS`), as a user types them.

    .venv/bin/python benchmarks/bench_design_identified.py --out FILE

Each command runs as a new process (the ``mkm`` script of this environment) in an empty
folder, its caches and state in folders of their own, empty at the start. Records the commands,
identify's verdict and design's line on the chosen design's forces within the identified
muscle's 95 % band (what the guide quotes under "A muscle identified by mkm identify"), with
each command's wall time. The FE identification takes minutes (half an hour on a loaded
2-core machine).
"""

from __future__ import annotations

import argparse
import json
import os
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from mkm.core.home import CACHE_ENV, STATE_ENV
from mkm.core.records import provenance

#: the guide's commands, as it shows them
COMMANDS = [
    "mkm data copy martens_boblan_2017_forcemaps.csv",
    "mkm import martens_boblan_2017_forcemaps.csv --muscle \"Festo DMSP-20-300\" --id dmsp-20 "
    "--D0 20 --t0 1.8 --accuracy force=1N+1%,pressure=0.01bar",
    "mkm identify \"mkm-out/runs/*dmsp-20-eps0-*\" \"mkm-out/runs/*dmsp-20-eps0.0473-*\" "
    "--params theta0,rubber,L0 --model axisym --search model --out id20-axisym",
    "mkm design --calibration id20-axisym/calibration.json --require 300N@5bar,eps=0.1 "
    "--require 100N@5bar,eps=0.2",
]
#: how design's line on the identified muscle's uncertainty starts
BAND_LINE = ("mkm design: the chosen design's forces with the identified muscle's own "
             "uncertainty")


def run(command: str, cwd: Path) -> tuple[str, str, float]:
    """``command`` (an ``mkm`` line) as a new process in ``cwd``; its stdout, stderr and wall
    time [s]."""
    script = Path(sys.executable).parent / ("mkm.exe" if os.name == "nt" else "mkm")
    argv = [str(script), *shlex.split(command)[1:]]
    start = time.perf_counter()
    done = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, env={
        **os.environ, CACHE_ENV: str(cwd / ".cache"), STATE_ENV: str(cwd / ".state")})
    seconds = time.perf_counter() - start
    # design exits 1 where no verified design meets every requirement: still its line
    if done.returncode not in (0, 1):
        raise SystemExit(f"{command} failed ({done.returncode}): {done.stderr.strip()}")
    return done.stdout, done.stderr, seconds


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="the JSON record")
    args = parser.parse_args(argv)
    outputs = []
    with tempfile.TemporaryDirectory() as work:
        for command in COMMANDS:
            stdout, stderr, seconds = run(command, Path(work))
            outputs.append({"command": command, "seconds": round(seconds, 1),
                            "stdout": stdout.splitlines(), "stderr": stderr.splitlines()})
    identified, designed = outputs[2], outputs[3]
    record = {**provenance(), "load_average_after": os.getloadavg()
              if hasattr(os, "getloadavg") else None,
              "commands": COMMANDS,
              "verdict": next(line for line in identified["stdout"]
                              if line.startswith("verdict:")),
              "band_line": next(line for line in designed["stderr"] + designed["stdout"]
                                if line.startswith(BAND_LINE)),
              "outputs": outputs}
    Path(args.out).write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
    print(record["verdict"])
    print(record["band_line"])
    return record


if __name__ == "__main__":
    main()
