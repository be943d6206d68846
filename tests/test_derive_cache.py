"""The disk cache of derived relations (hertzmdr.derive._cache): it returns what was derived,
derives afresh when the cache is off, unreadable or its key changes, and a bad setting is one
clear error."""

import subprocess
import sys

import pytest

from hertzmdr.derive import _cache


@pytest.fixture
def folder(tmp_path, monkeypatch):
    monkeypatch.setenv("HERTZMDR_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("HERTZMDR_DERIVE_CACHE", raising=False)
    return tmp_path


def counting(value):
    calls = []

    def derive():
        calls.append(1)
        return value

    return derive, calls


def test_second_call_reads_what_the_first_derived(folder):
    derive, calls = counting({"x": (1, 2.5)})
    assert _cache.cached(derive) == ({"x": (1, 2.5)}, "derived")
    assert _cache.cached(derive) == ({"x": (1, 2.5)}, "cache")
    assert len(calls) == 1
    assert [p.suffix for p in folder.glob("relations-*")] .count(".pickle") == 1


@pytest.mark.parametrize("setting, expect", [("0", "derived, cache off"), ("refresh", "derived")])
def test_off_and_refresh_derive_every_time(folder, monkeypatch, setting, expect):
    derive, calls = counting([3])
    _cache.cached(derive)
    monkeypatch.setenv("HERTZMDR_DERIVE_CACHE", setting)
    assert _cache.cached(derive) == ([3], expect)
    assert len(calls) == 2


def test_a_truncated_cache_file_is_derived_afresh(folder):
    derive, calls = counting(list(range(1000)))
    _cache.cached(derive)
    (path,) = folder.glob("relations-*.pickle")
    path.write_bytes(path.read_bytes()[:50])
    assert _cache.cached(derive) == (list(range(1000)), "derived")
    assert len(calls) == 2


def test_the_key_follows_the_sources(folder, monkeypatch):
    """Any change to a derive source changes the key: an edited family is never read from an
    older cache."""
    before = _cache.key()
    real = _cache.Path.read_bytes

    def edited(self):
        data = real(self)
        return data + b"# edited" if self.name == "hertz.py" else data

    monkeypatch.setattr(_cache.Path, "read_bytes", edited)
    assert _cache.key() != before


def test_a_bad_setting_is_one_clear_error(folder, monkeypatch):
    monkeypatch.setenv("HERTZMDR_DERIVE_CACHE", "yes")
    with pytest.raises(ValueError, match=r"HERTZMDR_DERIVE_CACHE='yes': use 1 .* refresh .* 0"):
        _cache.cached(lambda: 1)


@pytest.mark.parametrize("var, value", [("HERTZMDR_DERIVE_CACHE", "maybe"),
                                        ("HERTZMDR_DERIVE_JOBS", "two")])
def test_the_command_line_names_a_bad_setting(tmp_path, var, value):
    env = {"HERTZMDR_CACHE_DIR": str(tmp_path), var: value, "PATH": "/usr/bin:/bin"}
    out = subprocess.run([sys.executable, "-m", "hertzmdr.derive", "--check"],
                         capture_output=True, text=True, env=env)
    assert out.returncode == 2
    assert "Traceback" not in out.stderr
    assert out.stderr.strip().splitlines() == [
        next(line for line in out.stderr.splitlines() if var in line)]
    assert f"{var}={value!r}" in out.stderr


def test_named_results_are_kept_apart(folder):
    """A result cached under another name (derive/stress.py's axis stresses) has its own file:
    it neither reads nor replaces the relations'."""
    rel, rel_calls = counting(["relations"])
    axis, axis_calls = counting(["axis"])
    assert _cache.cached(rel) == (["relations"], "derived")
    assert _cache.cached(axis, "stress-axis") == (["axis"], "derived")
    assert _cache.cached(rel) == (["relations"], "cache")
    assert _cache.cached(axis, "stress-axis") == (["axis"], "cache")
    assert (len(rel_calls), len(axis_calls)) == (1, 1)
    assert len(list(folder.glob("stress-axis-*.pickle"))) == 1
