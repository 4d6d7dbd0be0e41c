"""The device-loss revive on a real NI USB-6001: how long DAQmx Reset Device, fresh tasks and
the 0 V write take, and how long after a USB cable is plugged back the bench is vented again.
Needs the hardware: refuses (exit 2) without NI-DAQmx, without the device, or on a device that
NI MAX simulates.

    python benchmarks/bench_ni_reset.py --device Dev1 [--config my_bench.toml] [--repeats 20]
        [--unplug 3] [--json reset.json]

It writes 0 V only (the vent command): nothing is pressurised, so the muscle may stay mounted,
but the supply to the regulator should be closed. Two parts:

1. ``--repeats`` times on the live device: :meth:`mkm.bench.ni.NIBackend.revive` (reset, fresh
   AI and AO tasks, 0 V, AI started), and DAQmx Reset Device alone; median and maximum [s].
   :data:`mkm.bench.ni.REVIVE_WITHIN_S` (3 s) and :data:`~mkm.bench.ni.REVIVE_EVERY_S` (0.5 s)
   assume a revive takes well under 0.5 s;
2. ``--unplug N`` times, with the operator: the script reads the device until the cable is
   pulled (the read error is recorded, e.g. NI-DAQmx -50405), then waits for it to be plugged
   back, and times from the device being listed again by the driver
   (``nidaqmx.system.System.local().devices``) to the first revive that succeeds (retried every
   0.1 s for up to 30 s): what a run or `mkm vent` waits after a glitch.

Prints a Markdown table; ``--json`` writes every time with the provenance and the device's
serial number.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time

RETRY_S, GIVE_UP_S = 0.1, 30.0  # the unplug part: revive attempts after the device is back


def refuse(message: str) -> int:
    print(f"bench_ni_reset: error: {message}", file=sys.stderr)
    return 2


def hardware(device: str) -> str | None:
    """Why ``device`` is not a real USB-6001 this script can use, or None."""
    try:
        import nidaqmx.system
        from nidaqmx.errors import DaqError, DaqNotFoundError, DaqNotSupportedError
    except ImportError:
        return "nidaqmx is not installed (pip install nidaqmx, then NI-DAQmx on Windows)"
    try:
        names = [d.name for d in nidaqmx.system.System.local().devices]
        if device not in names:
            return (f"device {device!r} is not connected (NI-DAQmx lists "
                    f"{', '.join(names) or 'no device'})")
        dev = nidaqmx.system.Device(device)
        if dev.is_simulated:
            return f"device {device!r} is simulated in NI MAX: its timing says nothing"
        if dev.product_type != "USB-6001":
            return f"device {device!r} is a {dev.product_type}, not a USB-6001"
    except (DaqNotFoundError, DaqNotSupportedError):
        return ("the NI-DAQmx driver is not installed here (NI supports the USB-6001 on "
                "Windows): this measurement needs the bench PC")
    except DaqError as exc:
        return f"NI-DAQmx error {exc.error_code} asking for {device!r}"
    return None


def listed(device: str) -> bool:
    import nidaqmx.system

    try:
        return device in [d.name for d in nidaqmx.system.System.local().devices]
    except Exception:  # the driver's list may fail while the device re-enumerates
        return False


def timed(fn) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def live_revives(backend, repeats: int) -> dict:
    revive = [timed(lambda: backend.revive(within_s=0.0)) for _ in range(repeats)]
    reset = [timed(backend._reset_device) for _ in range(repeats)]
    backend.revive(within_s=0.0)  # fresh tasks after the bare resets
    return {"revive_s": revive, "reset_s": reset}


def unplugged(backend, device: str, rate_hz: float) -> dict:
    """One pull and plug-back of the USB cable, guided on the terminal."""
    from mkm.bench.backend import BenchError, ReadTimeout

    print(f"PULL the USB cable of {device} now.", file=sys.stderr, flush=True)
    while True:
        try:
            backend.read(1, timeout_s=2.0 / rate_hz + 1.0)
        except ReadTimeout:
            continue
        except BenchError as exc:
            error = f"{type(exc).__name__}: {exc}"
            break
    lost_at = time.perf_counter()
    print(f"lost ({error}). PLUG IT BACK now.", file=sys.stderr, flush=True)
    while not listed(device):
        time.sleep(0.02)
    back_at = time.perf_counter()
    attempts = 0
    while True:
        attempts += 1
        try:
            backend.revive(within_s=0.0)
            break
        except BenchError as exc:
            if time.perf_counter() - back_at > GIVE_UP_S:
                return {"error": error, "listed_after_s": back_at - lost_at,
                        "vented_after_listed_s": None, "attempts": attempts,
                        "last_failure": f"{type(exc).__name__}: {exc}"}
            time.sleep(RETRY_S)
    return {"error": error, "listed_after_s": back_at - lost_at,
            "vented_after_listed_s": time.perf_counter() - back_at, "attempts": attempts}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--device", required=True, help="the USB-6001's name in NI MAX")
    parser.add_argument("--config", help="the bench configuration (default: the packaged one "
                        "with [daq] backend = ni)")
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--unplug", type=int, default=0, help="cable pulls to time (default 0)")
    parser.add_argument("--json", help="write every time and the provenance here")
    args = parser.parse_args(argv)
    if not 1 <= args.repeats <= 1000 or not 0 <= args.unplug <= 20:
        return refuse(f"--repeats {args.repeats} / --unplug {args.unplug}: expected 1-1000 "
                      "and 0-20")
    why = hardware(args.device)
    if why:
        return refuse(f"{why}; BLOCKED: no measurement without the hardware")

    from mkm.bench.config import load_config
    from mkm.bench.ni import REVIVE_EVERY_S, REVIVE_WITHIN_S, NIBackend
    from mkm.core.records import provenance, write_atomic

    config = load_config(args.config, backend="ni").replace(daq={"device": args.device})
    backend = NIBackend(config)
    info = backend.open()  # writes 0 V
    try:
        backend.start()
        live = live_revives(backend, args.repeats)
        pulls = [unplugged(backend, args.device, config.daq.sample_rate_hz)
                 for _ in range(args.unplug)]
    finally:
        backend.close()  # 0 V again
    rows = [{"what": "revive (reset, fresh tasks, 0 V)", "n": args.repeats,
             "median [s]": statistics.median(live["revive_s"]), "max [s]": max(live["revive_s"])},
            {"what": "DAQmx Reset Device alone", "n": args.repeats,
             "median [s]": statistics.median(live["reset_s"]), "max [s]": max(live["reset_s"])}]
    vented = [p["vented_after_listed_s"] for p in pulls if p["vented_after_listed_s"] is not None]
    if pulls:
        rows.append({"what": "cable back (listed) to vented", "n": len(pulls),
                     "median [s]": statistics.median(vented) if vented else None,
                     "max [s]": max(vented) if vented else None})
    print("| what | n | median [s] | max [s] |\n|---|---|---|---|")
    for r in rows:
        shown = [f"{r[k]:.3f}" if isinstance(r[k], float) else str(r[k])
                 for k in ("median [s]", "max [s]")]
        print(f"| {r['what']} | {r['n']} | {shown[0]} | {shown[1]} |")
    print(f"\n{info.product_type} serial {info.serial_number}; the code retries every "
          f"{REVIVE_EVERY_S:g} s for at most {REVIVE_WITHIN_S:g} s")
    if args.json:
        record = {**provenance(), "device": info.as_dict(), "rows": rows, "live": live,
                  "unplugged": pulls, "revive_every_s": REVIVE_EVERY_S,
                  "revive_within_s": REVIVE_WITHIN_S}
        write_atomic(args.json, json.dumps(record, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
