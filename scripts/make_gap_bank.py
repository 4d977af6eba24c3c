#!/usr/bin/env python3
"""Writes the gap bank: normal-contact cases whose gaps are not Hertzian, for the benchmark
(examples/bench/) and, with --scale small, for the unit tests. Every shape is made here from
the formulas below and seeded random numbers (numpy's RandomState, whose streams are frozen):
the same files on every run. Steel on steel (G = 82 GPa, nu = 0.28 both, E* = G / (1 - nu)).

  python3 scripts/make_gap_bank.py [--out DIR] [--only NAME[,NAME]] [--scale full|small] [--list]

Full scale (default, --out examples/bench):
  measured-wheel-rail-{6k,23k,93k,372k}  a worn wheel on a worn rail from "measured" lateral
                                         profiles, approach-controlled (Fn about 10 kN);
  measured-wheel-rail-23k-force          the same at 10 kN;
  conformal-band                         a lateral gap flat to +-0.4 um over 8 mm, 10 kN;
  two-patches                            tread and flange-root contact at once, 10 kN;
  rough-sphere-512                       a self-affine rough sphere on 512 x 512 (its 13 MB table
                                         is not committed: this script regenerates it);
  flat-punch-sharp                       a rectangular punch with sharp edges and corners;
  cone                                   a cone of 2 degrees (Sneddon's closed form).
Small scale (--scale small, for tests; default --out build/gap_bank): the same shapes on grids of
at most 64 x 64 (the rough surface on 128 x 128, synthesised by the same recipe), as
measured-wheel-rail, measured-wheel-rail-force, conformal-band, two-patches, rough-sphere,
flat-punch-sharp, cone.

Each case is a dyncontact normal case (docs/CASES.md) with a table profile: CSV columns x,y,h
in metres on a regular lattice, interpolated at the element centres (exactly for quadratics; dyncontact
shifts the table's minimum to 0). The tables of the measured profiles are sampled at 0.1 mm
laterally (y) and coarser along x; the formula shapes are tabulated at the element centres,
where the interpolation is exact.
"""
import argparse
import json
import math
import os
import sys

try:
    import numpy as np
except ImportError:  # pragma: no cover
    sys.exit("make_gap_bank.py needs numpy (Debian: python3-numpy; run it with /usr/bin/python3)")

G = 82e9
NU = 0.28
E_STAR = G / (1.0 - NU)  # 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, E = 2 G (1 + nu), both bodies alike
R_WHEEL = 0.46           # wheel radius along x (rolling direction), m
MM = 1e-3
UM = 1e-6
QUANTUM = 0.01 * UM      # the profile instrument's height resolution

# Table files above this size are not committed (listed in .gitignore; this script makes them).
BIG_TABLE_BYTES = 1 << 20


# ----------------------------------------------------------------------------------------------
# helpers

def centres(lo, hi, n):
    """Element centres of n equal elements on [lo, hi]."""
    return lo + (np.arange(n) + 0.5) * ((hi - lo) / n)


def lattice(lo, hi, step):
    """lo, lo + step, ..., hi (hi - lo must be a whole number of steps)."""
    m = int(round((hi - lo) / step))
    if abs(lo + m * step - hi) > 1e-9 * step:
        raise ValueError("lattice [%g, %g] is not a whole number of steps %g" % (lo, hi, step))
    return lo + np.arange(m + 1) * ((hi - lo) / m)


def gaussian_smooth(values, step, sigma):
    """Convolution with a normalised Gaussian of standard deviation sigma (same length; the
    ends are padded with their edge values)."""
    half = int(math.ceil(4.0 * sigma / step))
    s = np.arange(-half, half + 1) * step
    kernel = np.exp(-0.5 * (s / sigma) ** 2)
    kernel /= kernel.sum()
    padded = np.concatenate([np.full(half, values[0]), values, np.full(half, values[-1])])
    return np.convolve(padded, kernel, mode="valid")


def band_limited_noise(rng, y, corr, peak):
    """Measurement noise at the points y (a regular lattice): white Gaussian noise on a 10 um
    lattice filtered by a Gaussian kernel of standard deviation corr / 2 (autocorrelation
    exp(-(s / corr)^2): correlation length corr), scaled so that its largest |value| over y is
    `peak`, then taken at y."""
    fine = 10 * UM
    half = int(math.ceil(3.0 * corr / fine))
    n = int(round((y[-1] - y[0]) / fine)) + 1
    white = rng.standard_normal(n + 2 * half)
    s = np.arange(-half, half + 1) * fine
    kernel = np.exp(-0.5 * (s / (0.5 * corr)) ** 2)
    smooth = np.convolve(white, kernel, mode="valid")  # n values on y[0] + k * fine
    yf = y[0] + np.arange(n) * fine
    noise = np.interp(y, yf, smooth)
    return noise * (peak / np.max(np.abs(noise)))


