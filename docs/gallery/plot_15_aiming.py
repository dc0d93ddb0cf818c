"""
Aiming: the launch that stops at a target
=========================================

:func:`slidespin.simulate` answers "where does this launch stop?". :func:`slidespin.aim`
answers the inverse question: *which launch stops here?* Give it the target (x, y) of the
mass centre G and, if wanted, the body's total angle φ at the stop, and say which of the
start's velocities it may choose (``free``, among ``vx``, ``vy``, ``omega``); the others stay
as given in ``start``. It returns the start :class:`~slidespin.State`, found by
Levenberg–Marquardt on the stop's exact sensitivities (:func:`slidespin.stop_sensitivities`),
and measures the miss with :func:`slidespin.simulate` itself, so the launch stops where
``simulate`` says it does. When no launch reaches the target it raises
:class:`~slidespin.UnreachableTarget`, which holds the nearest stop pose it found.

Three stories:

1. **A draw to the button.** The curling stone of :doc:`plot_09_curling_stone` is released
   from the hack and must stop on the button 28 m down the sheet. The skip calls the turn
   (the spin); ``aim`` finds the weight and the line (the release speed and angle). Under
   Coulomb friction the stone does not curl (:doc:`plot_09_curling_stone`), so the line is
   straight down the sheet for every turn, and only the weight changes: a spinning stone
   carries a little farther and needs less speed. Freeing the spin as well sets the stone's
   orientation at the stop.
2. **A part slid into a pose.** A rectangular part on an anisotropic surface is flicked so
   that it stops at a given position *and* angle: all three velocities are free.
3. **An unreachable pose.** The same part launched without spin can reach the position but
   not the angle, and ``aim`` says so.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss

# %%
# The stone and the target
# ------------------------
# The stone of ``examples/curling_stone.toml``: 19.96 kg on its running band (a ring 6 mm
# wide at a mean radius of 62.5 mm), I = 0.2113 kg m², on pebbled ice with μ = 0.0068. The
# hack is at the origin, the sheet runs along +y, and the button is at (0, 28 m).
m, inertia, mu, g = 19.96, 0.2113, 0.0068, 9.81
stone = ss.Body(ss.Annulus(0.0595, 0.0655), ss.UniformPressure(), m, inertia)
ice = ss.FrictionTensor(mu, mu)
button = (0.0, 28.0)


def miss_of(body, friction, start, target):
    """Re-simulate the launch; the distance [m] of the stop from the target's (x, y), and
    the miss of the angle [rad] if the target has one."""
    tr = ss.simulate(body, friction, start)
    s = tr.stop_state
    dist = math.hypot(s.x - target[0], s.y - target[1])
    dphi = abs(s.phi - target[2]) if len(target) == 3 else 0.0
    return tr, dist, dphi


# %%
# The turn is called; the weight and the line are aimed
# -----------------------------------------------------
# For each spin ω (negative: clockwise), ``aim`` with ``free=("vx", "vy")`` and the spin fixed
# in ``start``. The release angle is measured from the x axis (90°: straight down the sheet).
# The dashed line is the closed form of :doc:`plot_09_curling_stone` for v ≫ ωρ, solved for
# the speed: d = v₀²/(2 μ g) + I ω₀²/(4 μ m g) gives v₀ = √(2 μ g (d − I ω₀²/(4 μ m g))).
spins = [-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5]
draws = {}
for w in spins:
    start = ss.aim(stone, ice, target=button, start=ss.State(omega=w), free=("vx", "vy"))
    tr, miss, _ = miss_of(stone, ice, start, button)
    draws[w] = (start, tr)
    speed = math.hypot(start.vx, start.vy)
    angle = math.degrees(math.atan2(start.vy, start.vx))
    closed = math.sqrt(2 * mu * g * (button[1] - inertia * w**2 / (4 * mu * m * g)))
    print(
        f"draw, spin {w:+.2f} rad/s: release speed = {speed:.6f} m/s "
        f"(closed form {closed:.6f}), angle = {angle:.6f} deg, miss = {miss:.1e} m"
    )
    print(f"    stops after {tr.t_stop:.3f} s, {tr.stop_state.phi / (2 * math.pi):+.3f} turns")

ww = np.linspace(min(spins), max(spins), 121)
v_closed = np.sqrt(2 * mu * g * (button[1] - inertia * ww**2 / (4 * mu * m * g)))
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8.4, 3.4))
ax1.plot(ww, v_closed, "k--", lw=1, label="closed form, v ≫ ωρ")
ax1.plot(spins, [math.hypot(s.vx, s.vy) for s, _ in draws.values()], "C0o", label="aim")
ax1.set_xlabel("spin ω at release [rad/s]")
ax1.set_ylabel("release speed [m/s]")
ax1.legend(fontsize=8)
ax2.plot(spins, [math.degrees(math.atan2(s.vy, s.vx)) for s, _ in draws.values()], "C1o-")
ax2.set_ylim(89.0, 91.0)
ax2.set_xlabel("spin ω at release [rad/s]")
ax2.set_ylabel("release angle [deg] (90: down the sheet)")
fig.suptitle("draw to the button at 28 m: the launches aim finds", fontsize=10)
fig.tight_layout()

# %%
# The paths of the stones, across the sheet (in millimetres: they run straight, to round-off),
# and their speed over the last seconds (re-run with a step of at most 0.2 s for smooth
# curves): a spinning stone is released slower, and near the end the spin takes a growing
# share of the friction away from the slide, so it slides longer.
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8.4, 3.6))
for w, (start, _) in draws.items():
    dense = ss.simulate(stone, ice, start, max_step=0.2)
    ax1.plot(1000 * np.asarray(dense.x), dense.y, lw=1, label=f"ω = {w:+.1f} rad/s")
    if w >= 0.0:  # the clockwise stones move the same (mirror symmetry)
        ax2.plot(dense.t, dense.speed, lw=1, label=f"|ω| = {w:.1f} rad/s")
ax1.plot(0.0, button[1], "k+", ms=14, mew=2)
ax1.set_xlim(-1.0, 1.0)
ax1.set_xlabel("offset across x [mm]")
ax1.set_ylabel("distance down the sheet y [m]")
ax1.set_title("paths (+: the button)", fontsize=9)
ax2.set_xlabel("t [s]")
ax2.set_ylabel("speed of G [m/s]")
ax2.set_xlim(25.0, 31.0)
ax2.set_ylim(0.0, 0.3)
ax2.set_title("speed over the last seconds", fontsize=9)
ax2.legend(fontsize=7)
fig.tight_layout()

# %%
# The orientation at the stop as well
# -----------------------------------
# With the spin free too, the target can include the stone's total angle at the stop: here
# two and a half turns counter-clockwise (φ = 5π), so that the handle, which points along the
# body axis at release, stops pointing the other way. ``aim`` picks the spin that turns the
# stone exactly that much over the draw, and the weight that still stops it on the button.
target = (0.0, 28.0, 5 * math.pi)
start = ss.aim(stone, ice, target=target, start=ss.State(), free=("vx", "vy", "omega"))
tr, miss, miss_phi = miss_of(stone, ice, start, target)
print(
    f"draw, 2.5 turns: release speed = {math.hypot(start.vx, start.vy):.6f} m/s, "
    f"angle = {math.degrees(math.atan2(start.vy, start.vx)):.6f} deg, "
    f"spin = {start.omega:.6f} rad/s, miss = {miss:.1e} m, angle miss = {miss_phi:.1e} rad"
)

# %%
# A part slid into a pose
# -----------------------
# A 120 × 80 mm rectangular part of 0.5 kg, on a surface whose friction is anisotropic
# (μ = 0.3 along X, 0.45 along Y: a grooved or brushed surface), must stop with its centre at
# (0.25 m, 0.10 m) turned by φ = 0.8 rad. All three velocities are free; the part starts at
# the origin with its long axis ξ along X.
part = ss.Body(ss.Rectangle(0.12, 0.08), ss.UniformPressure(), 0.5)
surface = ss.FrictionTensor(0.3, 0.45)
pose = (0.25, 0.10, 0.8)
launch = ss.aim(part, surface, target=pose)
tr, miss, miss_phi = miss_of(part, surface, launch, pose)
print(
    f"part: launch vx = {launch.vx:.6f} m/s, vy = {launch.vy:.6f} m/s, "
    f"omega = {launch.omega:.6f} rad/s, miss = {miss:.1e} m, angle miss = {miss_phi:.1e} rad"
)
print(f"    stops after {tr.t_stop:.6f} s, ending {tr.ending}")


def outline(x, y, phi):
    """The part's outline placed at G = (x, y), turned by phi."""
    (c,) = part.patch.outlines()
    rot = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])
    return c @ rot.T + (x, y)


