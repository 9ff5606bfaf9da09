#!/usr/bin/env python3
"""What each effect of the sample's default scene costs, through the real frame graph.

For each effect (terrain, clouds, atmosphere, cloud shadows, terrain shadows, god rays, the
clouds' sky light that lights the ambient and the exposure meter, the terrain's close-up
detail) the default scene is
rendered with everything and without that effect, headless at 640x360 and Medium, runs
interleaved round by round so that drift of the machine's speed spreads over all of them. Reported per effect: the frame's GPU time with and without (sums of the per-pass
GPU-timestamp medians the sample prints), the effect's cost as the median of the paired
differences, and what the scene without it lacks exactly: frame-graph passes, pipelines (as
--describe lists them) and GPU memory (as the sample reports it at exit).

Weather is measured the same way: the storm front's regions against the same scene without
them, and a change of weather against the same weather held steady at the change's midpoint.

The HUD and the settings panel are measured the same way (OUT_DIR/hud.md): the tonemap pass
they are drawn in, with and without them.

Usage: tools/effects_bench.py [--rounds N] [--frames N] [--hud-only] OUT_DIR   (writes
       OUT_DIR/results.md and OUT_DIR/hud.md; the project's: tools/effects_bench.py
       docs/effects, about fifteen minutes)
"""
import argparse
import copy
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLE = os.path.join(ROOT, "build", "bin", "sample_game")
BASE_SCENE = os.path.join(ROOT, "assets_src", "scenes", "default.json")


def without(key, field=None, value=None):
    """A scene edit: drop `key`, or set `key.field` to `value`."""
    def edit(scene):
        if field is None:
            scene.pop(key, None)
        else:
            scene.setdefault(key, {})[field] = value
    return edit


EFFECTS = [
    ("terrain", without("terrain")),
    ("clouds", without("clouds")),
    ("atmosphere", without("atmosphere")),
    ("cloud shadows", without("clouds", "shadows", False)),
    ("terrain shadows", without("terrain", "castsShadows", False)),
    ("god rays", without("clouds", "godRays", False)),
    ("cloud sky light", without("clouds", "skyLight", False)),
    ("terrain close-up detail", without("terrain", "closeDetail", False)),
]
# The default scene's opening flight looks away from the sun, where god rays cost only a clear:
# also measured looking into the sun through broken cumulus (the sample's god-ray test scene).
SUN_SCENE = os.path.join(ROOT, "tests", "sample_game", "scenes", "god_rays_sunset.json")
SUN_EFFECT = "god rays, sun in view"
# Lightning, in the thunderstorm scene at its own strike rate, and with a flash always active
# (a storm whose strikes a script asks for every 8 frames).
STORM_SCENE = os.path.join(ROOT, "assets_src", "scenes", "thunderstorm.json")
CALM_STORM_SCENE = os.path.join(ROOT, "tests", "sample_game", "scenes", "storm_calm.json")
STRIKES_SCRIPT = os.path.join(ROOT, "tests", "sample_game", "scripts",
                              "strikes_every_8_frames.json")
STORM_EFFECT = "lightning"
FLASH_EFFECT = "lightning, a flash always active"
# The same with ground discharges: each flash with its bolt.
GROUND_STRIKES_SCRIPT = os.path.join(ROOT, "tests", "sample_game", "scripts",
                                     "ground_strikes_every_8_frames.json")
BOLT_EFFECT = "lightning, a ground strike and its bolt always active"
# Weather regions: the storm front (one region over the range, its own schedule) against the
# same scene without its regions, both without lightning (the region's storm would strike, the
# plains' fair weather would not: the row would measure the flashes too).
FRONT_SCENE = os.path.join(ROOT, "assets_src", "scenes", "storm_front.json")
REGIONS_EFFECT = "weather regions (the storm front)"
# A change of weather against the same weather held: the default scene changing from FAIR to
# TOWERING over CHANGE_SECONDS, measured over the frames from CHANGE_START_SECONDS on (the middle
# of the change), against the state halfway held (the look of the change's middle frame). The
# two states blow with the same wind, so the clouds drift to the same places in both runs and
# only the look differs: what a change can cost more is the module's work to follow it (the
# history's tolerance, the shadow map's remakes, the led look), not other clouds.
FAIR = {"coverage": 0.5, "cloudType": 0.6, "densityMultiplier": 1.0, "anvilBias": 0.0,
        "detailErosion": 0.45}
