#!/usr/bin/env python3
"""Which basis radiance caching's records use: spherical harmonics (SH) or the hemispherical
harmonics (HSH) of Gautron et al. 2004 (docs/spherical-harmonics.md, "Basis";
the tables in docs/lab/radiance-caching.md).

An independent numpy implementation (not radcache's kernels) of both bases, measuring on the
same lobes, by Gauss-Legendre x midpoint quadrature over the hemisphere:

  1. projection error: relative L2 error over the hemisphere of the order-n projection of
     clamped-cosine and cosine-weighted Phong lobes (exponents 5, 8, 20, 60, outgoing directions
     at 0, 45 and 75 degrees), for SH also the error over the sphere (the energy measure of
     Ramamoorthi and Hanrahan that radcache's BRDF tables use);
  2. the error that reaches the image: |<lambda, c> - integral of L F| / integral of L F for two
     incoming radiances L (smooth, and a bright patch) and the same lobes;
  3. rotation: the same after aligning a record tilted by 5, 15 or 30 degrees with the query
     frame, SH by its exact rotation, HSH by the course's first method (HSH paper §4: convert to
     SH with the matrix C of eq. 18, rotate, convert back) with an intermediate SH order of n
     and of 2n.

Prints markdown tables. Needs numpy only; runs in about a minute.

usage: tools/sh_basis_study.py [--order N]
"""
import argparse

import numpy as np
from numpy.polynomial.legendre import leggauss

PI = np.pi


def sh_eval(x, y, z, order):
    """Real SH Y_l^m, index l(l+1)+m, without the Condon-Shortley phase (HSH paper eq. 3-4),
    by the normalized associated-Legendre recurrence."""
    out = np.zeros((order * order,) + np.shape(z))
    cos_m, sin_m = [np.ones_like(z)], [np.zeros_like(z)]
    for m in range(1, order):
        cos_m.append(x * cos_m[m - 1] - y * sin_m[m - 1])
        sin_m.append(x * sin_m[m - 1] + y * cos_m[m - 1])
    q_mm = np.sqrt(1 / (4 * PI)) * np.ones_like(z)
    for m in range(order):
        if m > 0:
            q_mm = q_mm * np.sqrt((2 * m + 1) / (2 * m))

        def put(l, q):
            if m == 0:
                out[l * (l + 1)] = q
            else:
                out[l * (l + 1) + m] = np.sqrt(2) * q * cos_m[m]
                out[l * (l + 1) - m] = np.sqrt(2) * q * sin_m[m]

        put(m, q_mm)
        if m + 1 < order:
            q_prev, q = q_mm, np.sqrt(2 * m + 3) * z * q_mm
            put(m + 1, q)
            for l in range(m + 2, order):
                a = np.sqrt((4 * l * l - 1) / (l * l - m * m))
                b = np.sqrt(((l - 1) ** 2 - m * m) / (4 * (l - 1) ** 2 - 1))
                q_prev, q = q, a * (z * q - b * q_prev)
                put(l, q)
    return out


def hsh_eval(x, y, z, order):
    """H_l^m = sqrt(2) Y_l^m at the direction with polar cosine 2z - 1 (HSH paper eq. 5-9)."""
    k = 2 * np.sqrt(z / (1 + z))
    return np.sqrt(2) * sh_eval(x * k, y * k, 2 * z - 1, order)


