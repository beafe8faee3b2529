#!/usr/bin/env python3
"""The BRDF averaged over cells of directions, straight from a photon map (red component).

    photon_bins.py MAP.pm [--phi-in DEG] THETA_IN ...

For each light zenith THETA_IN (a band of ±2.5°; with --phi-in also ±15° of that light
azimuth, for anisotropic maps) and each ring of viewer zeniths (55-65°, 65-75°, 75-85°), the
BRDF averaged over three Δφ sectors: back towards the light (|Δφ| < 15°), the side
(75° < |Δφ| < 105°) and forward (|Δφ| > 165°), with its standard error, and the ratios
back/side and forward/side; then, per light, the growth towards the horizon: each sector's f̄
at 75-85° over that at 55-65°.

Why cells: the splat estimate divides each photon by its own cos θ_out (DESIGN.md), so near the
horizon a few photons carry huge weights, and a 0.4-rad splat carries the horizon's BRDF into a
cut at θ_out = 80° (docs/gallery.md). A cell average divides by the cell's ∫cos θ dω instead:
bounded weights, no smoothing across cells. With F(A→B) = (1/N) Σ β cos θ′ / p_in over the
photons with ω′ in A and ω in B (N traced paths, p_in the map's incidence density),
    f̄(A, B) = F(A→B) / (∫_A cos θ′ dω′ · ∫_B cos θ dω),
the estimator of tests/photon/models_test.cpp; its standard error is that of the mean of the N
per-path terms.
"""

import math
import sys

RINGS = [(55.0, 65.0), (65.0, 75.0), (75.0, 85.0)]
SECTORS = [("back", 0.0, 15.0), ("side", 75.0, 105.0), ("forward", 165.0, 180.0)]


def cos_solid_angle(theta0, theta1, width):
    """∫ cos θ dω over θ0..θ1 (degrees) and an azimuth range of `width` radians."""
    s0, s1 = math.sin(math.radians(theta0)), math.sin(math.radians(theta1))
    return (s1 * s1 - s0 * s0) / 2 * width


def sector_of(dphi):
    d = abs((math.degrees(dphi) + 180.0) % 360.0 - 180.0)
    for k, (_, lo, hi) in enumerate(SECTORS):
        if lo <= d < hi or (hi == 180.0 and d == 180.0):
            return k
    return -1


def ring_of(theta_out):
    t = math.degrees(theta_out)
    for k, (lo, hi) in enumerate(RINGS):
        if lo <= t < hi:
            return k
    return -1


def accumulate(path, lights, phi_in):
    """Per light, ring and sector: the sums of the per-path terms and of their squares."""
    sums = {}
    with open(path) as photons:
        header = photons.readline().split()
        paths = int(header[1]) if len(header) > 1 else int(header[0])
        for line in photons:
            v = line.split()
            t_in, p_in, t_out, p_out = (float(x) for x in v[:4])
            deg_in = math.degrees(t_in)
            if phi_in is not None and abs(
                    (math.degrees(p_in) - phi_in + 180.0) % 360.0 - 180.0) > 15.0:
                continue
            for light in lights:
                if abs(deg_in - light) > 2.5:
                    continue
                ring, sector = ring_of(t_out), sector_of(p_out - p_in)
                if ring < 0 or sector < 0:
                    continue
                w = float(v[5]) * math.cos(t_in) / float(v[4])
                s = sums.setdefault((light, ring, sector), [0.0, 0.0])
                s[0] += w
                s[1] += w * w
    return sums, paths


def cell_means(sums, paths, light, ring, in_norm):
    """f̄ and its standard error in the three sectors of one light and ring."""
    lo, hi = RINGS[ring]
    f, err = [], []
    for sector, (_, a, b) in enumerate(SECTORS):
        total, squares = sums.get((light, ring, sector), [0.0, 0.0])
        mean = total / paths
        sigma = math.sqrt(max(squares / paths - mean * mean, 0.0) / paths)
        norm = in_norm * cos_solid_angle(lo, hi, 2 * math.radians(b - a))
        f.append(mean / norm)
        err.append(sigma / norm)
    return f, err


def ratio(a, ea, b, eb):
    """a / b with its standard error (independent errors), as text."""
    if a <= 0 or b <= 0:
        return "-"
    return "%5.2f±%.2f" % (a / b, a / b * math.hypot(ea / a, eb / b))


def report(sums, paths, lights, phi_in):
    in_width = 2 * math.pi if phi_in is None else math.radians(30.0)
    print("%-8s %-8s %17s %17s %17s %10s %10s" % ("θi", "θo", "back", "side", "forward",
                                                  "back/side", "fwd/side"))
    for light in lights:
        in_norm = cos_solid_angle(light - 2.5, light + 2.5, in_width)
        cells = [cell_means(sums, paths, light, ring, in_norm) for ring in range(len(RINGS))]
        for (lo, hi), (f, err) in zip(RINGS, cells):
            print("%-8g %-8s %s %10s %10s" % (light, "%g-%g" % (lo, hi), " ".join(
                "%8.4f±%.4f" % (v, e) for v, e in zip(f, err)), ratio(f[0], err[0], f[1], err[1]),
                ratio(f[2], err[2], f[1], err[1])))
        (low, elow), (high, ehigh) = cells[0], cells[-1]
        print("%-8g %-8s %s  (the highest ring over the lowest)" % (light, "growth", " ".join(
            "%17s" % ratio(high[k], ehigh[k], low[k], elow[k]) for k in range(3))))


def main():
    args = sys.argv[1:]
    phi_in = None
    if len(args) > 2 and args[1] == "--phi-in":
        phi_in = float(args[2])
        del args[1:3]
    if len(args) < 2:
        sys.exit(__doc__)
    lights = [float(a) for a in args[1:]]
    sums, paths = accumulate(args[0], lights, phi_in)
    report(sums, paths, lights, phi_in)


if __name__ == "__main__":
    main()