def quantise(z):
    return np.round(z / QUANTUM) * QUANTUM


def circular_arcs(Y, pieces):
    """A convex profile z(Y) of tangent-continuous circular arcs, top z = 0 at Y = 0 with slope
    0. pieces: {"gauge": [(radius, end), ...], "field": [...]}: the arcs from Y = 0 outwards on
    the gauge side (Y > 0) and the field side (Y < 0), each to |Y| = end (the last end inf)."""
    z = np.full_like(Y, np.nan, dtype=float)
    for side, sign in (("gauge", 1.0), ("field", -1.0)):
        arcs = pieces[side]
        yc, zc = 0.0, -arcs[0][0]  # first centre below the top
        start = 0.0
        for radius, end in arcs:
            u = sign * Y
            sel = (u >= start) & (u <= end) if side == "gauge" else (u > start) & (u <= end)
            d = u[sel] - yc
            if np.any(np.abs(d) >= radius):
                raise ValueError("profile runs past a vertical tangent")
            z[sel] = zc + np.sqrt(radius * radius - d * d)
            if math.isinf(end):
                break
            # junction at u = end: the next arc shares its normal there
            zj = zc + math.sqrt(radius * radius - (end - yc) ** 2)
            nu_, nz = (end - yc) / radius, (zj - zc) / radius
            start = end
            nxt = arcs[arcs.index((radius, end)) + 1][0]
            yc, zc = end - nxt * nu_, zj - nxt * nz
    return z


def write_table(path, xs, ys, h):
    """CSV x,y,h (m): h[j, i] at (xs[i], ys[j]), rows y-major like scripts/make_wheel_rail.sh."""
    X, Y = np.meshgrid(xs, ys)
    rows = np.column_stack([X.ravel(), Y.ravel(), h.ravel()])
    with open(path, "w") as f:
        f.write("x,y,h\n")
        np.savetxt(f, rows, fmt=("%.15g", "%.15g", "%.10g"), delimiter=",")


def case(name, description, table, grid, normal):
    return {
        "schema": "dyncontact/1",
        "name": name,
        "description": description,
        "problem": "normal",
        "dimension": 3,
        "materials": {"body": {"G": G, "nu": NU}, "base": {"G": G, "nu": NU}},
        "profile": {"type": "table", "file": table},
        "grid": grid,
        "normal": normal,
        "solver": {"backend": "auto", "tol": 1e-9},
    }


def grid_block(nx, ny, x, y):
    r = lambda v: float("%.12g" % v)  # -0.0036, not -0.0036000000000000003
    return {"nx": nx, "ny": ny, "x": [r(x[0]), r(x[1])], "y": [r(y[0]), r(y[1])]}


def fmt_mm(v):
    return "%.4g mm" % (v / MM)


def fmt_um(v):
    return "%.4g um" % (v / UM)


# ----------------------------------------------------------------------------------------------
# 1. measured wheel/rail: worn rail, worn wheel, both "measured"

# Rail head (new): circular arcs, tangent-continuous, top at Y = 0 (rail coordinates, Y towards
# the gauge side): crown 300 mm to |Y| = 10 mm, then 80 mm to 25 mm, then the 13 mm gauge corner
# (gauge side; the field side keeps 80 mm).
RAIL_ARCS = {"gauge": [(0.300, 10 * MM), (0.080, 25 * MM), (0.013, math.inf)],
             "field": [(0.300, 10 * MM), (0.080, math.inf)]}
