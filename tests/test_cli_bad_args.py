"""Every subcommand's bad-argument paths (issue 12): unknown flags, missing values, extra
arguments, nonexistent or unreadable files, an --out that cannot be written; each ends in one
line on stderr that starts with ``hertzmdr:``, exit 2, nothing on stdout and nothing written.

Run in-process through ``main(argv)`` in an empty working folder, which is compared before and
after (``hertzmdr accuracy`` writes under the current folder by default).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hertzmdr.numeric.cli import main, parser, tour_scenes

SCENE = str(next(p for p in tour_scenes() if p.stem == "problem1_rail_wheel"))
EXAMPLES = Path(__file__).parents[1] / "examples"
FIT_SCENE = str(EXAMPLES / "fit_colloidal_probe.toml")
FIT_CURVE = str(EXAMPLES / "fit_colloidal_probe_curve.csv")

#: (argv, a word the message must contain); {scene}: a valid scene, {file}: an existing file,
#: {dir}: an existing non-empty folder, {toml}: a file of broken TOML, {binary}: bytes that
#: are not UTF-8, {curve}/{fitscene}: the fit example's curve and tip, {png}: an existing figure
CASES = [
    ([], "required"),
    (["frob"], "invalid choice"),
    (["--bogus"], "required"),  # argparse names the missing command first
    (["run", "--bogus"], "--bogus"),
    (["run", "{scene}", "--out"], "--out"),
    (["run", "{scene}", "extra"], "extra"),
    (["run", "{scene}", "--force=yes"], "--force"),
    (["run", "missing.toml"], "no such file"),
    (["run", "{dir}"], "cannot read"),
    (["run", "{toml}"], "TOML"),
    (["run", "{binary}"], "cannot read"),
    (["run", "{scene}", "--out", "{file}"], "is a file"),
    (["run", "{scene}", "--out", "{file}/sub"], "is a file"),
    (["run", "{scene}", "--out", "{dir}"], "not empty"),
    (["run", "{scene}", "--json", "--out", "{file}"], "is a file"),
    (["effects", "--bogus"], "--bogus"),
    (["effects", "extra"], "extra"),
    (["accuracy", "--bogus"], "--bogus"),
    (["accuracy", "--only"], "--only"),
    (["accuracy", "--only", "no such quantity"], "matches no quantity"),
    (["accuracy", "--out"], "--out"),
    (["accuracy", "--out", "{dir}"], "is a folder"),
    (["accuracy", "--out", "{file}/report.md"], "is a file"),
    (["accuracy", "--quick", "3"], "3"),
    (["fit"], "required"),
    (["fit", "{curve}"], "--scene"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--bogus"], "--bogus"),
    (["fit", "{curve}", "--scene", "{fitscene}", "extra"], "extra"),
    (["fit", "{curve}", "--scene"], "--scene"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--z0"], "--z0"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--z0", "abc"], "--z0"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--z0", "1 s"], "--z0"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--sigma", "1 m"], "--sigma"),
    (["fit", "missing.csv", "--scene", "{fitscene}"], "no such file"),
    (["fit", "{curve}", "--scene", "missing.toml"], "no such file"),
    (["fit", "{curve}", "--scene", "{toml}"], "TOML"),
    (["fit", "{curve}", "--scene", "{scene}"], "flat"),  # two cylinders: no flat sample
    (["fit", "{dir}", "--scene", "{fitscene}"], "cannot read"),
    (["fit", "{binary}", "--scene", "{fitscene}"], "cannot read"),
    (["fit", "{file}", "--scene", "{fitscene}"], "two columns"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--out", "{file}"], "png"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--out", "{png}"], "--force"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--out", "{dir}"], "is a folder"),
    (["fit", "{curve}", "--scene", "{fitscene}", "--out", "{file}/fit.png"], "is a file"),
]


def _tree(root):
    return sorted((str(p.relative_to(root)), p.stat().st_size if p.is_file() else -1)
                  for p in root.rglob("*"))


@pytest.mark.parametrize("argv, word", CASES, ids=[" ".join(a) or "(none)" for a, _ in CASES])
def test_bad_arguments(argv, word, tmp_path, monkeypatch, capsys):
    work = tmp_path / "work"
    work.mkdir()
    (work / "taken.txt").write_text("keep me")
    (work / "folder").mkdir()
    (work / "folder" / "x").write_text("")
    (work / "broken.toml").write_text("title = \n")
    (work / "binary.toml").write_bytes(b"\xff\xfe\x00title")
    (work / "fit.png").write_bytes(b"\x89PNG keep me")
    monkeypatch.chdir(work)
    subs = {"{scene}": SCENE, "{file}": "taken.txt", "{dir}": "folder",
            "{toml}": "broken.toml", "{binary}": "binary.toml", "{png}": "fit.png",
            "{curve}": FIT_CURVE, "{fitscene}": FIT_SCENE}
    args = []
    for a in argv:
        for k, v in subs.items():
            a = a.replace(k, v)
        args.append(a)
    before = _tree(work)
    assert main(args) == 2
    out, err = capsys.readouterr()
    assert out == "", out
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("hertzmdr: "), err
    assert "Traceback" not in err and word in err, (word, err)
    assert _tree(work) == before, "something was written"


def test_every_subcommand_has_bad_argument_cases():
    """A new subcommand fails here until its bad-argument paths are listed above."""
    subs = next(a for a in parser._actions if a.dest == "command").choices
    assert set(subs) <= {a[0] for a, _ in CASES if a}, sorted(subs)


@pytest.mark.parametrize("argv", [["--version"], ["run", "-h"]])
def test_help_and_version_still_exit_0(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip()


#: a place no one can write in, not even root (os.access says yes to root on most file
#: systems; /proc refuses the mkdir itself)
UNWRITABLE = Path("/proc/hertzmdr-cannot-write-here")


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize("argv", [
    ["run", "{scene}", "--out", "{bad}/out"],
    ["accuracy", "--quick", "--out", "{bad}/report.md"],
    ["fit", "{curve}", "--scene", "{fitscene}", "--out", "{bad}/fit.png"],
], ids=["run", "accuracy", "fit"])
def test_out_where_the_file_system_refuses(argv, capsys):
    subs = {"{scene}": SCENE, "{bad}": str(UNWRITABLE), "{curve}": FIT_CURVE,
            "{fitscene}": FIT_SCENE}
    args = [next((a.replace(k, v) for k, v in subs.items() if k in a), a) for a in argv]
    assert main(args) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1, (out, err)
    assert err.startswith("hertzmdr: --out ") and "cannot write in /proc" in err, err
