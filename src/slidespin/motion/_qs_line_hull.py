"""A quasi-static line pusher on a hull of discs (pads with disks: straight edges, arcs and
sharp corners; MODEL §13): the separating-axis gap and the contact features for
:mod:`slidespin.motion.quasi_static_line`, in its frame ``fr`` (SI units, positions relative
to G in the plane's orientation).

A disc of radius r touches the face at its support point c − r N (N the pushing normal, into
the body), a ``vertex`` contact as a polygon's corner (r = 0) with the same margins (the
face's normal inside the disc's normal cone, the arc's angular range); an end of the pusher
touches a straight edge (``end``) or an arc (``endarc``: the inward normal from the end to
the disc's centre, inside its cone).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.motion._pushed_geometry import disc_hull_axes

__all__ = ["hull_features", "hull_gap"]


def hull_gap(prob, fr) -> float:
    """The separating-axis gap [m] (> 0 apart) over the face's normals, the edges' normals
    and the directions from the pusher's ends to the discs' centres."""
    rot = fr["rot"]
    gaps, _, _ = disc_hull_axes(
        prob.verts @ rot.T, prob.radii, prob.normals @ rot.T, np.array(fr["E"]), fr["d"]
    )
    return float(gaps.max())


def hull_features(prob, fr, tol):
    """The features touching the pusher: [("face", i)], or ("vertex", i) (a disc's support
    point on the face), ("end", k, j) (end k on edge j), ("endarc", k, i) (on disc i's arc)."""
    rot, e0, d, npush = fr["rot"], fr["E"][0], fr["d"], fr["N"]
    a, b = prob.ea @ rot.T, prob.eb @ rot.T
    dna, dsa = (a - e0) @ npush, (a - e0) @ d
    dnb, dsb = (b - e0) @ npush, (b - e0) @ d
    for i in range(len(a)):
        lo, hi = max(min(dsa[i], dsb[i]), 0.0), min(max(dsa[i], dsb[i]), prob.L)
        if abs(dna[i]) <= tol and abs(dnb[i]) <= tol and hi - lo > tol:
            return [("face", i)]
    c = prob.verts @ rot.T
    s = c - prob.radii[:, None] * npush
    dn, ds = (s - e0) @ npush, (s - e0) @ d
    out = [
        ("vertex", i) for i in range(len(c)) if abs(dn[i]) <= tol and -tol <= ds[i] <= prob.L + tol
    ]
    nw = prob.normals @ rot.T
    for k, ek in enumerate(fr["E"]):
        for j in range(len(a)):
            ab = b[j] - a[j]
            u = float((ek - a[j]) @ ab) / prob.lengths[j] ** 2
            ut = tol / prob.lengths[j]
            if abs(float((ek - a[j]) @ nw[j])) <= tol and -ut <= u <= 1.0 + ut:
                out.append(("end", k, j))
        for i in np.flatnonzero(prob.radii > 0.0):
            if abs(math.hypot(*(ek - c[i])) - prob.radii[i]) <= tol:
                out.append(("endarc", k, int(i)))
    return out