TOWERING = {"coverage": 0.75, "cloudType": 0.9, "densityMultiplier": 1.5, "anvilBias": 0.5,
            "detailErosion": 0.3}
CHANGE_SECONDS = 20.0
CHANGE_START_SECONDS = 8.0  # 120 frames at 30 fps: 8 to 12 s, eased from 35% to 65% of it
CHANGE_EFFECT = "a change of weather (its middle, against that weather held)"
# Water: the lake scene (the default scene's cumulus over a lake in the foothills, most of the
# view water) against the same view without it (its bed, the terrain, in its place).
LAKE_SCENE = os.path.join(ROOT, "assets_src", "scenes", "lake.json")
WATER_EFFECT = "water (the lake scene)"
# Extra comparisons: (effect, the scene with it, its script, the scene without it).
EXTRA = [(SUN_EFFECT, "sun in view"), (STORM_EFFECT, "storm"), (FLASH_EFFECT, "flashing"),
         (BOLT_EFFECT, "bolting"), (REGIONS_EFFECT, "storm front"),
         (CHANGE_EFFECT, "weather changing"), (WATER_EFFECT, "lake")]
# Lightning's budget (1 ms a frame while flashes are active) is smaller than the frame sum's
# noise (other passes swing by more between runs: the cloud shadows' is bimodal), so its cost is
# also summed over the passes it changes only: the frame graph's scene pass (the terrain's
# lightning variant: per-pass medians) and the clouds module's passes it adds or specializes
# (means per frame: a pass that runs in some frames costs its share of each). The passes it does
# not change do the same work in both scenes.
# The scenes with the effects, as the list of scenes names them.
WITH_SCENES = {
    "everything": "the default scene, everything",
    "sun in view": "the god-ray scene (sun in view), everything",
    "storm": "the thunderstorm scene, everything",
    "flashing": "the calm storm, a strike every 8 frames",
    "bolting": "the calm storm, a ground strike every 8 frames",
    "storm front": "the storm front without lightning, everything",
    "weather changing": "the default scene as its weather changes",
    CHANGE_EFFECT: "the default scene, the change's midpoint held",
    "lake": "the lake scene, everything",
}
LIGHTNING_EFFECTS = [STORM_EFFECT, FLASH_EFFECT, BOLT_EFFECT]
# Weather's cost in the passes it may change: the cloud shadow map's cascades and the march.
WEATHER_EFFECTS = [REGIONS_EFFECT, CHANGE_EFFECT]
# (The march is one of the module's passes inside the frame's "clouds": shown, not summed.)
WEATHER_PASSES = ["frame: cloud shadows", "frame: clouds", "clouds: march"]
WEATHER_FRAME_PASSES = ["frame: cloud shadows", "frame: clouds"]
LIGHTNING_PASSES = ["frame: scene", "clouds: lightning", "clouds: reconstruct",
                    "clouds: upsample", "clouds: lightning bolts"]


def pipeline_items(pipelines):
    """A pipeline list as items: "clouds module (shadow map, god rays)" gives the module and
    "clouds module: shadow map", "clouds module: god rays"."""
    items = []
    for entry in pipelines:
        match = re.fullmatch(r"(.*) \((.*)\)", entry)
        if match and match.group(1).endswith(" module"):
            items.append(match.group(1))
            items += [f"{match.group(1)}: {e}" for e in match.group(2).split(", ")]
        else:
            items.append(entry)
    return items


# Set from the command line: the sample and the frames' size.
OPTIONS = {"sample": SAMPLE, "width": 640, "height": 360}


SCRIPTS = {}  # scene path -> the script it runs with
RUN_ARGS = {}  # scene path -> the sample's options it runs with (its clock)


