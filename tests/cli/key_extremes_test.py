#!/usr/bin/env python3
"""Every scene key, and every column of a CSV list of sources, at its extremes.

The keys come from the scene schema (`hsb keys`). Each is set in turn (with
--set, or in a scene file for the keys of [[seeds.grid]] and [[panel]]), on
a small scene, to what its type can be pushed to: numbers to 0, -1, 1e-300,
1e300, the largest doubles, NaN and +-inf (every element of a list of
numbers alike); integers also to the limits of 32- and 64-bit integers;
names and text to an unknown word and an empty string; every key also to a
value of the wrong type. Each column of a CSV list of sources gets the
same numbers, a word and an empty cell. Every render must:

- end by itself within a few seconds with exit status 0 or 1 (never a
  signal: Embree's assertions once aborted on lengths of 1e20);
- on status 1, say where: the key (or its --set argument), the scene's or
  CSV file's file:line:column;
- on status 0, leave an image that is not blank, or say why in a warning;
- leave no temporary file behind.

  key_extremes_test.py HSB SOURCE_DIR [KEY_PREFIX...]
"""

import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile

HSB, SOURCE = sys.argv[1], sys.argv[2]
ONLY = sys.argv[3:]
SCENE = os.path.join(SOURCE, "scenes", "fig07_point_load_normalized.toml")
SCRATCH = tempfile.mkdtemp(prefix="hsb_extremes_scenes_")
CURVE = os.path.join(SCRATCH, "curve.toml")
with open(CURVE, "w", encoding="utf-8") as f:
    f.write('[glyphs]\nplacement = "curve"\n[glyphs.curve]\nkind = "helix"\ncount = 12\n')
PANELS = os.path.join(SOURCE, "scenes", "fig02_blending_along_a_curve.toml")
DATA = os.path.join(SOURCE, "scenes", "data", "generated", "beam_bending.vtu")
VTK_KEYS = ("data.file", "data.array", "data.field", "data.association", "data.cell_tensors", "data.step", "data.components")
# Keys of arrays of tables: written into a scene file, not --set.
IN_FILE = {"seeds.grid.": "[[seeds.grid]]\n", "panel.": "[[panel]]\n"}


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
INTEGER_LIMITS = ["2147483647", "2147483648", "-2147483649", "9223372036854775807", "-9223372036854775808"]
WORDS = ['"nosuchword"', '""']


def schema():
    """(key, type, count) for every key `hsb keys` lists."""
    out = subprocess.run([HSB, "keys"], capture_output=True, text=True, check=True).stdout.splitlines()
    keys = []
    for line in out[1:]:
        key, kind = line.split("\t")[:2]
        count = re.match(r"(\d+) numbers", kind)
        keys.append((key, kind, int(count.group(1)) if count else 0))
    return keys


def vectors(width):
    return ["[" + ", ".join([n] * width) + "]" for n in NUMBERS] + ["[]"]


def trials(kind, count):
    """The values to try for a key of this type (as `hsb keys` words it)."""
    if kind == "true or false":
        return ["0", '"yes"']
    if kind in ("string", "name"):
        return WORDS + ["1"]
    if kind == "integer":
        return NUMBERS + INTEGER_LIMITS + WORDS[:1]
    if kind == "number":
        return NUMBERS + WORDS[:1]
    if kind.startswith("[x, y, z]"):
        return vectors(3) + WORDS[:1]
    if kind == "name or [x, y, z]":
        return WORDS + vectors(3)
    if kind.startswith("[r, g, b]"):
        return vectors(3) + WORDS
    if kind.endswith("numbers"):
        return vectors(count or 3) + WORDS[:1]
    if kind == "[[x, y, z], ...]":
        return ["[" + v + "]" for v in vectors(3)[:-1]] + ["[]", "1"]
    if kind == "[strings]":
        return ['["nosuchword"]', "[]", "[1]"]
    return []  # [[tables]]: their keys are tried one by one


def scene_with(key, value):
    """A scene file holding `key = value` in its array of tables."""
    for prefix, header in IN_FILE.items():
        if key.startswith(prefix):
            path = os.path.join(SCRATCH, f"{abs(hash((key, value)))}.toml")
            with open(scene_for(key), encoding="utf-8") as base, open(path, "w", encoding="utf-8") as f:
                f.write(base.read() + "\n" + header + f"{key[len(prefix):]} = {value}\n")
            return path
    return None


