"""The one compiled entry of the loaded engine (MODEL §11): every task of
:class:`slidespin.motion._loaded_engine.CompiledSlip` in one function, :func:`run_loaded`.

numba compiles a function called from Python together with everything it calls, the wrench
kernel included, and caches it per kind of patch. One entry for the four tasks (the
explicit stepper, the implicit stepper, the stiffness ratio, the onset direction) compiles
the kernel into one library instead of four: the first run of a loaded slip costs one
compile per kind of patch (ellipse, footprint), then loads from numba's on-disk cache. The
task is a float argument, so that no integer literal reaches a compiled call.
"""

from __future__ import annotations

import numpy as np

from slidespin._jit import jit
from slidespin.contact._engine import kernel_constants
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE
from slidespin.motion._loaded_dop853 import NROW, run_dop853
from slidespin.motion._loaded_flow import slaved_direction, stiffness
from slidespin.motion._loaded_radau import run_radau

TASK_DOP853 = 0.0
TASK_RADAU = 1.0
TASK_STIFFNESS = 2.0
TASK_ONSET = 3.0


@jit(error_model="numpy")
def run_loaded(
    task, par, fp, tab, mode, y0, rtol, atol, h_max, t_end, breaks, ln_stop, s_arg, t_tol, steps
):
    """Run ``task`` on the state y0 (natural units; the layout of
    :mod:`slidespin.motion._loaded_flow`).

    * ``TASK_DOP853``: :func:`~slidespin.motion._loaded_dop853.run_dop853` in ``mode``
      (``s_arg``: the slow speed of the slaved start);
    * ``TASK_RADAU``: :func:`~slidespin.motion._loaded_radau.run_radau` in ``mode``
      (``s_arg``: the stiffness ratio at which it hands over);
    * ``TASK_STIFFNESS``: :func:`~slidespin.motion._loaded_flow.stiffness` at (u, t, φ) of
      y0, in aux[0];
    * ``TASK_ONSET``: :func:`~slidespin.motion._loaded_flow.slaved_direction` from u of y0
      at (t, φ) of y0: aux = (u*, λ, |residual|, ok).

    Returns (y, reason, n_steps, n_calls, n_fail, rec, aux); rows are always recorded by
    the steppers.
    """
    aux = np.zeros(6)
    if task == TASK_DOP853:
        y, reason, n, calls, rec, nfail = run_dop853(
            par,
            fp,
            tab,
            mode,
            y0,
            rtol,
            atol,
            h_max,
            t_end,
            breaks,
            ln_stop,
            s_arg,
            t_tol,
            steps,
            True,
        )
        return y, reason, n, calls, nfail, rec, aux
    if task == TASK_RADAU:
        y, reason, n, calls, nfail, rec = run_radau(
            par,
            fp,
            tab,
            mode,
            y0,
            rtol,
            atol,
            h_max,
            t_end,
            breaks,
            ln_stop,
            s_arg,
            steps,
            True,
        )
        return y, reason, n, calls, nfail, rec, aux
    kc = kernel_constants(par)
    W = np.empty(WORKSPACE_SHAPE)
    if task == TASK_STIFFNESS:
        ratio, calls = stiffness(par, kc, W, fp, tab, y0[0], y0[1], y0[2], y0[4], y0[7])
        aux[0] = ratio
        return y0.copy(), 0, 0, calls, 0, np.empty((0, NROW)), aux
    out = np.empty(5)
    ok, calls = slaved_direction(par, kc, W, fp, tab, y0[4], y0[7], y0[0], y0[1], y0[2], out)
    for i in range(5):
        aux[i] = out[i]
    aux[5] = 1.0 if ok else 0.0
    return y0.copy(), 0, 0, calls, 0, np.empty((0, NROW)), aux