def run(scene_path, frames, extra=()):
    script = ("--script", SCRIPTS[scene_path]) if scene_path in SCRIPTS else ()
    clock = RUN_ARGS.get(scene_path, ())
    command = [OPTIONS["sample"], "--headless", "--width", str(OPTIONS["width"]), "--height",
               str(OPTIONS["height"]), "--quality", "medium", "--frames", str(frames), "--scene",
               scene_path, *script, *clock, *extra]
    env = dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "2"))
    result = subprocess.run(command, capture_output=True, text=True, env=env, check=False)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{result.stdout}\n{result.stderr}")
    return result.stdout + result.stderr


def timing_list(text):
    """"a 1.00 ms, b c 2.00 ms" as {"a": 1.0, "b c": 2.0}."""
    return {name.strip(): float(ms) for name, ms in re.findall(r"([a-z +]+) ([\d.]+) ms", text)}


def measure(scene_path, frames, extra=()):
    """The frame's GPU time (ms), GPU memory (MiB), memory by owner, and each pass's time:
    "frame: NAME" the frame graph's per-pass medians, "clouds: NAME" the module's means."""
    out = run(scene_path, frames, extra)
    total = re.search(r"GPU time per pass, median of the measured frames: (.*) \(sum ([\d.]+) ms\)",
                      out)
    memory = re.search(r"GPU memory: (.*) \(total ([\d.]+) MiB\)", out)
    if not total or not memory:
        sys.exit(f"no timings or memory in the output of {scene_path}:\n{out}")
    parts = {name.strip(): float(mib) for name, mib in
             re.findall(r"([a-z ]+) ([\d.]+) MiB", memory.group(1))}
    passes = {f"frame: {k}": v for k, v in timing_list(total.group(1)).items()}
    clouds = re.search(r"clouds passes, mean per measured frame: (.*)", out)
    if clouds:
        passes.update({f"clouds: {k}": v for k, v in timing_list(clouds.group(1)).items()})
    return float(total.group(2)), float(memory.group(2)), parts, passes


# The HUD and the settings panel: the default scene without a HUD, with its one line, with the
# panel open (F2), and with the panel's opaque backgrounds drawn as triangles instead of cleared.
# They are drawn in the tonemap pass (after its draw): their cost is that pass's time less its
# time without them, paired run by run.
HUD_VARIANTS = [
    ("no HUD", ()),
    ("the HUD's line", ("--hud-headless",)),
    ("the settings panel open", ("--hud-headless", "--script", "{panel}")),
    ("the settings panel open, backgrounds as triangles",
     ("--hud-headless", "--script", "{panel}", "--hud-as-triangles")),
]


def final_pass(passes):
    """The tonemap pass's time, with or without the HUD in it."""
    return next(v for k, v in passes.items() if k.startswith("frame: tonemap"))


def measure_hud(rounds, frames, scratch):
    """Rows of the HUD's table: (variant, its final pass's time, the paired differences against
    no HUD), each measured `rounds` times, interleaved."""
    panel = os.path.join(scratch, "open_the_panel.json")
    with open(panel, "w") as f:
        json.dump({"events": [{"frame": 1, "press": ["F2"]}, {"frame": 2, "release": ["F2"]}]}, f)
    times = {name: [] for name, _ in HUD_VARIANTS}
    for round_index in range(rounds):
        shift = round_index % len(HUD_VARIANTS)
        for name, extra in HUD_VARIANTS[shift:] + HUD_VARIANTS[:shift]:
            _, _, _, passes = measure(BASE_SCENE, frames,
                                      tuple(a.format(panel=panel) for a in extra))
            times[name].append(final_pass(passes))
            print(f"round {round_index + 1}, {name}: tonemap pass {times[name][-1]:.2f} ms",
                  flush=True)
    base = times[HUD_VARIANTS[0][0]]
    return [(name, times[name], [a - b for a, b in zip(times[name], base)])
            for name, _ in HUD_VARIANTS[1:]]


