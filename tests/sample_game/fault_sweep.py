#!/usr/bin/env python3
"""Fault injection over the sample: runs it under validation with one Vulkan call failing (the
fault layer, tests/support/fault_layer), once per fault, and checks that every run ends
cleanly:

  - it exits with 1 and an "error:" line naming the failed call and its VkResult, or it goes
    on and exits with 0 after a line naming the call: a module that cannot create its objects
    at install time is left out with a warning (engine/ecs/module.h), and a module whose
    prepare() fails in a frame logs it, skips its passes that frame and tries again the next;
  - no validation message, so nothing is leaked (the layer reports undestroyed objects when the
    device and instance go) and no failed handle is used;
  - no crash, abort or hang (each run has a time limit), and the device is destroyed (the fault
    layer writes its report then).

Faults: object creations spread over all the run makes (each kind's first and last, and every
one of the first few), vkAllocateMemory's, every submission failing, and the device lost at
every submission. A first run without a fault counts the calls.

With --windowed the sample opens a window (run it under Xvfb) and the faults are the window's:
the swapchain's creations, and the first and last-but-one acquire and present reporting each of
out-of-date and suboptimal (the run must rebuild the swapchain and go on: a second
"swapchain:" line, exit 0), surface-lost and out-of-memory (a clear error), besides a shorter
spread of creations and the first and last submissions' faults. Its runs fix the cloud preset
(--quality medium): no sweep fails the governor's compilations of the other presets.

usage: fault_sweep.py [--windowed] SAMPLE LAYER_DATA_HOME OUT_DIR
(CLOUDSCAPE_FAULT_SWEEP_ALL=1 fails every creation in turn instead, for a longer search.)
"""
import os
import subprocess
import sys
from pathlib import Path

FRAMES = 3
RUN_TIMEOUT_S = 120
# Creation functions whose first and last calls are failed on their own, besides the spread
# over all creations (pipelines, descriptor sets and memory are where per-frame and per-module
# failures differ).
CREATION_KINDS = ["vkAllocateMemory", "vkCreateImage", "vkCreateBuffer", "vkCreateImageView",
                  "vkCreateComputePipelines", "vkCreateGraphicsPipelines",
                  "vkAllocateDescriptorSets", "vkCreateDescriptorPool", "vkCreateQueryPool",
                  "vkCreateShaderModule", "vkCreateSampler", "vkAllocateCommandBuffers",
                  "vkCreateCommandPool", "vkCreateSemaphore"]
# The window's own: the swapchain, its image views and semaphores.
WINDOW_CREATION_KINDS = ["vkCreateSwapchainKHR", "vkCreateImageView", "vkCreateSemaphore"]
PRESENTATION_CALLS = ["vkAcquireNextImageKHR", "vkQueuePresentKHR"]
# What a presentation fault reports, and whether the run must go on (rebuilding its swapchain).
PRESENTATION_RESULTS = {"out-of-date": True, "suboptimal": True, "surface-lost": False,
                        "out-of-memory": False}
RESULT_NAMES = {"out-of-date": "VK_ERROR_OUT_OF_DATE_KHR", "suboptimal": "VK_SUBOPTIMAL_KHR",
                "surface-lost": "VK_ERROR_SURFACE_LOST_KHR",
                "out-of-memory": "VK_ERROR_OUT_OF_DEVICE_MEMORY"}
SPREAD_POINTS = 16
WINDOWED_SPREAD_POINTS = 6


