"""The figure functions write PNG files (Fig. 5.8 and Fig. 5.9)."""

import pytest

pytest.importorskip("matplotlib")

from hertzmdr.numeric import plots  # noqa: E402


def test_figures_are_written(tmp_path):
    for fn, name in ((plots.axis_stresses_figure, "a.png"), (plots.von_mises_figure, "b.png")):
        out = fn(tmp_path / name, nu=0.3)
        data = out.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000


def test_bad_nu_is_named(tmp_path):
    with pytest.raises(ValueError, match="nu = 0.7"):
        plots.axis_stresses_figure(tmp_path / "x.png", nu=0.7)
