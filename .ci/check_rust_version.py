#!/usr/bin/env python3
"""Checks that the workspace's declared rust-version is no lower than the
rust-version of any locked dependency (as `cargo metadata` reports them).

Only the installed toolchain can be run here, so the MSRV is checked from the
metadata instead of by building with the old compiler. Prints the dependencies
that need the highest version and exits 1 if the declaration is too low.
Run from anywhere: `python3 .ci/check_rust_version.py`.
"""

import json
import pathlib
import subprocess
import sys


def version(text):
    """'1.89' or '1.89.0' as a comparable tuple (1, 89, 0)."""
    parts = [int(p) for p in text.strip().split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    metadata = json.loads(
        subprocess.run(
            ["cargo", "metadata", "--format-version", "1", "--locked"],
            cwd=root,
            check=True,
            capture_output=True,
            text=True,
        ).stdout
    )
    members = set(metadata["workspace_members"])
    declared = {
        p["name"]: p.get("rust_version")
        for p in metadata["packages"]
        if p["id"] in members
    }
    missing = sorted(name for name, rv in declared.items() if not rv)
    if missing:
        print(f"rust-version: no rust-version declared by {', '.join(missing)}")
        return 1
    lowest = min(declared.values(), key=version)
    needed = [
        (version(p["rust_version"]), p["name"], p["version"], p["rust_version"])
        for p in metadata["packages"]
        if p["id"] not in members and p.get("rust_version")
    ]
    top = max(v for v, *_ in needed) if needed else (0, 0, 0)
    which = sorted(f"{name} {ver} ({rv})" for v, name, ver, rv in needed if v == top)
    if version(lowest) < top:
        print(
            f"rust-version: declared {lowest} but locked dependencies need "
            f"{'.'.join(map(str, top))}: {', '.join(which)}"
        )
        return 1
    print(
        f"rust-version: declared {lowest} >= {'.'.join(map(str, top))}, the highest "
        f"of the locked dependencies ({', '.join(which)})"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
