"""References that must resolve: in the docs and in the code's comments, every path into
the project's folders names a file or folder that exists, every Markdown link reaches its
file and heading, and every section cited as `name.md, "Heading"` is a heading there."""

from __future__ import annotations

import re
import subprocess
from dataclasses import dataclass
from pathlib import Path

# Paths into the project's own folders, as prose and comments write them (a run of
# one bike with another's network is a folder such as docs/experiment/naked_700+street_390).
PATH = re.compile(r"(?<![\w./+-])((?:docs|tools|scripts|scenes|native|tests|addons|models|\.ci)"
                  r"/[\w./+-]*[\w])")
LINK = re.compile(r"\]\(([^)\s]+)\)")
# `results.md, "Planners side by side"` or `results.md "Lean reversals"`.
SECTION = re.compile(r"([\w./-]+\.md)(?:'s)?,? \"([A-Za-z][^\"]*)\"")
# Comment leaders that a quoted section title may run across.
COMMENT_BREAK = re.compile(r"\n[ \t]*(?:#+|//+!?|;+)?[ \t]*")
# Written by the build or a run, never committed.
GENERATED = ("build", "native/target", "addons/cpbp/bin", ".godot", ".venv")
CHECKED_SUFFIXES = (".md", ".rs", ".gd", ".py", ".sh", ".toml", ".cfg", ".tscn", ".json")
# A path that goes on as a pattern (tools/windows-*.sh, ode-<key>/, $dir) names no one file.
PATTERN_GOES_ON = "*<{$"
# Made-up paths: the unit tests' fixtures and this checker's own examples.
NOT_CHECKED = re.compile(r"(^|/)test_[^/]*\.py$|^tools/doc_check/")


@dataclass(frozen=True)
class Broken:
    file: str
    line: int
    message: str

    def text(self) -> str:
        return f"{self.file}:{self.line}: {self.message}"


def tracked_files(root: Path) -> list[str]:
    listed = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=root,
                            check=True, capture_output=True, text=True).stdout.split("\n")
    return [f for f in listed if f and (root / f).exists()]


def slug(heading: str) -> str:
    """A heading's anchor as GitHub makes it: lower case, punctuation dropped, spaces to -."""
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def headings(path: Path) -> list[str]:
    in_code = False
    found = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            in_code = not in_code
        elif not in_code and (m := re.match(r"#{1,6} +(.*?)\s*#*$", line)):
            found.append(m.group(1))
    return found


class Tree:
    def __init__(self, root: Path):
        self.root = root
        self.files = set(tracked_files(root))
        self.folders = {str(Path(f).parent) for f in self.files}
        self.folders |= {str(p) for f in self.files for p in Path(f).parents}
        self.crates = [str(Path(f).parent) for f in self.files
                       if f.startswith("native/") and f.endswith("/Cargo.toml")]
        self._headings: dict[str, list[str]] = {}

    def exists(self, path: str, near: str = "") -> bool:
        """Whether `path` names a file or folder from the root, from the Cargo crate the
        citing file `near` is in (Rust writes tests/rides/feet.rs), or a Godot resource
        without its ending (tests/saves/save_stress for its .tscn)."""
        path = path.rstrip("/.")
        bases = [""] + [f"{c}/" for c in self.crates if near.startswith(f"{c}/")]
        return path.startswith(GENERATED) or any(
            candidate in self.files or candidate in self.folders
            or f"{candidate}.tscn" in self.files
            for candidate in (base + path for base in bases))

    def headings_of(self, path: str) -> list[str]:
        if path not in self._headings:
            self._headings[path] = headings(self.root / path)
        return self._headings[path]

    def markdown_named(self, name: str, near: str) -> list[str]:
        """The tracked Markdown files `name` may mean: a path from the root or from the
        citing file's folder, else any file of that base name."""
        for candidate in (name, str(Path(near).parent / name)):
            candidate = str(Path(candidate))
            if candidate in self.files:
                return [candidate]
        return [f for f in self.files if Path(f).name == Path(name).name]


def _line(text: str, offset: int) -> int:
    return text.count("\n", 0, offset) + 1


def check_file(tree: Tree, name: str) -> list[Broken]:
    text = (tree.root / name).read_text(encoding="utf-8", errors="replace")
    broken = []
    for m in PATH.finditer(text):
        goes_on = any(c in PATTERN_GOES_ON for c in text[m.end():m.end() + 2])
        placeholder = any(part.isupper() for part in m.group(1).split("/"))
        if goes_on or placeholder or NOT_CHECKED.search(name):
            continue
        if not tree.exists(m.group(1), name):
            broken.append(Broken(name, _line(text, m.start()),
                                 f"no such file or folder: {m.group(1)}"))
    if name.endswith(".md"):
        broken += _links(tree, name, text)
    joined = COMMENT_BREAK.sub(" ", text)
    for m in SECTION.finditer(joined):
        documents = tree.markdown_named(m.group(1), name)
        wanted = m.group(2).lower()
        if not any(wanted in h.lower() for d in documents for h in tree.headings_of(d)):
            where = text.find(m.group(1))
            broken.append(Broken(name, _line(text, max(where, 0)),
                                 f"{m.group(1)} has no section \"{m.group(2)}\""))
    return broken


def _links(tree: Tree, name: str, text: str) -> list[Broken]:
    broken = []
    for m in LINK.finditer(text):
        target = m.group(1)
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        resolved = str(Path(name).parent / path) if path else name
        resolved = str(Path(resolved)).replace("\\", "/")
        resolved = _normalise(resolved)
        if path and not tree.exists(resolved):
            broken.append(Broken(name, _line(text, m.start()), f"link to a missing file: {target}"))
        elif anchor and resolved.endswith(".md") and \
                anchor not in {slug(h) for h in tree.headings_of(resolved)}:
            broken.append(Broken(name, _line(text, m.start()),
                                 f"link to a missing heading: {target}"))
    return broken


def _normalise(path: str) -> str:
    parts: list[str] = []
    for part in path.split("/"):
        if part == "..":
            parts = parts[:-1]
        elif part not in ("", "."):
            parts.append(part)
    return "/".join(parts)


def check(root: Path) -> list[Broken]:
    tree = Tree(root)
    broken = []
    for name in sorted(tree.files):
        if (name.endswith(CHECKED_SUFFIXES) or Path(name).parent.name == "tools") \
                and not NOT_CHECKED.search(name):
            broken += check_file(tree, name)
    return broken
