"""The guide cannot go stale: every ```python block of the workspace README and of
docs/guide/*.md is executed here, each on its own (a fresh namespace) from the
repository root, so its paths (`examples/scenes/...`) resolve. A block states what
it shows with plain `assert` lines."""

import re

import pytest

from conftest import ROOT

FENCE = re.compile(r"^```(\S*)\s*$")


def python_blocks():
    files = [ROOT / "README.md", *sorted((ROOT / "docs" / "guide").glob("*.md"))]
    blocks = []
    for path in files:
        lines = path.read_text(encoding="utf-8").splitlines()
        i = 0
        while i < len(lines):
            m = FENCE.match(lines[i])
            if m and m.group(1):
                end = next((j for j in range(i + 1, len(lines)) if lines[j].strip() == "```"), len(lines))
                if m.group(1) == "python":
                    name = f"{path.relative_to(ROOT)}:{i + 1}"
                    blocks.append(pytest.param("\n".join(lines[i + 1:end]) + "\n", name, id=name))
                i = end
            i += 1
    return blocks


BLOCKS = python_blocks()


def test_the_guide_has_python_blocks():
    # the README's package example and the guide's (researcher.md)
    assert len(BLOCKS) >= 2, BLOCKS


@pytest.mark.parametrize("source,name", BLOCKS)
def test_guide_python_block_runs(source, name, monkeypatch):
    monkeypatch.chdir(ROOT)
    code = compile(source, name, "exec")
    exec(code, {"__name__": "__guide__"})