WEAR_SLOPE = -0.006      # the wear flat's lateral slope (its tangent point is Y = +1.8 mm)
WEAR_DEPTH = 20 * UM     # depth of the flat below the tangent line (half-width sqrt(2 R d) = 3.5 mm)
WEAR_ROUND = 0.4 * MM    # the flat's edges rounded by a Gaussian of this standard deviation
HOLLOW_RADIUS = 3.0      # the wheel's hollow-worn tread (concave laterally), m
HOLLOW_CENTRE = 2.3 * MM
WHEEL_TILT = 1.5e-4      # the wheel's tread line against the wear flat, rad
WAVES = [(6.1 * MM, 1.0 * UM), (3.7 * MM, 0.6 * UM), (2.3 * MM, 0.4 * UM)]  # tread waviness
NOISE_CORR = 0.3 * MM    # instrument noise: correlation length, peak of each profile
NOISE_PEAK = 0.3 * UM
SAMPLE = 0.1 * MM        # the instrument's lateral sampling
MWR_Y0 = 2.0 * MM        # the grid's lateral centre in rail coordinates
MWR_X = (-3.6 * MM, 3.6 * MM)
MWR_Y = (-6.0 * MM, 6.0 * MM)  # grid y (relative to MWR_Y0)
MWR_TABLE_DX = 0.2 * MM
MWR_FORCE = 10e3
# The approach of the approach-controlled cases: measured-wheel-rail-23k-force's approach at
# 10 kN (17.605 um with dyncontact's native solver), rounded to 0.1 um; the small scale too.
MWR_APPROACH = 17.6 * UM


def measured_lateral_gap(y, seed=20240611):
    """The lateral gap g(y) (m) at y (grid coordinates, a 0.1 mm lattice) between the measured
    worn wheel and the measured worn rail; min shifted to 0. Also returns the noise-free gap."""
    rng = np.random.RandomState(seed)
    phases = rng.uniform(0.0, 2.0 * math.pi, len(WAVES))
    # true shapes on a fine 10 um lattice in rail coordinates, wide enough for the smoothing
    Yf = lattice(-20 * MM, 22 * MM, 10 * UM)
    rail_new = circular_arcs(Yf, RAIL_ARCS)
    # wear flat: the line of slope WEAR_SLOPE tangent to the new rail, lowered by WEAR_DEPTH
    k = np.argmax(rail_new - WEAR_SLOPE * Yf)
    flat = rail_new[k] + WEAR_SLOPE * (Yf - Yf[k]) - WEAR_DEPTH
    rail_worn = gaussian_smooth(np.minimum(rail_new, flat), 10 * UM, WEAR_ROUND)
    wheel = (flat + WEAR_DEPTH + WHEEL_TILT * (Yf - Yf[k])
             - (Yf - HOLLOW_CENTRE) ** 2 / (2.0 * HOLLOW_RADIUS))
    for (lam, amp), phi in zip(WAVES, phases):
        wheel += amp * np.cos(2.0 * math.pi * (Yf - Yf[k]) / lam + phi)
    Y = y + MWR_Y0
    rail_true = np.interp(Y, Yf, rail_worn)
    wheel_true = np.interp(Y, Yf, wheel)
    # the two measurements: instrument noise, then the 0.01 um resolution
    rail_meas = quantise(rail_true + band_limited_noise(rng, Y, NOISE_CORR, NOISE_PEAK))
    wheel_meas = quantise(wheel_true + band_limited_noise(rng, Y, NOISE_CORR, NOISE_PEAK))
    g = wheel_meas - rail_meas
    g_true = wheel_true - rail_true
    return g - g.min(), g_true - g_true.min(), Yf[k]


