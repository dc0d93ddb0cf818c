"""Figures of the four footprint examples (curling stone, box, sled, robot part).

Runs each case file of ``examples/`` with :func:`slidespin.simulate` (recording a point every
0.05 of regularised time, as ``slidespin simulate --plot`` does) and writes one four-panel
figure per case, with the footprint's outline drawn along the path::

    python examples/footprint_figures.py [OUTPUT_DIR]      # default: slidespin-out/

Prints one line per case: stop time, distance, turns and ending.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import slidespin as ss

HERE = Path(__file__).resolve().parent
CASES = ("curling_stone", "box", "sled", "robot_part")


def main(out_dir: str = "slidespin-out") -> None:
    import matplotlib

    matplotlib.use("Agg")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    for name in CASES:
        case = ss.load_case(HERE / f"{name}.toml")
        tr = ss.simulate(
            case.body,
            case.friction,
            case.initial_state,
            g=case.g,
            rtol=case.rtol,
            max_steps=case.max_steps,
            max_step=0.05,
        )
        turns = (tr.stop_state.phi - case.initial_state.phi) / (2.0 * math.pi)
        print(
            f"{name:14s} t_stop = {tr.t_stop:.6g} s, distance = {tr.distance:.6g} m, "
            f"turns = {turns:.4g}, ending = {tr.ending}"
        )
        fig = ss.plot_trajectory(tr, title=case.name)
        fig.savefig(out / f"{name}.png", dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:2])