# A list of sources: every column of the CSV format, with rotation as two
# axes or as a quaternion.
CSV_HEADERS = {
    "axes": ("x,y,z,r1,r2,r3,ax,ay,az,bx,by,bz,scalar", "0,0,0,0.3,0.2,0.1,1,0,0,0,1,0,1", "1,0,0,0.3,0.2,0.1,1,0,0,0,1,0,2"),
    "quaternion": ("x,y,z,r,qw,qx,qy,qz,scalar", "0,0,0,0.3,1,0,0,0,1", "1,0,0,0.3,1,0,0,0,2"),
}


def csv_cases():
    cases = []
    for name, (header, row, other) in CSV_HEADERS.items():
        columns = header.split(",")
        for i, column in enumerate(columns):
            for value in NUMBERS + ["abc", ""]:
                cells = row.split(",")
                cells[i] = value
                cases.append((f"csv {name} column {column}", value, header + "\n" + ",".join(cells) + "\n" + other + "\n"))
    return cases


def csv_scene(label, text):
    folder = tempfile.mkdtemp(dir=SCRATCH)
    with open(os.path.join(folder, "sources.csv"), "w", encoding="utf-8") as f:
        f.write(text)
    path = os.path.join(folder, "list.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write('[glyphs]\nplacement = "list"\nfile = "sources.csv"\n')
    return path


def blank_images(images):
    """The images of `images` in which every pixel is the same. One oiiotool
    reads them all: loading OpenImageIO costs a process more than reading
    a 40x40 picture, and most cases leave one."""
    blank = set()
    for start in range(0, len(images), 200):
        chunk = images[start:start + 200]
        stats = subprocess.run(["oiiotool", "--stats", *chunk], capture_output=True, text=True, check=True).stdout
        # Each image's report starts with its path, then its statistics.
        starts = sorted((stats.find(image + " "), image) for image in chunk)
        for (at, image), (end, _) in zip(starts, starts[1:] + [(len(stats), None)]):
            report = stats[at:end]
            lo = re.search(r"Stats Min: ([^\n]*)", report)
            hi = re.search(r"Stats Max: ([^\n]*)", report)
            if at < 0 or not (lo and hi):
                raise RuntimeError(f"oiiotool gave no statistics for {image}")
            if lo.group(1).split("(")[0].strip() == hi.group(1).split("(")[0].strip():
                blank.add(image)
    return blank


def run(case):
    """None if the case passed, the images it left to check for blankness,
    or what went wrong."""
    key, value, csv = case
    if csv is not None:
        scene, setting = csv_scene(key, csv), []
    else:
        scene = scene_with(key, value)
        scene, setting = (scene, []) if scene else (scene_for(key), ["--set", f"{key}={value}"])
    out = tempfile.mkdtemp(prefix="out_", dir=SCRATCH)
    try:
        done = subprocess.run([HSB, "render", scene, *SMALL, *setting, "-o", out],
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
        where = key.split()[-1] if csv is not None else key
        located = (where in said or re.search(r"\.(toml|vtu|csv):\d+:\d+: ", said) or "--set" in said)
        return None if located else f"{key}={value}: an error that does not say where: {said[-300:]}"
    images = [os.path.join(out, f) for f in os.listdir(out) if f.endswith((".png", ".tif", ".exr"))]
    if images and "warning" not in said:
        return images
    return None


def main():
    cases = []
    for key, kind, count in schema():
        if ONLY and not any(key.startswith(p) for p in ONLY):
            continue
        cases += [(key, v, None) for v in trials(kind, count)]
    if not ONLY or "csv" in ONLY:
        cases += csv_cases()
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        outcomes = list(pool.map(run, cases))
    failures = [o for o in outcomes if isinstance(o, str)]
    unwarned = [(case, o) for case, o in zip(cases, outcomes) if isinstance(o, list)]
    blank = blank_images([image for _, images in unwarned for image in images])
    failures += [f"{key}={value}: exit 0, a blank picture and no warning"
                 for (key, value, _), images in unwarned if all(i in blank for i in images)]
    shutil.rmtree(SCRATCH, ignore_errors=True)
    for f in failures:
        print("FAIL:", f)
    print(f"{len(cases) - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