def measured_wheel_rail(scale):
    y = lattice(MWR_Y[0], MWR_Y[1], SAMPLE)
    x = lattice(MWR_X[0], MWR_X[1], MWR_TABLE_DX)
    g, g_true, y_tangent = measured_lateral_gap(y)
    h = x[None, :] ** 2 / (2.0 * R_WHEEL) + g[:, None]
    table = "measured-wheel-rail.csv"
    shape = (
        "A wheel, circular along x (R = 0.46 m), on a worn rail, from lateral (y) profiles as "
        "a profile instrument gives them: h(x, y) = x^2 / (2 R) + g(y), g = wheel - rail. Rail "
        "(rail coordinates Y = y + %s, towards the gauge side): tangent-continuous circular arcs, "
        "crown 300 mm to |Y| = 10 mm, 80 mm to 25 mm, 13 mm gauge corner; worn: min(rail, a flat "
        "of lateral slope %g tangent to it at Y = %s lowered by %s), its edges rounded by a "
        "Gaussian of sigma %s. Wheel: the flat's line raised by %s, tilted by %g rad, hollow-worn "
        "-(Y - %s)^2 / (2 * %g m), waviness sum A cos(2 pi Y / lambda + phi) with (lambda, A) = "
        "%s and seeded phases. Both profiles sampled at 0.1 mm in y with band-limited noise "
        "(Gaussian-filtered white noise, correlation length %s, peak %s each) and quantised to "
        "0.01 um: the gap's noise up to %s (noise-free gap against measured: max |diff| %s). A "
        "nearly conformal band: g <= 3 um over %s, <= 10 um over %s. Table %s: y every 0.1 mm over [%s, %s], x every %s (bilinear interpolation along x would be at most "
        "%s above x^2 / 2R; the table's is exact for it). No closed form. Steel on steel (G = 82 GPa, nu = 0.28 both). "
        "scripts/make_gap_bank.py."
    ) % (fmt_mm(MWR_Y0), WEAR_SLOPE, fmt_mm(y_tangent), fmt_um(WEAR_DEPTH), fmt_mm(WEAR_ROUND),
         fmt_um(WEAR_DEPTH), WHEEL_TILT, fmt_mm(HOLLOW_CENTRE), HOLLOW_RADIUS,
         ", ".join("(%s, %s)" % (fmt_mm(l), fmt_um(a)) for l, a in WAVES),
         fmt_mm(NOISE_CORR), fmt_um(NOISE_PEAK), fmt_um(2 * NOISE_PEAK + QUANTUM),
         fmt_um(np.max(np.abs(g - g_true))), fmt_mm(SAMPLE * np.count_nonzero(g <= 3 * UM)),
         fmt_mm(SAMPLE * np.count_nonzero(g <= 10 * UM)),
         table, fmt_mm(MWR_Y[0]), fmt_mm(MWR_Y[1]), fmt_mm(MWR_TABLE_DX),
         fmt_um(MWR_TABLE_DX ** 2 / (8.0 * R_WHEEL)))
    if scale == "full":
        sizes = [("6k", 60, 100), ("23k", 118, 197), ("93k", 236, 394), ("372k", 472, 788)]
        force_size = ("23k", 118, 197)
    else:
        sizes = [("", 30, 50)]
        force_size = ("", 30, 50)
    cases = {}
    for label, nx, ny in sizes:
        name = "measured-wheel-rail" + ("-" + label if label else "")
        desc = ("Benchmark: " if scale == "full" else "Test (small): ") + shape + (
            " Grid %d x %d = %d elements over x [%s, %s], y [%s, %s]. Load: approach %s (about "
            "10 kN; measured on measured-wheel-rail-23k-force)." % (
                nx, ny, nx * ny, fmt_mm(MWR_X[0]), fmt_mm(MWR_X[1]), fmt_mm(MWR_Y[0]),
                fmt_mm(MWR_Y[1]), fmt_um(MWR_APPROACH)))
        cases[name] = case(name, desc, table, grid_block(nx, ny, MWR_X, MWR_Y), {"approach": MWR_APPROACH})
    label, nx, ny = force_size
    name = "measured-wheel-rail" + ("-" + label if label else "") + "-force"
    desc = ("Benchmark: " if scale == "full" else "Test (small): ") + shape + (
        " Grid %d x %d = %d elements over x [%s, %s], y [%s, %s]. Load: 10 kN." % (
            nx, ny, nx * ny, fmt_mm(MWR_X[0]), fmt_mm(MWR_X[1]), fmt_mm(MWR_Y[0]), fmt_mm(MWR_Y[1])))
    cases[name] = case(name, desc, table, grid_block(nx, ny, MWR_X, MWR_Y), {"force": MWR_FORCE})
    return cases, {table: (x, y, h)}


# ----------------------------------------------------------------------------------------------
# 2. conformal band

CB_HALF = 4.0 * MM       # half-width of the flat band
CB_EDGE = 0.1            # radius of the rise beyond the band, m
CB_NOISE_PEAK = 0.4 * UM
CB_SAMPLE = 0.05 * MM
CB_X = (-3.0 * MM, 3.0 * MM)
CB_Y = (-6.5 * MM, 6.5 * MM)
CB_TABLE_DX = 0.2 * MM
CB_FORCE = 10e3


