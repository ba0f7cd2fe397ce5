"""Every reference inside the repository resolves: relative links of the README and docs/,
and file paths and Markdown file names named in source files and their comments.

The project's documentation must stand alone: a reference to a file that does not exist (or
that lies outside the repository) is a broken promise to the reader."""

from __future__ import annotations

import pathlib
import re
import subprocess

import pytest

pytestmark = pytest.mark.text  # run once per CI, not under the sanitizers (conftest.py)

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Markdown links [text](target) and images ![alt](target).
MARKDOWN_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
# A repository path as written in prose and comments: a known top-level folder, then a path.
REPOSITORY_PATH = re.compile(
    r"(?<![\w./-])((?:cpp|python|tests|docs|scenarios|scripts|benchmarks|cmake)/[\w./-]*[\w])")
# A Markdown file named anywhere (README.md, mathematics.md, docs/results.md ...).
MARKDOWN_NAME = re.compile(r"(?<![\w./-])([\w-]+\.md)\b")
TEXT_SUFFIXES = {".md", ".py", ".cpp", ".hpp", ".txt", ".toml", ".sh", ".cmake", ".in", ".pyi"}
# Files the command lines write into an output folder: named as outputs, not as references.
OUTPUT_FILES = {"metrics.md", "comparison.md", "report.md", "summary.md", "planned.md"}


def tracked_files() -> list[pathlib.Path]:
    listed = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True)
    files = [ROOT / line for line in listed.stdout.splitlines()]
    return [p for p in files if p.is_file() and (p.suffix in TEXT_SUFFIXES or p.name in {"CMakeLists.txt", "run"})]


def prose(path: pathlib.Path) -> str:
    """What a reader reads as text: all of a Markdown file; the comments and docstrings of
    source files (string literals in code are data: a label passed to a parser as the name of
    its source is not a reference)."""
    text = path.read_text(errors="replace")
    if path.suffix == ".md":
        return text
    if path.suffix in {".cpp", ".hpp"}:
        return "\n".join(re.findall(r"//.*", text))
    parts = re.findall(r"#.*", text)
    if path.suffix in {".py", ".pyi"}:
        parts += re.findall(r'"""(.*?)"""', text, flags=re.S)
    return "\n".join(parts)


def markdown_files() -> list[pathlib.Path]:
    return [p for p in tracked_files() if p.suffix == ".md"]


def anchors(path: pathlib.Path) -> set[str]:
    """GitHub-style anchors of a Markdown file's headings."""
    found = set()
    for line in path.read_text().splitlines():
        if line.startswith("#"):
            title = line.lstrip("#").strip().lower()
            found.add(re.sub(r"[^\w\- ]", "", title).replace(" ", "-"))
    return found


@pytest.mark.parametrize("path", markdown_files(), ids=lambda p: str(p.relative_to(ROOT)))
def test_markdown_links_resolve(path):
    broken = []
    for target in MARKDOWN_LINK.findall(path.read_text()):
        if re.match(r"^[a-z]+:", target):  # http:, https:, mailto:
            continue
        file_part, _, anchor = target.partition("#")
        resolved = (path.parent / file_part).resolve() if file_part else path
        if not resolved.exists():
            broken.append(f"{target}: no such file")
        elif anchor and resolved.suffix == ".md" and anchor not in anchors(resolved):
            broken.append(f"{target}: no heading '{anchor}' in {resolved.relative_to(ROOT)}")
    assert not broken, f"{path.relative_to(ROOT)}: broken links: {broken}"


def test_paths_named_in_sources_and_comments_exist():
    """Every repository path (cpp/..., docs/..., tests/...) and every Markdown file name written
    in a tracked text file exists in the repository (glob patterns and folders count)."""
    markdown_names = {p.name for p in markdown_files()} | OUTPUT_FILES
    broken = []
    for path in tracked_files():
        text = prose(path)
        for name in REPOSITORY_PATH.findall(text):
            name = name.rstrip(".")
            # A prefix followed by a wildcard in the text ("scenarios/poor_*.toml") is a pattern.
            if (ROOT / name).exists() or list(ROOT.glob(name + "*")):
                continue
            broken.append(f"{path.relative_to(ROOT)}: {name}")
        for name in MARKDOWN_NAME.findall(text):
            if name not in markdown_names:
                broken.append(f"{path.relative_to(ROOT)}: {name}")
    assert not broken, "references to files that are not in the repository:\n" + "\n".join(sorted(set(broken)))
