#!/usr/bin/env python3
"""Writes the built-in brushes' toolbar icons (CC0-1.0, drawn here, no outside artwork).

Each icon is a 48 x 48 SVG: a rounded square in the brush category's colour (the colours the
modeller's generated fallback icons use, app/gui/brush_icons.cpp) with a white pictogram. It is
written to resources/icons/brushes/<id>.svg and, byte for byte the same, to
plugins/brushes/<id>/icon.svg, which the brush's manifest names: a brush folder stays complete
on its own (the manifest parser refuses an icon outside it). A test checks that the two copies
agree and that every built-in manifest names its icon.

Usage: tools/make_brush_icons.py            (from the repository root or anywhere)
       tools/make_brush_icons.py --check    (exit 1 if a file differs from what this writes)
"""

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

CATEGORY_COLOURS = {"sculpt": "#b8673f", "paint": "#3f78b8", "splat": "#4f9a57"}

W = 'stroke="#fff" stroke-width="3.5" stroke-linecap="round" stroke-linejoin="round" fill="none"'
FILL = 'fill="#fff"'

# The pictogram of each brush, drawn in a 48 x 48 box.
GLYPHS = {
    # A surface line with a bump and an arrow pushing it up.
    "push": f'<path {W} d="M6 36 H14 C18 36 19 22 24 22 C29 22 30 36 34 36 H42"/>'
            f'<path {W} d="M24 17 V6 M19 11 L24 6 L29 11"/>',
    # A circle with arrows swelling out of it.
    "inflate": f'<circle {W} cx="24" cy="24" r="8"/>'
               f'<path {W} d="M24 12 V5 M24 36 V43 M12 24 H5 M36 24 H43"/>',
    # A rough line running into a smooth one.
    "smooth": f'<path {W} d="M5 20 L9 14 L13 22 L17 13 L21 21 C26 17 34 17 43 17"/>'
              f'<path {W} d="M5 34 C16 30 32 30 43 34"/>',
    # A bump cut off by a plane.
    "flatten": f'<path {W} d="M5 36 H11 C14 36 15 24 19 24 H29 C33 24 34 36 37 36 H43"/>'
               f'<path stroke="#fff" stroke-width="2" stroke-dasharray="3 3" d="M5 24 H43"/>',
    # Samples bunched on the left spread out evenly.
    "relax": "".join(f'<circle {FILL} cx="{x}" cy="16" r="2.6"/>' for x in (6, 10, 14, 18, 42))
             + "".join(f'<circle {FILL} cx="{x}" cy="32" r="2.6"/>' for x in (6, 15, 24, 33, 42))
             + f'<path stroke="#fff" stroke-width="2" d="M24 20 V27 M21 24 L24 27 L27 24" fill="none"/>',
    # A ball added to the surface.
    "sphere-add": f'<path {W} d="M5 38 H43"/><circle {W} cx="24" cy="26" r="10"/>'
                  f'<path {W} d="M24 21 V31 M19 26 H29"/>',
    # A ball carved out of the surface.
    "sphere-subtract": f'<path {W} d="M5 16 H14 A10 10 0 0 0 34 16 H43"/>'
                       f'<path {W} d="M19 38 H29"/>',
    # A paint brush.
    "paint": f'<path {W} d="M31 7 L41 17 L24 30 L18 24 Z"/>'
             f'<path {FILL} d="M17 26 L22 31 C21 38 14 42 6 42 C8 37 9 28 17 26 Z"/>',
    # A highlight: a four-pointed sparkle.
    "paint-specular": f'<path {FILL} d="M24 5 C26 18 30 22 43 24 C30 26 26 30 24 43 '
                      f'C22 30 18 26 5 24 C18 22 22 18 24 5 Z"/>',
    # A mirror ball: a circle with a reflected window.
    "paint-reflectivity": f'<circle {W} cx="24" cy="24" r="16"/>'
                          f'<path {FILL} d="M15 17 L22 14 L23 22 L16 25 Z"/>'
                          f'<path {W} d="M29 33 C32 31 34 28 35 25"/>',
    # A stencil: half a circle blocked out.
    "mask": f'<circle {W} cx="24" cy="24" r="15"/>'
            f'<path {FILL} d="M24 9 A15 15 0 0 1 24 39 Z"/>',
    # Bricks laid by a stamp.
    "splat": f'<rect {W} x="6" y="8" width="36" height="32" rx="2"/>'
             f'<path stroke="#fff" stroke-width="2.5" fill="none" '
             f'd="M6 19 H42 M6 29 H42 M20 8 V19 M30 19 V29 M16 29 V40 M34 29 V40"/>',
    # A hand-drawn grip: a region dragged sideways (a bump and an arrow along the surface).
    "grab": f'<path {W} d="M5 36 H12 C17 36 18 20 26 20 C33 20 33 36 38 36 H43"/>'
            f'<path {W} d="M14 12 H34 M29 7 L34 12 L29 17"/>',
    # A limb drawn out along a curved path.
    "snake-hook": f'<path {W} d="M5 40 H14 C16 40 17 33 19 28 C22 20 30 14 40 10"/>'
                  f'<path {W} d="M34 8 L40 10 L38 16"/>',
    # Two arrows meeting at a centre line.
    "pinch": f'<path {W} d="M5 24 H18 M13 19 L18 24 L13 29 M43 24 H30 M35 19 L30 24 L35 29"/>'
             f'<path stroke="#fff" stroke-width="2" d="M24 8 V40"/>',
    # A sharp valley cut into a surface.
    "crease": f'<path {W} d="M5 18 H15 L24 38 L33 18 H43"/>',
    # A raised plateau of even height over the surface.
    "layer": f'<path {W} d="M5 36 H12 L16 22 H32 L36 36 H43"/>'
             f'<path stroke="#fff" stroke-width="2" stroke-dasharray="3 3" d="M16 36 H32"/>',
    # Square strips of clay laid side by side.
    "clay-strips": f'<path {W} d="M5 38 H43"/><rect {W} x="9" y="26" width="10" height="8"/>'
                   f'<rect {W} x="19" y="18" width="10" height="16"/>'
                   f'<rect {W} x="29" y="26" width="10" height="8"/>',
    # A bump scraped flat by a blade.
    "scrape": f'<path {W} d="M5 36 H13 L17 26 H31 L35 36 H43"/>'
              f'<path {W} d="M14 20 L34 20 M30 14 L38 20 L30 26"/>',
    # A circular arrow around a centre.
    "twist": f'<path {W} d="M36 16 A14 14 0 1 0 38 28"/>'
             f'<path {W} d="M31 15 L37 16 L38 10"/><circle {FILL} cx="24" cy="24" r="3"/>',
}