def rotation_bands(r, order):
    """Ivanic-Ruedenberg recurrence: band matrices D_l with sum (D c)_i Y_i(R d) = sum c_i Y_i(d)."""
    axis = {-1: 1, 0: 2, 1: 0}
    r1 = np.array([[r[axis[i], axis[j]] for j in (-1, 0, 1)] for i in (-1, 0, 1)])
    bands = [np.ones((1, 1)), r1]
    for l in range(2, order):
        prev = bands[-1]
        band = np.zeros((2 * l + 1, 2 * l + 1))

        def p(i, a, b):
            def at(u, v):
                return prev[u + l - 1, v + l - 1]

            if b == l:
                return r1[i + 1, 2] * at(a, l - 1) - r1[i + 1, 0] * at(a, -l + 1)
            if b == -l:
                return r1[i + 1, 2] * at(a, -l + 1) + r1[i + 1, 0] * at(a, l - 1)
            return r1[i + 1, 1] * at(a, b)

        for m in range(-l, l + 1):
            for n in range(-l, l + 1):
                d = 1 if m == 0 else 0
                den = (l + n) * (l - n) if abs(n) < l else 2 * l * (2 * l - 1)
                u = np.sqrt((l + m) * (l - m) / den)
                v = 0.5 * np.sqrt((1 + d) * (l + abs(m) - 1) * (l + abs(m)) / den) * (1 - 2 * d)
                w = -0.5 * np.sqrt((l - abs(m) - 1) * (l - abs(m)) / den) * (1 - d)
                value = u * p(0, m, n) if u else 0.0
                if v:
                    if m == 0:
                        big_v = p(1, 1, n) + p(-1, -1, n)
                    elif m > 0:
                        big_v = p(1, m - 1, n) * np.sqrt(1 + (m == 1)) - p(-1, -m + 1, n) * (m != 1)
                    else:
                        big_v = p(1, m + 1, n) * (m != -1) + p(-1, -m - 1, n) * np.sqrt(1 + (m == -1))
                    value += v * big_v
                if w:
                    big_w = (p(1, m + 1, n) + p(-1, -m - 1, n)) if m > 0 else (p(1, m - 1, n) - p(-1, -m + 1, n))
                    value += w * big_w
                band[m + l, n + l] = value
        bands.append(band)
    return bands


def rotate(bands, c):
    out = np.zeros_like(c)
    for l in range(int(round(np.sqrt(len(c))))):
        out[l * l:(l + 1) ** 2] = bands[l] @ c[l * l:(l + 1) ** 2]
    return out


class Hemisphere:
    """Gauss-Legendre in z over [0, 1] times the midpoint rule in phi."""

    def __init__(self, theta_nodes, phi_nodes):
        z, w = leggauss(theta_nodes)
        z, w = 0.5 * (z + 1), 0.5 * w
        phi = (np.arange(phi_nodes) + 0.5) * 2 * PI / phi_nodes
        self.z, p = np.meshgrid(z, phi, indexing="ij")
        self.w = np.outer(w, np.full(phi_nodes, 2 * PI / phi_nodes))
        s = np.sqrt(1 - self.z ** 2)
        self.x, self.y = s * np.cos(p), s * np.sin(p)

    def project(self, f, basis):
        return np.einsum("iab,ab->i", basis, f * self.w)

    def norm2(self, f):
        return np.sum(f * f * self.w)


def phong_lobe(h, theta_o_degrees, exponent):
    """The cosine-weighted modified-Phong lobe (n + 2) / 2pi cos^n(alpha) cos(theta_i)."""
    t = np.radians(theta_o_degrees)
    mirror = np.array([-np.sin(t), 0.0, np.cos(t)])
    c = np.maximum(mirror[0] * h.x + mirror[1] * h.y + mirror[2] * h.z, 0.0)
    return (exponent + 2) / (2 * PI) * c ** exponent * h.z


def lobes(h):
    yield "clamped cosine", h.z
    for exponent in (5, 8, 20, 60):
        for theta in (0, 45, 75):
            yield f"Phong {exponent}, {theta} deg", phong_lobe(h, theta, exponent)


def radiances(x, y, z):
    a = np.array([np.sin(0.6), 0.3, np.cos(0.6)])
    a /= np.linalg.norm(a)
    for name, width in (("smooth", 0.5), ("patch", 0.1)):
        value = 1 + 3 * np.exp(-((x - a[0]) ** 2 + (y - a[1]) ** 2 + (z - a[2]) ** 2) / width)
        yield name, np.where(z > 0, value, 0.0)


def projection_table(h, ys, yh, orders):
    print("| lobe | basis | " + " | ".join(f"n = {n}" for n in orders) + " |")
    print("|---|---|" + "---|" * len(orders))
    for name, f in lobes(h):
        norm2 = h.norm2(f)
        cs, ch = h.project(f, ys), h.project(f, yh)
        rows = {"SH (hemisphere)": [], "SH (sphere)": [], "HSH": []}
        for n in orders:
            k = n * n
            rows["SH (hemisphere)"].append(np.sqrt(h.norm2(f - np.einsum("i,iab->ab", cs[:k], ys[:k])) / norm2))
            rows["SH (sphere)"].append(np.sqrt(max(0.0, 1 - np.sum(cs[:k] ** 2) / norm2)))
            rows["HSH"].append(np.sqrt(h.norm2(f - np.einsum("i,iab->ab", ch[:k], yh[:k])) / norm2))
        for basis, values in rows.items():
            print(f"| {name} | {basis} | " + " | ".join(f"{v:.3f}" for v in values) + " |")


