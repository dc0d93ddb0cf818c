"""Spoiled inputs at the command line (issue #11 item 4): every one ends in one line on stderr
that names the file and the key, exit status 2, no traceback, nothing written, in seconds.

Each case runs ``slidespin`` in a subprocess with a time limit, so that a hang (a FIFO read
without a size limit, a 10**8-point grid) fails the test instead of blocking it.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DEMO = (EXAMPLES / "demo.toml").read_text()
SWEEP = (
    'name = "small"\nkind = "random"\nchunk_size = 10\n'
    "[random]\nsamples = 20\nseed = 1\n"
    '[fixed]\na = 0.05\nfx = 0.3\nmass = 1.0\nlaw = "uniform"\n'
    "[vary]\nmu = {low = 0.0, high = 0.3}\nv0 = {low = 0.1, high = 1.0}\n"
)


def run(*args, cwd=None, timeout=60):
    t0 = time.monotonic()
    r = subprocess.run(
        [sys.executable, "-m", "slidespin", *map(str, args)],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=timeout,
    )
    return r, time.monotonic() - t0


def assert_one_line_error(r, *fragments):
    assert r.returncode == 2, (r.returncode, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith("slidespin: error: ")
    assert "Traceback" not in r.stderr and "internal error" not in r.stderr
    for frag in fragments:
        assert frag in lines[0], (frag, lines[0])
    assert r.stdout == ""


def files_in(folder: Path) -> set:
    return {p.name for p in folder.iterdir()}


def with_key(text: str, table: str, line: str) -> str:
    """``text`` with ``line`` added as the first key of ``[table]``."""
    head = f"[{table}]\n"
    assert head in text
    return text.replace(head, head + line + "\n", 1)


# ------------------------------------------------------------------------------ case files
CASE_EDITS = [
    # (name, file text, fragments that must appear in the message)
    (
        "max_steps 2**64",
        with_key(DEMO, "solver", "max_steps = 18446744073709551616"),
        ("[solver] max_steps = 18446744073709551616", "64-bit"),
    ),
    (
        "max_steps too large",
        DEMO + "max_steps = 10000000000\n",
        ("[solver] max_steps = 10000000000", "<= 1000000000"),
    ),
    (
        "huge integer mass",
        DEMO.replace("mass = 1.0", "mass = 100000000000000000000000"),
        ("[body] mass = 100000000000000000000000", "64-bit"),
    ),
    (
        "long name",
        DEMO.replace('name = "demo:', 'name = "' + "x" * 10_000 + " demo:"),
        ("name is 10", "at most 200 characters"),
    ),
    ("deep nesting", DEMO + "[patch.deep]\nv = " + "[" * 50 + "]" * 50 + "\n", ("nested",)),
    ("very deep nesting", "x = " + "[" * 5000 + "]" * 5000 + "\n", ("nested too deeply",)),
    ("not UTF-8", DEMO.replace("demo:", "d\udcffmo:"), ("not UTF-8 text", "offset")),
    # values the physics cannot honour: refused up front (not a hang), naming table and key
    ("speed 1e300", DEMO.replace("speed = 1.0 ", "speed = 1e300 "), ("[initial] speed",)),
    ("mass 5e-324", DEMO.replace("mass = 1.0 ", "mass = 5e-324 "), ("[body] mass",)),
    ("a 1e-200", DEMO.replace("a = 0.1 ", "a = 1e-200 "), ("[patch] a",)),
]


@pytest.mark.parametrize("name, text, fragments", CASE_EDITS, ids=[c[0] for c in CASE_EDITS])
def test_spoiled_case_file(tmp_path, name, text, fragments):
    case = tmp_path / "case.toml"
    case.write_bytes(text.encode("utf-8", errors="surrogateescape"))
    out = tmp_path / "out"
    out.mkdir()
    r, secs = run("simulate", case, "--plot", out / "f.png", "--csv", out / "t.csv")
    assert_one_line_error(r, "case.toml", *fragments)
    assert files_in(out) == set()
    assert secs < 30


def test_case_file_that_is_a_fifo_is_refused_quickly(tmp_path):
    fifo = tmp_path / "case.toml"
    os.mkfifo(fifo)
    r, secs = run("simulate", fifo, timeout=30)
    assert_one_line_error(r, "case.toml", "not a regular file")
    assert secs < 20


def test_dev_zero_is_refused_quickly():
    r, secs = run("simulate", "/dev/zero", timeout=30)
    assert_one_line_error(r, "/dev/zero", "not a regular file")
    assert secs < 20


def test_ten_megabyte_case_file_is_refused_without_reading_it(tmp_path):
    big = tmp_path / "big.toml"
    big.write_text(DEMO + "# " + "x" * 10_000_000 + "\n")
    r, secs = run("simulate", big)
    assert_one_line_error(r, "big.toml", "10000", "at most 1000000 bytes")
    assert secs < 20


def test_read_toml_caps_the_bytes_read(tmp_path):
    from slidespin.studies.case import read_toml

    p = tmp_path / "c.toml"
    p.write_text("a = 1\n" + "#" * 200 + "\n")
    assert read_toml(p, "case file") == {"a": 1}
    with pytest.raises(ValueError, match="at most 100 bytes"):
        read_toml(p, "case file", max_bytes=100)


# ------------------------------------------------------------------------------ sweep specs
def spec_with(table: str, line: str) -> str:
    return with_key(SWEEP, table, line)


SPEC_EDITS = [
    (
        "samples 10**12",
        SWEEP.replace("samples = 20", "samples = 1000000000000"),
        ("[random] samples = 1000000000000", "<= 10000000"),
    ),
    (
        "grid num 10**8",
        'kind = "grid"\n[fixed]\na = 0.05\nfx = 0.3\n'
        "[vary]\nmu = {start = 0.0, stop = 0.3, num = 100000000}\n",
        ("[vary] mu.num = 100000000", "<= 1000000"),
    ),
    (
        "grid of too many cases",
        'kind = "grid"\n[fixed]\na = 0.05\nfx = 0.3\n'
        "[vary]\nmu = {start = 0.0, stop = 0.3, num = 10000}\n"
        "v0 = {start = 0.1, stop = 1.0, num = 10000}\n",
        ("10000 x 10000 = 100000000 cases", "at most 10000000"),
    ),
    (
        "log with low <= 0",
        SWEEP.replace("v0 = {low = 0.1, high = 1.0}", "v0 = {low = 0.0, high = 1.0, log = true}"),
        ("[vary] v0", "low > 0"),
    ),
    (
        "low > high",
        SWEEP.replace("v0 = {low = 0.1, high = 1.0}", "v0 = {low = 1.0, high = 0.1}"),
        ("[vary] v0", "low = 1.0 > high = 0.1"),
    ),
    (
        "range overflows",
        SWEEP.replace("v0 = {low = 0.1, high = 1.0}", "x0 = {low = -1e308, high = 1e308}"),
        ("[vary] x0", "overflows"),
    ),
    (
        "seed 2**64",
        SWEEP.replace("seed = 1", "seed = 18446744073709551616"),
        ("[random] seed = 18446744073709551616", "64-bit"),
    ),
    (
        "chunk_size too large",
        SWEEP.replace("chunk_size = 10", "chunk_size = 100000000"),
        ("chunk_size = 100000000", "<= 1000000"),
    ),
    (
        "long name",
        SWEEP.replace('name = "small"', 'name = "' + "y" * 5000 + '"'),
        ("name is 5000 characters",),
    ),
    (
        "log flag not a bool",
        SWEEP.replace("v0 = {low = 0.1, high = 1.0}", 'v0 = {low = 0.1, high = 1.0, log = "yes"}'),
        ("[vary] v0.log = 'yes'",),
    ),
]


@pytest.mark.parametrize("name, text, fragments", SPEC_EDITS, ids=[c[0] for c in SPEC_EDITS])
def test_spoiled_sweep_spec(tmp_path, name, text, fragments):
    spec = tmp_path / "spec.toml"
    spec.write_text(text)
    r, secs = run("sweep", spec, "--out", tmp_path / "run", "--quiet")
    assert_one_line_error(r, "spec.toml", *fragments)
    assert not (tmp_path / "run").exists()
    assert secs < 30


def test_sweep_spec_fifo_is_refused(tmp_path):
    fifo = tmp_path / "spec.toml"
    os.mkfifo(fifo)
    r, _ = run("sweep", fifo, "--out", tmp_path / "run", timeout=30)
    assert_one_line_error(r, "spec.toml", "not a regular file")
    assert not (tmp_path / "run").exists()