def hud_lines(rows, rounds, frames, width, height):
    lines = [
        "# What the HUD and the settings panel cost",
        "",
        f"Generated by `tools/effects_bench.py` ({rounds} rounds of {frames} frames, headless, "
        f"{width}x{height}, the default scene at Medium, `LP_NUM_THREADS=2`, interleaved). The "
        "HUD is recorded into the tonemap pass after its draw; its cost is that pass's GPU "
        "time (the median over the frames of a run) less the same pass's time in a run without "
        "a HUD: the median of the paired differences, the range in brackets. Budget: 0.5 ms "
        "with the panel open, nothing without a HUD (no pass, no pipeline).",
        "",
        "| what is shown | tonemap pass (ms) | cost (ms) |",
        "|---|---|---|",
    ]
    for name, times, diffs in rows:
        lines.append(f"| {name} | {statistics.median(times):.2f} | "
                     f"{statistics.median(diffs):+.2f} ({min(diffs):+.2f} to {max(diffs):+.2f}) |")
    return lines


def calm_front(scene):
    """The storm front without lightning: its stormy state strikes nothing, and no storm."""
    scene.pop("lightning", None)
    weather = scene["weather"]
    weather.setdefault("states", {})["calm storm"] = {"like": "stormy",
                                                      "lightningStrikesPerMinute": 0}
    for region in weather.get("regions", []):
        for key in region.get("schedule", []):
            if key["state"] == "stormy":
                key["state"] = "calm storm"


def without_regions(scene):
    calm_front(scene)
    scene["weather"].pop("regions")


def changing_weather(scene):
    """The default scene changing from FAIR to TOWERING (a scene edit)."""
    scene["weather"] = {
        "states": {"fair": FAIR, "towering": TOWERING},
        "schedule": [{"state": "fair", "holdSeconds": 0, "transitionSeconds": CHANGE_SECONDS},
                     {"state": "towering", "holdSeconds": 1e6, "transitionSeconds": 0}],
        "repeat": False}


def midway_weather(scene):
    """The default scene holding the state halfway from FAIR to TOWERING (every field is
    blended linearly; the schedule eases, so its middle is at half the change's time)."""
    midway = {k: (FAIR[k] + TOWERING[k]) / 2 for k in FAIR}
    scene["weather"] = {"states": {"midway": midway},
                        "schedule": [{"state": "midway", "holdSeconds": 1e6,
                                      "transitionSeconds": 0}],
                        "repeat": False}