def conformal_band(scale):
    rng = np.random.RandomState(20240612)
    y = lattice(CB_Y[0], CB_Y[1], CB_SAMPLE)
    x = lattice(CB_X[0], CB_X[1], CB_TABLE_DX)
    out = np.maximum(np.abs(y) - CB_HALF, 0.0)
    g = out ** 2 / (2.0 * CB_EDGE) + quantise(band_limited_noise(rng, y, NOISE_CORR, CB_NOISE_PEAK))
    g -= g.min()
    h = x[None, :] ** 2 / (2.0 * R_WHEEL) + g[:, None]
    nx, ny = (140, 170) if scale == "full" else (28, 34)
    table = "conformal-band.csv"
    desc = ("Benchmark: " if scale == "full" else "Test (small): ") + (
        "A nearly conformal contact: a worn wheel (R = 0.46 m along x) whose lateral gap is flat "
        "over a band, h(x, y) = x^2 / (2 R) + g(y), g(y) = max(|y| - b, 0)^2 / (2 Re) + n(y), "
        "b = %s, Re = %g m (the rise beyond the band), n band-limited noise (Gaussian-filtered "
        "white noise, correlation length %s, peak %s, quantised to 0.01 um): flat to within "
        "+-%s over the 8 mm band. Table %s: y every %s, x every %s. Grid %d x %d = %d elements "
        "over x [%s, %s], y [%s, %s]. Load: 10 kN. No closed form. Steel on steel (G = 82 GPa, "
        "nu = 0.28 both). scripts/make_gap_bank.py."
    ) % (fmt_mm(CB_HALF), CB_EDGE, fmt_mm(NOISE_CORR), fmt_um(CB_NOISE_PEAK), fmt_um(CB_NOISE_PEAK),
         table, fmt_mm(CB_SAMPLE), fmt_mm(CB_TABLE_DX), nx, ny, nx * ny, fmt_mm(CB_X[0]),
         fmt_mm(CB_X[1]), fmt_mm(CB_Y[0]), fmt_mm(CB_Y[1]))
    name = "conformal-band"
    return {name: case(name, desc, table, grid_block(nx, ny, CB_X, CB_Y), {"force": CB_FORCE})}, \
        {table: (x, y, h)}


# ----------------------------------------------------------------------------------------------
# 3. two patches: tread and flange root

TP_TREAD_Y = -3.0 * MM   # tread contact
TP_TREAD_R = 0.30        # relative lateral radius there (rail crown 300 mm, conical tread)
TP_ROOT_Y = 5.0 * MM     # flange-root contact
TP_ROOT_R = 1.0 / (1.0 / 0.013 - 1.0 / 0.016)  # gauge corner 13 mm in a flange root of 16 mm
TP_ROOT_LIFT = 4.0 * UM  # the flange root's well lies this much above the tread's
TP_X = (-4.0 * MM, 4.0 * MM)
TP_Y = (-7.5 * MM, 7.5 * MM)
TP_TABLE_DX = 0.1 * MM
TP_FORCE = 10e3


def two_patches_gap(x, y):
    tread = (y - TP_TREAD_Y) ** 2 / (2.0 * TP_TREAD_R)
    root = (y - TP_ROOT_Y) ** 2 / (2.0 * TP_ROOT_R) + TP_ROOT_LIFT
    return x[None, :] ** 2 / (2.0 * R_WHEEL) + np.minimum(tread, root)[:, None]


def two_patches(scale):
    nx, ny = (128, 150) if scale == "full" else (32, 50)
    x, y = lattice(TP_X[0], TP_X[1], TP_TABLE_DX), centres(TP_Y[0], TP_Y[1], ny)
    h = two_patches_gap(x, y)
    # where the two wells meet (the kink of the min), and its height: far above any contact
    ys = np.linspace(TP_TREAD_Y, TP_ROOT_Y, 200001)
    t = (ys - TP_TREAD_Y) ** 2 / (2.0 * TP_TREAD_R)
    r = (ys - TP_ROOT_Y) ** 2 / (2.0 * TP_ROOT_R) + TP_ROOT_LIFT
    km = np.argmin(np.abs(t - r))
    table = "two-patches.csv"
    desc = ("Benchmark: " if scale == "full" else "Test (small): ") + (
        "Two-point wheel/rail contact, tread and flange root at once: h(x, y) = x^2 / (2 R) + "
        "min((y - y1)^2 / (2 R1), (y - y2)^2 / (2 R2) + d), R = 0.46 m (wheel along x); tread "
        "y1 = %s, R1 = %g m (rail crown 300 mm, conical tread); flange root y2 = %s, R2 = 1 / "
        "(1/13 mm - 1/16 mm) = %.2f mm (gauge corner in the flange root), its well d = %s above "
        "the tread's: two separate patches %s apart, both loaded (the wells meet at y = %s, "
        "h = %s: far above the contact). Table: y at the element centres, x every %s (bilinear interpolation "
        "along x would be at most %s above x^2 / 2R; the table's is exact for it). Grid %d x %d = %d "
        "elements over x [%s, %s], y [%s, %s]. Load: 10 kN. No closed form (each patch alone is "
        "Hertzian; they interact through the half-space and share the approach). Steel on "
        "steel (G = 82 GPa, nu = 0.28 both). scripts/make_gap_bank.py."
    ) % (fmt_mm(TP_TREAD_Y), TP_TREAD_R, fmt_mm(TP_ROOT_Y), TP_ROOT_R / MM, fmt_um(TP_ROOT_LIFT),
         fmt_mm(TP_ROOT_Y - TP_TREAD_Y), fmt_mm(ys[km]), fmt_um(t[km]), fmt_mm(TP_TABLE_DX),
         fmt_um(TP_TABLE_DX ** 2 / (8.0 * R_WHEEL)), nx, ny, nx * ny,
         fmt_mm(TP_X[0]), fmt_mm(TP_X[1]), fmt_mm(TP_Y[0]), fmt_mm(TP_Y[1]))
    name = "two-patches"
    return {name: case(name, desc, table, grid_block(nx, ny, TP_X, TP_Y), {"force": TP_FORCE})}, \
        {table: (x, y, h)}


