"""Tracked pushes in the layout of the MIT push dataset (MODEL §12–13).

Yu, Bauza, Fazeli & Rodriguez (2016), "More than a million ways to be pushed: a high-fidelity
experimental dataset of planar pushing" (IROS 2016), recorded a steel object pushed by a
robot's round probe on several surfaces. Each push is one file, published as JSON and as
HDF5, holding three time series (one row per sample, each stream on its own clock):

=================  ====================================  =================================
key / dataset      row                                   units
=================  ====================================  =================================
``tip_pose``       (t, x, y) or (t, x, y, θ_tip)          s, m, m (, rad)
``object_pose``    (t, x, y, θ)                          s, m, m, rad
``ft_wrench``      (t, fx, fy, τz)                       s, N, N, N m
=================  ====================================  =================================

What the layout is, as found in the authors' public processing code (``mcubelab/push-est-public``,
``catkin_ws/src/pnpush_planning/src/analyze/parse_bagfile_to_rawjson.py``, which writes both
forms from the recorded ROS bags, and the example file
``motion_surface=plywood_shape=hex_a=0_v=150_i=1.000_s=0.000_t=-0.349.json`` next to it):

* JSON: one object ``{"tip_pose": [[...], ...], "ft_wrench": [...], "object_pose": [...]}``
  of lists of rows; HDF5: three 2-D datasets of those names, the same rows.
* Times are absolute (UNIX epoch seconds of the ROS messages), different for every stream.
* Positions are in metres in the robot's base frame (the probe's position converted from
  millimetres, the object's from the motion-capture frame); angles are yaw angles [rad].
* ``tip_pose`` has **four** columns in the files the code writes (the fourth is the tool's
  yaw, irrelevant for a round probe), while the authors' MATLAB reader documents three,
  (t, x, y): both are accepted here, the fourth column is kept as ``PushRun.tip_angle``.
* ``ft_wrench`` holds the probe's force-torque sensor reading, flipped into the robot frame:
  (fx, fy) and the torque about the sensor's vertical axis. In the example file the mean
  measured force points against the probe's motion, so it is the force **of the object on
  the probe**; the pusher's force on the object (MODEL §13's λ) is its negative. The torque
  is about the probe's own axis (nearly 0 for a point contact), not about G.
* ``object_pose`` is the pose of the object's tracked frame; for the dataset's shapes (the
  shape database draws each outline about this frame) we take it to be the pose (x, y, φ)
  of the mass centre G and of the body frame of MODEL §1 (**an assumption**: an object whose
  tracked frame is not at G needs its poses moved there first).
* The file name carries the push's settings as ``key=value`` fields separated by ``_``
  (``surface``, ``shape``, ``a`` acceleration [mm/s²], ``v`` speed [mm/s], ``i`` the
  contact position along the side, ``s`` the side, ``t`` the push angle [rad]); they are
  parsed into ``PushRun.meta`` as found (strings).
* The probe is a cylinder of radius 4.75 mm (``probe4`` in the authors' code): the
  contact is on the probe's rim, not at ``tip_pose``. A point pusher (MODEL §13) at the
  probe's centre touches the object's outline grown by that radius (``outline=`` of
  :func:`~slidespin.analysis.fit_push.fit_pushes`).

:func:`read_push` reads one file (``.json``, or ``.h5``/``.hdf5`` with the optional h5py:
``pip install slidespin[hdf5]``) into a frozen :class:`PushRun`, in SI units, with times
measured from the earliest sample of the file (the subtracted clock time is
``PushRun.t_origin``); :func:`read_pushes` reads a directory or a list of files.
Every problem is one ``ValueError`` line naming the file, the key and what is wrong.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from slidespin._io import read_regular_file
from slidespin.motion.pushers import PointPusher

__all__ = ["MAX_PUSH_BYTES", "PUSH_KEYS", "PushRun", "read_push", "read_pushes"]

#: the three time series of a push, as named in the dataset
PUSH_KEYS = ("tip_pose", "object_pose", "ft_wrench")
#: largest push file :func:`read_push` reads [bytes]
MAX_PUSH_BYTES = 200_000_000
_JSON = (".json",)
_HDF5 = (".h5", ".hdf5")
_COLUMNS = {
    "tip_pose": ((3, 4), "(t, x, y) or (t, x, y, theta)"),
    "object_pose": ((4,), "(t, x, y, theta)"),
    "ft_wrench": ((4,), "(t, fx, fy, torque)"),
}


def _frozen(a: NDArray[np.float64]) -> NDArray[np.float64]:
    a = np.ascontiguousarray(a, dtype=float)
    a.flags.writeable = False
    return a


@dataclass(frozen=True, slots=True, eq=False)
class PushRun:
    """One tracked push (MODEL §12–13), in SI units, times from the file's earliest sample.

    Attributes
    ----------
    source : str
        The file it was read from (or ``"<memory>"``).
    tip : ndarray, shape (n, 3)
        Rows (t, x, y) of the pusher tip (the probe's centre) [s, m, m], plane frame.
    object_pose : ndarray, shape (m, 4)
        Rows (t, x, y, φ) of the object (taken as G and the body frame) [s, m, m, rad].
    wrench : ndarray, shape (k, 4), or None
        Rows (t, fx, fy, τz) of the force-torque sensor as published [s, N, N, N m]: the
        force of the object on the probe (the pusher's force on the object is
        ``-wrench[:, 1:3]``); ``None`` when the file has no (or an empty) ``ft_wrench``.
    tip_angle : ndarray, shape (n,), or None
        The tool's yaw [rad] when ``tip_pose`` has a fourth column.
    t_origin : float
        The published time of the earliest sample [s] (UNIX time in the dataset), subtracted
        from every time here: published time = t + t_origin.
    meta : dict
        ``key=value`` fields of the file name (strings), e.g. ``{"shape": "rect1", "v": "20"}``.
    extra : dict
        Other top-level JSON entries (or HDF5 attributes), e.g. the ``"source"`` label of a
        synthetic file.
    """

    source: str
    tip: NDArray[np.float64]
    object_pose: NDArray[np.float64]
    wrench: NDArray[np.float64] | None = None
    tip_angle: NDArray[np.float64] | None = None
    t_origin: float = 0.0
    meta: dict = field(default_factory=dict)
    extra: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        k = 0 if self.wrench is None else self.wrench.shape[0]
        return (
            f"PushRun({os.path.basename(self.source)!r}, tip rows={self.tip.shape[0]}, "
            f"object rows={self.object_pose.shape[0]}, wrench rows={k}, "
            f"t=[0, {self.duration:.6g}] s)"
        )

    @property
    def duration(self) -> float:
        """Time from the earliest to the latest sample of any stream [s]."""
        ends = [self.tip[-1, 0], self.object_pose[-1, 0]]
        if self.wrench is not None:
            ends.append(self.wrench[-1, 0])
        return float(max(ends))

    @property
    def has_force(self) -> bool:
        """Whether the push has force samples."""
        return self.wrench is not None and self.wrench.shape[0] > 0

    def pusher(self, mu: float = 0.0) -> PointPusher:
        """The tip path as a :class:`~slidespin.PointPusher` (rows (t, x, y), μp = ``mu``)."""
        return PointPusher(self.tip, mu=mu)

    def pose_run(self) -> dict:
        """The object's poses as a run of :func:`slidespin.fit` (``t``, ``x``, ``y``, ``phi``;
        φ unwrapped)."""
        o = self.object_pose
        return {
            "t": o[:, 0].copy(),
            "x": o[:, 1].copy(),
            "y": o[:, 2].copy(),
            "phi": np.unwrap(o[:, 3]),
        }

    def pusher_force(self) -> NDArray[np.float64] | None:
        """Rows (t, λx, λy): the measured force of the pusher on the object [s, N, N] (the
        negated sensor force), or ``None`` without force samples."""
        if not self.has_force:
            return None
        w = self.wrench
        assert w is not None
        return np.column_stack((w[:, 0], -w[:, 1], -w[:, 2]))


# --------------------------------------------------------------------------------------------
# validation


def _table(name: str, key: str, value: Any, required: bool) -> NDArray[np.float64] | None:
    cols, layout = _COLUMNS[key]
    if value is None:
        if required:
            raise ValueError(
                f"{name}: key {key!r} is missing; valid: a list of rows {layout} (the MIT push "
                f"dataset's keys {', '.join(PUSH_KEYS)})"
            )
        return None
    if isinstance(value, (str, bytes, Mapping)) or isinstance(value, (bool, int, float)):
        raise ValueError(
            f"{name}: key {key!r} holds a {type(value).__name__}; valid: a list of rows {layout}"
        )
    rows = list(value) if not isinstance(value, np.ndarray) else value
    if len(rows) == 0:
        if required:
            raise ValueError(f"{name}: key {key!r} has no rows; valid: at least 2 rows {layout}")
        return None
    if isinstance(rows, np.ndarray):
        if rows.ndim != 2 or rows.shape[1] not in cols:
            raise ValueError(
                f"{name}: key {key!r} has shape {rows.shape}; valid: rows {layout}, "
                f"shape (n, {' or '.join(str(c) for c in cols)})"
            )
        if rows.dtype.kind not in "fiu":
            raise ValueError(
                f"{name}: key {key!r} holds {rows.dtype} values; valid: real numbers, rows {layout}"
            )
        arr = rows.astype(float)
    else:
        width = None
        for i, r in enumerate(rows):
            if isinstance(r, (str, bytes, Mapping)) or not isinstance(r, (list, tuple)):
                raise ValueError(
                    f"{name}: key {key!r} row {i} is {type(r).__name__}; valid: a row {layout}"
                )
            if len(r) not in cols:
                raise ValueError(
                    f"{name}: key {key!r} row {i} has {len(r)} values; valid: rows {layout}"
                )
            if width is None:
                width = len(r)
            elif len(r) != width:
                raise ValueError(
                    f"{name}: key {key!r} row {i} has {len(r)} values, row 0 has {width}; "
                    "valid: rows of one length"
                )
            for j, x in enumerate(r):
                if isinstance(x, bool) or not isinstance(x, (int, float)):
                    raise ValueError(
                        f"{name}: key {key!r} row {i} column {j} is {x!r}; valid: a real number"
                    )
        arr = np.array(rows, dtype=float)
    bad = np.argwhere(~np.isfinite(arr))
    if bad.size:
        i, j = (int(q) for q in bad[0])
        raise ValueError(
            f"{name}: key {key!r} row {i} column {j} is {float(arr[i, j])!r}; valid: a finite number"
        )
    if arr.shape[0] < 2:
        raise ValueError(f"{name}: key {key!r} has 1 row; valid: at least 2 rows {layout}")
    back = np.flatnonzero(np.diff(arr[:, 0]) <= 0.0)
    if back.size:
        i = int(back[0]) + 1
        raise ValueError(
            f"{name}: key {key!r} row {i} has time {float(arr[i, 0])!r} s, not after row {i - 1}'s "
            f"{float(arr[i - 1, 0])!r} s; valid: strictly increasing times"
        )
    return arr


def _meta_from_name(path: str) -> dict:
    stem = os.path.basename(path)
    for ext in _JSON + _HDF5:
        if stem.lower().endswith(ext):
            stem = stem[: -len(ext)]
    meta = {}
    for part in stem.split("_"):
        k, sep, val = part.partition("=")
        if sep and k:
            meta[k] = val
    return meta


def _build(name: str, tables: Mapping, extra: dict) -> PushRun:
    tip = _table(name, "tip_pose", tables.get("tip_pose"), True)
    obj = _table(name, "object_pose", tables.get("object_pose"), True)
    ft = _table(name, "ft_wrench", tables.get("ft_wrench"), False)
    assert tip is not None and obj is not None
    t0 = min(float(tip[0, 0]), float(obj[0, 0]), math.inf if ft is None else float(ft[0, 0]))
    tip = tip.copy()
    obj = obj.copy()
    tip[:, 0] -= t0
    obj[:, 0] -= t0
    angle = _frozen(tip[:, 3]) if tip.shape[1] == 4 else None
    if ft is not None:
        ft = ft.copy()
        ft[:, 0] -= t0
    for key, arr in (("tip_pose", tip), ("object_pose", obj), ("ft_wrench", ft)):
        # times of ~1e9 s lose digits when shifted: they must still increase
        if arr is not None and np.any(np.diff(arr[:, 0]) <= 0.0):
            raise ValueError(
                f"{name}: key {key!r}: times too close for their size (round-off); valid: "
                "times that stay strictly increasing after subtracting the earliest"
            )
    return PushRun(
        source=name,
        tip=_frozen(tip[:, :3]),
        object_pose=_frozen(obj),
        wrench=None if ft is None else _frozen(ft),
        tip_angle=angle,
        t_origin=t0,
        meta=_meta_from_name(name),
        extra=extra,
    )


# --------------------------------------------------------------------------------------------
# reading


def _read_json(name: str, path) -> PushRun:
    raw = read_regular_file(path, "push file", "JSON", MAX_PUSH_BYTES)
    try:
        doc = json.loads(raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        raise ValueError(f"{name}: not UTF-8 text; valid: a JSON push file") from None
    except json.JSONDecodeError as exc:
        raise ValueError(
            f"{name}: invalid JSON at line {exc.lineno} column {exc.colno}: {exc.msg}; valid: "
            "a JSON object with keys tip_pose, object_pose, ft_wrench"
        ) from None
    if not isinstance(doc, dict):
        raise ValueError(
            f"{name}: the top level is a {type(doc).__name__}; valid: a JSON object with keys "
            "tip_pose, object_pose, ft_wrench"
        )
    extra = {k: v for k, v in doc.items() if k not in PUSH_KEYS}
    return _build(name, doc, extra)


def _read_hdf5(name: str, path) -> PushRun:
    try:
        # lazy: h5py is optional (the hdf5 extra)
        import h5py  # type: ignore[import-untyped, import-not-found, unused-ignore]
    except ImportError:
        raise ImportError(
            f"{name}: reading HDF5 push files needs h5py: pip install slidespin[hdf5]"
        ) from None
    if not os.path.isfile(path):
        raise ValueError(f"push file {name!r} does not exist or is not a regular file")
    if os.path.getsize(path) > MAX_PUSH_BYTES:
        raise ValueError(
            f"push file {name!r} is larger than MAX_PUSH_BYTES = {MAX_PUSH_BYTES} bytes"
        )
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        raise ValueError(
            f"{name}: not a readable HDF5 file ({exc}); valid: an HDF5 push file"
        ) from None
    with f:
        tables: dict[str, Any] = {}
        for key in PUSH_KEYS:
            if key in f:
                obj = f[key]
                if not isinstance(obj, h5py.Dataset):
                    raise ValueError(
                        f"{name}: {key!r} is an HDF5 group; valid: a 2-D dataset of rows "
                        f"{_COLUMNS[key][1]}"
                    )
                data = np.asarray(obj[()])
                if data.size == 0:
                    data = np.empty((0, _COLUMNS[key][0][-1]))
                tables[key] = data
        extra = {}
        for k, val in f.attrs.items():
            extra[k] = (
                val.decode()
                if isinstance(val, bytes)
                else (val.item() if isinstance(val, np.generic) else val)
            )
    return _build(name, tables, extra)


def read_push(path) -> PushRun:
    """Read one push file in the MIT push dataset's layout (module notes; MODEL §12–13).

    Parameters
    ----------
    path : str or os.PathLike
        A ``.json`` file (an object with the keys ``tip_pose``, ``object_pose`` and, optionally,
        ``ft_wrench``) or an ``.h5``/``.hdf5`` file with datasets of those names, at most
        :data:`MAX_PUSH_BYTES` bytes. Other top-level JSON entries (HDF5 attributes) are kept
        in ``PushRun.extra``.

    Returns
    -------
    PushRun
        SI units; times from the earliest sample of the three streams (the subtracted clock
        time is ``PushRun.t_origin``); rows as published otherwise.

    Raises
    ------
    ValueError
        One line naming the file, the key (and row, column) and the problem: a missing key,
        a row of the wrong length, a non-finite value, times that do not increase.
    ImportError
        For an HDF5 file without h5py (``pip install slidespin[hdf5]``).
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ValueError(
            f"push file path = {path!r} ({type(path).__name__}) is invalid; valid values: a str "
            "or os.PathLike path to a .json, .h5 or .hdf5 file"
        )
    name = os.fsdecode(os.fspath(path))
    low = name.lower()
    if low.endswith(_JSON):
        return _read_json(name, path)
    if low.endswith(_HDF5):
        return _read_hdf5(name, path)
    raise ValueError(
        f"push file {name!r} has an unknown extension; valid: .json, .h5 or .hdf5 (the MIT push "
        "dataset's two forms)"
    )


def read_pushes(paths) -> list[PushRun]:
    """Read several pushes: every ``.json``/``.h5``/``.hdf5`` file of a directory (sorted by
    name, not recursive), or the files of a list, or one file.

    Returns
    -------
    list of PushRun

    Raises
    ------
    ValueError
        When no push file is found, or from :func:`read_push` for the first bad file.
    """
    if isinstance(paths, (str, os.PathLike)):
        name = os.fsdecode(os.fspath(paths))
        if os.path.isdir(name):
            files = sorted(
                os.path.join(name, f)
                for f in os.listdir(name)
                if f.lower().endswith(_JSON + _HDF5) and os.path.isfile(os.path.join(name, f))
            )
            if not files:
                raise ValueError(
                    f"directory {name!r} holds no push file; valid: .json, .h5 or .hdf5 files"
                )
            return [read_push(f) for f in files]
        return [read_push(paths)]
    if isinstance(paths, Iterable) and not isinstance(paths, (bytes, Mapping)):
        items = list(paths)
        if not items:
            raise ValueError("paths = [] holds no file; valid: one or more push files")
        return [read_push(p) for p in items]
    raise ValueError(
        f"paths = {paths!r} is invalid; valid values: a directory, a push file, or a list of "
        "push files"
    )
