"""Build the ahead-of-time compiled core (run once by the package's build; never at runtime).

Build-time only: nothing in the package imports this module (it imports the layers whose
code it compiles).

The core is the integrator's entries, the batch loop and the recorded-wrench loops of
:func:`simulate`, compiled by numba's ``pycc`` from the same sources the JIT compiles (no
second implementation): :func:`slidespin.motion._integrator.integrate_fp` for an ellipse and
for a footprint, the batch loop of :mod:`slidespin.motion._parallel` run serially (for small
batches), the ``wrench_world`` entries and ``wrench_array`` loops of the ellipse and footprint
kernels (one twist, called from Python by the statics, and many), and the loaded
engine's one entry :func:`slidespin.motion._loaded_core.run_loaded` for each, the
sensitivity run :func:`slidespin.motion._sensitivity_core.integrate_sensitivities` for each
its path's conversion to fixed time (:func:`~slidespin.motion._sensitivity_core.fixed_time`) and
the terminal direction's (:func:`~slidespin.motion._sensitivity_core.terminal_direction`),
and the MuJoCo coupling's steady step :mod:`slidespin.engines._stepcore` for each. The result
is an ordinary extension module, ``slidespin/_aot_core.*.so`` (it needs neither numba
nor LLVM at runtime), and beside it ``_aot_core.json``: the numba version, the CPU it was
compiled for, and the SHA-256 of every slidespin source file imported while compiling.
:mod:`slidespin._aot` uses the module only while those hashes still match the sources
(an edited source falls back to the JIT, and says so).

Run by ``hatch_build.py`` (the build hook in ``pyproject.toml``) in a subprocess as
``build(OUTPUT_DIR, CPU)``; ``CPU`` is ``host`` for an editable
or local build (the speed of the JIT) and ``generic`` for a wheel meant for other machines.
"""

from __future__ import annotations

import hashlib
import json
import sys
import time
from pathlib import Path

import numba
from numba import types as T
from numba.pycc import CC

from slidespin import _jit
from slidespin.contact._kernel_ellipse import wrench_loop as _ellipse_wrench_array
from slidespin.contact._kernel_ellipse import wrench_world as _ellipse_wrench_world
from slidespin.contact._kernel_footprint import wrench_array as _footprint_wrench_array
from slidespin.contact._kernel_footprint import wrench_world as _footprint_wrench_world
from slidespin.engines._stepcore import steady_ellipse, steady_footprint
from slidespin.motion._integrator import integrate_fp
from slidespin.motion._loaded_core import run_loaded
from slidespin.motion._parallel import _integrate_many, _stop_direction
from slidespin.motion._sensitivity_core import (
    fixed_time,
    integrate_sensitivities,
    terminal_direction,
)

_jit.numba_module()  # every deferred jit function becomes numba's (the names above too)

#: the extension module's name (in ``slidespin.motion``) and its manifest's file name
MODULE = "_aot_core"
MANIFEST = MODULE + ".json"

_F = T.float64
_I = T.int64
_A1 = T.Array(T.float64, 1, "C")
_A2 = T.Array(T.float64, 2, "C")
_IA1 = T.Array(T.int64, 1, "C")
# integrate_fp's result and its arguments after (par, fp)
_RUN = T.Tuple((_A1, _I, _I, _I, _I, _F, _A2, _A1))
_TAIL = (_A1, _F, _F, _F, _F, _I, _F, T.boolean, T.boolean)
# _integrate_many's result and its arguments after (pars, fps, init)
_IA2 = T.Array(T.int64, 2, "C")
_MANY = T.Tuple((_A2, _IA1, _IA1, _IA1, _IA1, _A2))
_MANY_TAIL = (_F, _F, _F, _F, _I)
# run_loaded's result, and its arguments after (task, par, fp)
_LOADED = T.Tuple((_A1, _I, _I, _I, _I, _A2, _A1))
_LOADED_TAIL = (_A1, _F, _A1, _F, _A1, _F, _F, _A1, _F, _F, _F, _I)

# integrate_sensitivities' result, and its arguments after (pars, fp, geos)
_SENS = T.Tuple((_A1, _A1, _I, _I, _I, _A2, _A2))
_SENS_TAIL = (_A1, _A1, _F, _F, _F, _F, T.boolean, _I, _A1, _A2, _A2, _A1)

# the MuJoCo coupling's steady step: MuJoCo's arrays, the contacts' geom pairs (a strided
# int32 view), body, dof, time, step, state, then the kernel's arguments
_STEADY = (_A1, _A2, _A2, _A2, _A1, _A1, _A2, _A1, T.Array(T.int32, 2, "A"), _I, _I, _F, _F, _A1)