# ----------------------------------------------------------------------------------------------
# 4. rough sphere

RS_HURST = 0.8
RS_SLOPE = 0.1           # rms slope sqrt(<|grad h|^2>) of the roughness
RS_ELEMENT = 1.0 * UM    # element size
RS_ROLLOFF = 4           # lambda_r = L / 4 (PSD flat from L to lambda_r, like the challenge's)
RS_SHORT = 4             # lambda_s = 4 elements
RS_RADIUS = 0.005        # the sphere on 512^2, m (on n^2: scaled by n / 512)
RS_HERTZ_FRACTION = 0.25 # Hertz radius / grid length


def rough_surface(n, seed):
    """Random-phase Fourier synthesis on n x n elements (periodic): |h_q| = sqrt(C(q)), C flat
    for q_L <= q < q_r, C ~ q^(-2(1+H)) for q_r <= q <= q_s, 0 else (q_L = 2 pi / L, the mean
    removed); scaled to the rms slope RS_SLOPE (spectral gradient)."""
    L = n * RS_ELEMENT
    k = np.fft.fftfreq(n, d=1.0 / n)
    KX, KY = np.meshgrid(k, k)
    q = 2.0 * math.pi * np.hypot(KX, KY) / L
    q_r = 2.0 * math.pi * RS_ROLLOFF / L
    q_s = 2.0 * math.pi / (RS_SHORT * RS_ELEMENT)
    C = np.where(q < q_r, 1.0, (np.maximum(q, q_r) / q_r) ** (-2.0 * (1.0 + RS_HURST)))
    C[(q == 0.0) | (q > q_s * (1.0 + 1e-12))] = 0.0
    rng = np.random.RandomState(seed)
    phase = np.fft.fft2(rng.standard_normal((n, n)))
    phase /= np.abs(phase)               # unit modulus, Hermitian: a real surface
    Hq = np.sqrt(C) * phase
    h = np.real(np.fft.ifft2(Hq))
    qx = 2.0 * math.pi * KX / L
    qy = 2.0 * math.pi * KY / L
    hx = np.real(np.fft.ifft2(1j * qx * Hq))
    hy = np.real(np.fft.ifft2(1j * qy * Hq))
    s = math.sqrt(np.mean(hx ** 2 + hy ** 2))
    h *= RS_SLOPE / s
    # finite-difference slope (the grid's own view of it) for the description
    fd = math.sqrt(np.mean(((np.roll(h, -1, 1) - h) / RS_ELEMENT) ** 2 + ((np.roll(h, -1, 0) - h) / RS_ELEMENT) ** 2))
    return h, fd


