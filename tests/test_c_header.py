"""The C header of the contact laws for DEM codes (issue 18): ``numeric/c/hertzmdr_laws.h``.

A small driver includes the header, reads ``name k v1 ... vk`` lines and prints each result
with ``%.17g`` (both ways exact: Python's repr and glibc's strtod round-trip a double). It is
compiled with the system C compiler as C99 and, when present, as C++ (DEM codes are C++),
with every warning an error; every function is then compared with the NumPy function of the
same name in ``hertzmdr.numeric._generated`` over the domain its comment documents
(:data:`hertzmdr.derive.c_codegen.LAWS`: log-uniform samples, the corners of the box and the
hard cases of the catalogue). Skipped, with the reason, where no compiler is installed.
"""

from __future__ import annotations

import inspect
import re
import shutil
import subprocess
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from hertzmdr.derive.c_codegen import HEADER, LAWS, PREFIX, CLaw
from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric.c import header_path, include_dir

from oracle import Arg, sample

ROOT = Path(__file__).resolve().parents[1]
CC = shutil.which("cc")
CXX = shutil.which("c++")
STRICT = ["-Wall", "-Wextra", "-Werror", "-pedantic"]
N_POINTS = 100  # per law, besides the corners and the hard cases
#: The two routes print the same relation; the header folds the constant factors of a product
#: into one correctly rounded literal and takes x^(p/3) as cbrt(x)^p (NumPy: pow(x, p/3.) with
#: the exponent rounded, 3e-14 off at x = 1e-300). Each rounds up to about 5 ulp in its longest
#: products (the JKR pull-off laws: five cube roots, squares and quotients), so the header is
#: held to 2e-15 (9 ulp) beyond the NumPy route's own error at the same point, both measured
#: against the 30-digit mpmath route of the relation; where a form is ill-conditioned (the JKR
#: radius next to the pull-off force, the stick radius next to full sliding) both carry the same
#: amplified rounding, equal to within a few per mille: hence 1.01 times NumPy's error.
RTOL = 2e-15
DPS = 30
#: the exact ellipse: NumPy takes SciPy's hyp2f1 at m = 1 - t^2 rounded (1e-16 (R1/R2)
#: log(R1/R2), documented in hertzmdr.numeric.ellipse), the header Carlson's R_D at t^2 itself:
#: there the header is held to RTOL of the truth, whatever NumPy's error


def signature(law: CLaw) -> list[str]:
    """The argument names of the law, in call order (those of the NumPy function)."""
    return list(inspect.signature(getattr(gen, law.relation)).parameters)


def points(law: CLaw, n: int = N_POINTS, seed: int = 0) -> dict[str, np.ndarray]:
    """The law's documented domain, sampled: corners and Latin hypercube of ``spans``, the hard
    cases appended, then the arguments of ``where`` computed from them."""
    drawn = sample({k: Arg(s.lo, s.hi, s.log) for k, s in law.spans.items()}, n, seed)
    for case in law.hard:
        for k in drawn:
            drawn[k] = np.append(drawn[k], case[k])
    for name, text in law.where.items():
        expr = sp.sympify(text)
        syms = sorted(expr.free_symbols, key=lambda s: s.name)
        fn = sp.lambdify(syms, expr, modules=["scipy", "numpy"])
        drawn[name] = np.asarray(fn(*(drawn[s.name] for s in syms)), dtype=float)
    return {k: drawn[k] for k in signature(law)}


def driver_source(laws=LAWS) -> str:
    """C source of the driver: one line ``name k v1 .. vk`` in, one ``%.17g`` value out."""
    calls = [("carlson_rd", 3)] + [(law.relation, len(signature(law))) for law in laws]
    cases = "".join(
        f"        {'else ' if i else ''}if (strcmp(name, \"{name}\") == 0 && k == {k})\n"
        f"            r = {PREFIX}{name}({', '.join(f'v[{j}]' for j in range(k))});\n"
        for i, (name, k) in enumerate(calls))
    return f"""\
#include <stdio.h>
#include <string.h>
#include "hertzmdr_laws.h"

int main(void)
{{
    char name[128];
    double v[16], r;
    int k, j;
    while (scanf("%127s %d", name, &k) == 2) {{
        if (k < 0 || k > 16) return 2;
        for (j = 0; j < k; ++j)
            if (scanf("%lf", &v[j]) != 1) return 2;
{cases}        else {{
            fprintf(stderr, "unknown function %s/%d\\n", name, k);
            return 3;
        }}
        printf("%.17g\\n", r);
    }}
    return 0;
}}
"""


