"""Bad input is rejected before any work, with a message naming parameter, value and range."""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.studies.case import case_from_dict

BAD_CONSTRUCTORS = [
    (lambda: ss.Ellipse(0.0, 1.0), "a = 0.0"),
    (lambda: ss.Ellipse(1.0, -2.0), "b = -2.0"),
    (lambda: ss.Ellipse(math.nan, 1.0), "a = nan"),
    (lambda: ss.Ellipse(1.0, math.inf), "b = inf"),
    (lambda: ss.Ellipse("1", 1.0), "a must be a real number"),
    (lambda: ss.Ellipse.from_eccentricity(1.0, 1.0), "eccentricity = 1.0"),
    (lambda: ss.Ellipse.from_eccentricity(1.0, -0.1), "eccentricity = -0.1"),
    (lambda: ss.Circle(-1.0), "radius = -1.0"),
    (lambda: ss.FrictionTensor(0.0, 0.3), "fx = 0.0"),
    (lambda: ss.FrictionTensor(0.3, -0.1), "fy = -0.1"),
    (lambda: ss.FrictionTensor(0.3, 0.3, f=math.inf), "f = inf"),
    (lambda: ss.FrictionTensor(0.3, 0.3, frame="world"), "frame = 'world'"),
    (lambda: ss.LinearPressure(math.nan, 0.0), "xi_c = nan"),
    (lambda: ss.Body(ss.Circle(1.0), ss.UniformPressure(), mass=0.0), "mass = 0.0"),
    (lambda: ss.Body(ss.Circle(1.0), ss.UniformPressure(), 1.0, -1.0), "moment_of_inertia = -1.0"),
    (lambda: ss.Body(ss.Ellipse(1.0, 1.0), ss.LinearPressure(0.3, 0.0), 1.0), "outside the core"),
    (lambda: ss.Body(ss.Circle(1.0), ss.LinearPressure(0.3, 0.0), 1.0), "turns negative"),
    (lambda: ss.Body(ss.Circle(1.0), "uniform", 1.0), "pressure = 'uniform'"),
    (lambda: ss.Body((1.0, 1.0), ss.UniformPressure(), 1.0), "patch = (1.0, 1.0)"),
    (lambda: ss.State(vx=math.nan), "vx = nan"),
    (lambda: ss.State.from_speed(-1.0, 1.0), "speed = -1.0"),
]


@pytest.mark.parametrize("make, fragment", BAD_CONSTRUCTORS)
def test_constructors_reject_bad_values(make, fragment):
    with pytest.raises(ValueError) as err:
        make()
    assert fragment in str(err.value)
    msg = str(err.value)
    assert "valid" in msg or "must be" in msg


def test_linear_law_core_boundary_is_accepted():
    # (xi_c/a)^2 + (eta_c/b)^2 = 1/16 exactly: p vanishes at one rim point, still valid
    ss.Body(ss.Ellipse(1.0, 0.5), ss.LinearPressure(0.25, 0.0), 1.0)