def rough_sphere(scale):
    n = 512 if scale == "full" else 128
    L = n * RS_ELEMENT
    rough, fd_slope = rough_surface(n, 20240613 if scale == "full" else 20240614)
    c = centres(-L / 2, L / 2, n)
    a_hertz = RS_HERTZ_FRACTION * L
    radius = RS_RADIUS * n / 512.0
    force = 4.0 * E_STAR * a_hertz ** 3 / (3.0 * radius)
    h = (c[None, :] ** 2 + c[:, None] ** 2) / (2.0 * radius) + rough
    decades = math.log10(n / RS_SHORT)
    affine = math.log10(n / RS_ROLLOFF / RS_SHORT)
    name = "rough-sphere-512" if scale == "full" else "rough-sphere"
    table = name + ".csv"
    p0 = 3.0 * force / (2.0 * math.pi * a_hertz ** 2)
    desc = ("Benchmark: " if scale == "full" else "Test (small): ") + (
        "A rough sphere: h = (x^2 + y^2) / (2 R) + z(x, y), R = %g m, z a self-affine random "
        "surface (the kind of Muser et al., Tribol. Lett. 65:118, 2017) by random-phase Fourier "
        "synthesis on the %d x %d element centres (element %s, L = %s, periodic in z only): "
        "|z_q| = sqrt(C(q)), C(q) flat for 2 pi / L <= q < q_r (roll-off lambda_r = L / %d = %s), "
        "C ~ q^(-2 (1 + H)) with H = %g from q_r to q_s (lambda_s = %d elements = %s), zero beyond "
        "and at q = 0, phases seeded; scaled to rms slope %g (spectral gradient; forward "
        "differences give %.3f), rms height %s, peak-to-valley %s. Wavelengths from L to "
        "lambda_s: %.2f decades (self-affine %.2f). Three decades cannot be held on %d^2: "
        "L / lambda_s = 1000 needs lambda_s = %.2f elements, below the 2-element Nyquist limit, "
        "and a short cut-off is only resolved (contact area converged) with several elements per "
        "wavelength; with the sphere the contact covers only part of L, so wavelengths beyond its "
        "diameter merely tilt and bend the sphere. Load: %.6g N, the Hertz force of a smooth "
        "sphere with a = %s = %g L (p0 = %.3g GPa, approach a^2 / R = %s; Greenwood-Tripp "
        "alpha = sigma R / a^2 = %.2f): the nominal area well inside the grid, many asperity "
        "patches. Steel on steel (G = 82 GPa, nu = 0.28 both). Table at the element "
        "centres (%s, not committed: scripts/make_gap_bank.py --only %s writes it)."
    ) % (radius, n, n, fmt_um(RS_ELEMENT), fmt_mm(L), RS_ROLLOFF, fmt_um(L / RS_ROLLOFF),
         RS_HURST, RS_SHORT, fmt_um(RS_SHORT * RS_ELEMENT), RS_SLOPE, fd_slope,
         fmt_um(np.std(rough)), fmt_um(np.ptp(rough)), decades, affine, n, n / 1000.0, force,
         fmt_um(a_hertz), RS_HERTZ_FRACTION, p0 / 1e9, fmt_um(a_hertz ** 2 / radius),
         np.std(rough) * radius / a_hertz ** 2, table, name)
    grid = grid_block(n, n, (-L / 2, L / 2), (-L / 2, L / 2))
    return {name: case(name, desc, table, grid, {"force": float("%.6g" % force)})}, {table: (c, c, h)}


# ----------------------------------------------------------------------------------------------
# 5. flat punch with sharp edges

FP_ELEMENT = MM / 32
FP_FACE = (64, 32)       # face, elements along x and y
FP_MARGIN = 4            # elements between the face and the grid edge
FP_RISE = 1.0 * MM       # per element outside the face
FP_PRESSURE = 500e6      # mean pressure on the face


def flat_punch_sharp(scale):
    fx, fy = FP_FACE if scale == "full" else (24, 12)
    m = FP_MARGIN if scale == "full" else 3
    e = FP_ELEMENT if scale == "full" else MM / 12
    ax, ay = 0.5 * fx * e, 0.5 * fy * e
    nx, ny = fx + 2 * m, fy + 2 * m
    X, Y = (-(ax + m * e), ax + m * e), (-(ay + m * e), ay + m * e)
    x, y = centres(X[0], X[1], nx), centres(Y[0], Y[1], ny)
    out = np.maximum(np.maximum(np.abs(x)[None, :] - ax, np.abs(y)[:, None] - ay), 0.0)
    h = out * (FP_RISE / e)
    force = FP_PRESSURE * 4.0 * ax * ay
    name = "flat-punch-sharp"
    table = name + ".csv"
    desc = ("Benchmark: " if scale == "full" else "Test (small): ") + (
        "A rectangular flat punch with sharp edges and corners: h = 0 on the face |x| <= %s, "
        "|y| <= %s (%d x %d elements of %s), outside h = k max(|x| - a, |y| - b) with k = 1 mm "
        "per element (%g): the face's %d elements and nothing else can touch. Tabulated at the "
        "element centres. Grid %d x %d, %d elements beyond the face on each side. Load: %g N "
        "(mean pressure %g MPa). No closed form for a rectangle; the contact is the face "
        "(n_contact = %d), the pressure singular along the edges and stronger at the corners "
        "(the circular punch is profile flat_punch). Steel on steel (G = 82 GPa, nu = 0.28 "
        "both). scripts/make_gap_bank.py."
    ) % (fmt_mm(ax), fmt_mm(ay), fx, fy, fmt_um(e), FP_RISE / e, fx * fy, nx, ny, m, force,
         FP_PRESSURE / 1e6, fx * fy)
    return {name: case(name, desc, table, grid_block(nx, ny, X, Y), {"force": force})}, {table: (x, y, h)}