def build(compiler: str, tmp: Path, header_dir: Path, cxx: bool = False) -> Path:
    """Compile the driver against the header in ``header_dir``; fail with the compiler's words."""
    src = tmp / "driver.c"
    src.write_text(driver_source())
    exe = tmp / ("driver_cxx" if cxx else "driver_c")
    lang = ["-x", "c++", "-std=c++11"] if cxx else ["-std=c99"]
    cmd = [compiler, *lang, *STRICT, "-O1", "-I", str(header_dir), str(src), "-o", str(exe),
           "-lm"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, " ".join(cmd) + "\n" + done.stderr[-4000:]
    return exe


def run(exe: Path, calls: list[tuple[str, list[np.ndarray]]]) -> list[np.ndarray]:
    """Evaluate every (name, argument arrays) through the driver, in one process."""
    lines = []
    for name, args in calls:
        for row in zip(*args, strict=True):
            lines.append(f"{name} {len(row)} " + " ".join(repr(float(v)) for v in row))
    out = subprocess.run([str(exe)], input="\n".join(lines) + "\n", capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    values = np.array([float(s) for s in out.stdout.split()])
    assert values.size == len(lines)
    res, i = [], 0
    for _, args in calls:
        res.append(values[i:i + len(args[0])])
        i += len(args[0])
    return res


def rel_diff(got: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """|got - ref|/|ref|, 0 where both are exactly equal (zeros included)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        d = np.abs(got - ref) / np.abs(ref)
    return np.where(got == ref, 0.0, d)


@pytest.fixture(scope="module")
def c_driver(tmp_path_factory):
    if CC is None:
        pytest.skip("no C compiler (`cc`) on PATH: the header cannot be compiled here")
    return build(CC, tmp_path_factory.mktemp("c"), include_dir())


@pytest.fixture(scope="module")
def inputs():
    # fewer points for the ellipse, whose 30-digit hyp2f1 near m = 1 costs ~10 ms a point
    return {law.relation: points(law, 30 if law.relation.startswith("ellipse") else N_POINTS)
            for law in LAWS}


@pytest.fixture(scope="module")
def c_values(c_driver, inputs):
    calls = [(law.relation, list(inputs[law.relation].values())) for law in LAWS]
    return dict(zip([law.relation for law in LAWS], run(c_driver, calls), strict=True))


def test_header_is_the_package_data_and_lists_every_law():
    """header_path() is the generated file; its functions are exactly LAWS and R_D."""
    assert header_path() == (ROOT / HEADER).resolve() and header_path().is_file()
    text = header_path().read_text()
    names = set(re.findall(r"static inline double " + PREFIX + r"(\w+)\(", text))
    assert names == {law.relation for law in LAWS} | {"carlson_rd"}
    assert "GENERATED FILE -- DO NOT EDIT" in text and "python -m hertzmdr.derive" in text
    assert re.findall(r"#include <(\w+\.h)>", text) == ["math.h"]


def _numpy(law: CLaw, args: dict[str, np.ndarray]) -> np.ndarray:
    return np.asarray(getattr(gen, law.relation)(**args), dtype=float) * np.ones(
        len(next(iter(args.values()))))


def truth(law: CLaw, args: dict[str, np.ndarray]) -> np.ndarray:
    """The relation at ``args`` by the mpmath route (``_generated_mp``) at 30 digits."""
    fn = getattr(gen_mp, law.relation)
    size = len(next(iter(args.values())))
    with mp.workdps(DPS):
        return np.array([float(fn(*(mp.mpf(float(v[i])) for v in args.values())))
                         for i in range(size)])


@pytest.mark.parametrize("law", LAWS, ids=lambda law: law.relation)
def test_agrees_with_numpy(law, inputs, c_values):
    """Over the documented domain, its corners and its hard cases: the header agrees with the
    NumPy route, and is as accurate, to RTOL beyond the NumPy route's own error."""
    args = inputs[law.relation]
    got, ref, exact = c_values[law.relation], _numpy(law, args), truth(law, args)
    assert np.all(np.isfinite(ref)) and np.all(np.isfinite(got)), law.relation
    err_np, err_c, diff = rel_diff(ref, exact), rel_diff(got, exact), rel_diff(got, ref)
    bound = RTOL + 1.01 * err_np
    where = lambda i: {k: float(v[i]) for k, v in args.items()}  # noqa: E731
    i = int(np.argmax(diff - bound))
    assert diff[i] <= bound[i], (f"{law.relation}: C {got[i]!r} vs NumPy {ref[i]!r} "
                                 f"(relative {diff[i]:.3g}, NumPy's error {err_np[i]:.3g}) "
                                 f"at {where(i)}")
    i = int(np.argmax(err_c - bound))
    assert err_c[i] <= bound[i], (f"{law.relation}: C error {err_c[i]:.3g}, NumPy's "
                                  f"{err_np[i]:.3g} at {where(i)}")
    if law.relation.startswith("ellipse"):
        assert err_c.max() <= RTOL, (law.relation, float(err_c.max()), where(err_c.argmax()))


def test_carlson_rd_to_a_few_ulp(c_driver):
    """R_D(x, y, z) against mpmath's elliprd at 30 digits, over the arguments the ellipse
    uses ((0, t^2, 1) and (0, 1, t^2), t from 1e-150 to 1) and a general log-uniform box.
    Bound: 6 ulp (2^-53 each) -- Carlson's truncation is below one, the rest is rounding in
    the duplication steps and the final sum (measured: 3 ulp at worst, with y -> 0)."""
    t2 = np.geomspace(1e-300, 1.0, 60)
    rng = np.random.default_rng(1)
    box = np.exp(rng.uniform(np.log(1e-20), np.log(1e20), (3, 200)))
    xs = np.concatenate([np.zeros(120), box[0]])
    ys = np.concatenate([t2, np.ones(60), box[1]])
    zs = np.concatenate([np.ones(60), t2, box[2]])
    (got,) = run(c_driver, [("carlson_rd", [xs, ys, zs])])
    with mp.workdps(30):
        truth = np.array([float(mp.elliprd(mp.mpf(x), mp.mpf(y), mp.mpf(z)))
                          for x, y, z in zip(xs, ys, zs, strict=True)])
    err = rel_diff(got, truth)
    assert err.max() <= 6 * 2.0**-53, (float(err.max()), xs[err.argmax()], ys[err.argmax()],
                                       zs[err.argmax()])


def test_cxx_build_gives_the_same_numbers(tmp_path, inputs, c_values):
    """Compiled as C++ (c++ -x c++ -std=c++11, every warning an error), the header gives
    bit-identical results: the same expressions, the same libm."""
    if CXX is None:
        pytest.skip("no C++ compiler (`c++`) on PATH")
    exe = build(CXX, tmp_path, include_dir(), cxx=True)
    calls = [(law.relation, list(inputs[law.relation].values())) for law in LAWS]
    for law, got in zip(LAWS, run(exe, calls), strict=True):
        np.testing.assert_array_equal(got, c_values[law.relation], err_msg=law.relation)


def test_a_changed_constant_is_caught(tmp_path, inputs, c_driver):
    """The comparison can fail: a copy of the header with Hertz's 4/3 printed as 4/3.000001
    compiles, and hertz_force then misses the NumPy value by 3e-7 while the other laws agree."""
    text = header_path().read_text()
    body = text.index("hertzmdr_hertz_force(double")
    i = text.index("(4.0/3.0)", body)
    (tmp_path / "hertzmdr_laws.h").write_text(text[:i] + "(4.0/3.000001)" + text[i + 9:])
    exe = build(CC, tmp_path, tmp_path)
    law = next(law for law in LAWS if law.relation == "hertz_force")
    args = inputs["hertz_force"]
    (got,) = run(exe, [("hertz_force", list(args.values()))])
    assert rel_diff(got, _numpy(law, args)).min() > 1e-7


def test_printer_refuses_what_it_cannot_print():
    """A relation the C printer cannot print (a 2F1 other than the ellipse's two, a function
    C99 lacks) is an error naming it, never a comment or a silent wrong call in the header."""
    from hertzmdr.derive.c_codegen import print_c

    x = sp.Symbol("x", positive=True)
    with pytest.raises(ValueError, match="hyper"):
        print_c(sp.hyper([1, 1], [2], 1 - x**2))
    with pytest.raises(ValueError, match="besselj"):
        print_c(sp.besselj(0, x))
    decls, body = print_c(sp.Rational(4, 3) * sp.sqrt(2) * sp.pi * x ** sp.Rational(3, 2))
    assert decls == [] and body.count("*") == 2 and "pow" not in body  # 5.92...*(x*sqrt(x))