# the batch loop of slidespin.motion._parallel without ``prange`` (pycc compiles no parallel
# code; a prange in a serial function is a range): the same source, run case after case.
# Not cached: it is compiled here only, into the core
_integrate_serial = numba.njit(error_model="numpy", cache=False)(_integrate_many.py_func)


def _compiler(output_dir: Path, target_cpu: str) -> CC:
    cc = CC(MODULE)
    cc.output_dir = str(output_dir)
    cc.target_cpu = target_cpu
    cc.verbose = False

    @cc.export("integrate_ellipse", _RUN(_A1, *_TAIL))
    def integrate_ellipse(par, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages):
        return integrate_fp(
            par, None, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages
        )

    @cc.export("integrate_footprint", _RUN(_A1, _A2, _A2, _A1, *_TAIL))
    def integrate_footprint(
        par, fe, fc, geo, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages
    ):
        fp = (fe, fc, geo)
        return integrate_fp(par, fp, y0, rtol, atol, utol, s_drop, max_steps, h_max, record, stages)

    @cc.export(
        "wrench_array_ellipse",
        T.Tuple((_A1, _A1, _A1, _IA1))(
            _F, _I, _F, _F, _F, _F, _F, _F, T.boolean, _A1, _A1, _A1, _A1, _F
        ),
    )
    def wrench_array_ellipse(bn, law, xg, yg, t00, t01, t10, t11, body, phi, vx, vy, om, tol):
        return _ellipse_wrench_array(
            bn, law, xg, yg, t00, t01, t10, t11, body, phi, vx, vy, om, tol
        )

    @cc.export(
        "wrench_array_footprint",
        T.Tuple((_A1, _A1, _A1))(_A2, _A2, _A1, _F, _F, _F, _F, T.boolean, _A1, _A1, _A1, _A1),
    )
    def wrench_array_footprint(edges, circles, geo, t00, t01, t10, t11, body, phi, vx, vy, om):
        return _footprint_wrench_array(
            edges, circles, geo, t00, t01, t10, t11, body, phi, vx, vy, om
        )

    @cc.export(
        "wrench_world_ellipse",
        T.Tuple((_F, _F, _F, _I))(_F, _I, _F, _F, _F, _F, _F, _F, T.boolean, _F, _F, _F, _F, _F),
    )
    def wrench_world_ellipse(bn, law, xg, yg, t00, t01, t10, t11, body, phi, vx, vy, om, tol):
        return _ellipse_wrench_world(
            bn, law, xg, yg, t00, t01, t10, t11, body, phi, vx, vy, om, tol
        )

    @cc.export(
        "wrench_world_footprint",
        T.UniTuple(_F, 3)(_A2, _A2, _A1, _F, _F, _F, _F, T.boolean, _F, _F, _F, _F),
    )
    def wrench_world_footprint(edges, circles, geo, t00, t01, t10, t11, body, phi, vx, vy, om):
        return _footprint_wrench_world(
            edges, circles, geo, t00, t01, t10, t11, body, phi, vx, vy, om
        )

    @cc.export("integrate_batch_ellipse", _MANY(_A2, _A2, *_MANY_TAIL))
    def integrate_batch_ellipse(pars, init, rtol, atol, utol, s_drop, max_steps):
        return _integrate_serial(pars, None, init, rtol, atol, utol, s_drop, max_steps)

    @cc.export("integrate_batch_footprint", _MANY(_A2, _A2, _A2, _IA2, _IA2, _A2, _A2, *_MANY_TAIL))
    def integrate_batch_footprint(
        pars, edges, circles, eidx, cidx, geos, init, rtol, atol, utol, s_drop, max_steps
    ):
        fps = (edges, circles, eidx, cidx, geos)
        return _integrate_serial(pars, fps, init, rtol, atol, utol, s_drop, max_steps)

    @cc.export("loaded_ellipse", _LOADED(_F, _A1, *_LOADED_TAIL))
    def loaded_ellipse(
        task, par, tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop, s_arg, t_tol, steps
    ):
        return run_loaded(
            task, par, None, tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop, s_arg,
            t_tol, steps,
        )  # fmt: skip

    @cc.export("loaded_footprint", _LOADED(_F, _A1, _A2, _A2, _A1, *_LOADED_TAIL))
    def loaded_footprint(
        task, par, fe, fc, geo, tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop, s_arg,
        t_tol, steps,
    ):  # fmt: skip
        return run_loaded(
            task, par, (fe, fc, geo), tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop,
            s_arg, t_tol, steps,
        )  # fmt: skip

    @cc.export("sensitivities_ellipse", _SENS(_A2, _A2, *_SENS_TAIL))
    def sensitivities_ellipse(
        pars, geos, hs, y0, rtol, atol, drop, conv, collocate, steps, taus, rows, stg, yterm
    ):
        return integrate_sensitivities(
            pars, None, geos, hs, y0, rtol, atol, drop, conv, collocate, steps, taus, rows,
            stg, yterm,
        )  # fmt: skip

    @cc.export("sensitivities_footprint", _SENS(_A2, _A2, _A2, _A2, *_SENS_TAIL))
    def sensitivities_footprint(
        pars, fe, fc, geos, hs, y0, rtol, atol, drop, conv, collocate, steps, taus, rows, stg,
        yterm,
    ):  # fmt: skip
        fp = (fe, fc, geos[0])
        return integrate_sensitivities(
            pars, fp, geos, hs, y0, rtol, atol, drop, conv, collocate, steps, taus, rows,
            stg, yterm,
        )  # fmt: skip

    @cc.export("fixed_time", T.Array(T.float64, 3, "C")(_A2, _A2, _A2, _A1, _F, _A1, _F, _F, _F))
    def fixed_time_aot(rows, accel, rec, y, k, dk, a, t_unit, v_unit):
        return fixed_time(rows, accel, rec, y, k, dk, a, t_unit, v_unit)

    @cc.export("terminal_direction", T.Tuple((_A2, T.boolean))(_A1, _A2, _A1))
    def terminal_direction_aot(u, term, s_phi):
        return terminal_direction(u, term, s_phi)

    @cc.export("steady_ellipse", _I(*_STEADY, _A1))
    def steady_ellipse_aot(qv, xm, xi, xp, qc, qa, xf, qp, geom, b, a, t, h, s, par):
        return steady_ellipse(qv, xm, xi, xp, qc, qa, xf, qp, geom, b, a, t, h, s, par)

    @cc.export("steady_footprint", _I(*_STEADY, _A1, _A2, _A2, _A1))
    def steady_footprint_aot(qv, xm, xi, xp, qc, qa, xf, qp, geom, b, a, t, h, s, par, fe, fc, geo):
        return steady_footprint(
            qv, xm, xi, xp, qc, qa, xf, qp, geom, b, a, t, h, s, par, fe, fc, geo
        )

    @cc.export("stop_direction", T.Tuple((_A1, _A1))(_A2))
    def stop_direction(yend):
        return _stop_direction(yend)

    return cc