# ----------------------------------------------------------------------------------------------
# 6. cone

CONE_BETA = math.radians(2.0)
CONE_FORCE = 6250.0     # a = 1.0002 mm
CONE_ELEMENT = 0.02 * MM


def cone_closed_form(force, beta=CONE_BETA):
    """Sneddon (1965), Johnson (1985) section 5.2(b): a cone h = r tan(beta) pressed by F has
    F = (pi / 2) a^2 E* tan(beta), approach delta = (pi / 2) a tan(beta), mean pressure
    E* tan(beta) / 2, p(r) = (E* tan(beta) / 2) arccosh(a / r)."""
    a = math.sqrt(2.0 * force / (math.pi * E_STAR * math.tan(beta)))
    return a, 0.5 * math.pi * a * math.tan(beta)


def cone(scale):
    a, delta = cone_closed_form(CONE_FORCE)
    # n odd, elements of CONE_ELEMENT (full) on +-1.31 mm = +-1.31 a: the apex at the centre
    # element's centre, the element centres on round multiples of the element
    n, e = (131, CONE_ELEMENT) if scale == "full" else (33, 0.08 * MM)
    half = 0.5 * n * e
    x = centres(-half, half, n)
    h = np.hypot(x[None, :], x[:, None]) * math.tan(CONE_BETA)
    name = "cone"
    table = name + ".csv"
    desc = ("Benchmark: " if scale == "full" else "Test (small): ") + (
        "A cone h = r tan(beta), beta = 2 deg (its apex sharp), tabulated at the element centres "
        "(n odd: the apex is the centre element's centre). Closed form (Sneddon 1965; Johnson, "
        "Contact Mechanics, 1985, section 5.2(b), with beta = pi/2 - alpha for his cone "
        "semi-angle alpha): F = (pi/2) a^2 E* tan(beta), delta = (pi/2) a tan(beta), i.e. "
        "F = (2/pi) E* delta^2 cot(beta), p(r) = (E* tan(beta) / 2) arccosh(a / r) (mean pressure "
        "E* tan(beta) / 2 = %.4g GPa, log-singular at the apex). Load: %g N, so a = %.6g mm, "
        "delta = %.6g um, contact area pi a^2 = %.6g mm^2 (E* = G / (1 - nu) = %.6g GPa). Grid "
        "%d x %d over +-%s = +-%.3f a. Steel on steel (G = 82 GPa, nu = 0.28 both). "
        "scripts/make_gap_bank.py."
    ) % (0.5 * E_STAR * math.tan(CONE_BETA) / 1e9, CONE_FORCE, a / MM, delta / UM,
         math.pi * a * a / MM ** 2, E_STAR / 1e9, n, n, fmt_mm(half), half / a)
    grid = grid_block(n, n, (-half, half), (-half, half))
    return {name: case(name, desc, table, grid, {"force": CONE_FORCE})}, {table: (x, x, h)}


# ----------------------------------------------------------------------------------------------

BUILDERS = [measured_wheel_rail, conformal_band, two_patches, rough_sphere, flat_punch_sharp, cone]


def build(scale):
    cases, tables = {}, {}
    for b in BUILDERS:
        c, t = b(scale)
        cases.update(c)
        tables.update(t)
    return cases, tables


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--out", help="output folder (default examples/bench; small: build/gap_bank)")
    ap.add_argument("--only", help="comma-separated case names")
    ap.add_argument("--scale", choices=["full", "small"], default="full")
    ap.add_argument("--list", action="store_true", help="print the case names and exit")
    args = ap.parse_args(argv)
    cases, tables = build(args.scale)
    if args.list:
        print("\n".join(cases))
        return 0
    names = list(cases)
    if args.only:
        names = [s.strip() for s in args.only.split(",") if s.strip()]
        unknown = [s for s in names if s not in cases]
        if unknown:
            ap.error("unknown case(s) %s; the %s scale has: %s" % (", ".join(unknown), args.scale, ", ".join(cases)))
    out = args.out or os.path.join(root, "examples/bench" if args.scale == "full" else "build/gap_bank")
    os.makedirs(out, exist_ok=True)
    written = set()
    for name in names:
        doc = cases[name]
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(doc, f, indent=2)
            f.write("\n")
        table = doc["profile"]["file"]
        if table not in written:
            x, y, h = tables[table]
            write_table(os.path.join(out, table), x, y, h)
            written.add(table)
        print("wrote %s" % os.path.join(out, name + ".json"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