def test_api_functions_reject_bad_arguments():
    body = ss.Body(ss.Circle(1.0), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(ValueError, match="g = 0.0"):
        ss.friction_wrench(body, fr, 1.0, 0.0, 0.0, g=0.0)
    with pytest.raises(ValueError, match="omega = nan"):
        ss.friction_wrench(body, fr, 1.0, 0.0, math.nan)
    with pytest.raises(ValueError, match="do not broadcast"):
        ss.friction_wrench(body, fr, [1.0, 2.0], [0.0, 1.0, 2.0], 0.0)
    with pytest.raises(ValueError, match="rtol = 0.1"):
        ss.simulate(body, fr, ss.State(vx=1.0), rtol=0.1)
    with pytest.raises(ValueError, match="initial_state"):
        ss.simulate(body, fr, (0, 0, 0, 1, 0, 0))
    with pytest.raises(ValueError, match="max_steps"):
        ss.simulate(body, fr, ss.State(vx=1.0), max_steps=0)


def good_case():
    return {
        "patch": {"a": 0.1, "eccentricity": 0.5},
        "pressure": {"law": "uniform"},
        "friction": {"fx": 0.3, "fy": 0.4},
        "body": {"mass": 1.0},
        "initial": {"speed": 1.0, "omega": 2.0},
    }


def test_good_case_loads():
    case = case_from_dict(good_case())
    assert case.body.patch.b == pytest.approx(0.1 * math.sqrt(0.75))


BAD_CASES = [
    (("patch", "eccentricity", 1.2), "eccentricity = 1.2"),
    (("patch", "a", -1.0), "a = -1.0"),
    (("patch", "aa", 1.0), "unknown key 'aa' in [patch]"),
    (("pressure", "law", "parabolic"), "pressure law = 'parabolic'"),
    (("pressure", "xi_c", 0.01), "takes no parameter 'xi_c'"),
    (("friction", "fx", 0.0), "fx = 0.0"),
    (("friction", "frame", "world"), "frame = 'world'"),
    (("body", "mass", "heavy"), "mass must be a real number"),
    (("body", "inertia_ratio", 0.0), "inertia_ratio = 0.0"),
    (("initial", "omgea", 1.0), "unknown key 'omgea' in [initial]"),
    (("initial", "vx", 1.0), "either speed/theta or vx/vy"),
    (("solver", "rtol", 1.0), "rtol = 1.0"),
    (("solver", "g", -9.81), "g = -9.81"),
]


@pytest.mark.parametrize("edit, fragment", BAD_CASES)
def test_case_files_reject_bad_entries(edit, fragment):
    data = good_case()
    table, key, value = edit
    data.setdefault(table, {})[key] = value
    with pytest.raises(ValueError) as err:
        case_from_dict(data)
    assert fragment in str(err.value)


def test_case_missing_table_and_key():
    data = good_case()
    del data["friction"]
    with pytest.raises(ValueError, match=r"missing the table \[friction\]"):
        case_from_dict(data)
    data = good_case()
    del data["body"]["mass"]
    with pytest.raises(ValueError, match=r"\[body\] is missing the required key 'mass'"):
        case_from_dict(data)
    data = good_case()
    data["sovler"] = {}
    with pytest.raises(ValueError, match="unknown table or key 'sovler'"):
        case_from_dict(data)


# ------------------------------------------------------------------------------------------
# issue 11: the edges of the valid ranges, angle_deg, and import anywhere
# ------------------------------------------------------------------------------------------
def _just_outside(x, direction):
    return math.nextafter(x, direction)


EDGES = [
    (lambda x: ss.Ellipse(x, x), 1e-9, 1e6, "a = "),
    (lambda x: ss.Circle(x), 1e-9, 1e6, "radius = "),
    (lambda x: ss.Ellipse(1.0, x), 1e-3, 30.0, "b/a = "),
    (lambda x: ss.Body(ss.Circle(0.1), ss.UniformPressure(), x), 1e-12, 1e12, "mass = "),
    (
        lambda x: ss.Body.from_inertia_ratio(ss.Circle(0.1), ss.HertzPressure(), 2.0, x),
        1e-8,
        1e8,
        "inertia_ratio = ",
    ),
    (lambda x: ss.FrictionTensor(x, 0.3), 1e-6, 5.0, "fx = "),
    (lambda x: ss.FrictionTensor(0.3, 0.3, f=x), -5.0, 5.0, "f = "),
    (lambda x: ss.State(vx=x), -1e8, 1e8, "vx = "),
    (lambda x: ss.State(omega=x), -1e12, 1e12, "omega = "),
]


@pytest.mark.parametrize("make, lo, hi, name", EDGES, ids=[e[3].strip(" =") for e in EDGES])
def test_range_edges_are_in_and_the_next_floats_out(make, lo, hi, name):
    make(lo)
    make(hi)
    for x in (_just_outside(lo, -math.inf), _just_outside(hi, math.inf)):
        with pytest.raises(ValueError) as err:
            make(x)
        assert name in str(err.value) and "valid range" in str(err.value)


def test_inertia_ratio_bound_applies_to_an_explicit_inertia():
    body = ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), 2.0, 1e8 * 2.0 * 0.01)
    assert body.inertia_ratio == pytest.approx(1e8)
    with pytest.raises(
        ValueError, match=r"I/\(m a\^2\) = 1.1e\+08; valid range: \[1e-08, 1e\+08\]"
    ):
        ss.Body(ss.Ellipse(0.1, 0.1), ss.UniformPressure(), 2.0, 1.1e8 * 2.0 * 0.01)
    # a disk (Circle) measures I* in units of its extent, the radius
    with pytest.raises(ValueError, match=r"I/\(m extent\^2\) = 1.1e\+08"):
        ss.Body(ss.Circle(0.1), ss.UniformPressure(), 2.0, 1.1e8 * 2.0 * 0.01)


