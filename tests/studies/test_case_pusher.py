"""The [pusher] table of a case file (MODEL §13): good inputs build the API's pushers, bad ones
are refused in one line naming [pusher], the key and the valid range, and every command that
reads a case uses or refuses the table."""

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.studies.case import case_from_dict, read_case, refuse_unused

BASE = {
    "name": "finger",
    "patch": {"shape": "rectangle", "length": 0.2, "width": 0.15},
    "pressure": {"law": "uniform"},
    "friction": {"fx": 0.35, "fy": 0.35},
    "body": {"mass": 2.0},
    "initial": {},
}
FINGER = {"kind": "point", "mu": 0.3, "path": [[0.0, -0.2, -0.03], [2.0, 0.2, -0.03]]}


def case(pusher, **tables):
    return case_from_dict({**BASE, **tables, "pusher": pusher})


def test_point_pusher_is_the_api_object():
    c = case(FINGER)
    assert c.pusher == ss.PointPusher([(0.0, -0.2, -0.03), (2.0, 0.2, -0.03)], mu=0.3)
    assert c.pushed and not c.loaded
    assert c.outline is None


def test_t_end_defaults_to_the_path_end_and_solver_wins():
    assert case(FINGER).t_end == 2.0
    assert case(FINGER, solver={"t_end": 3.5}).t_end == 3.5


def test_mu_defaults_to_zero():
    c = case({"kind": "point", "path": [[0, -0.2, 0], [1, 0, 0]]})
    assert c.pusher.mu == 0.0


def test_line_pusher_path_and_path_deg_agree():
    rad = case(
        {"kind": "line", "length": 0.1, "path": [[0, -0.2, 0, math.pi / 2], [1, 0, 0, math.pi / 2]]}
    )
    deg = case({"kind": "line", "length": 0.1, "path_deg": [[0, -0.2, 0, 90], [1, 0, 0, 90]]})
    assert isinstance(rad.pusher, ss.LinePusher)
    assert rad.pusher.length == 0.1
    np.testing.assert_allclose(deg.pusher.path, rad.pusher.path, rtol=0, atol=1e-15)


@pytest.mark.parametrize(
    "outline",
    [
        [[-0.15, -0.1], [0.15, -0.1], [0.15, 0.1], [-0.15, 0.1]],
        {"shape": "rectangle", "length": 0.3, "width": 0.2},
        {"shape": "ellipse", "a": 0.15, "b": 0.1},
    ],
)
def test_outline_forms(outline):
    c = case({**FINGER, "outline": outline})
    ol = ss.body_outline(c.body, c.outline)
    assert ol.contains((0.14, 0.0)) and not ol.contains((0.16, 0.0))


@pytest.mark.parametrize(
    ("pusher", "words"),
    [
        ({"mu": 0.3, "path": [[0, 0, 0]]}, ["[pusher]", "'kind'", "point"]),
        ({**FINGER, "kind": "finger"}, ["[pusher] kind", "'finger'", "point, line"]),
        ({"kind": "point"}, ["[pusher]", "'path'", "[[t, x, y]"]),
        ({**FINGER, "mu": -0.1}, ["[pusher] mu", "-0.1", "valid range: [0, 1e+09]"]),
        ({**FINGER, "mu": True}, ["[pusher] mu", "True"]),
        ({**FINGER, "path": [[0, 1]]}, ["[pusher] path", "(1, 2)", "(n, 3)"]),
        ({**FINGER, "path": [[0, 0, 0], [0, 1, 0]]}, ["[pusher] path[1, 0]", "increasing"]),
        ({**FINGER, "path": [[0, 0, float("nan")]]}, ["[pusher] path[0, 2]", "finite"]),
        ({**FINGER, "path": [[0, 0, True]]}, ["[pusher] path[0][2]", "bool"]),
        ({**FINGER, "path": "fast"}, ["[pusher] path", "'fast'", "rows"]),
        ({**FINGER, "length": 0.1}, ["[pusher] length", 'kind = "line"']),
        ({**FINGER, "path_deg": [[0, 0, 0, 0]]}, ["[pusher]", "path and path_deg"]),
        ({**FINGER, "speed": 1.0}, ["unknown key 'speed' in [pusher]", "valid keys"]),
        ({"kind": "line", "path": [[0, 0, 0, 0], [1, 1, 0, 0]]}, ["[pusher]", "'length'", "1e-09"]),
        ({"kind": "line", "length": -1.0, "path": [[0, 0, 0, 0]]}, ["[pusher] length", "-1"]),
        ({"kind": "line", "length": 0.1, "path": [[0, 0, 0]]}, ["[pusher] path", "(n, 4)"]),
        (
            {"kind": "line", "length": 0.1, "path_deg": [[0, 0, 0, 0], [0, 0, 0, 1]]},
            ["[pusher] path_deg[1, 0]", "path_deg[0, 0]"],
        ),
        (
            {"kind": "point", "path": [[0, -0.2, 0]]},
            ["[pusher] path ends at t = 0", "[solver] t_end"],
        ),
        ({**FINGER, "outline": [[0, 0], [1, 0]]}, ["[pusher] outline", "n >= 3"]),
        ({**FINGER, "outline": [[1, 1], [2, 1], [2, 2]]}, ["[pusher] outline", "not inside"]),
        ({**FINGER, "outline": "box"}, ["[pusher] outline", "'box'", "vertices"]),
        ({**FINGER, "outline": {"shape": "pads"}}, ["[pusher.outline]", "pads"]),
        ({**FINGER, "outline": {"shape": "ellipse", "a": 0.1}}, ["[pusher.outline]", "a and b"]),
        (
            {**FINGER, "outline": {"shape": "rectangle", "length": 0.3}},
            ["[pusher.outline]", "'width'"],
        ),
    ],
)
def test_bad_pusher_inputs_name_the_key(pusher, words):
    with pytest.raises(ValueError) as info:
        case(pusher)
    msg = str(info.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg, (w, msg)


def test_pusher_must_be_a_table():
    with pytest.raises(ValueError, match=r"\[pusher\] must be a table"):
        case_from_dict({**BASE, "pusher": 3})


def test_read_case_and_refusal(tmp_path):
    p = tmp_path / "case.toml"
    p.write_text(
        '[patch]\nshape = "disk"\nradius = 0.05\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.3\nfy = 0.3\n[body]\nmass = 1.0\n[initial]\n"
        '[pusher]\nkind = "point"\npath = [[0, -0.1, 0], [1, 0.0, 0]]\n'
    )
    c, data = read_case(p)
    assert c.pushed and c.t_end == 1.0
    with pytest.raises(ValueError, match=r"\[pusher\] is not used by slidespin fit"):
        refuse_unused(p, data, "slidespin fit", (("pusher", None, "coasting only"),))
