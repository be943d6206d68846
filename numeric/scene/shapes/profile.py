"""A measured axisymmetric tip: samples r, f (or a file of them), solved by the numerical MDR."""

from __future__ import annotations

import math
from pathlib import Path

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class Profile(Shape):
    name = "profile"
    doc = "a measured tip; r starts at 0 and increases"
    keys = (Key("r", "length_list", required=False, doc="samples r = [...] (m)"),
            Key("f", "length_list", required=False, doc="samples f = [...] (m)"),
            Key("file", "path", required=False,
                doc='or file = "tip.csv" (two columns r, f, relative to the scene file)'),
            Key("unit", "length_unit", required=False,
                doc='with file: the unit of both columns, e.g. unit = "nm" (default "m")'),
            Key("breakpoints", "lengths", required=False,
                doc='radii of the tip\'s kinks, each one of the samples r, e.g. breakpoints = '
                    '["1 um"] (m): the spline is not continued across them'))
    kinds = ("numerical_mdr",)

    def check(self, p, fail, base_dir):
        if "file" in p:
            if "r" in p or "f" in p:
                fail("", "give samples r and f, or file, not both")
            r, f = read_samples(base_dir / p.pop("file"), fail)
            scale = p.pop("unit", 1.0)  # the columns' unit in m (schema: kind length_unit)
            p["r"], p["f"] = [v * scale for v in r], [v * scale for v in f]
        elif "unit" in p:
            fail("unit", "is the unit of a sample file's columns; give r and f with their "
                 "units instead (r = [\"0 nm\", \"10 nm\", ...])")
        elif not ("r" in p and "f" in p):
            fail("", "a profile needs samples r = [...] and f = [...], or file = \"...\"")
        r, f = p["r"], p["f"]
        if len(r) != len(f):
            fail("", f"r has {len(r)} samples and f has {len(f)}")
        for j in range(len(r)):
            if not (math.isfinite(r[j]) and math.isfinite(f[j])):
                fail(f"r/f[{j}]", "samples must be finite numbers, not NaN or inf")
        if r[0] != 0 or any(b <= a for a, b in zip(r, r[1:], strict=False)):
            fail("r", "samples must start at r = 0 and increase strictly")
        drop = next((j for j in range(1, len(f)) if f[j] < f[j - 1]), None)
        if drop is not None:
            fail(f"f[{drop}]", f"the profile decreases there (f = {float(f[drop])} m after "
                 f"{float(f[drop - 1]) + 0.0} m, at r = {float(r[drop])} m): the MDR of "
                 "section 5.6 takes a tip that rises from its apex, f non-decreasing in r")

        if "breakpoints" in p:
            p["breakpoints"] = self._breakpoints(p["breakpoints"], r, fail)

    @staticmethod
    def _breakpoints(bps, r, fail):
        """Each breakpoint as the sample r_i it names (to 1e-9 of the largest r: a value with
        another unit than the samples' differs from them by rounding), strictly inside
        (0, r_max) and each once: the numerical MDR's spline ends and restarts there."""
        out = []
        for j, b in enumerate(bps):
            i = min(range(len(r)), key=lambda i: abs(r[i] - b))
            if not 0 < i < len(r) - 1 or abs(r[i] - b) > 1e-9 * r[-1]:
                inner = f"r[1] = {r[1]:.6g} m ... r[{len(r) - 2}] = {r[-2]:.6g} m"
                # the value and its nearest sample in all their digits, and how far apart:
                # at 6 digits 1.0000001 um read as the sample 1 um it misses
                fail(f"breakpoints[{j}]", f"{float(b)!r} m is not one of the samples inside "
                     f"the profile; valid: a sample radius strictly between 0 and r_max = "
                     f"{r[-1]:.6g} m ({inner}; nearest: r[{i}] = {float(r[i])!r} m, "
                     f"{abs(float(r[i]) - float(b)):.3g} m away)")
            if r[i] in out:
                fail(f"breakpoints[{j}]", f"{b:.6g} m is given twice (as r[{i}] = {r[i]:.6g} m); "
                     "valid: each kink once")
            out.append(r[i])
        idx = sorted(r.index(b) for b in out)
        ends = [0, *idx, len(r) - 1]
        short = next((j for j in range(len(ends) - 1) if ends[j + 1] - ends[j] < 2), None)
        if short is not None:
            fail("breakpoints", f"{[float(f'{b:.6g}') for b in sorted(out)]} m leave one sample "
                 f"interval between r = {r[ends[short]]:.6g} m and {r[ends[short + 1]]:.6g} m; "
                 "valid: at least two intervals (three samples) in every piece between 0, the "
                 "breakpoints and r_max (the numerical MDR's error bound compares a piece's "
                 "samples with a coarser set of them)")
        return sorted(out)

    @staticmethod
    def breakpoints(p):
        """The radii [m] of the profile's kinks (samples, sorted): none unless given."""
        return tuple(p.get("breakpoints", ()))

    def samples(self, p):
        """The profile's samples r, f [m] and the spline degree the numerical MDR uses."""
        return p["r"], p["f"], (3 if len(p["r"]) < 20 else 5)


def read_samples(path: Path, fail):
    """Two columns r, f of a text file (commas or spaces, # comments, one header line), in the
    unit the scene's ``unit`` key names (m by default)."""
    from hertzmdr.numeric.scene.columns import read_pairs

    rows = read_pairs(path, lambda msg: fail("file", msg), "sample", "r, f")
    r = [row[0] for _, row in rows]
    f = [row[1] for _, row in rows]
    if len(r) < 2:
        fail("file", f"{path.name} has fewer than two samples")
    return r, f