def describe(scene_path):
    out = run(scene_path, 1, ("--describe",))
    line = next(l for l in out.splitlines() if l.startswith("{"))
    return json.loads(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--sample", default=SAMPLE, help="the sample_game executable")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--hud-only", action="store_true",
                        help="measure the HUD and the panel only (OUT_DIR/hud.md)")
    args = parser.parse_args()
    OPTIONS.update(sample=args.sample, width=args.width, height=args.height)
    os.makedirs(args.out_dir, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        rows = measure_hud(args.rounds, args.frames, scratch)
    with open(os.path.join(args.out_dir, "hud.md"), "w") as f:
        f.write("\n".join(hud_lines(rows, args.rounds, args.frames, args.width, args.height))
                + "\n")
    print(f"wrote {os.path.join(args.out_dir, 'hud.md')}")
    if args.hud_only:
        return
    with open(BASE_SCENE) as f:
        base = json.load(f)
    os.makedirs(args.out_dir, exist_ok=True)
    with tempfile.TemporaryDirectory() as scenes:
        paths = {}
        def load(path):
            with open(path) as f:
                return json.load(f)
        sun, storm, calm = load(SUN_SCENE), load(STORM_SCENE), load(CALM_STORM_SCENE)
        front, lake = load(FRONT_SCENE), load(LAKE_SCENE)
        variants = [("everything", base, lambda s: None)]
        variants += [(name, base, edit) for name, edit in EFFECTS]
        variants += [("sun in view", sun, lambda s: None),
                     (SUN_EFFECT, sun, without("clouds", "godRays", False)),
                     ("storm", storm, lambda s: None),
                     (STORM_EFFECT, storm, without("lightning")),
                     ("flashing", calm, lambda s: None),
                     (FLASH_EFFECT, calm, without("lightning")),
                     ("bolting", calm, lambda s: None),
                     (BOLT_EFFECT, calm, without("lightning")),
                     ("storm front", front, calm_front),
                     (REGIONS_EFFECT, front, without_regions),
                     ("weather changing", base, changing_weather),
                     (CHANGE_EFFECT, base, midway_weather),
                     ("lake", lake, lambda s: None),
                     (WATER_EFFECT, lake, without("water"))]
        for name, source, edit in variants:
            scene = copy.deepcopy(source)
            edit(scene)
            paths[name] = os.path.join(scenes, re.sub(r"[^a-z]+", "_", name) + ".json")
            with open(paths[name], "w") as f:
                json.dump(scene, f)
        SCRIPTS[paths["flashing"]] = STRIKES_SCRIPT
        SCRIPTS[paths["bolting"]] = GROUND_STRIKES_SCRIPT
        # The weather's clock at a 30 fps game's pace (headless runs otherwise step by the
        # wall clock, 0.1 to 0.25 s a frame here), from the change's middle on.
        for name in ("weather changing", CHANGE_EFFECT):
            RUN_ARGS[paths[name]] = ("--fixed-dt", str(1 / 30), "--start-time",
                                     str(CHANGE_START_SECONDS))
        described = {name: describe(path) for name, path in paths.items()}
        times = {name: [] for name in paths}
        pass_times = {name: [] for name in paths}
        memory = {}
        names = list(paths)
        # One run first, not counted: the first of a series runs slow on this machine.
        measure(paths["everything"], args.frames)
        for round_index in range(args.rounds):
            # Each round starts with another scene: none is always first after a pause.
            order = names[round_index % len(names):] + names[:round_index % len(names)]
            for name in order:
                path = paths[name]
                ms, mib, parts, passes = measure(path, args.frames)
                times[name].append(ms)
                pass_times[name].append(passes)
                memory[name] = (mib, parts)
                print(f"round {round_index + 1}, {name}: {ms:.2f} ms, {mib:.2f} MiB", flush=True)

    lines = [
        "# What each effect costs",
        "",
        f"Generated by `tools/effects_bench.py` ({args.rounds} rounds of {args.frames} frames, "
        f"headless, {args.width}x{args.height}, Medium, `LP_NUM_THREADS=2`, on this project's "
        "machine; one uncounted run first). Each round "
        "renders the default scene with every effect and once without each, the scenes "
        "below with and without god rays, lightning, weather regions or water, and a change of "
        "weather and its midpoint held, interleaved. GPU "
        "time is the frame's: the sum of the per-pass GPU-timestamp medians the sample prints; "
        "the cost is the median of the paired differences (the range in brackets). What the "
        "scene without the effect lacks is exact: its frame-graph passes, pipelines (as "
        "`--describe` lists them) and GPU memory (as the sample reports it: the renderer's own "
        "and each module's).",
        "",
        "| effect | with (ms) | without (ms) | cost (ms) | passes it adds | pipelines it adds | "
        "GPU memory it adds (MiB) |",
        "|---|---|---|---|---|---|---|",
    ]
    extra_full = dict(EXTRA)
    for name in [name for name, _ in EFFECTS] + [effect for effect, _ in EXTRA]:
        full = extra_full.get(name, "everything")
        with_ms = statistics.median(times[full])
        without_ms = statistics.median(times[name])
        diffs = [a - b for a, b in zip(times[full], times[name])]
        lacking = described[name]
        passes = [p for p in described[full]["passes"] if p not in lacking["passes"]]
        lacking_items = pipeline_items(lacking["pipelines"])
        pipelines = [p for p in pipeline_items(described[full]["pipelines"])
                     if p not in lacking_items]
        mib = memory[full][0] - memory[name][0]
        lines.append(
            f"| {name} | {with_ms:.2f} | {without_ms:.2f} | {statistics.median(diffs):+.2f} "
            f"({min(diffs):+.2f} to {max(diffs):+.2f}) | {', '.join(passes) or '-'} | "
            f"{', '.join(pipelines) or '-'} | {mib:.2f} |")
    def pass_table(effects, passes, summed=None):
        """Rows of each effect's paired cost in each of `passes`, and in the sum of `summed`
        (default: all of them; passes nested in another are left out of the sum)."""
        summed = passes if summed is None else summed
        total = "all of them" if summed == passes else " + ".join(summed)
        rows = ["| effect | " + " | ".join(passes) + f" | {total} |",
                "|---|" + "---|" * (len(passes) + 1)]
        for name in effects:
            full = extra_full[name]
            def paired(keys):
                diffs = [sum(a.get(k, 0.0) - b.get(k, 0.0) for k in keys)
                         for a, b in zip(pass_times[full], pass_times[name])]
                return (f"{statistics.median(diffs):+.2f} ({min(diffs):+.2f} to "
                        f"{max(diffs):+.2f})")
            rows.append(f"| {name} | " + " | ".join(paired([k]) for k in passes) +
                        f" | {paired(summed)} |")
        return rows

    lines += [
        "",
        "Lightning in the passes it changes (ms; the median of the paired differences, the range "
        "in brackets; a pass a scene does not run counts 0). Its budget: 1 ms a frame while "
        "flashes are active.",
        "",
        *pass_table(LIGHTNING_EFFECTS, LIGHTNING_PASSES),
        "",
        "Weather in the clouds' passes (as above). A change of weather is measured in its middle "
        f"(the default scene's look eased over {CHANGE_SECONDS:.0f} s from coverage "
        f"{FAIR['coverage']} to {TOWERING['coverage']}, type {FAIR['cloudType']} to "
        f"{TOWERING['cloudType']}, density x{FAIR['densityMultiplier']} to "
        f"x{TOWERING['densityMultiplier']}, anvils {FAIR['anvilBias']} to "
        f"{TOWERING['anvilBias']}; the frames from {CHANGE_START_SECONDS:.0f} s on at 30 fps) "
        "against the look of its midpoint held, under the same wind: what the change costs "
        "more is the module following it (the cloud shadow map's cascades remade as the look "
        "moves, the march led ahead of the history), not other clouds. Its budget: what steady "
        "weather costs, within the runs' noise.",
        "",
        *pass_table(WEATHER_EFFECTS, WEATHER_PASSES, WEATHER_FRAME_PASSES),
    ]
    lines += [
        "",
        "God rays and lightning are also measured where they work: looking into the sun (the "
        "god-ray test scene), and in the thunderstorm scene (`assets_src/scenes/thunderstorm.json`)"
        " at its own strike rate, and with a flash always in progress (strikes a script asks for "
        "every 8 frames; then ground strikes, each drawing its bolt) in a calm storm seen from "
        "low over the plains (`tests/sample_game/scenes/storm_calm.json`: the ground fills the "
        "lower half of the view, the terrain's flash light's worst case), each against the same "
        "scene without the effect. Weather regions are measured in the storm front "
        "(`assets_src/scenes/storm_front.json`: one region over the range, on a schedule of its "
        "own) against it without its regions, both without its lightning (its storm strikes "
        "nothing).",
        "",
        "An effect a scene leaves out costs it nothing it can be charged with: the passes and "
        "pipelines above are absent from the scene without it (an effect inside a module, such "
        "as god rays or the cloud shadow map, shows as that module's pipeline entry listing it), "
        "and so is the memory. Where an effect only changes what other passes do (terrain "
        "shadows feed the clouds' march and the terrain's sunlight), it adds no pass; its cost "
        "is in theirs.",
        "",
        "Scenes' passes and pipelines (`--describe`):",
        "",
    ]
    for name in paths:
        d = described[name]
        lines.append(f"- {WITH_SCENES.get(name, 'without ' + name)}: passes "
                     f"{', '.join(d['passes'])}; pipelines {', '.join(d['pipelines'])}")
    with open(os.path.join(args.out_dir, "results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {os.path.join(args.out_dir, 'results.md')}")


if __name__ == "__main__":
    main()
