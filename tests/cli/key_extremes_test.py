#!/usr/bin/env python3
"""Every scene key at its extremes.

Each key documented in scenes/README.md is set in turn (with --set, on a
small scene) to 0, -1, 1e-300, 1e300, the largest doubles, NaN and +-inf
(numbers, and every element of a list of numbers), or to an unknown word
and an empty string (strings). Every render must:

- end by itself within a few seconds with exit status 0 or 1 (never a
  signal: Embree's assertions once aborted on lengths of 1e20);
- on status 1, say where: the key (or its --set argument) or the scene's
  file:line:column;
- on status 0, leave an image that is not blank, or say why in a warning;
- leave no temporary file behind.

  key_extremes_test.py HSB SOURCE_DIR [KEY_PREFIX...]
"""

import concurrent.futures
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib

HSB, SOURCE = sys.argv[1], sys.argv[2]
ONLY = sys.argv[3:]
SCENE = os.path.join(SOURCE, "scenes", "fig07_point_load_normalized.toml")
SCRATCH = tempfile.mkdtemp(prefix="hsb_extremes_scenes_")
CURVE = os.path.join(SCRATCH, "curve.toml")
with open(CURVE, "w", encoding="utf-8") as f:
    f.write('[glyphs]\nplacement = "curve"\n[glyphs.curve]\nkind = "helix"\ncount = 12\n')
PANELS = os.path.join(SOURCE, "scenes", "fig02_blending_along_a_curve.toml")
DATA = os.path.join(SOURCE, "scenes", "data", "generated", "beam_bending.vtu")
VTK_KEYS = ("data.file", "data.array", "data.field", "data.association", "data.cell_tensors")


def scene_for(key):
    """A scene in which `key` applies."""
    if key.startswith("glyphs.curve."):
        return CURVE
    if key.startswith(("figure.", "panel.")):
        return PANELS
    if key.startswith(VTK_KEYS):
        return DATA
    return SCENE
# Without the colour bar and the box, a blank picture means no glyph.
SMALL = ["--set", "render.width=40", "--set", "render.height=40", "--set", "render.samples=1",
         "--set", "light.ambient_occlusion.samples=0", "--set", "output.colorbar=false", "--set", "render.box=false"]
TIMEOUT = 30  # seconds; a render of this scene takes well under one

NUMBERS = ["0", "-1", "1e-300", "1e300", "1.7976931348623157e308", "-1.7976931348623157e308", "nan", "inf", "-inf"]
WORDS = ['"nosuchword"', '""']

# Keys whose values are files or colours with rules of their own, tried
# with words only, and keys that name a table rather than a value.
NOT_VALUES = {"seeds.grid", "sweep", "panel"}


def documented_keys():
    """(key, default text) for every row of scenes/README.md's key tables."""
    keys, section = [], None
    with open(os.path.join(SOURCE, "scenes", "README.md"), encoding="utf-8") as readme:
        for line in readme:
            heading = re.match(r"^#+ `\[+([a-z_.]+)\]+`", line)
            if heading:
                section = heading.group(1)
                continue
            row = re.match(r"^\| (`[^|]+`) \| ([^|]*) \|", line)
            if not row or section is None:
                continue
            for name in re.findall(r"`([a-z_.0-9]+)`", row.group(1)):
                full = name if name.startswith(section + ".") else f"{section}.{name}"
                if section == "seeds" and name.startswith("grid."):
                    continue  # a [[seeds.grid]] table's keys: not --set-able one by one
                keys.append((full, row.group(2).strip()))
    return keys


def pinned_values():
    out = subprocess.run([HSB, "info", SCENE], capture_output=True, text=True, check=True).stdout
    flat = {}

    def walk(prefix, node):
        for k, v in node.items():
            path = f"{prefix}.{k}" if prefix else k
            if isinstance(v, dict):
                walk(path, v)
            else:
                flat[path] = v
    walk("", tomllib.loads(out))
    return flat


def trials(key, default, pinned):
    value = pinned.get(key)
    text = default
    if isinstance(value, bool) or text.startswith("`true`") or text.startswith("`false`"):
        return []
    if isinstance(value, str) or text.startswith('`"'):
        return WORDS
    if isinstance(value, list) or text.startswith("`["):
        sample = value if isinstance(value, list) else None
        if sample is None:
            inner = re.match(r"`(\[.*?\])`", text)
            try:
                sample = tomllib.loads("v = " + inner.group(1))["v"] if inner else [0.0, 0.0, 0.0]
            except tomllib.TOMLDecodeError:
                sample = [0.0, 0.0, 0.0]
        if sample and isinstance(sample[0], list):
            return ["[[" + ", ".join([n] * len(sample[0])) + "]]" for n in NUMBERS]
        if sample and isinstance(sample[0], str):
            return ['["nosuchword"]', "[]"]
        width = max(1, len(sample))
        return ["[" + ", ".join([n] * width) + "]" for n in NUMBERS] + ["[]"]
    return NUMBERS + WORDS[:1]


def blank(image):
    """True when every pixel of the image is the same."""
    stats = subprocess.run(["oiiotool", image, "--printstats"], capture_output=True, text=True).stdout
    lo = re.search(r"Stats Min: ([^\n]*)", stats)
    hi = re.search(r"Stats Max: ([^\n]*)", stats)
    return bool(lo and hi and lo.group(1).split("(")[0].strip() == hi.group(1).split("(")[0].strip())


def run(case):
    key, value = case
    with tempfile.TemporaryDirectory(prefix="hsb_extremes_") as out:
        try:
            done = subprocess.run([HSB, "render", scene_for(key), *SMALL, "--set", f"{key}={value}", "-o", out],
                                  capture_output=True, text=True, timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            return f"{key}={value}: still running after {TIMEOUT} s"
        said = done.stderr.strip()
        left = [f for f in os.listdir(out) if ".partial" in f]
        if left:
            return f"{key}={value}: left {left}"
        if done.returncode not in (0, 1):
            return f"{key}={value}: exit {done.returncode}: {said[-300:]}"
        if done.returncode == 1:
            located = key in said or re.search(r"\.(toml|vtu):\d+:\d+: ", said) or "--set" in said
            return None if located else f"{key}={value}: an error that does not say where: {said[-300:]}"
        images = [os.path.join(out, f) for f in os.listdir(out) if f.endswith((".png", ".tif", ".exr"))]
        if images and all(blank(i) for i in images) and "warning" not in said:
            return f"{key}={value}: exit 0, a blank picture and no warning"
        return None


def main():
    pinned = pinned_values()
    cases = []
    for key, default in documented_keys():
        if key.split(".")[0] in NOT_VALUES or (ONLY and not any(key.startswith(p) for p in ONLY)):
            continue
        cases += [(key, v) for v in trials(key, default, pinned)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        failures = [f for f in pool.map(run, cases) if f]
    shutil.rmtree(SCRATCH, ignore_errors=True)
    for f in failures:
        print("FAIL:", f)
    print(f"{len(cases) - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