def test_friction_angle_in_degrees():
    a = ss.FrictionTensor(0.3, 0.4, f=0.05, frame="body", angle_deg=30.0)
    b = ss.FrictionTensor(0.3, 0.4, f=0.05, frame="body", angle=math.radians(30.0))
    assert a == b and a.angle == math.radians(30.0)
    assert a.angle_deg == pytest.approx(30.0, rel=1e-15)
    assert ss.FrictionTensor.from_degrees(0.3, 0.4, angle_deg=90.0).world_matrix() == pytest.approx(
        np.array([[0.4, 0.0], [0.0, 0.3]]), abs=1e-15
    )  # axes turned by 90°: fx and fy swap
    assert ss.FrictionTensor(0.3, 0.4).angle_deg == 0.0
    with pytest.raises(ValueError, match="gives both angle"):
        ss.FrictionTensor(0.3, 0.4, angle=0.2, angle_deg=30.0)


_IMPORT_ANYWHERE = r"""
import math, os, sys, warnings
warnings.simplefilter("always")
if os.environ.get("SLIDESPIN_TEST_NO_TMP"):
    import tempfile
    def refuse(*args, **kwargs):
        raise PermissionError("no temporary directory either")
    tempfile.mkdtemp = refuse
import slidespin as ss
import slidespin.contact._engine  # the compiled modules: declaring their functions needs a cache
from slidespin import _jit
assert os.path.dirname(ss.__file__).startswith(sys.argv[1]), ss.__file__
@_jit.jit
def f(x):
    return 2.0 * math.sqrt(x)
assert f(4.0) == 4.0
print("dir", _jit._fallback["dir"])
"""


def _run_import_anywhere(tmp, extra_env=None):
    """Import a copy of slidespin from a read-only directory with a read-only HOME.

    As root, write permissions are not enforced, so the child runs as uid/gid 65534 (nobody)
    through ``setpriv``; as any other user chmod alone makes both read-only. As root without
    ``setpriv`` the failure is simulated: numba may then only use NUMBA_CACHE_DIR, which is
    set to a path under a regular file (never a directory, even for root).
    """
    import os
    import shutil
    import stat
    import subprocess
    import sys
    from pathlib import Path

    src = Path(ss.__file__).resolve().parent
    pkg = Path(tmp) / "site"
    shutil.copytree(src, pkg / "slidespin", ignore=shutil.ignore_patterns("__pycache__"))
    home = Path(tmp) / "home"
    home.mkdir()
    for path in [Path(tmp), *Path(tmp).rglob("*")]:
        mode = stat.S_IRUSR | stat.S_IRGRP | stat.S_IROTH
        if path.is_dir():
            mode |= stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH
        path.chmod(mode)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_CACHE", "XDG_"))}
    env.update(
        HOME=str(home),
        XDG_CACHE_HOME=str(home / ".cache"),
        PYTHONPATH=str(pkg),
        **(extra_env or {}),
    )
    prefix = []
    if os.geteuid() == 0:
        if shutil.which("setpriv"):
            prefix = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"]
        else:  # pragma: no cover - depends on the machine
            plain = Path(tmp) / "plain-file"
            plain.write_text("")
            env.update(
                NUMBA_CACHE_LOCATOR_CLASSES="UserProvidedCacheLocator",
                NUMBA_CACHE_DIR=str(plain / "cache"),
            )
    return subprocess.run(
        [*prefix, sys.executable, "-c", _IMPORT_ANYWHERE, str(pkg)],
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
        cwd=str(home),
        check=False,
    )


@pytest.fixture
def readonly_tmp():
    import os
    import shutil
    import stat
    import tempfile

    tmp = tempfile.mkdtemp(prefix="slidespin-ro-")  # not under pytest's 0700 root directory
    yield tmp
    for root, dirs, _ in os.walk(tmp):
        for d in dirs:
            os.chmod(os.path.join(root, d), stat.S_IRWXU)
    os.chmod(tmp, stat.S_IRWXU)
    shutil.rmtree(tmp)


def test_import_with_read_only_install_and_home_caches_in_a_temporary_directory(readonly_tmp):
    r = _run_import_anywhere(readonly_tmp)
    assert r.returncode == 0, r.stderr
    assert "dir /" in r.stdout and "slidespin-numba-" in r.stdout
    notes = [line for line in r.stderr.splitlines() if "CacheWarning" in line]
    assert len(notes) == 1 and "cached in" in notes[0], r.stderr


def test_import_without_any_writable_directory_compiles_without_cache(readonly_tmp):
    r = _run_import_anywhere(readonly_tmp, {"SLIDESPIN_TEST_NO_TMP": "1"})
    assert r.returncode == 0, r.stderr
    assert "dir \n" in r.stdout or r.stdout.strip() == "dir"
    notes = [line for line in r.stderr.splitlines() if "CacheWarning" in line]
    assert len(notes) == 1 and "without a disk cache" in notes[0], r.stderr
