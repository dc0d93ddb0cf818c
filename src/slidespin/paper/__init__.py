"""Reproduction of the paper's tables and figures, with its errata (MODEL §6–7).

One module per table or figure, each with ``compute()`` (the numbers, as a result object with
``as_dict()`` and ``to_text()``) and ``main()`` (print them and write the files):

=============  ===========================================================================
module         reproduces
=============  ===========================================================================
``table1``     Table 1: β of eq. 16 (ϑ = 0 imposed), fx inferred by least squares, and the
               true terminal states beside it
``table2``     Table 2: inertia boundaries for three pressure laws, numeric vs printed,
               simulations in each interval, terminal ratio against I*
``fig2``       Figure 2: β(t), ϑ(t), uniform law, and the paths
``fig3``       Figure 3: β(t), ϑ(t), linear law (ξc = ηc = 0.1a), and the paths
``fig4``       Figure 4: F_n(t), linear law
``errata``     every erratum of MODEL §7, printed vs corrected, with the error it causes
``phase``      phase portraits (a ω, v) converging on the terminal ratio
``report``     everything, into one folder with an ``index.html``
=============  ===========================================================================

``semianalytic`` is the paper's own route (eq. 8–9, 12–13) in vectorised NumPy, used by
``errata`` and as a benchmark baseline. The ``slidespin reproduce`` command is
:mod:`slidespin.cli.reproduce`.
"""

from slidespin.paper import (
    errata,
    fig2,
    fig3,
    fig4,
    phase,
    report,
    semianalytic,
    table1,
    table2,
)

#: the names ``slidespin reproduce`` takes (besides ``all``): one per table, figure or check
REPRODUCTIONS = ("table1", "table2", "fig2", "fig3", "fig4", "errata", "phase")

__all__ = [
    "REPRODUCTIONS",
    "errata",
    "fig2",
    "fig3",
    "fig4",
    "phase",
    "report",
    "semianalytic",
    "table1",
    "table2",
]
