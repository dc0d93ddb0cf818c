"""Sphinx configuration of the slidespin documentation site.

Build (from the README's test environment, ``.venv/bin/pip install -e ".[test]"``)::

    .venv/bin/python -m sphinx -W --keep-going -b html docs docs/_build/html

Warnings are errors (``-W``): a broken cross-reference, a dead internal link, a page missing
from the tables of contents or a failing gallery script fails the build. The gallery
(``docs/gallery/plot_*.py``) is executed on every build by sphinx-gallery; its output goes to
``docs/auto_examples/`` (generated, not tracked). The front page's animation is made at the
start of the build into ``docs/_generated/`` (generated, not tracked).
"""

from __future__ import annotations

import os
import re
import warnings
from pathlib import Path

import slidespin

HERE = Path(__file__).resolve().parent

project = "slidespin"
author = "slidespin developers"
copyright = "slidespin developers"  # noqa: A001 - Sphinx's name
release = slidespin.__version__
version = release

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = [
    "_build",
    "_generated",
    "Thumbs.db",
    ".DS_Store",
    "auto_examples/*.ipynb",
    "auto_examples/*.py",
    "auto_examples/*.zip",
    "auto_examples/*.json",
    "auto_examples/*.md5",
    "gallery/GALLERY_HEADER.rst",
]

# -- Markdown (the existing docs/*.md pages) ----------------------------------------------
myst_enable_extensions = ["dollarmath", "colon_fence"]
# links such as model.md#91-what-slidespin-reports-at-the-stop resolve to heading anchors
myst_heading_anchors = 3

# -- API reference ------------------------------------------------------------------------
autodoc_default_options: dict[str, object] = {}  # each api/*.rst page says :members:
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # numpydoc's Parameters sections carry the types and units
# numpydoc renders the docstrings; it does not validate them (the docstrings follow the
# project's numpydoc habit, but numpydoc's full validation also flags stylistic choices)
numpydoc_validation_checks: set[str] = set()
numpydoc_show_class_members = False  # members are documented by autodoc itself
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
# every Python cross-reference must resolve (-W then fails on a broken one), except names of
# the external libraries (no intersphinx: the build needs no network) and private modules
nitpicky = True
nitpick_ignore_regex = [
    ("py:.*", r"(numpy|np|pandas|pd|scipy|matplotlib|dask|distributed|pyarrow|numba)(\..*)?"),
    # the engines' own names (pydrake, mujoco)
    ("py:.*", r"(pydrake|mujoco)(\..*)?"),
    # private modules (``slidespin._io``, ``slidespin.contact._engine``, ...) and their names
    ("py:.*", r"slidespin(\..*)?\._.*"),
]

# -- Gallery ------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "gallery",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"plot_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "write_computation_times": False,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "show_memory": False,
    "capture_repr": (),
    # execute every script on every build (a stale cache must not hide a broken example)
    "run_stale_examples": True,
}
os.environ.setdefault("MPLBACKEND", "Agg")
# matplotlib's note that Agg cannot show figures is noise here, not a documentation error
warnings.filterwarnings("ignore", message="FigureCanvasAgg is non-interactive")

# -- HTML ---------------------------------------------------------------------------------
html_theme = "alabaster"
html_title = f"slidespin {release}"
html_theme_options = {
    "description": "a flat body sliding and spinning under anisotropic dry friction",
    "fixed_sidebar": True,
    # below this window width the sidebar goes above the text (alabaster's narrow layout);
    # above it, _static/slidespin.css lets the page grow with the window (up to 1440 px)
    "page_width": "1000px",
    "sidebar_width": "250px",
    "body_max_width": "none",  # the text column takes the page's width, not 800 px
}
html_static_path: list[str] = ["_static"]
# the layout at laptop widths: a page as wide as the window, code blocks that fit it, a
# sidebar that scrolls to its last entry (measured at 1280 x 800: docs/_static/slidespin.css)
html_css_files = ["slidespin.css"]
# the API pages are long (one section per module): their sidebar also lists the page's
# modules, whose long dotted names wrap there (slidespin.css)
html_sidebars = {
    "api/*": ["about.html", "searchfield.html", "navigation.html", "localtoc.html", "relations.html"],
}
html_extra_path: list[str] = []


# -- Docstrings written for the terminal as well as for Sphinx ------------------------------
# The docstrings use |x| for absolute values and norms, which reStructuredText reads as
# substitution references, and a few simple tables whose first column overflows its border.
# Both are fixed here, on the way into Sphinx, instead of in the source: ``|`` outside
# inline literals and tables is escaped, and a simple table that docutils would reject is
# shown as preformatted text.
_BORDER = re.compile(r"^(\s*)(=+)(\s+=+)+\s*$")


