"""Two columns of numbers from a text file (numeric/scene/columns.py's read_pairs): the rows
with their line numbers, comments from the first '#', blank lines, one header line, a
byte-order mark; each refusal is one line naming the file, the line number and its text."""

import pytest

from hertzmdr.numeric.scene.columns import read_pairs


class Refused(Exception):
    pass


def _fail(message):
    raise Refused(message)


def _read(path):
    return read_pairs(path, _fail, "sample", "r, f")


def _refusal(path):
    with pytest.raises(Refused) as info:
        _read(path)
    (message,) = info.value.args
    assert isinstance(message, str) and "\n" not in message
    return message


def test_rows_with_their_line_numbers(tmp_path):
    """Line numbers count from 1 and count the blank, comment and header lines; commas and/or
    spaces separate; a comment starts at the first '#' (a second '#' is inside it)."""
    path = tmp_path / "tip.csv"
    path.write_text("# a comment line\n"
                    "r, f\n"
                    "\n"
                    "0, 0   # apex # still the comment\n"
                    "   \n"
                    "1e-4 5e-7\n"
                    "2e-4,\t2e-6#\n")
    assert _read(path) == [(4, (0.0, 0.0)), (6, (1e-4, 5e-7)), (7, (2e-4, 2e-6))]


def test_byte_order_mark_is_skipped(tmp_path):
    """A file saved with a UTF-8 byte-order mark: its first line is a row, not a header."""
    path = tmp_path / "tip.csv"
    path.write_bytes(b"\xef\xbb\xbf1e-6,2e-9\n3e-6,4e-9\n")
    assert _read(path) == [(1, (1e-6, 2e-9)), (2, (3e-6, 4e-9))]


def test_missing_file(tmp_path):
    path = tmp_path / "nothere.csv"
    assert _refusal(path) == f"sample file {str(path)!r} not found"


def test_unreadable_file(tmp_path):
    """Bytes that are not UTF-8: the message names the file and the decoder's reason."""
    path = tmp_path / "tip.csv"
    path.write_bytes(b"0 0\n\xff\xfe 1\n")
    message = _refusal(path)
    assert message.startswith(f"cannot read {str(path)!r} (")
    assert "can't decode byte 0xff" in message


def test_a_directory_is_unreadable(tmp_path):
    assert _refusal(tmp_path).startswith(f"cannot read {str(tmp_path)!r} (")


@pytest.mark.parametrize("text, message", [
    # one header line only: a second one is refused, with its line number
    ("r f\nr f\n0 0\n", "tip.csv line 2: expected two numbers r, f, got 'r f'"),
    # a header after a comment and a blank line, then a bad line
    ("# c\n\nr f\nr\n", "tip.csv line 4: expected two numbers r, f, got 'r'"),
    # no header: a bad line after the first row is refused, not taken as a header
    ("0 0\n1e-4 x\n", "tip.csv line 2: expected two numbers r, f, got '1e-4 x'"),
    ("0 0\n1 2 3\n", "tip.csv line 2: expected two numbers r, f, got '1 2 3'"),
    # the text shown is the line without its comment
    ("0 0\n\n1e-4 # f missing\n", "tip.csv line 3: expected two numbers r, f, got '1e-4'"),
])
def test_bad_lines(tmp_path, text, message):
    path = tmp_path / "tip.csv"
    path.write_text(text)
    assert _refusal(path) == message


def test_a_long_bad_line_is_cut_at_60_characters(tmp_path):
    """The message quotes the first 60 characters of the line (the line has 81)."""
    path = tmp_path / "tip.csv"
    long = "1" * 59 + "ab" + "c" * 20   # characters 60 and 61 are 'a' and 'b'
    path.write_text(f"0 0\n{long}\n")
    assert _refusal(path) == f"tip.csv line 2: expected two numbers r, f, got '{'1' * 59}a'"
