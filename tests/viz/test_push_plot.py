"""The figure of a pushed run (MODEL §13): it draws, saves, shades the modes and refuses a bad
number of poses."""

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402
from round_feet import FEET  # noqa: E402

import slidespin as ss  # noqa: E402
from slidespin.viz.push_plot import MODE_GID, mode_colour, plot_pushed_trajectory  # noqa: E402


@pytest.fixture(scope="module")
def pushed():
    box = ss.Body(ss.Rectangle(0.2, 0.15), ss.UniformPressure(), mass=2.0)
    finger = ss.PointPusher([(0.0, -0.2, -0.03), (1.0, 0.0, -0.03), (1.5, 0.05, 0.1)], mu=0.3)
    return ss.simulate(box, ss.FrictionTensor.isotropic(0.35), ss.State(), pusher=finger, t_end=2.0)


def test_figure_axes_and_save(pushed, tmp_path):
    fig = plot_pushed_trajectory(pushed, title="finger")
    plane, force, energy = fig.axes[:3]
    assert plane.get_xlabel() == "x [cm]" and plane.get_ylabel() == "y [cm]"
    assert force.get_ylabel() == "|force| [N]" and energy.get_ylabel() == "energy [J]"
    spans = [p for p in force.patches if p.get_gid() == MODE_GID]
    assert len(spans) == len(pushed.phases())
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "sticking" in labels and "separated" in labels and "finger" in labels
    out = tmp_path / "push.png"
    fig.savefig(out)
    assert out.stat().st_size > 10_000


def test_wider_outline_is_drawn(pushed):
    fig = plot_pushed_trajectory(
        pushed, outline=[[-0.12, -0.09], [0.12, -0.09], [0.12, 0.09], [-0.12, 0.09]], n_poses=3
    )
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "contact outline" in labels


def test_hull_of_pads_is_drawn_and_the_box_has_none(pushed):
    """The outline a finger touches is drawn dashed where it is not the footprint's own: the
    hull of pads (the tangent edges between round feet), not a box's own outline."""
    finger = ss.PointPusher([(0.0, -0.14, 0.0), (1.84, 0.0, 0.12)], mu=0.1)
    tr = ss.simulate(FEET, ss.FrictionTensor.isotropic(0.3), ss.State(), pusher=finger, t_end=1.84)
    labels = [t.get_text() for t in plot_pushed_trajectory(tr, n_poses=3).legends[0].get_texts()]
    assert "contact outline" in labels
    labels = [
        t.get_text() for t in plot_pushed_trajectory(pushed, n_poses=3).legends[0].get_texts()
    ]
    assert "contact outline" not in labels


@pytest.mark.parametrize("n", [1, 41, 2.5, True])
def test_bad_n_poses(pushed, n):
    with pytest.raises(ValueError, match="n_poses"):
        plot_pushed_trajectory(pushed, n_poses=n)


def test_mode_colours_are_stable():
    seen: dict = {}
    assert mode_colour("sticking") == "C2"
    assert mode_colour("face_contact", seen) == mode_colour("face_contact", seen)
    assert mode_colour("face_contact", seen) != mode_colour("rolling_left", seen)
