#!/usr/bin/env python3
"""Closed forms of the three rock-slope mechanisms, independent of cdem
(references/joints.md). Standard library only; run from the crate root:

    python3 scripts/rock_slope_closed_forms.py            # prints the table
    python3 scripts/rock_slope_closed_forms.py --json     # the same numbers as JSON

1. Plane failure with a dry tension crack in the upper slope surface
   (Hoek & Bray, Rock Slope Engineering, ch. 7; Wyllie & Mah 2004, eq. 6.3-6.6):
       z = H - (H cot(psi_f) + b) tan(psi_p)          crack depth
       A = (H - z) / sin(psi_p)                        plane length (per m)
       W = 1/2 gamma H^2 [(1 - (z/H)^2) cot(psi_p) - cot(psi_f)]
       FS = (c A + W cos(psi_p) tan(phi)) / (W sin(psi_p))
   The weight is also computed from the block's polygon (shoelace) as a check.
2. Wedge failure: the wedge factor (Hoek & Bray ch. 8), friction only,
       FS = K tan(phi) / tan(psi_i),  K = sin(beta) / sin(xi / 2),
   beta and xi measured in the section normal to the line of intersection;
   and the vector solution (the wedge's vertices from its four planes, the
   normal reactions from equilibrium normal to the line of intersection,
       N_1 + N_2 (n_1.n_2) = W n_1z,   N_1 (n_1.n_2) + N_2 = W n_2z,
       FS = (c_1 A_1 + c_2 A_2 + N_1 tan(phi_1) + N_2 tan(phi_2)) / (-W i_z)),
   which for equal friction and no cohesion must equal the wedge factor's.
3. Block toppling on a stepped base (Goodman & Bray 1976; Hoek & Bray ch. 9;
   Wyllie & Mah 2004 section 9.4): the recursion from the top block down,
       P_{n-1,t} = [P_n (M_n - dx tan(phi)) + W_n/2 (y_n sin(psi) - dx cos(psi))] / L_n
       P_{n-1,s} = P_n - W_n (tan(phi) cos(psi) - sin(psi)) / (1 - tan(phi)^2)
   and the friction angle at which the support force at the toe P_0 is zero.
"""

import argparse
import json
import math

D = math.radians


# ---------------------------------------------------------------- 1. plane

def plane_failure(H, psi_f, psi_p, c, phi, gamma, b, gamma_w=0.0, z_w=0.0, uplift=True):
    """Hoek & Bray's plane failure, tension crack a distance b behind the crest,
    filled with water to z_w: V = gamma_w z_w^2 / 2 in the crack and, if uplift,
    U = gamma_w z_w A / 2 on the plane (falling linearly to the toe)."""
    tf, tp = math.tan(D(psi_f)), math.tan(D(psi_p))
    x_crest = H / tf
    x_crack = x_crest + b
    z_plane = x_crack * tp  # the plane through the toe at the crack
    z = H - z_plane  # crack depth
    A = (H - z) / math.sin(D(psi_p))
    W = 0.5 * gamma * H**2 * ((1 - (z / H) ** 2) / tp - 1 / tf)
    poly = [(0.0, 0.0), (x_crest, H), (x_crack, H), (x_crack, z_plane)]
    area = 0.5 * abs(sum(x0 * z1 - x1 * z0 for (x0, z0), (x1, z1) in zip(poly, poly[1:] + poly[:1])))
    assert abs(gamma * area - W) < 1e-9 * W, (gamma * area, W)
    U = 0.5 * gamma_w * z_w * A if uplift else 0.0
    V = 0.5 * gamma_w * z_w**2
    fs = (c * A + (W * math.cos(D(psi_p)) - U - V * math.sin(D(psi_p))) * math.tan(D(phi))) / (
        W * math.sin(D(psi_p)) + V * math.cos(D(psi_p))
    )
    return {"z": z, "A": A, "W": W, "U": U, "V": V, "x_crest": x_crest, "x_crack": x_crack, "FS": fs}