def _escape_bars(line: str, inside: bool = False) -> tuple[str, bool]:
    """Escape ``|`` outside inline literals; ``inside``: a literal is open at the start."""
    parts = line.split("``")
    for i in range(1 if inside else 0, len(parts), 2):  # outside ``inline literals``
        parts[i] = re.sub(r"(?<!\\)\|", r"\\|", parts[i])
    return "``".join(parts), inside ^ (len(parts) % 2 == 0)


def _table_ok(block: list[str], border: str) -> bool:
    gaps = [i for i, ch in enumerate(border) if ch == " " and i > len(border) - len(
        border.lstrip())]
    last_start = border.rstrip().rfind(" ") + 1
    gaps = [i for i in gaps if i < last_start]
    for row in block:
        if _BORDER.match(row) or not row.strip():
            continue
        if any(i < len(row) and row[i] != " " for i in gaps):
            return False
    return True


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _fix_docstring(lines: list[str]) -> list[str]:
    out: list[str] = []
    i, literal_indent, inside = 0, None, False
    while i < len(lines):
        line = lines[i]
        indent = len(line) - len(line.lstrip())
        if literal_indent is not None and line.strip() and indent <= literal_indent:
            literal_indent = None
        m = _BORDER.match(line)
        if m and literal_indent is None:
            # a simple table: up to the border that closes it (two or three borders)
            j, borders = i + 1, 1
            while j < len(lines) and lines[j].strip():
                if _BORDER.match(lines[j]):
                    borders += 1
                j += 1
            block = lines[i:j]
            if _table_ok(block, line):
                last = line.rstrip().rfind(" ") + 1  # the last column may hold bars
                out.extend(b if _BORDER.match(b) else b[:last] + _escape_bars(b[last:])[0]
                           for b in block)
            else:
                out.extend(["", m.group(1) + "::", ""])
                out.extend("    " + b for b in block)
                out.append("")
            i = j
            continue
        if (literal_indent is None and line.rstrip().endswith(",") and i + 2 < len(lines)
                and lines[i + 1].strip() and _indent(lines[i + 1]) == indent
                and _indent(lines[i + 2]) > indent and lines[i + 2].strip()):
            # a definition-list term broken over two lines: join them
            lines = lines[:i] + [line.rstrip() + " " + lines[i + 1].strip()] + lines[i + 2:]
            continue
        if not line.strip():
            inside = False  # an inline literal never crosses a paragraph
        if literal_indent is None:
            escaped, inside = _escape_bars(line, inside)
            out.append(escaped)
            if line.rstrip().endswith("::"):
                literal_indent = indent
        else:
            out.append(line)
        i += 1
    return out


# A docstring is written in its own module, where ``:data:`MAX_VERTICES``` or
# ``:meth:`Load.piecewise_linear``` name that module's globals; but a function or class
# re-exported by the package is also documented on the ``slidespin`` page, where such a short
# name does not resolve. A short target that is a global of the object's own module is
# therefore pointed at the page that documents it (its defining module), keeping its text;
# a target that does not exist there is left alone, so it still fails the build.
_ROLE = re.compile(r":(func|meth|class|data|attr|exc|obj):`(~?)([A-Za-z_][\w.]*)`")


def _home_module(what: str, name: str, obj) -> str | None:
    if what == "module":
        return name
    for o in (obj, getattr(obj, "fget", None), getattr(obj, "__func__", None)):
        mod = getattr(o, "__module__", None)
        if isinstance(mod, str) and mod.startswith("slidespin"):
            return mod
    return None


def _private(modname: str) -> bool:
    return any(p.startswith("_") for p in modname.split("."))


def _qualify(match: re.Match, module) -> str:
    import inspect

    role, tilde, target = match.groups()
    if target.startswith("slidespin"):
        return match.group(0)
    first, *rest = target.split(".")
    if not hasattr(module, first):
        return match.group(0)
    head = getattr(module, first)
    if inspect.ismodule(head):
        return match.group(0)
    found = head
    for part in rest:  # the whole target must exist
        if not hasattr(found, part):
            return match.group(0)
        found = getattr(found, part)
    if inspect.isclass(head) or inspect.isroutine(head):
        home_mod = getattr(head, "__module__", "") or ""
        full = f"{home_mod}.{head.__qualname__}"
        if _private(home_mod) and not _private(module.__name__) and first in getattr(
            module, "__all__", ()
        ):  # defined in a private module, documented where this module re-exports it
            home_mod = module.__name__
            full = f"{home_mod}.{first}"
    else:  # a constant: the module whose ``#:`` comment documents it, else this one
        home_mod = module.__name__
        full = _documented_home(module.__name__, head) or f"{home_mod}.{first}"
    if not home_mod.startswith("slidespin") or _private(home_mod):
        return match.group(0)
    full = ".".join([full, *rest])
    title = target.rpartition(".")[2] if tilde else target
    return f":{role}:`{title} <{full}>`"


