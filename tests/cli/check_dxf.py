#!/usr/bin/env python3
"""Checks a DXF file written by `pkm dxf` with an independent reader, ezdxf (MIT licence).

Usage: check_dxf.py FILE.dxf [--eval EVAL.json]

EVAL.json is the output of `pkm eval DESIGN --json` for the same design and --set values:
with it the checker also compares the drawing with the design — every link of a known
mechanism kind is a LINE between two pin circles exactly as long as the link (1e-6 mm), and
the dimension texts state the design's lengths and pose.

Checks:
  - ezdxf.readfile() reads it as AC1009 and ezdxf.recover.readfile() audits it without errors;
  - the file is ASCII; the header has $INSUNITS 4 (mm), $EXTMIN and $EXTMAX;
  - the layers GROUND, LINKS, ACTUATORS, GUIDES, JOINTS, DIMENSIONS, TEXT and PATHS exist with
    distinct colours;
  - every coordinate, radius, height and angle is finite, and $EXTMIN/$EXTMAX hold every
    entity (text by its alignment point);
  - every length dimension text "name = 123.45" is the distance between the tips of the two
    arrowheads of its dimension line (the distance between the two joints), to its 2 decimals;
  - every angle label "θ = 12.3°" is the sweep of an angle arc, to its decimals;
  - with --eval: the links' lengths and the dimension texts of the mechanism kind (pjoint,
    fourbar, fivebar, moma, oxglide; another kind gets the generic checks and a note).

Prints one line per failure and "ok: …" at the end; exit status 0 when every check passed,
1 when one failed, 77 when ezdxf is missing (the test skips then).
"""

import argparse
import json
import math
import re
import sys

try:
    import ezdxf
    from ezdxf import recover
except ImportError:  # pragma: no cover - the caller skips
    print("ezdxf is missing: install python3-ezdxf (Debian) or 'pip install ezdxf'")
    sys.exit(77)

LAYERS = ["GROUND", "LINKS", "ACTUATORS", "GUIDES", "JOINTS", "DIMENSIONS", "TEXT", "PATHS"]
LENGTH_TOLERANCE = 1e-6  # mm
UNICODE_ESCAPE = re.compile(r"\\U\+([0-9A-Fa-f]{4})")

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def decode(text):
    """The text as shown: \\U+XXXX escapes and the %%d, %%p, %%c control codes decoded."""
    text = UNICODE_ESCAPE.sub(lambda m: chr(int(m.group(1), 16)), text)
    return text.replace("%%d", "°").replace("%%p", "±").replace("%%c", "⌀")


def finite(*values):
    return all(math.isfinite(v) for v in values)


def points_of(entity):
    """The points that bound an entity, for the finiteness and the extents checks."""
    kind = entity.dxftype()
    if kind == "LINE":
        return [entity.dxf.start, entity.dxf.end]
    if kind == "CIRCLE":
        c, r = entity.dxf.center, entity.dxf.radius
        return [(c[0] - r, c[1] - r, 0.0), (c[0] + r, c[1] + r, 0.0)]
    if kind == "ARC":
        c, r = entity.dxf.center, entity.dxf.radius
        start, end = entity.dxf.start_angle, entity.dxf.end_angle
        sweep = (end - start) % 360.0 or 360.0
        steps = max(2, int(sweep))
        return [(c[0] + r * math.cos(math.radians(start + sweep * k / steps)),
                 c[1] + r * math.sin(math.radians(start + sweep * k / steps)), 0.0) for k in range(steps + 1)]
    if kind == "SOLID":
        return [entity.dxf.vtx0, entity.dxf.vtx1, entity.dxf.vtx2, entity.dxf.vtx3]
    if kind == "POLYLINE":
        return [v.dxf.location for v in entity.vertices]
    if kind == "TEXT":
        points = [entity.dxf.insert]
        if entity.dxf.hasattr("align_point"):
            points.append(entity.dxf.align_point)
        return points
    return []


def scalars_of(entity):
    kind = entity.dxftype()
    if kind in ("CIRCLE", "ARC"):
        values = [entity.dxf.radius]
        if kind == "ARC":
            values += [entity.dxf.start_angle, entity.dxf.end_angle]
        return values
    if kind == "TEXT":
        return [entity.dxf.height, entity.dxf.rotation]
    return []


def text_anchor(entity):
    return entity.dxf.align_point if entity.dxf.hasattr("align_point") else entity.dxf.insert