def barton_bandis_tau(sigma_n, jrc, jcs, phi_r, cap=70.0):
    """Barton & Choubey (1977): tau = sigma_n tan(phi_r + JRC log10(JCS / sigma_n)),
    the total angle capped (70 deg, as RS2 and Slide) and the roughness term at
    least zero (sigma_n >= JCS); no strength at sigma_n <= 0."""
    if sigma_n <= 0.0:
        return 0.0
    return sigma_n * math.tan(D(min(phi_r + max(jrc * math.log10(jcs / sigma_n), 0.0), cap)))


def plane_failure_bb(p, jrc, jcs, phi_r):
    """A plane-failure case of plane_failure() with the plane a Barton-Bandis joint,
    its normal stress uniform: FS = tau(sigma_n') A / (W sin psi_p + V cos psi_p)."""
    psi_p = D(30.0)
    s = (p["W"] * math.cos(psi_p) - p["U"] - p["V"] * math.sin(psi_p)) / p["A"]
    return barton_bandis_tau(s, jrc, jcs, phi_r) * p["A"] / (p["W"] * math.sin(psi_p) + p["V"] * math.cos(psi_p))


def infinite_slope(beta, z, gamma, c, phi, gamma_w, m):
    """The infinite slope, water table parallel to the surface m z above the slip plane."""
    u = gamma_w * m * z * math.cos(D(beta)) ** 2
    return (c + (gamma * z * math.cos(D(beta)) ** 2 - u) * math.tan(D(phi))) / (
        gamma * z * math.sin(D(beta)) * math.cos(D(beta))
    )


# ---------------------------------------------------------------- 2. wedge

def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return [x / n for x in a]


def normal(dip, dip_direction):
    """Upward unit normal of a plane (x east, y north, z up)."""
    d, a = D(dip), D(dip_direction)
    return [math.sin(d) * math.sin(a), math.sin(d) * math.cos(a), math.cos(d)]


def solve3(rows, rhs):
    """Cramer's rule for a 3x3 system."""
    def det(m):
        return dot(m[0], cross(m[1], m[2]))
    d = det(rows)
    out = []
    for k in range(3):
        m = [list(r) for r in rows]
        for i in range(3):
            m[i][k] = rhs[i]
        out.append(det(m) / d)
    return out


def line_of_intersection(n1, n2):
    """Unit direction of the intersection of two planes, plunging (z < 0)."""
    i = unit(cross(n1, n2))
    return i if i[2] < 0 else [-x for x in i]


def plunge_trend(i):
    """Plunge and trend (degrees) of a downward line."""
    plunge = math.degrees(math.asin(-i[2]))
    trend = math.degrees(math.atan2(i[0], i[1])) % 360.0
    return plunge, trend


def wedge_factor(n1, n2):
    """K = sin(beta) / sin(xi / 2) and psi_i, from the two upward normals."""
    i = line_of_intersection(n1, n2)
    psi_i = math.degrees(math.asin(-i[2]))
    # The section normal to i: the normals lie in it; xi is the wedge's
    # included angle, 180 deg minus the angle between the normals.
    xi = 180.0 - math.degrees(math.acos(dot(n1, n2)))
    # The bisector of the wedge (pointing into the wedge): along n1 + n2.
    bis = unit([n1[k] + n2[k] for k in range(3)])
    # "Up" in the section: the vertical minus its component along i.
    up = unit([0 - i[k] * i[2] for k in range(2)] + [1 - i[2] * i[2]])
    beta = math.degrees(math.asin(max(-1.0, min(1.0, dot(bis, up)))))
    return math.sin(D(beta)) / math.sin(D(xi / 2)), psi_i, beta, xi