t = np.asarray(tr.t)
fig, ax = plt.subplots(figsize=(6.4, 4.4))
ax.plot(tr.x, tr.y, "k-", lw=1, label="path of G")
for k, tk in enumerate(np.linspace(0.0, tr.t_stop, 6)[:-1]):
    xk, yk, pk = (np.interp(tk, t, np.asarray(a)) for a in (tr.x, tr.y, tr.phi))
    c = outline(xk, yk, pk)
    ax.plot(c[:, 0], c[:, 1], "C0-", lw=1, alpha=0.35 + 0.1 * k)
    ax.plot([xk, xk + 0.06 * math.cos(pk)], [yk, yk + 0.06 * math.sin(pk)], "C0-", lw=0.8)
c = outline(*pose)
ax.fill(c[:, 0], c[:, 1], color="C3", alpha=0.25, lw=0, label="target pose")
s = tr.stop_state
c = outline(s.x, s.y, s.phi)
ax.plot(c[:, 0], c[:, 1], "C3-", lw=1.5, label="stop")
ax.plot([s.x, s.x + 0.06 * math.cos(s.phi)], [s.y, s.y + 0.06 * math.sin(s.phi)], "C3-")
ax.set_aspect("equal")
ax.set_xlabel("X [m]")
ax.set_ylabel("Y [m]")
ax.set_title("part slid into (0.25 m, 0.10 m, 0.8 rad): every t_stop/5 (line: axis ξ)")
ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()

# %%
# A pose that cannot be reached
# -----------------------------
# Without spin the part cannot turn: its footprint is centrally symmetric about G, so the
# traction of a pure translation is uniform and has no moment about G. The position alone is
# reachable, the angle is not; ``aim`` raises :class:`~slidespin.UnreachableTarget` with the
# nearest stop pose, whose miss weighs the angle's miss by the body's length unit ℓ (here
# ℓ ⋅ 0.8 rad, since the nearest pose is the target's position at φ = 0).
try:
    ss.aim(part, surface, target=pose, start=ss.State(omega=0.0), free=("vx", "vy"))
except ss.UnreachableTarget as err:
    near = err.nearest
    print(
        f"unreachable without spin: nearest pose = ({near.x:.6f} m, {near.y:.6f} m, "
        f"{near.phi:.6f} rad), miss = {err.miss:.6f} m (length unit {part.length_unit:.6f} m)"
    )