def _type_docstring(what: str, obj, lines: list[str]) -> bool:
    """True if ``lines`` are the docstring of the type of a constant (autodoc's fallback for
    a constant without a ``#:`` comment: a tuple would show "Built-in immutable sequence")."""
    import inspect

    if what not in ("data", "attribute") or inspect.isclass(obj) or inspect.isroutine(obj):
        return False
    text = [line.strip() for line in lines if line.strip()]
    for doc in (getattr(obj, "__doc__", None), getattr(type(obj), "__doc__", None)):
        doc = inspect.cleandoc(doc) if isinstance(doc, str) else ""
        if doc and text and doc.splitlines()[0].strip() == text[0]:
            return True
    return False


def _drop_type_docstring(app, what, name, obj, options, lines) -> None:
    """Before numpydoc renders it: a constant without a comment has no docstring."""
    if _type_docstring(what, obj, lines):
        lines[:] = []


def _process_docstring(app, what, name, obj, options, lines) -> None:
    import sys

    lines[:] = _fix_docstring(lines)
    modname = _home_module(what, name, obj)
    module = sys.modules.get(modname) if modname else None
    if module is not None:
        lines[:] = [_ROLE.sub(lambda m: _qualify(m, module), line) for line in lines]


# -- API pages -----------------------------------------------------------------------------
# The reference follows the layers of the code (docs/development.md, "Where things live"):
# docs/api/slidespin.rst documents the top-level names (``slidespin.__all__``), and one page
# per layer, docs/api/<layer>.rst, includes _generated/api/slidespin.<layer>.rst, written here:
# the sub-package's docstring, then one section per public module of the layer (every module
# whose name has no leading underscore, found on disk, so that a new module is documented
# without a change here). Each module's section is
# * ``automodule`` with every member of ``__all__``; autodoc documents module data only when
#   it has a ``#:`` doc comment, so each constant without one gets an ``autodata`` entry, and
#   every public name is in the reference;
# * for a module whose name its parent package hides (``slidespin.cli.main`` is also the
#   function re-exported by ``slidespin.cli``), which cannot be declared under that name a
#   second time: the module docstring and its members one by one.
# Private modules (``_*.py``) are not documented; references to them are ignored above.
LAYERS = ("contact", "motion", "analysis", "studies", "engines", "viz", "paper", "cli")


def layer_modules(layer: str) -> list[str]:
    """The public modules of ``slidespin.<layer>`` (no leading underscore), sorted."""
    import importlib
    import pkgutil

    package = importlib.import_module(f"slidespin.{layer}")
    return sorted(
        f"{package.__name__}.{info.name}"
        for info in pkgutil.iter_modules(package.__path__)
        if not info.name.startswith("_")
    )


API_MODULES = (
    "slidespin",
    *(f"slidespin.{layer}" for layer in LAYERS),
    *(module for layer in LAYERS for module in layer_modules(layer)),
)


def _public_names(mod) -> list[str]:
    import inspect

    names = getattr(mod, "__all__", None)
    if names is None:
        names = [n for n, o in vars(mod).items() if not n.startswith("_")
                 and (inspect.isclass(o) or inspect.isroutine(o))
                 and getattr(o, "__module__", None) == mod.__name__]
    return [n for n in names if not n.startswith("__")]


def shadowed(module: str) -> bool:
    """True if ``<parent>.<name>`` is not this module (a name re-exported by the parent
    package hides it, as the function ``slidespin.cli.main`` hides the module)."""
    import importlib

    parent, _, short = module.rpartition(".")
    if not parent:
        return False
    mod = importlib.import_module(module)
    return getattr(importlib.import_module(parent), short, mod) is not mod


def _documented_home(module: str, obj) -> str | None:
    """``other.NAME`` if ``obj`` is a constant that another API module documents (``#:``)."""
    import importlib

    from sphinx.pycode import ModuleAnalyzer

    if isinstance(obj, (int, float, str)):  # small values are not unique objects
        return None
    for other in API_MODULES:
        if other == module:
            continue
        mod = importlib.import_module(other)
        for name in _public_names(mod):
            if getattr(mod, name, None) is obj:
                try:
                    docs = ModuleAnalyzer.for_module(other).find_attr_docs()
                except Exception:
                    continue
                if ("", name) in docs:
                    return f"{other}.{name}"
    return None


