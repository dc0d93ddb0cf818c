"""The documentation site: one Sphinx build with warnings as errors (a broken reference, a dead
internal link, a malformed page or a failing gallery script fails it), then checks that every
public name is in the API reference and that the gallery and the animation are on the site.

Deselect with ``-m "not docs"`` (the build takes about a minute once the kernel is compiled).
"""

from __future__ import annotations

import importlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("sphinx")
pytest.importorskip("sphinx_gallery")
pytest.importorskip("numpydoc")
pytest.importorskip("myst_parser")

pytestmark = pytest.mark.docs

DOCS = Path(__file__).resolve().parents[1] / "docs"
PUBLIC_MODULES = (
    "slidespin",
    "slidespin.motion.batch",
    "slidespin.studies.sweep",
    "slidespin.studies.sweep_loads",
    "slidespin.analysis.terminal",
    "slidespin.analysis.intervals",
    "slidespin.analysis.phase_portrait",
    "slidespin.motion.outcomes",
    "slidespin.analysis.fit",
    "slidespin.analysis.fit_data",
    "slidespin.analysis.fit_result",
    "slidespin.motion.loads",
    "slidespin.contact.statics",
    "slidespin.contact.static_set",
    "slidespin.motion.loaded",
    "slidespin.contact.limit_surface",
    "slidespin.contact.shapes",
    "slidespin.contact.footprint_arrays",
    "slidespin.contact.pressure_map",
    "slidespin.contact.footprint_wrench",
    "slidespin.viz.animate",
)


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("docs")
    html, doctrees = out / "html", out / "doctrees"
    env = dict(os.environ, MPLBACKEND="Agg")
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "sphinx",
            "-W",
            "--keep-going",
            "-q",
            "-b",
            "html",
            "-d",
            str(doctrees),
            str(DOCS),
            str(html),
        ],
        env=env,
        capture_output=True,
        text=True,
        timeout=900,
        check=False,
    )
    assert proc.returncode == 0, f"the docs build failed:\n{proc.stderr[-6000:]}"
    return html


def _inventory(html: Path) -> set[str]:
    from sphinx.util.inventory import InventoryFile

    with open(html / "objects.inv", "rb") as fh:
        inv = InventoryFile.load(fh, "", lambda base, uri: uri)
    if hasattr(inv, "data"):  # Sphinx >= 8.2: an _Inventory object
        return {name for (_, name) in inv.data}
    return {name for entries in inv.values() for name in entries}


def _public(module: str) -> list[str]:
    mod = importlib.import_module(module)
    names = getattr(mod, "__all__", None)
    if names is None:
        names = [
            n
            for n, obj in vars(mod).items()
            if not n.startswith("_") and getattr(obj, "__module__", None) == module
        ]
    return [n for n in names if n != "__version__"]


def test_every_public_name_is_in_the_api_reference(site):
    documented = _inventory(site)
    missing = [
        f"{m}.{n}" for m in PUBLIC_MODULES for n in _public(m) if f"{m}.{n}" not in documented
    ]
    assert not missing, f"not in the API reference: {missing}"
    # a module hidden by a re-exported function of its name has no module entry of its own
    hidden = {
        m
        for m in PUBLIC_MODULES
        if "." in m
        and getattr(importlib.import_module("slidespin"), m.rpartition(".")[2])
        is not importlib.import_module(m)
    }
    assert all(m in documented for m in PUBLIC_MODULES if m not in hidden)


def test_pages_of_the_site(site):
    for page in (
        "index",
        "getting_started",
        "guide/index",
        "guide/simulation",
        "model",
        "paper",
        "benchmarks",
        "errors",
        "loads",
        "fit",
        "api/index",
        "development",
        "changelog",
        "auto_examples/index",
    ):
        assert (site / f"{page}.html").is_file(), page
    # the user guide links MODEL §9.1 by its heading anchor
    text = (site / "guide" / "simulation.html").read_text(encoding="utf-8")
    assert (
        "model.html#what-slidespin-reports-at-the-stop" in text
        or "model.html#91-what-slidespin-reports-at-the-stop" in text
    )


def test_gallery_executed_with_figures(site):
    scripts = sorted(p.stem for p in (DOCS / "gallery").glob("plot_*.py"))
    assert len(scripts) >= 8
    for stem in scripts:
        page = (site / "auto_examples" / f"{stem}.html").read_text(encoding="utf-8")
        assert "sphx_glr_" + stem + "_001.png" in page, f"{stem}: no figure"
        assert "sphx-glr-script-out" in page, f"{stem}: no printed output"


def test_front_page_animation(site):
    gifs = list((site / "_images").glob("demo*.gif"))
    assert len(gifs) == 1
    from PIL import Image

    with Image.open(gifs[0]) as im:
        assert im.n_frames == 60
    assert gifs[0].stat().st_size < 1_000_000
    assert gifs[0].name in (site / "index.html").read_text(encoding="utf-8")


def _undocumented(module: str) -> tuple[list[str], list[str]]:
    """(functions and classes, members and constants) of ``module`` without documentation."""
    import inspect

    from sphinx.pycode import ModuleAnalyzer

    mod = importlib.import_module(module)
    attr_docs = ModuleAnalyzer.for_module(module).find_attr_docs()
    top, rest = [], []
    for name in _public(module):
        obj = getattr(mod, name)
        if inspect.isclass(obj) or inspect.isroutine(obj):
            if not (obj.__doc__ or "").strip():
                top.append(f"{module}.{name}")
            if inspect.isclass(obj):
                for k, member in vars(obj).items():
                    if k.startswith("_") or not (
                        inspect.isfunction(member) or isinstance(member, property)
                    ):
                        continue
                    if not (member.__doc__ or "").strip():
                        rest.append(f"{module}.{name}.{k}")
        elif not inspect.ismodule(obj) and ("", name) not in attr_docs:
            rest.append(f"{module}.{name}")
    return top, rest


def test_public_functions_and_classes_have_docstrings():
    missing = [n for m in PUBLIC_MODULES for n in _undocumented(m)[0]]
    assert not missing, f"no docstring: {missing}"


def test_public_constants_and_members_are_documented():
    missing = [n for m in PUBLIC_MODULES for n in _undocumented(m)[1]]
    assert not missing, f"undocumented: {missing}"
