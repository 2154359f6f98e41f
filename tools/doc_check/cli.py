"""`tools/doc-check`: the docs' figures against the committed rows and their references
against the tree. `check` (the default) fails on any difference and says where; `update`
rewrites the marked figures and tables from the rows; `figures` lists what a marker may
name."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import (experiment_figures, markers, project_figures, references, scenario_figures,
               sweep_figures, tables)

ROOT = Path(__file__).resolve().parents[2]
EXPERIMENT = Path("docs/experiment")
SCENARIOS = Path("docs/scenarios/scenarios.csv")


def registry(root: Path) -> tuple[dict, dict]:
    experiment = experiment_figures.ExperimentRows(root / EXPERIMENT)
    figures = experiment_figures.figures(experiment)
    figures.update(scenario_figures.figures(scenario_figures.ScenarioRows(root / SCENARIOS)))
    figures.update(sweep_figures.figures((root / SCENARIOS).parent))
    figures.update(project_figures.figures(root))
    return figures, tables.tables(experiment, root / SCENARIOS)


def marked_docs(root: Path) -> list[str]:
    return [name for name in references.tracked_files(root) if name.endswith(".md")
            and ("<!--=" in (text := (root / name).read_text(encoding="utf-8"))
                 or "<!-- figures:" in text)]


def check(root: Path) -> int:
    figures, blocks = registry(root)
    problems = []
    docs = marked_docs(root)
    marks = 0
    for name in docs:
        text = (root / name).read_text(encoding="utf-8")
        marks += len(markers.INLINE.findall(text)) + len(markers.BLOCK.findall(text))
        problems += [p.text(name) for p in markers.check(text, figures, blocks)]
    broken = [b.text() for b in references.check(root)]
    for line in problems + broken:
        print(line, file=sys.stderr)
    print(f"doc-check: {marks} figures and tables in {len(docs)} docs, {len(problems)} "
          f"differ from the rows; {len(broken)} references do not resolve")
    if problems:
        print("A figure differs from the rows: correct the rows' reading, or run "
              "`tools/doc-check update` after the rows changed.", file=sys.stderr)
    return 1 if problems or broken else 0


def update(root: Path) -> int:
    figures, blocks = registry(root)
    for name in marked_docs(root):
        path = root / name
        text = path.read_text(encoding="utf-8")
        try:
            new = markers.update(text, figures, blocks)
        except markers.FigureError as error:
            print(f"{name}: {error}", file=sys.stderr)
            return 1
        if new != text:
            path.write_text(new, encoding="utf-8")
            print(f"doc-check: updated {name}")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="tools/doc-check", description=__doc__)
    parser.add_argument("command", nargs="?", default="check",
                        choices=("check", "update", "figures"))
    args = parser.parse_args(argv)
    if args.command == "figures":
        figures, blocks = registry(ROOT)
        print("figures: " + ", ".join(sorted(figures)))
        print("tables:  " + ", ".join(sorted(blocks)))
        return 0
    return check(ROOT) if args.command == "check" else update(ROOT)
