"""Lays screenshots side by side into one picture for the docs (tools/pictures.sh).

    picture_compose.py OUT.png --height=H PANEL [PANEL ...] [/ PANEL ...]

A PANEL is `PATH` (the whole screenshot) or `PATH@X,Y,W,H` (that box of it, zoomed). Every
panel is scaled to the same height H and the panels are laid left to right; a `/` starts a
row below (a before/after: the same frames in two rows). Pillow comes with matplotlib,
which the tools' venv pins.
"""

import argparse
import sys

from PIL import Image


def panel(spec: str, height: int) -> Image.Image:
    """The screenshot `spec` names, cropped to its box if it gives one, `height` tall."""
    path, _, box = spec.partition("@")
    picture = Image.open(path).convert("RGB")
    if box:
        x, y, w, h = (int(v) for v in box.split(","))
        if w <= 0 or h <= 0 or x + w > picture.width or y + h > picture.height:
            raise ValueError(f"{spec}: the box is not inside the {picture.size} picture")
        picture = picture.crop((x, y, x + w, y + h))
    width = round(picture.width * height / picture.height)
    return picture.resize((width, height), Image.LANCZOS)


def row(specs: list[str], height: int) -> Image.Image:
    """The panels `specs` name, left to right."""
    panels = [panel(spec, height) for spec in specs]
    laid = Image.new("RGB", (sum(p.width for p in panels), height))
    x = 0
    for p in panels:
        laid.paste(p, (x, 0))
        x += p.width
    return laid


def compose(out: str, specs: list[str], height: int) -> None:
    rows, current = [], []
    for spec in specs + ["/"]:
        if spec == "/":
            if not current:
                raise ValueError("an empty row")
            rows.append(row(current, height))
            current = []
        else:
            current.append(spec)
    picture = Image.new("RGB", (max(r.width for r in rows), height * len(rows)))
    for i, laid in enumerate(rows):
        picture.paste(laid, (0, i * height))
    picture.save(out, optimize=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--height", type=int, required=True)
    parser.add_argument("panels", nargs="+")
    args = parser.parse_args()
    try:
        compose(args.out, args.panels, args.height)
    except (OSError, ValueError) as error:
        print(f"picture_compose: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
