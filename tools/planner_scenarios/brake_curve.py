"""A full brake as curves: rides `cargo run --example brake_curve` for each bike and speed
and plots speed, deceleration and pitch against time, the bikes side by side, beside the
real figures they are measured against (docs/bike-model.md, "The front brake")."""

from __future__ import annotations

import argparse
import csv
import io
import subprocess
import sys
from pathlib import Path

PROJECT_ROOT = Path(__file__).resolve().parents[2]
G = 9.81
# Real figures (m/s² over g): what road-safety calculations assume for an ordinary rider
# on a dry road, and what tests of riders on ABS bikes reach.
REFERENCES = {"dry road, ordinary rider (7 m/s²)": 7.0 / G,
              "tests with ABS (10 m/s²)": 10.0 / G}
BIKES = {"street_350 (the thesis's reference)": "scenes/bike/bikes/street_350.tres",
         "street_390 (the game's)": "scenes/bike/bikes/street_390.tres"}


def ride(kmh: float, controller: str, bike: str) -> list[dict]:
    """One full brake from `kmh`: a dict of the example's columns per control step."""
    command = [str(PROJECT_ROOT / "tools" / "cargo"), "run", "--quiet", "--release",
               "--example", "brake_curve", "--", str(kmh), controller,
               "--bike", str(PROJECT_ROOT / bike)]
    output = subprocess.run(command, check=True, capture_output=True, text=True,
                            cwd=PROJECT_ROOT / "native").stdout
    rows = list(csv.DictReader(io.StringIO(output)))
    if len(rows) < 2:
        raise ValueError(f"brake_curve from {kmh} km/h on {bike} printed no curve")
    return rows


def summary(rows: list[dict]) -> dict:
    """Distance and time from the trigger, the mean deceleration v₀²/2d, the deepest
    pitch and how high the rear tyre rose."""
    # Row i is printed at (i + 1) control steps; its time is rounded to the millisecond.
    dt = float(rows[-1]["t"]) / len(rows)
    speeds = [float(r["speed_kmh"]) / 3.6 for r in rows]
    # Row i is printed after step i + 1 of the brake: the speed as the trigger was pulled
    # is the first row's plus that step's deceleration.
    start = speeds[0] + float(rows[0]["decel_g"]) * G * dt
    path = [start] + [max(v, 0.0) for v in speeds]
    distance = sum((a + b) / 2 * dt for a, b in zip(path, path[1:]))
    return {"from_kmh": start * 3.6, "time_s": float(rows[-1]["t"]), "distance_m": distance,
            "mean_g": start * start / (2 * distance) / G,
            "nose_down_deg": -min(float(r["pitch_deg"]) for r in rows),
            "rear_lift_mm": max(float(r["rear_lift_mm"]) for r in rows),
            "fell": any(r["fell"] == "true" for r in rows)}


def plot(curves: dict[tuple[str, float], list[dict]], path: Path, controller: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (speed_ax, decel_ax, pitch_ax) = plt.subplots(3, 1, figsize=(8, 9), dpi=110,
                                                       sharex=True)
    colours = dict(zip(BIKES, ("tab:gray", "tab:blue")))
    for (bike, kmh), rows in curves.items():
        t = [float(r["t"]) for r in rows]
        style = "-" if kmh == max(k for _, k in curves) else "--"
        label = f"{bike.split(' ')[0]} from {kmh:g} km/h ({summary(rows)['mean_g']:.2f} g)"
        for ax, column in ((speed_ax, "speed_kmh"), (decel_ax, "decel_g"),
                           (pitch_ax, "pitch_deg")):
            ax.plot(t, [float(r[column]) for r in rows], style, color=colours[bike],
                    label=label)
    for (name, g), style in zip(REFERENCES.items(), (":", "-.")):
        decel_ax.axhline(g, color="tab:red", linestyle=style, linewidth=1, label=name)
    speed_ax.set_ylabel("speed (km/h)")
    decel_ax.set_ylabel("deceleration (g)")
    pitch_ax.set_ylabel("pitch (°, nose up +)")
    pitch_ax.set_xlabel("time since the trigger (s)")
    speed_ax.legend(fontsize=8)
    decel_ax.legend(fontsize=7, loc="lower center", ncol=2)
    for ax in (speed_ax, decel_ax, pitch_ax):
        ax.grid(alpha=0.3)
    fig.suptitle(f"A full brake with ABS on dry flat ground ({controller})")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="tools/brake-curve", description=__doc__)
    parser.add_argument("--speeds", default="60,90", help="km/h, comma-separated")
    parser.add_argument("--controller", default="arcade")
    parser.add_argument("--out", default="docs/brakes", help="directory of the CSVs and plot")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    try:
        curves = {(bike, float(kmh)): ride(float(kmh), args.controller, file)
                  for bike, file in BIKES.items() for kmh in args.speeds.split(",")}
    except (ValueError, OSError, subprocess.CalledProcessError) as error:
        print(f"brake-curve: {error}", file=sys.stderr)
        return 2
    for (bike, kmh), rows in curves.items():
        name = Path(BIKES[bike]).stem
        with open(out / f"{name}-{kmh:g}kmh-{args.controller}.csv", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
            writer.writeheader()
            writer.writerows(rows)
        s = summary(rows)
        print(f"{name} from {s['from_kmh']:.1f} km/h: {s['distance_m']:.1f} m in "
              f"{s['time_s']:.2f} s, {s['mean_g']:.3f} g, nose down {s['nose_down_deg']:.1f}°, "
              f"rear up {s['rear_lift_mm']:.1f} mm at most{', FELL' if s['fell'] else ''}")
    plot(curves, out / f"brake-curve-{args.controller}.png", args.controller)
    return 0


if __name__ == "__main__":
    sys.exit(main())