def distance2d(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dxf")
    parser.add_argument("--eval", dest="eval_json", help="`pkm eval DESIGN --json` output for the same pose")
    options = parser.parse_args()

    with open(options.dxf, "rb") as stream:
        raw = stream.read()
    if any(byte >= 0x80 for byte in raw):
        fail("the file is not plain ASCII")

    try:
        doc = ezdxf.readfile(options.dxf)
    except Exception as error:  # any reader error is the finding
        fail(f"ezdxf.readfile() cannot read it: {error}")
        return
    if doc.dxfversion != "AC1009":
        fail(f"DXF version {doc.dxfversion}, expected AC1009 (R12)")
    try:
        recovered, auditor = recover.readfile(options.dxf)
    except Exception as error:
        fail(f"ezdxf.recover.readfile() cannot read it: {error}")
        return
    if auditor.has_errors:
        fail("ezdxf's audit found errors: " + "; ".join(str(e.message) for e in auditor.errors))
    audit = doc.audit()
    if audit.has_errors:
        fail("ezdxf's audit of the loaded document found errors: " + "; ".join(str(e.message) for e in audit.errors))

    header = doc.header
    if header.get("$INSUNITS") != 4:
        fail(f"$INSUNITS is {header.get('$INSUNITS')}, expected 4 (mm)")
    if "$EXTMIN" not in header or "$EXTMAX" not in header:
        fail("$EXTMIN or $EXTMAX is missing")
        return
    low, high = header["$EXTMIN"], header["$EXTMAX"]

    colours = {}
    for name in LAYERS:
        if name not in doc.layers:
            fail(f"layer {name} is missing")
        else:
            colours[name] = doc.layers.get(name).color
    if len(set(colours.values())) != len(colours):
        fail(f"the layers' colours are not distinct: {colours}")

    msp = doc.modelspace()
    entities = list(msp)
    if not entities:
        fail("the drawing is empty")
    slack = 1e-6 * max(1.0, abs(high[0] - low[0]), abs(high[1] - low[1]))
    for entity in entities:
        if entity.dxf.layer not in LAYERS:
            fail(f"{entity.dxftype()} on layer {entity.dxf.layer}, not a linkage layer")
        points = points_of(entity)
        if not all(finite(p[0], p[1]) for p in points) or not finite(*scalars_of(entity)):
            fail(f"{entity.dxftype()} on {entity.dxf.layer} has a coordinate that is not finite")
            continue
        for p in points:
            if not (low[0] - slack <= p[0] <= high[0] + slack and low[1] - slack <= p[1] <= high[1] + slack):
                fail(f"{entity.dxftype()} on {entity.dxf.layer} at ({p[0]:.3f}, {p[1]:.3f}) lies outside "
                     f"$EXTMIN/$EXTMAX ({low[0]:.3f}, {low[1]:.3f})–({high[0]:.3f}, {high[1]:.3f})")
                break
        if entity.dxftype() == "TEXT" and any(ord(c) >= 0x80 for c in entity.dxf.text):
            fail(f"TEXT {entity.dxf.text!r} is not ASCII")

    # the joints: pin circles; the links: LINEs from pin to pin
    pins = [e.dxf.center for e in msp.query('CIRCLE[layer=="JOINTS"]')]

    def at_pin(p):
        return any(distance2d(p, c) <= LENGTH_TOLERANCE for c in pins)

    bar_lines = {"LINKS": [], "GROUND": []}
    for layer in bar_lines:
        for line in msp.query(f'LINE[layer=="{layer}"]'):
            if at_pin(line.dxf.start) and at_pin(line.dxf.end):
                bar_lines[layer].append(distance2d(line.dxf.start, line.dxf.end))

    # dimensions: "name = 123.45" is the distance between the arrow tips of its dimension line
    dimension_lines = list(msp.query('LINE[layer=="DIMENSIONS"]'))
    # arrowheads: a SOLID's first corner is its tip; it points from the middle of its base
    arrows = []
    for solid in msp.query('SOLID[layer=="DIMENSIONS"]'):
        tip, left, right = solid.dxf.vtx0, solid.dxf.vtx1, solid.dxf.vtx2
        pointing = (tip[0] - (left[0] + right[0]) / 2, tip[1] - (left[1] + right[1]) / 2)
        length = math.hypot(*pointing)
        if length > 0:
            arrows.append(((tip[0], tip[1]), (pointing[0] / length, pointing[1] / length)))

    def on_line(line, a, d, n):
        """Whether a LINE lies on the straight line through a along d (|d| = n)."""
        return all(abs((p[0] - a[0]) * d[1] - (p[1] - a[1]) * d[0]) / n < 1e-6 for p in (line.dxf.start, line.dxf.end))

    arcs = list(msp.query('ARC[layer=="DIMENSIONS"]'))
    lengths = {}  # name → the stated value of each length dimension
    angles = {}
    for text in msp.query('TEXT[layer=="DIMENSIONS"]'):
        shown = decode(text.dxf.text)
        angle = re.fullmatch(r"(.*?)\s*=\s*(-?\d+(?:\.(\d+))?)°", shown)
        if angle:
            value, decimals = abs(float(angle.group(2))), len(angle.group(3) or "")
            angles[angle.group(1)] = value
            sweeps = [abs((a.dxf.end_angle - a.dxf.start_angle) % 360.0) for a in arcs]
            tolerance = 0.5 * 10 ** -decimals + 1e-9
            if value > tolerance and not any(abs(s - value) <= tolerance for s in sweeps):
                fail(f"angle label {shown!r}: no angle arc sweeps {value}° (arcs: {sorted(round(s, 3) for s in sweeps)})")
            continue
        length = re.fullmatch(r"(?:(.*?)\s*=\s*)?(-?\d+\.\d\d)", shown)
        if not length:
            fail(f"dimension text {shown!r} is neither 'name = 123.45' nor an angle")
            continue
        value = float(length.group(2))
        lengths[length.group(1) or ""] = value
        anchor = text_anchor(text)
        direction = (math.cos(math.radians(text.dxf.rotation)), math.sin(math.radians(text.dxf.rotation)))

        # the dimension line of this text: the pair of arrow tips along the text's direction,
        # on a DIMENSIONS line, nearest to the text; its value is the distance between the tips
        best = None
        for i, (a, da) in enumerate(arrows):
            for b, db in arrows[i + 1:]:
                d = (b[0] - a[0], b[1] - a[1])
                n = math.hypot(*d)
                if n <= 0 or abs(d[0] * direction[1] - d[1] * direction[0]) / n > 1e-6:
                    continue
                if abs(d[0] * da[1] - d[1] * da[0]) / n > 1e-6 or abs(d[0] * db[1] - d[1] * db[0]) / n > 1e-6:
                    continue  # an arrowhead that does not point along the line
                if not any(on_line(line, a, d, n) for line in dimension_lines):
                    continue
                middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
                if best is None or distance2d(anchor, middle) < best[0]:
                    best = (distance2d(anchor, middle), n)
        if best is None:
            fail(f"dimension text {shown!r} has no dimension line with two arrowheads along it")
            continue
        measured = best[1]
        if abs(abs(value) - measured) > 0.005 + 1e-9:
            fail(f"dimension text {shown!r} states {abs(value)} mm but its arrow tips are {measured:.6f} mm apart")

    note = ""
    if options.eval_json:
        with open(options.eval_json, encoding="utf-8") as stream:
            report = json.load(stream)
        kind, parameters, pose = report["mechanism"], report["parameters"], report["pose"]

        def links(layer, length, count, name):
            found = sum(1 for l in bar_lines[layer] if abs(l - length) <= LENGTH_TOLERANCE)
            if found < count:
                fail(f"{kind}: expected {count} LINE(s) of {name} = {length} mm from pin to pin on {layer}, found {found} "
                     f"(pin-to-pin lines: {sorted(round(l, 6) for l in bar_lines[layer])})")

        def dimension(name, value):
            if name not in lengths:
                fail(f"{kind}: no dimension text for {name} (found {sorted(lengths)})")
            elif abs(abs(lengths[name]) - abs(value)) > 0.005 + 1e-9:
                fail(f"{kind}: dimension {name} = {lengths[name]}, the design says {value}")

        if kind == "pjoint":
            a, b = parameters["a"], parameters["b"]
            links("LINKS", a, 2, "a")  # the crank BA and the parallel link OC
            links("LINKS", b, 1, "b")  # the coupler CA
            links("GROUND", b, 1, "b")  # the frame OB
            dimension("a", a)
            dimension("b", b)
            dimension("d", pose["d"])
        elif kind == "fourbar":
            for name in ("AB", "BC", "CD"):
                links("LINKS", parameters[name], 1, name)
            links("GROUND", parameters["AD"], 1, "AD")
        elif kind == "fivebar":
            for name in ("AB", "BC", "CD", "DE"):
                links("LINKS", parameters[name], 1, name)
            links("GROUND", parameters["AE"], 1, "AE")
        elif kind == "moma":
            links("LINKS", parameters["l1"], 1, "l1")
            links("LINKS", parameters["l2"], 1, "l2")
            for index, name in ((1, "p₁"), (2, "p₂")):
                p = pose[f"p{index}"]
                if abs(p) > 1.0:
                    dimension(name, p)
        elif kind == "oxglide":
            links("LINKS", parameters["l"], 2, "l")  # the two rods
            links("LINKS", parameters["s"], 1, "s")  # the platform
            links("LINKS", parameters["a"], 1, "a")  # the compensation element of A
        else:
            note = f" (no design checks for the mechanism kind {kind!r}: the generic checks only)"

    if failures:
        sys.exit(1)
    print(f"ok: {len(entities)} entities, {len(pins)} pins, "
          f"{len(bar_lines['LINKS']) + len(bar_lines['GROUND'])} links, {len(lengths)} length dimensions, "
          f"{len(angles)} angles{note}")


if __name__ == "__main__":
    main()
    sys.exit(1 if failures else 0)
