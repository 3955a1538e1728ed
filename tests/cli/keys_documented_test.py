#!/usr/bin/env python3
"""scenes/README.md documents every scene key, as the schema has it.

`hsb keys` prints the schema. Each of its keys must have a row in one of
the README's key tables, and each key in those tables must be in the
schema; where the schema has a fixed default the README's default column
must give the same value, an automatic key must say "automatic", and a key
with no default must say "none" or "required".

  keys_documented_test.py HSB SOURCE_DIR
"""

import os
import re
import subprocess
import sys
import tomllib

HSB, SOURCE = sys.argv[1], sys.argv[2]


def schema():
    lines = subprocess.run([HSB, "keys"], capture_output=True, text=True, check=True).stdout.splitlines()
    header = lines[0].split("\t")
    rows = [dict(zip(header, line.split("\t"))) for line in lines[1:]]
    return {r["key"]: r for r in rows}


def documented(tables):
    """{key: default cell} from the README's tables, keys made whole from their section."""
    found, section = {}, None
    with open(os.path.join(SOURCE, "scenes", "README.md"), encoding="utf-8") as readme:
        for line in readme:
            heading = re.match(r"^#+ `\[+([a-z_.]+)\]+`", line)
            if heading:
                section = heading.group(1)
                continue
            row = re.match(r"^\| (`[^|]+`) \| ([^|]*) \|", line)
            if not row or section is None:
                continue
            names = re.findall(r"`\[*([a-z_.0-9]+)\]*`", row.group(1))
            for name in names:
                whole = name if "." in name and name.split(".")[0] in tables else f"{section}.{name}"
                found[whole] = (row.group(2).strip(), len(names), names.index(name))
    return found


def toml_value(text):
    try:
        return tomllib.loads("v = " + text)["v"]
    except tomllib.TOMLDecodeError:
        return None


def main():
    keys = schema()
    tables = {k.split(".")[0] for k in keys}
    readme = documented(tables)
    problems = []
    for key in keys:
        if key not in readme:
            problems.append(f"{key}: in the schema, not in scenes/README.md")
    for key in readme:
        if key not in keys:
            problems.append(f"{key}: in scenes/README.md, not in the schema (hsb keys)")
    for key, row in keys.items():
        if key not in readme:
            continue
        cell, count, position = readme[key]
        default = row["default"]
        if default.startswith("automatic"):
            if not cell.startswith("automatic"):
                problems.append(f"{key}: automatic in the schema, README says {cell!r}")
            continue
        if cell.startswith("automatic"):
            problems.append(f"{key}: README says automatic, the schema {default!r}")
            continue
        wanted = toml_value(default)
        if wanted is None:  # no default: none, or one that follows another key
            continue
        values = re.findall(r"`([^`]+)`", cell)
        given = values[position] if len(values) == count else values[0] if len(values) == 1 else None
        if given is None or toml_value(given) != wanted:
            problems.append(f"{key}: the schema's default is {default}, README says {cell!r}")
    for p in problems:
        print("FAIL:", p)
    print(f"{len(keys)} keys in the schema, {len(readme)} in the README, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