#: imported while compiling but holding nothing compiled (package docstrings and lazy
#: exports, the version, the runtime loader): edits there leave the core valid
NOT_COMPILED = ("__init__.py", "_version.py", "_aot.py")


def source_hashes(package_dir: Path) -> dict[str, str]:
    """SHA-256 of every imported ``slidespin`` module's source that holds compiled code or
    the constants it uses, by path relative to the package (the sources the compiled core
    was built from; :data:`NOT_COMPILED` left out)."""
    out = {}
    for name, mod in sorted(sys.modules.items()):
        path = getattr(mod, "__file__", None)
        if not (name == "slidespin" or name.startswith("slidespin.")) or not path:
            continue
        p = Path(path).resolve()
        if p.suffix != ".py":
            continue
        rel = p.relative_to(package_dir).as_posix()
        if rel.endswith("__init__.py") or rel in NOT_COMPILED:
            continue
        out[rel] = hashlib.sha256(p.read_bytes()).hexdigest()
    return out


def build(output_dir: str | Path, target_cpu: str = "host") -> Path:
    """Compile the core into ``output_dir`` and write its manifest; return the manifest's path."""
    output_dir = Path(output_dir)
    output_dir.mkdir(parents=True, exist_ok=True)
    _jit._compiling["enabled"] = False  # the build says what it compiles itself
    # the sources as they are compiled (hashed first: an edit during the build must leave
    # the core stale, not recorded as built from the edited file)
    sources = source_hashes(Path(__file__).resolve().parent)
    t0 = time.perf_counter()
    _compiler(output_dir, target_cpu).compile()
    manifest = {
        "numba": numba.__version__,
        "target_cpu": target_cpu,
        "seconds": round(time.perf_counter() - t0, 1),
        "sources": sources,
    }
    path = output_dir / MANIFEST
    path.write_text(json.dumps(manifest, indent=1) + "\n")
    return path


if __name__ == "__main__":  # pragma: no cover - run by hatch_build.py
    print(build(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "host"))