CATEGORIES = {
    "push": "sculpt", "inflate": "sculpt", "smooth": "sculpt", "flatten": "sculpt",
    "relax": "sculpt", "sphere-add": "sculpt", "sphere-subtract": "sculpt",
    "paint": "paint", "paint-specular": "paint", "paint-reflectivity": "paint", "mask": "paint",
    "splat": "splat",
    "grab": "sculpt", "snake-hook": "sculpt", "pinch": "sculpt", "crease": "sculpt",
    "layer": "sculpt", "clay-strips": "sculpt", "scrape": "sculpt", "twist": "sculpt",
}


def svg(brush_id):
    colour = CATEGORY_COLOURS[CATEGORIES[brush_id]]
    return (
        '<svg xmlns="http://www.w3.org/2000/svg" width="48" height="48" viewBox="0 0 48 48">\n'
        f'<!-- Octaclay brush icon "{brush_id}", CC0-1.0, made by tools/make_brush_icons.py -->\n'
        f'<rect x="0" y="0" width="48" height="48" rx="8" fill="{colour}"/>\n'
        f"{GLYPHS[brush_id]}\n"
        "</svg>\n"
    )


def targets(brush_id):
    return [ROOT / "resources" / "icons" / "brushes" / f"{brush_id}.svg",
            ROOT / "plugins" / "brushes" / brush_id / "icon.svg"]


def main():
    check = "--check" in sys.argv[1:]
    stale = []
    for brush_id in sorted(GLYPHS):
        text = svg(brush_id).encode()
        for path in targets(brush_id):
            if check:
                if not path.is_file() or path.read_bytes() != text:
                    stale.append(str(path))
                continue
            path.parent.mkdir(parents=True, exist_ok=True)
            temporary = path.with_suffix(".svg.tmp")
            temporary.write_bytes(text)
            temporary.replace(path)
    if stale:
        print("out of date (run tools/make_brush_icons.py):\n  " + "\n  ".join(stale))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