def dot_table(h, ys, yh, orders):
    print("| radiance | lobe | basis | " + " | ".join(f"n = {n}" for n in orders) + " |")
    print("|---|---|---|" + "---|" * len(orders))
    for lname, light in radiances(h.x, h.y, h.z):
        ls, lh = h.project(light, ys), h.project(light, yh)
        for name, f in lobes(h):
            if name == "clamped cosine":
                continue
            exact = np.sum(light * f * h.w)
            fs, fh = h.project(f, ys), h.project(f, yh)
            es = [abs(ls[:n * n] @ fs[:n * n] - exact) / exact for n in orders]
            eh = [abs(lh[:n * n] @ fh[:n * n] - exact) / exact for n in orders]
            print(f"| {lname} | {name} | SH | " + " | ".join(f"{v:.4f}" for v in es) + " |")
            print(f"| {lname} | {name} | HSH | " + " | ".join(f"{v:.4f}" for v in eh) + " |")


def rotation_table(h, ys, yh, order):
    ys2 = sh_eval(h.x, h.y, h.z, 2 * order)
    conversion = np.einsum("iab,jab,ab->ij", yh, ys2, h.w)  # eq. 18, HSH(n) x SH(2n)
    k = order * order
    print(f"| tilt | radiance | lobe | SH exact rotation | HSH via SH order {order} | HSH via SH order {2 * order} |")
    print("|---|---|---|---|---|---|")
    for tilt in (5, 15, 30):
        b = np.radians(tilt)
        r = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
        bands, bands2 = rotation_bands(r, order), rotation_bands(r, 2 * order)
        # The record's directions of the query's quadrature nodes: d_record = R^T d_query.
        xr = r[0, 0] * h.x + r[1, 0] * h.y + r[2, 0] * h.z
        yr = r[0, 1] * h.x + r[1, 1] * h.y + r[2, 1] * h.z
        zr = r[0, 2] * h.x + r[1, 2] * h.y + r[2, 2] * h.z
        for (lname, record_light), (_, query_light) in zip(radiances(h.x, h.y, h.z), radiances(xr, yr, zr)):
            for name, theta, exponent in (("Phong 8, 45 deg", 45, 8), ("Phong 20, 45 deg", 45, 20),
                                          ("Phong 20, 75 deg", 75, 20)):
                f = phong_lobe(h, theta, exponent)
                exact = np.sum(query_light * f * h.w)
                sh = rotate(bands, h.project(record_light, ys)) @ h.project(f, ys)
                hsh_coefficients = h.project(record_light, yh)
                low = conversion[:, :k] @ rotate(bands, conversion[:, :k].T @ hsh_coefficients)
                high = conversion @ rotate(bands2, conversion.T @ hsh_coefficients)
                fh = h.project(f, yh)
                errors = [abs(v - exact) / exact for v in (sh, low @ fh, high @ fh)]
                print(f"| {tilt} deg | {lname} | {name} | " + " | ".join(f"{e:.4f}" for e in errors) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--order", type=int, default=10, help="n_max (default 10)")
    args = parser.parse_args()
    h = Hemisphere(96, 192)
    ys, yh = sh_eval(h.x, h.y, h.z, args.order), hsh_eval(h.x, h.y, h.z, args.order)
    orders = [n for n in (2, 4, 6, 8, 10) if n <= args.order]
    print("Relative L2 projection error\n")
    projection_table(h, ys, yh, orders)
    print("\nRelative error of the reflected radiance <lambda, c>\n")
    dot_table(h, ys, yh, orders)
    print(f"\nRelative error of the reflected radiance after rotation, order {args.order}\n")
    rotation_table(h, ys, yh, args.order)


if __name__ == "__main__":
    main()