def run_sample(sample, data_home, out_dir, fault, name, windowed):
    report = out_dir / f"{name}.report"
    report.unlink(missing_ok=True)
    env = dict(os.environ, XDG_DATA_HOME=str(data_home), CLOUDSCAPE_FAULT_LAYER="1",
               CLOUDSCAPE_FAULT_REPORT=str(report))
    env.pop("CLOUDSCAPE_FAULT", None)
    if fault:
        env["CLOUDSCAPE_FAULT"] = fault
    command = [sample, "--validation", "--frames", str(FRAMES), "--width", "160", "--height", "90"]
    if windowed:
        # A fixed preset: the frame-rate governor a window has would compile the other presets'
        # pipelines too (9 s a run on lavapipe) and the sweep is there for the window's faults.
        command += ["--quality", "medium"]
        # The swapchain's faults: a software device would otherwise present through MIT-SHM.
        command += ["--present", "swapchain"]
    else:
        command += ["--headless", "--capture", str(out_dir / "capture")]
    try:
        done = subprocess.run(command, env=env, capture_output=True, text=True,
                              timeout=RUN_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None, "", {}
    calls, injected = {}, None
    if report.exists():
        for line in report.read_text().splitlines():
            words = line.split(" ", 2)
            if words[0] == "calls":
                calls[words[1]] = int(words[2])
            elif words[0] == "injected":
                injected = line[len("injected "):]
    calls["injected"] = injected
    return done.returncode, done.stdout + done.stderr, calls


def first_and_last(calls, kind):
    count = calls.get(kind, 0)
    return [n for n in sorted({1, count}) if n >= 1]


def faults_to_try(calls, windowed):
    creations = calls["create"]
    if os.environ.get("CLOUDSCAPE_FAULT_SWEEP_ALL"):  # every creation (about 8 minutes)
        return [f"create:{n}" for n in range(1, creations + 1)]
    # In a window, fewer points of the spread and the first and last submissions only: the
    # headless sweep fails the spread's every point and every submission, and a windowed run
    # (about 10 s: it compiles the pipelines each time) is there for the window's own faults.
    points = WINDOWED_SPREAD_POINTS if windowed else SPREAD_POINTS
    spread = sorted({1, 2, 3, 4, 5, creations} |
                    {1 + (creations - 1) * i // (points - 1) for i in range(points)})
    faults = [f"create:{n}" for n in spread]
    for kind in WINDOW_CREATION_KINDS if windowed else CREATION_KINDS:
        faults += [f"{kind}:{n}" for n in first_and_last(calls, kind)]
    if windowed:
        # The first call and the last but one: after the last there is no frame to rebuild in.
        for kind in PRESENTATION_CALLS:
            count = calls.get(kind, 0)
            faults += [f"{kind}:{n}:{result}" for n in sorted({1, max(count - 1, 1)})
                       for result in PRESENTATION_RESULTS]
    submissions = sorted({1, calls["submit"]}) if windowed else range(1, calls["submit"] + 1)
    faults += [f"vkQueueSubmit:{n}" for n in submissions]
    faults += [f"device-lost:{n}" for n in submissions]
    return faults


def verdict(fault, code, output, calls):
    """Returns (outcome, problem); problem is None for a clean end."""
    if code is None:
        return "hang", f"no exit within {RUN_TIMEOUT_S} s"
    injected = calls.get("injected")
    if injected is None:
        return f"exit {code}", "the device was not destroyed (no fault-layer report)"
    if injected == "nothing":
        return f"exit {code}", "the fault was never injected"
    lines = output.splitlines()
    validation = [line for line in lines if "Vulkan validation" in line]
    if validation:
        return f"exit {code}", "validation message: " + validation[0][:300]
    failed_call = injected.split(" ")[0]
    result = fault.split(":")[2] if fault.count(":") == 2 else None
    if result and PRESENTATION_RESULTS[result]:
        # Out of date or suboptimal: what a resized window reports. The swapchain is rebuilt.
        rebuilds = [line for line in lines if "swapchain: " in line]
        if code != 0:
            return f"exit {code}", f"{RESULT_NAMES[result]} ended the run"
        if len(rebuilds) < 2:
            return "exit 0", "the swapchain was not rebuilt"
        return f"went on: rebuilt, {rebuilds[-1].strip()[:100]}", None
    if fault.startswith("device-lost"):
        wanted = ["VK_ERROR_DEVICE_LOST"]
    else:
        wanted = [failed_call, RESULT_NAMES[result or "out-of-memory"]]
    if code == 1:
        errors = [line for line in lines if line.startswith("error:")]
        if not errors:
            return "exit 1", "no error: line"
        if not all(w in errors[0] for w in wanted):
            return "exit 1", f"the error does not name {' and '.join(wanted)}: {errors[0]}"
        return "error: " + errors[0][len("error: "):][:140], None
    if code == 0 and not fault.startswith(("device-lost", "vkQueueSubmit")):
        # A module left out at install time, or a module's frame skipped and retried: either
        # way a line names the call.
        reports = [line for line in lines if failed_call in line and
                   (("module '" in line and "skipped" in line) or line.startswith("[error]"))]
        if not reports:
            return "exit 0", f"the run went on and nothing named {failed_call}"
        return "went on: " + reports[0][:140], None
    return f"exit {code}", "exit code other than 1 (error) or 0 (a module skipped)"


def main():
    arguments = sys.argv[1:]
    windowed = arguments[:1] == ["--windowed"]
    if windowed:
        arguments = arguments[1:]
    if len(arguments) != 3:
        sys.exit(__doc__)
    sample, data_home, out_dir = arguments[0], Path(arguments[1]), Path(arguments[2])
    out_dir.mkdir(parents=True, exist_ok=True)

    code, output, calls = run_sample(sample, data_home, out_dir, None, "baseline", windowed)
    if code != 0 or calls.get("injected") != "nothing":
        sys.exit(f"the run without a fault failed (exit {code}):\n{output}")
    print(f"without a fault: {calls['create']} creations, {calls['submit']} submissions, "
          f"{calls.get('vkQueuePresentKHR', 0)} presents in {FRAMES} frames"
          + (" in a window" if windowed else " headless"))

    rows, problems = [], []
    for index, fault in enumerate(faults_to_try(calls, windowed)):
        code, output, fault_calls = run_sample(sample, data_home, out_dir, fault, f"run{index}",
                                               windowed)
        outcome, problem = verdict(fault, code, output, fault_calls)
        injected = fault_calls.get("injected") or "-"
        rows.append(f"| {fault} | {injected} | {outcome} | {problem or 'clean'} |")
        print(f"{fault}: {injected}: {outcome}" + (f"  PROBLEM: {problem}" if problem else ""))
        if problem:
            problems.append(f"{fault}: {problem}\n--- output ---\n{output[-3000:]}")

    table = ["| fault | injected | outcome | verdict |", "|---|---|---|---|"] + rows
    (out_dir / "summary.md").write_text("\n".join(table) + "\n")
    print(f"{len(rows)} faults, {len(problems)} with problems; table in {out_dir / 'summary.md'}")
    if problems:
        print("\n\n".join(problems))
        sys.exit(1)


if __name__ == "__main__":
    main()