def wedge_vector(planes, H, gamma, strengths):
    """The tetrahedral wedge of joint planes 1, 2, the upper surface 3 and the
    face 4 (each (dip, dip direction)); the lowest vertex O (where the line of
    intersection daylights at the toe) at the origin, the upper surface
    through (0, 0, H). strengths: [(c1, phi1), (c2, phi2)]. Returns its
    geometry, the normal reactions and FS."""
    n1, n2, n3, n4 = (normal(*p) for p in planes)
    O = [0.0, 0.0, 0.0]
    d3 = dot(n3, [0.0, 0.0, H])
    P = solve3([n1, n2, n3], [0.0, 0.0, d3])  # the line of intersection meets the upper surface
    A1 = solve3([n1, n3, n4], [0.0, d3, 0.0])  # plane 1, top, face
    B2 = solve3([n2, n3, n4], [0.0, d3, 0.0])  # plane 2, top, face
    V = abs(dot(sub(A1, O), cross(sub(B2, O), sub(P, O)))) / 6.0
    area1 = 0.5 * norm(cross(sub(A1, O), sub(P, O)))
    area2 = 0.5 * norm(cross(sub(B2, O), sub(P, O)))
    W = gamma * V
    i = line_of_intersection(n1, n2)
    # the wedge's vertex P lies up the line of intersection from O: behind the face
    assert dot(sub(P, O), i) < 0 and dot(P, n4) < 0, "the line of intersection does not daylight"
    c12 = dot(n1, n2)
    det = 1 - c12 * c12
    N1 = W * (n1[2] - c12 * n2[2]) / det
    N2 = W * (n2[2] - c12 * n1[2]) / det
    assert N1 > 0 and N2 > 0, "contact lost on one plane: plane sliding, not a wedge"
    (c1, f1), (c2, f2) = strengths
    drive = -W * i[2]
    fs = (c1 * area1 + c2 * area2 + N1 * math.tan(D(f1)) + N2 * math.tan(D(f2))) / drive
    plunge, trend = plunge_trend(i)
    return {
        "vertices": {"O": O, "A": A1, "B": B2, "P": P},
        "volume": V, "W": W, "A1": area1, "A2": area2, "N1": N1, "N2": N2,
        "plunge": plunge, "trend": trend, "FS": fs,
    }


# ---------------------------------------------------------------- 3. toppling

def toppling_blocks(dx, a1, a2, b, n_crest, n_blocks):
    """Goodman & Bray's block heights on a stepped base: below the crest
    y_n = n (a1 - b); above it y_n = y_{n-1} - a2 - b. Returns (y_n, M_n, L_n)
    for n = 1..n_blocks: M_n the height of P_n (from the block above) on its
    upper face, L_n that of P_{n-1} on its lower face."""
    out = []
    y = 0.0
    for n in range(1, n_blocks + 1):
        y = n * (a1 - b) if n <= n_crest else y - a2 - b
        if n < n_crest:
            M, L = y, y - a1
        elif n == n_crest:
            M, L = y - a2, y - a1
        else:
            M, L = y - a2, y
        out.append((y, M, L))
    return out


def toppling_p0(blocks, dx, psi, phi, gamma=1.0):
    """The support force at the toe P_0 from the recursion, top block down;
    also the mode of each block (stable, topple, slide)."""
    tp, s, c = math.tan(D(phi)), math.sin(D(psi)), math.cos(D(psi))
    p = 0.0
    modes = []
    for y, M, L in reversed(blocks):
        W = gamma * y * dx
        pt = (p * (M - dx * tp) + 0.5 * W * (y * s - dx * c)) / L if L > 0 else -math.inf
        ps = p - W * (tp * c - s) / (1 - tp * tp)
        if pt <= 0 and ps <= 0:
            modes.append("stable")
            p = 0.0
        elif pt >= ps:
            modes.append("topple")
            p = pt
        else:
            modes.append("slide")
            p = ps
    return p, list(reversed(modes))