def _private_doc(name: str, obj) -> list[str]:
    """The ``#:`` comment of ``obj`` where a private module defines it under ``name`` (the
    public module that re-exports it is its documented home: the comment is shown there)."""
    import sys

    from sphinx.pycode import ModuleAnalyzer

    for modname, mod in sorted(sys.modules.items()):
        if not modname.startswith("slidespin.") or not any(
            p.startswith("_") for p in modname.split(".")
        ):
            continue
        if getattr(mod, name, None) is not obj:
            continue
        try:
            docs = ModuleAnalyzer.for_module(modname).find_attr_docs()
        except Exception:
            continue
        if ("", name) in docs:
            return [line for line in docs[("", name)] if line.strip()]
    return []


def _api_page(module: str) -> str:
    import importlib
    import inspect

    from sphinx.pycode import ModuleAnalyzer

    mod = importlib.import_module(module)
    try:
        attr_docs = ModuleAnalyzer.for_module(module).find_attr_docs()
    except Exception:  # no source
        attr_docs = {}
    hidden = shadowed(module)
    if hidden:
        parent, _, short = module.rpartition(".")
        lines = [f".. note:: ``{parent}.{short}`` is the function of the same name, which hides "
                 f"this module: take its names with ``from {module} import NAME`` (``import "
                 f"{module} as m`` gives the function).", "",
                 f".. automodule:: {module}", "   :no-index:", "",
                 f".. currentmodule:: {module}", ""]
    else:
        # no :undoc-members:, which would list every dataclass field a second time, empty,
        # below the numpydoc Attributes section that documents it (constants: autodata below)
        lines = [f".. automodule:: {module}", "   :members:", ""]
    for name in _public_names(mod):
        obj = getattr(mod, name, None)
        if inspect.ismodule(obj):
            continue
        if inspect.isclass(obj):
            if hidden:
                lines += [f".. autoclass:: {name}", "   :members:", ""]
        elif inspect.isroutine(obj):
            if hidden:
                lines += [f".. autofunction:: {name}", ""]
        elif ("", name) not in attr_docs and (home := _documented_home(module, obj)):
            # a constant re-exported from the module that documents it (``#:``)
            lines += [f".. py:data:: {name}", "", f"   The same object as :data:`{home}`.", ""]
        elif ("", name) not in attr_docs and (doc := _private_doc(name, obj)):
            # a constant defined and commented (``#:``) in a private module: its comment here
            lines += [f".. autodata:: {name}", "", *(f"   {line}" for line in doc), ""]
        elif hidden or ("", name) not in attr_docs:
            lines += [f".. autodata:: {name}", ""]
    return "\n".join(lines) + "\n"


def _layer_page(layer: str) -> str:
    """The sub-package's docstring, then one section per public module of the layer."""
    package = f"slidespin.{layer}"
    parts = [_api_page(package)]
    for module in layer_modules(layer):
        title = f"``{module}``"
        parts.append(f"{title}\n{'-' * len(title)}\n\n{_api_page(module)}")
    return "\n".join(parts)


def _api_pages(app) -> None:
    out = HERE / "_generated" / "api"
    out.mkdir(parents=True, exist_ok=True)
    pages = {"slidespin": _api_page("slidespin")}
    pages.update({f"slidespin.{layer}": _layer_page(layer) for layer in LAYERS})
    for path in out.glob("*.rst"):  # pages of an earlier layout
        if path.stem not in pages:
            path.unlink()
    for name, text in pages.items():
        path = out / f"{name}.rst"
        if not path.exists() or path.read_text() != text:
            path.write_text(text)


def _front_page_animation(app) -> None:
    """Write ``_generated/demo.gif`` (the demo as an animation) for the front page."""
    out = HERE / "_generated" / "demo.gif"
    out.parent.mkdir(exist_ok=True)
    import slidespin as ss
    from slidespin.cli.main import demo_case

    case = demo_case()
    traj = ss.simulate(case.body, case.friction, case.initial_state)
    ss.animate(traj, out, fps=20, frames=60, title="slidespin demo")


def setup(app):
    app.connect("autodoc-process-docstring", _drop_type_docstring, priority=100)
    app.connect("autodoc-process-docstring", _process_docstring)
    app.connect("builder-inited", _api_pages)
    app.connect("builder-inited", _front_page_animation)
