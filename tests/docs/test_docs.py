"""The documentation site: one Sphinx build with warnings as errors (a broken reference, a dead
internal link, a malformed page or a failing gallery script fails it), then checks that every
public name is in the API reference and that the gallery and the animation are on the site.

Deselect with ``-m "not docs"`` (the build takes about a minute once the kernel is compiled).
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("sphinx")
pytest.importorskip("sphinx_gallery")
pytest.importorskip("numpydoc")
pytest.importorskip("myst_parser")

# one worker builds the site: sphinx-gallery writes into docs/ (two builds at once collide)
pytestmark = [pytest.mark.docs, pytest.mark.xdist_group("docs")]

DOCS = Path(__file__).resolve().parents[2] / "docs"
SRC = Path(__file__).resolve().parents[2] / "src" / "slidespin"
# every public module: the package, its layers and each layer's modules without a leading
# underscore (docs/api/: the top-level names on one page, then one page per layer)
PUBLIC_MODULES = (
    "slidespin",
    # contact
    "slidespin.contact",
    "slidespin.contact.body",
    "slidespin.contact.ellipse",
    "slidespin.contact.footprint_arrays",
    "slidespin.contact.friction",
    "slidespin.contact.incline",
    "slidespin.contact.limit_surface",
    "slidespin.contact.motion_cone",
    "slidespin.contact.outline",
    "slidespin.contact.pressure",
    "slidespin.contact.pressure_map",
    "slidespin.contact.shapes",
    "slidespin.contact.speed_laws",
    "slidespin.contact.tall",
    "slidespin.contact.tall_speed",
    "slidespin.contact.tipping",
    "slidespin.contact.static_set",
    "slidespin.contact.statics",
    "slidespin.contact.wrench",
    # motion
    "slidespin.motion",
    "slidespin.motion.batch",
    "slidespin.motion.loaded",
    "slidespin.motion.loaded_trajectory",
    "slidespin.motion.loads",
    "slidespin.motion.outcomes",
    "slidespin.motion.pushed",
    "slidespin.motion.pushed_line",
    "slidespin.motion.pushed_trajectory",
    "slidespin.motion.pushers",
    "slidespin.motion.quasi_static",
    "slidespin.motion.quasi_static_line",
    "slidespin.motion.sensitivity",
    "slidespin.motion.simulate",
    "slidespin.motion.springs",
    "slidespin.motion.state",
    "slidespin.motion.trajectory",
    # analysis
    "slidespin.analysis",
    "slidespin.analysis.aim",
    "slidespin.analysis.fit",
    "slidespin.analysis.fit_data",
    "slidespin.analysis.fit_push",
    "slidespin.analysis.fit_result",
    "slidespin.analysis.intervals",
    "slidespin.analysis.phase_portrait",
    "slidespin.analysis.push_data",
    "slidespin.analysis.sensitivities",
    "slidespin.analysis.terminal",
    # studies
    "slidespin.studies",
    "slidespin.studies.case",
    "slidespin.studies.law_tables",
    "slidespin.studies.load_tables",
    "slidespin.studies.pusher_table",
    "slidespin.studies.sweep",
    "slidespin.studies.sweep_chunk",
    "slidespin.studies.sweep_loads",
    "slidespin.studies.sweep_parse",
    "slidespin.studies.sweep_read",
    "slidespin.studies.sweep_spec",
    "slidespin.studies.sweep_store",
    # viz
    "slidespin.viz",
    "slidespin.viz.animate",
    "slidespin.viz.fit_plot",
    "slidespin.viz.law_plot",
    "slidespin.viz.push_plot",
    "slidespin.viz.sweep_plot",
    "slidespin.viz.trajectory_plot",
    # paper
    "slidespin.paper",
    "slidespin.paper.errata",
    "slidespin.paper.fig2",
    "slidespin.paper.fig3",
    "slidespin.paper.fig4",
    "slidespin.paper.phase",
    "slidespin.paper.report",
    "slidespin.paper.semianalytic",
    "slidespin.paper.table1",
    "slidespin.paper.table2",
    # engines (and the names users import them by)
    "slidespin.engines",
    "slidespin.engines.drake",
    "slidespin.engines.mujoco",
    "slidespin.engines.parameters",
    "slidespin.engines.scenes",
    "slidespin.mujoco",
    "slidespin.drake",
    # cli
    "slidespin.cli",
    "slidespin.cli.animate",
    "slidespin.cli.bench",
    "slidespin.cli.fit",
    "slidespin.cli.limit_surface",
    "slidespin.cli.aim",
    "slidespin.cli.main",
    "slidespin.cli.reproduce",
)


#: the couplings' modules import their engine (an optional extra): they are checked where it
#: is installed (the test extra installs every engine; CI runs them)
ENGINE_MODULES = {
    "slidespin.engines.mujoco": "mujoco",
    "slidespin.mujoco": "mujoco",
    "slidespin.engines.drake": "pydrake",
    "slidespin.drake": "pydrake",
}
ENGINES_INSTALLED = all(importlib.util.find_spec(e) for e in set(ENGINE_MODULES.values()))
#: the public modules this installation can import
IMPORTABLE = tuple(
    m
    for m in PUBLIC_MODULES
    if m not in ENGINE_MODULES or importlib.util.find_spec(ENGINE_MODULES[m])
)


def _modules_on_disk() -> set[str]:
    """Every module under src/slidespin with no underscore-led part, ``__main__`` excepted."""
    found = set()
    for path in SRC.rglob("*.py"):
        parts = ("slidespin", *path.relative_to(SRC).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        if not any(p.startswith("_") for p in parts):
            found.add(".".join(parts))
    return found


def _hidden(module: str) -> bool:
    """True if the parent package's attribute of the module's name is not the module (a
    re-exported function of that name hides it: ``slidespin.cli.main``)."""
    parent, _, short = module.rpartition(".")
    if not parent:
        return False
    return getattr(importlib.import_module(parent), short) is not importlib.import_module(module)


def test_public_modules_are_the_modules_of_the_source_tree():
    assert set(PUBLIC_MODULES) == _modules_on_disk()


@pytest.fixture(scope="session")
def site(tmp_path_factory):
    if not ENGINES_INSTALLED:
        pytest.skip("the site documents the engine couplings: it needs the engines' extras")
    out = tmp_path_factory.mktemp("docs")
    html, doctrees = out / "html", out / "doctrees"
    # built from a copy of docs/ (and the CHANGELOG it includes): sphinx-gallery writes its
    # output beside the sources, and pytest-xdist may give this module's tests to two workers
    # (the xdist_group mark is not honoured by every pytest/xdist pair), whose two builds
    # would then collide in one docs/auto_examples
    src = out / "src"
    shutil.copytree(
        DOCS, src / "docs", ignore=shutil.ignore_patterns("auto_examples", "_generated", "_build")
    )
    shutil.copy2(DOCS.parent / "CHANGELOG.md", src / "CHANGELOG.md")
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
            str(src / "docs"),
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
    # a module hidden by a re-exported function of its name (in its parent package) has no
    # module entry of its own
    missing = [m for m in PUBLIC_MODULES if not _hidden(m) and m not in documented]
    assert not missing, f"modules not in the API reference: {missing}"
    # one page for the top-level names and one per layer
    for page in (
        "slidespin", "contact", "motion", "analysis", "studies", "engines", "viz", "paper", "cli"
    ):  # fmt: skip
        assert (site / "api" / f"{page}.html").is_file(), page


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
        elif (
            not inspect.ismodule(obj)
            and ("", name) not in attr_docs
            and not _documented_where_defined(module, name, obj)
        ):
            rest.append(f"{module}.{name}")
    return top, rest


def _documented_where_defined(module: str, name: str, obj) -> bool:
    """True if ``obj`` is a constant re-exported by ``module`` from another slidespin module
    that defines it under the same name with a ``#:`` comment (the API page shows it)."""
    from sphinx.pycode import ModuleAnalyzer

    for other, mod in list(sys.modules.items()):
        if other == module or not other.startswith("slidespin") or mod is None:
            continue
        if vars(mod).get(name, None) is not obj:
            continue
        try:
            if ("", name) in ModuleAnalyzer.for_module(other).find_attr_docs():
                return True
        except Exception:  # no source
            continue
    return False


def test_public_functions_and_classes_have_docstrings():
    missing = [n for m in IMPORTABLE for n in _undocumented(m)[0]]
    assert not missing, f"no docstring: {missing}"


def test_public_constants_and_members_are_documented():
    missing = [n for m in IMPORTABLE for n in _undocumented(m)[1]]
    assert not missing, f"undocumented: {missing}"