def toppling_limit_phi(blocks, dx, psi, lo=30.0, hi=50.0):
    """The friction angle at which P_0 = 0 (bisection; P_0 falls with phi)."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if toppling_p0(blocks, dx, psi, mid)[0] > 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


# ---------------------------------------------------------------- cases

def cases():
    out = {}
    # 1. Hoek & Bray's plane failure as the issue gives it (dry crack 9 m behind the crest).
    out["plane"] = plane_failure(H=30.0, psi_f=60.0, psi_p=30.0, c=48.0, phi=30.0, gamma=25.5, b=9.0)
    # 1b. The same with water (references/water.md): the crack half full and full
    # (gamma_w = 9.81 kN/m^3), and full with the plane drained (U = 0).
    zc = out["plane"]["z"]
    for name, z_w, uplift in (("half", 0.5 * zc, True), ("full", zc, True), ("crack_only", zc, False)):
        out[f"plane_water_{name}"] = plane_failure(
            H=30.0, psi_f=60.0, psi_p=30.0, c=48.0, phi=30.0, gamma=25.5, b=9.0, gamma_w=9.81, z_w=z_w, uplift=uplift
        )
    # 1d. The plane on a Barton-Bandis joint (references/laws.md): JRC 6, JCS 40 MPa
    # (40e3 kPa: the script's stresses are kPa), phi_r 25, dry and the crack full.
    out["plane_bb_dry"] = plane_failure_bb(out["plane"], 6.0, 40e3, 25.0)
    out["plane_bb_full"] = plane_failure_bb(out["plane_water_full"], 6.0, 40e3, 25.0)
    # The direct shear check of issue 58: JRC 10, JCS 100 MPa, phi_r 30 at 1 MPa (kPa).
    out["bb_tau_1mpa"] = barton_bandis_tau(1e3, 10.0, 100e3, 30.0)
    # 1c. The infinite slope with a parallel water table (references/water.md):
    # beta 30, z = 4 / cos 30, gamma 20 kN/m^3, c' 5 kPa, phi' 35.
    for m in (0.0, 0.5, 1.0):
        out[f"infinite_slope_m{m}"] = infinite_slope(30.0, 4.0 / math.cos(D(30.0)), 20.0, 5.0, 35.0, 9.81, m)
    # 2a. The verification wedge of verification/joints/wedge-geometry.toml:
    # symmetric, planes 55 deg dipping 55 deg either side of the face's dip
    # direction (face 75/270, top horizontal, H = 12 m), friction 35 deg, no
    # cohesion.
    face, top = (75.0, 270.0), (0.0, 270.0)
    j1, j2 = (55.0, 215.0), (55.0, 325.0)
    K, psi_i, beta, xi = wedge_factor(normal(*j1), normal(*j2))
    vec = wedge_vector([j1, j2, top, face], H=12.0, gamma=2600.0 * 9.81, strengths=[(0.0, 35.0), (0.0, 35.0)])
    out["wedge_symmetric"] = {
        "K": K, "psi_i": psi_i, "beta": beta, "xi": xi,
        "FS_wedge_factor": K * math.tan(D(35.0)) / math.tan(D(psi_i)),
        "FS_vector": vec["FS"], "W": vec["W"], "volume": vec["volume"],
        "plunge": vec["plunge"], "trend": vec["trend"],
    }
    # 2b. The general wedge of verification/joints/wedge-general-geometry.toml:
    # planes 50/230 (c 10 kPa, phi 30) and 65/320 (c 10 kPa, phi 35), face
    # 70/270, horizontal top, H = 12 m, rho = 2600 kg/m^3.
    out["wedge_general"] = wedge_vector(
        [(50.0, 230.0), (65.0, 320.0), (0.0, 270.0), (70.0, 270.0)], H=12.0, gamma=2600.0 * 9.81,
        strengths=[(10.0e3, 30.0), (10.0e3, 35.0)],
    )
    # 2c. Hoek & Bray's general wedge (planes 45/105, 70/235, upper surface
    # 12/195, face 65/185; H = 40 m, gamma = 25 kN/m^3; c_A = 24 kPa,
    # phi_A = 20, c_B = 48 kPa, phi_B = 30), dry, no tension crack. The
    # published factor of safety was not found (references/joints.md).
    hb = [(45.0, 105.0), (70.0, 235.0), (12.0, 195.0), (65.0, 185.0)]
    gen = wedge_vector(hb, H=40.0, gamma=25.0, strengths=[(24.0, 20.0), (48.0, 30.0)])
    fric = wedge_vector(hb, H=40.0, gamma=25.0, strengths=[(0.0, 30.0), (0.0, 30.0)])
    Kg, psig, _, _ = wedge_factor(normal(*hb[0]), normal(*hb[1]))
    gen["FS_friction30_vector"] = fric["FS"]
    gen["FS_friction30_wedge_factor"] = Kg * math.tan(D(30.0)) / math.tan(D(psig))
    out["wedge_hoek_bray"] = gen
    # 3. Goodman & Bray's toppling example: dx = 10 m, base psi_p = 30 deg,
    # a1 = 5 m, a2 = 5 m, b = 1 m, 16 blocks, block 10 at the crest.
    blocks = toppling_blocks(dx=10.0, a1=5.0, a2=5.0, b=1.0, n_crest=10, n_blocks=16)
    phi_lim = toppling_limit_phi(blocks, 10.0, 30.0)
    _, modes = toppling_p0(blocks, 10.0, 30.0, phi_lim + 1e-9)
    out["toppling"] = {
        "heights": [y for y, _, _ in blocks], "phi_limit": phi_lim, "modes_at_limit": modes,
        "FS_at_38.15": math.tan(D(38.15)) / math.tan(D(phi_lim)),
    }
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    out = cases()
    if a.json:
        print(json.dumps(out, indent=1))
        return
    p = out["plane"]
    print(f"plane: z = {p['z']:.4f} m, A = {p['A']:.4f} m, W = {p['W']:.2f} kN/m, FS = {p['FS']:.4f}")
    for name in ("half", "full", "crack_only"):
        q = out[f"plane_water_{name}"]
        print(f"plane, water {name}: U = {q['U']:.2f} kN/m, V = {q['V']:.2f} kN/m, FS = {q['FS']:.4f}")
    print(f"plane, Barton-Bandis JRC 6, JCS 40 MPa, phi_r 25: dry FS = {out['plane_bb_dry']:.5f}, crack full FS = {out['plane_bb_full']:.5f}")
    print(f"Barton-Bandis JRC 10, JCS 100 MPa, phi_r 30 at 1 MPa: tau = {out['bb_tau_1mpa']:.2f} kPa")
    for m in (0.0, 0.5, 1.0):
        print(f"infinite slope, m = {m}: FS = {out[f'infinite_slope_m{m}']:.4f}")
    w = out["wedge_symmetric"]
    print(
        f"symmetric wedge: psi_i = {w['psi_i']:.4f}, trend {w['trend']:.2f}, xi = {w['xi']:.4f}, "
        f"beta = {w['beta']:.4f}, K = {w['K']:.5f}, FS (wedge factor) = {w['FS_wedge_factor']:.5f}, "
        f"FS (vector) = {w['FS_vector']:.5f}, W = {w['W']:.1f} N, V = {w['volume']:.2f} m^3"
    )
    v = out["wedge_general"]
    print(
        f"general wedge: intersection {v['plunge']:.2f} -> {v['trend']:.2f}, V = {v['volume']:.3f} m^3, "
        f"W = {v['W']:.1f} N, A1 = {v['A1']:.3f}, A2 = {v['A2']:.3f} m^2, N1 = {v['N1']:.1f}, N2 = {v['N2']:.1f} N, "
        f"FS = {v['FS']:.6f}"
    )
    g = out["wedge_hoek_bray"]
    print(
        f"Hoek & Bray wedge: intersection {g['plunge']:.2f} -> {g['trend']:.2f}, V = {g['volume']:.1f} m^3, "
        f"W = {g['W']:.0f} kN, A1 = {g['A1']:.1f} m^2, A2 = {g['A2']:.1f} m^2, N1 = {g['N1']:.0f}, "
        f"N2 = {g['N2']:.0f} kN, FS = {g['FS']:.4f}; friction 30 only: vector {g['FS_friction30_vector']:.5f}, "
        f"wedge factor {g['FS_friction30_wedge_factor']:.5f}"
    )
    t = out["toppling"]
    print(f"toppling: heights {t['heights']}")
    _, below = toppling_p0(toppling_blocks(10.0, 5.0, 5.0, 1.0, 10, 16), 10.0, 30.0, t["phi_limit"] - 0.01)
    print(f"toppling: modes at phi_limit - 0.01: {below}")
    print(f"toppling: limit phi = {t['phi_limit']:.4f} deg; modes {t['modes_at_limit']}")
    print(f"toppling: FS (tan 38.15 / tan phi_limit) = {t['FS_at_38.15']:.4f}")


if __name__ == "__main__":
    main()
