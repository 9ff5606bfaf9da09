#!/usr/bin/env python3
"""Draws a benchmark's plots of error against cost from its plots.json.

Usage: plot_benchmark.py OUT_DIR/plots.json

The modules' benchmarks (clouds_bench, atmosphere_bench) write plots.json (one entry per plot:
file name, title, axis labels, and series of points with GPU milliseconds, PSNR in dB and a
label; a series is either a knob's sweep or the quality presets) and run this script, which
writes each plot as a PNG next to the JSON. Needs matplotlib (Debian: python3-matplotlib).
"""
import json
import pathlib
import sys

try:
    import matplotlib

    matplotlib.use("Agg")  # files only: no display needed
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FuncFormatter, LogLocator
except ImportError:
    sys.exit("plot_benchmark.py: matplotlib is missing (Debian: apt-get install python3-matplotlib)")

# Okabe-Ito: distinguishable with any colour vision. The presets take vermilion.
SWEEP_COLOURS = ["#0072B2", "#009E73", "#CC79A7", "#56B4E9", "#E69F00", "#282828", "#8C5A28"]
PRESET_COLOUR = "#D55E00"


def draw(plot, folder):
    figure, axes = plt.subplots(figsize=(10, 6.2), dpi=110)
    sweeps = [s for s in plot["series"] if not s["presets"]]
    for index, series in enumerate(sweeps):
        points = series["points"]
        colour = SWEEP_COLOURS[index % len(SWEEP_COLOURS)]
        # Past the palette, the colours come round again with dotted lines and diamonds.
        style = "-o" if index < len(SWEEP_COLOURS) else ":D"
        axes.plot([p["gpu_ms"] for p in points], [p["psnr_db"] for p in points], style,
                  color=colour, markersize=4, linewidth=1.2, label=series["name"])
        for p in points:
            if p["label"]:
                axes.annotate(p["label"], (p["gpu_ms"], p["psnr_db"]), textcoords="offset points",
                              xytext=(4, 3), fontsize=7, color=colour)
    for series in (s for s in plot["series"] if s["presets"]):
        points = series["points"]
        axes.plot([p["gpu_ms"] for p in points], [p["psnr_db"] for p in points], "s--",
                  color=PRESET_COLOUR, markersize=7, linewidth=1.6, label=series["name"], zorder=3)
        for p in points:
            axes.annotate(p["label"], (p["gpu_ms"], p["psnr_db"]), textcoords="offset points",
                          xytext=(6, -12), fontsize=9, fontweight="bold", color=PRESET_COLOUR)
    axes.set_xscale("log")
    # Plain milliseconds on the log axis: 1, 2, 5, 10, 20, 50...
    axes.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    axes.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axes.xaxis.set_minor_formatter(FuncFormatter(lambda value, _: ""))
    axes.set_title(plot["title"])
    axes.set_xlabel(plot["x_label"])
    axes.set_ylabel(plot["y_label"])
    axes.grid(True, which="both", linewidth=0.4, alpha=0.5)
    axes.legend(loc="lower right", fontsize=8)
    figure.tight_layout()
    path = folder / plot["file"]
    figure.savefig(path)
    plt.close(figure)
    print(f"plot_benchmark.py: wrote {path}")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    data_file = pathlib.Path(sys.argv[1])
    try:
        data = json.loads(data_file.read_text())
        plots = data["plots"]
    except (OSError, ValueError, KeyError) as error:
        sys.exit(f"plot_benchmark.py: cannot read {data_file}: {error}")
    for plot in plots:
        draw(plot, data_file.parent)


if __name__ == "__main__":
    main()
