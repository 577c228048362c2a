"""The scheme of the radial sleeve model (edp/scenes/sleeve-radial.edp) written again in numpy
from its equations: run(p) computes a whole run (radial_numpy.py is its command line, options and
files). Independent of the code it checks: numpy and LAPACK only.

The scheme (docs/model.md; the header of edp/problems/sleeve/radial.idp), per radian, SI units:
  mesh      nr equal P1 elements on [Ri, Ri + Hr]; one phase point per element (its midpoint),
            weight area_e = (b^2 - a^2) / 2.
  K         int (lambda tr e(u) tr e(v) + 2 mu (u'v' + u v / r^2)) r dr, 5-point Gauss per
            element; tridiagonal SPD, LDL' factorised once (LAPACK pttrf).
  B         (B s)_i = r_i (s_{i-1} - s_i) (s = 0 outside), so tr e = (B' u) / area exactly.
  contact   one unknown: u_0 + (Ri - Rp) >= 0, reaction R >= 0, complementarity; solved exactly:
            u_free = K^-1 B s, R = max(0, -(u_free_0 + Ri - Rp) / W), u = u_free + R K^-1 e_0,
            W = (K^-1 e_0)_0.
  law       alpha = rho a (Tc - T)+, c = rho L / T0 (T - T0) at the midpoints, T_mid the mean of
            the element's two nodes; the fraction local step (plugin/core/phase_fraction.hpp):
            D = (rho a [alpha > 0] |t| + rho L / T0) kappa, q = alpha^2 / (lambda + 2 mu),
            lower = (D b + alpha |t| - c) / (D + q), upper = lower + q / (D + q),
            |chi| = clamp(clamp(held, lower, upper), 0, 1), sign(chi) = sign(t) (t = 0: the
            previous sign), held = |chi_start| if chi_start has that sign else 0; s = alpha chi.
            kappa = rho L Interp(Q 1 ./ M) (= L / C0 up to round-off).
  DC loop   s = alpha chi; repeat: global step (contact), trace, local step; stop when no point
            changed or (from the second iteration) |u_new - u| <= dctol |u_new|.
  heat      lumped capacity M_i = rho C0 int phi_i r dr, conduction k r_mid / h per element,
            Robin exchange g l_i on the two surface nodes (l = Ri, Ro); the theta-method
            (M/dt + theta (Kt + G1)) T1 = (M/dt - (1-theta)(Kt + G0)) T0
                                          + theta G1 Text1 + (1-theta) G0 Text0 + S,
            theta = 1 for the first -rannacher steps, LDL' refactorised when theta or the inner
            coefficient changes; inner g = -gcontact if the reaction was > 0 at the end of the
            previous step, else -gpipe; inner outside temperature -Tpipe.
  latent    S = rho L / dt Q (b - b_start) (the step's whole latent heat), Q_ie = int phi_i r dr
            over element e; b_start the fractions the previous step's last heat solve used.
  fixed pt  per step, iteration r: S from b, heat step, alpha, c, DC loop, b_new = |chi|; stop
            when b_new == b exactly or (r >= 2) |T - T_prev| <= fptol |T|; otherwise
            Anderson(1) mixing of b <- b_new (from r = 2: b = b_new - gamma (b_new - b_new_prev),
            gamma = argmin |F - gamma (F - F_prev)|, F = b_new - b), clamped to [0, 1].
Vectorised over the points and nodes; Python loops only where the algorithm iterates (steps,
fixed point, DC loop).
"""
import math
import time

import numpy as np
from scipy.linalg import lapack

HISTORY_COLUMNS = ["t", "T_inner_mean", "T_min", "T_max", "fraction_austenite", "fraction_m1", "fraction_m2",
                   "contact_nodes", "pressure_mean", "fixed_point_iterations", "dc_iterations", "u_inner",
                   "reaction_per_radian"]


def not_converged(message, keep_going):
    """A loop that reached its limit: raises, or with keep_going counts it (returns 1), as the
    scenes' NotConverged (edp/lib/errors.idp) does."""
    if not keep_going:
        raise RuntimeError(message)
    return 1



def tridiagonal_factor(diagonal, off):
    """LDL' of the SPD tridiagonal matrix (diagonal, off); fails on a non-positive pivot."""
    d, e, info = lapack.dpttrf(diagonal, off)
    if info != 0:
        raise ArithmeticError(f"tridiagonal factorisation failed (LAPACK dpttrf info {info})")
    return d, e


def run(p):
    """The whole run; returns (history columns, summary dict)."""
    nr, steps = p["nr"], p["steps"]
    dt = p["tend"] / steps
    shear = p["E"] / (2 * (1 + p["nu"]))
    lam = p["E"] * p["nu"] / ((1 + p["nu"]) * (1 - 2 * p["nu"]))
    if p["plane"] == "stress":
        lam = 2 * lam * shear / (lam + 2 * shear)
    rho, a_law, L, T0, Tc = p["rho"], p["a"], p["latent"], p["T0"], p["Tc"]
    rhoa, rhoL = rho * a_law, rho * L
    laminate = lam + 2 * shear

    # ---- Mesh and mechanics ----
    r = p["Ri"] + p["thickness"] * np.arange(nr + 1) / nr
    a, b = r[:-1], r[1:]
    h = b - a
    area = (b * b - a * a) / 2
    total_area = area.sum()
    gx = np.array([-0.9061798459386640, -0.5384693101056831, 0., 0.5384693101056831, 0.9061798459386640])
    gw = np.array([0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                   0.2369268850561891])
    rq = (a + b)[:, None] / 2 + gx[None, :] * h[:, None] / 2      # elements x Gauss points
    wq = gw[None, :] * h[:, None] / 2 * rq                         # weight r dr
    Na, Nb = (b[:, None] - rq) / h[:, None], (rq - a[:, None]) / h[:, None]
    dNa, dNb = -1 / h[:, None], 1 / h[:, None]
    ta, tb = dNa + Na / rq, dNb + Nb / rq                          # tr e of each shape function
    kaa = (wq * (lam * ta * ta + 2 * shear * (dNa * dNa + Na * Na / rq ** 2))).sum(axis=1)
    kab = (wq * (lam * ta * tb + 2 * shear * (dNa * dNb + Na * Nb / rq ** 2))).sum(axis=1)
    kbb = (wq * (lam * tb * tb + 2 * shear * (dNb * dNb + Nb * Nb / rq ** 2))).sum(axis=1)
    K_diag = np.zeros(nr + 1)
    K_diag[:-1] += kaa
    K_diag[1:] += kbb
    K_d, K_e = tridiagonal_factor(K_diag, kab)
    solve_K = lapack.dpttrs
    e0 = np.zeros(nr + 1)
    e0[0] = 1
    G_contact, _ = solve_K(K_d, K_e, e0)      # K^-1 e_0: the inner node's response to its reaction
    W = G_contact[0]
    gap0 = r[0] - p["pipeA"]
    r_left, r_right = -r[:-1], r[1:]           # B: element e acts on nodes e (-r_e) and e+1 (r_e+1)
    trace_left, trace_right = r_left / area, r_right / area   # tr e = (B' u) / area per element
    # Lame's shrink-fit pressure of the interference (the all-austenite end state, for the summary).
    lame_C = -gap0 / (shear * r[0] / ((lam + shear) * r[-1] ** 2) + 1 / r[0])
    lame = 2 * shear * lame_C * (1 / r[0] ** 2 - 1 / r[-1] ** 2)

    # ---- Heat ----
    w_first, w_second = h * (2 * a + b) / 6, h * (a + 2 * b) / 6   # int phi r dr of the element's nodes
    capacity = np.zeros(nr + 1)
    capacity[:-1] += p["rho"] * p["C0"] * w_first
    capacity[1:] += p["rho"] * p["C0"] * w_second
    ke = p["k"] * (a + b) / 2 / h
    Kt_diag = np.zeros(nr + 1)
    Kt_diag[:-1] += ke
    Kt_diag[1:] += ke
    exchange_length = np.zeros(nr + 1)
    exchange_length[0], exchange_length[-1] = r[0], r[-1]
    nodal_one = np.zeros(nr + 1)
    nodal_one[:-1] += w_first
    nodal_one[1:] += w_second
    nodal_ratio = nodal_one / capacity
    kappa = rhoL * 0.5 * (nodal_ratio[:-1] + nodal_ratio[1:])   # = L / C0 per unit fraction
    # Per point, the parts of D that do not change: D = (rho a [alpha > 0] |t| + rho L / T0) kappa.
    D_latent = rhoL / T0 * kappa
    D_slope = rhoa * kappa
    latent_first, latent_second = rhoL / dt * w_first, rhoL / dt * w_second
    rc_T0 = rhoL / T0

    def heat_lhs(theta, g_inner):
        g = exchange_length * p["g"]
        g[0] = exchange_length[0] * g_inner
        return tridiagonal_factor(capacity / dt + theta * g + theta * Kt_diag, -theta * ke)

    # ---- State ----
    T = np.full(nr + 1, p["Tinit"])
    u = np.zeros(nr + 1)
    chi = np.zeros(nr)
    b_start = np.zeros(nr)            # the fractions the last heat solve accounted for
    reaction = 0.0
    Text_node = np.full(nr + 1, p["Text"])
    Text_node[0] = p["Tpipe"]
    g_prev = np.full(nr + 1, p["g"])
    g_prev[0] = p["gpipe"]
    factor_key, H_d, H_e = None, None, None
    dctol, dcmaxit, fptol, fpmaxit = p["dctol"], p["dcmaxit"], p["fptol"], p["fpmaxit"]
    keep_going = bool(p["keepgoing"])
    unconverged = 0

    cols = {k: np.zeros(steps) for k in HISTORY_COLUMNS}
    heat_balance_max = 0.0
    reverted = np.zeros(nr, dtype=bool)
    reversal_steps = 0
    zig = [0.0, 0.0, 0.0, 0.0]  # p_prev, dp_prev, dp_prev2, max |p|
    zigzag_steps = 0
    loop_start = time.perf_counter()
    for n in range(steps):
        theta = 1.0 if n < p["rannacher"] else p["theta"]
        # Boundary data: the start of the step is the end of the last one; the inner surface's
        # coefficient at the end from the contact status at the end of the last step.
        g_now = np.full(nr + 1, p["g"])
        g_now[0] = p["gcontact"] if reaction > 0 else p["gpipe"]
        G0 = g_prev * exchange_length
        G1 = g_now * exchange_length
        key = (theta, g_now[0])
        if key != factor_key:
            H_d, H_e = heat_lhs(theta, g_now[0])
            factor_key = key
        # The right side without the latent load (the same for every fixed-point iteration).
        KtT = Kt_diag * T
        KtT[:-1] -= ke * T[1:]
        KtT[1:] -= ke * T[:-1]
        rhs_base = capacity * T / dt - (1 - theta) * (KtT + G0 * T) + (1 - theta) * G0 * Text_node \
            + theta * G1 * Text_node
        chi_start = chi.copy()
        b_seen = np.abs(chi)
        T_prev = T
        last_F = last_G = None
        dc_total = 0
        fp_its = 0
        converged_fp = False
        while not converged_fp and fp_its < fpmaxit:
            fp_its += 1
            db_load = b_seen - b_start
            rhs = rhs_base.copy()
            rhs[:-1] += latent_first * db_load
            rhs[1:] += latent_second * db_load
            T1, info = lapack.dpttrs(H_d, H_e, rhs)
            # Law at the midpoints, and the local step's coefficients of this iterate.
            Tq = 0.5 * (T1[:-1] + T1[1:])
            alpha = np.maximum(rhoa * (Tc - Tq), 0.0)
            c = rc_T0 * (Tq - T0)
            D_slope_now = np.where(alpha > 0, D_slope, 0.0)
            q_lam = alpha * alpha / laminate
            num_t = D_slope_now * b_seen + alpha        # numerator: |t| num_t + num_0
            num_0 = D_latent * b_seen - c
            den_0 = D_latent + q_lam                    # denominator: |t| D_slope_now + den_0
            # ---- DC loop ----
            s = alpha * chi
            it = 0
            converged_dc = False
            while not converged_dc and it < dcmaxit:
                rhs_u = np.empty(nr + 1)
                np.multiply(r_left, s, out=rhs_u[:-1])
                rhs_u[-1] = 0.0
                rhs_u[1:] += r_right * s
                u_new, info = solve_K(K_d, K_e, rhs_u)
                free_gap = -(u_new[0] + gap0)
                reaction = free_gap / W if free_gap > 0 else 0.0
                if reaction > 0:
                    u_new += reaction * G_contact
                du = u_new - u
                unorm = math.sqrt(u_new.dot(u_new))
                change = math.sqrt(du.dot(du))
                rel = change / unorm if unorm > 0 else change
                trace = trace_right * u_new[1:]
                trace += trace_left * u_new[:-1]
                # Local step (vectorised plugin/core/phase_fraction.hpp project_fraction).
                at = np.abs(trace)
                sign = np.copysign(1.0, trace)
                if not at.all():
                    zero = at == 0
                    sign[zero] = np.where(chi[zero] < 0, -1.0, 1.0)
                held = np.maximum(chi_start * sign, 0.0)
                den = at * D_slope_now + den_0
                lower = (at * num_t + num_0) / den
                upper = lower + q_lam / den
                fraction = np.maximum(lower, held)
                np.minimum(fraction, upper, out=fraction)
                np.maximum(fraction, 0.0, out=fraction)   # (ufuncs: np.clip costs 10 us a call)
                np.minimum(fraction, 1.0, out=fraction)
                chi_new = sign * fraction
                changed = np.count_nonzero(chi_new != chi)
                chi = chi_new
                s = alpha * chi
                u = u_new
                converged_dc = changed == 0 or (it >= 1 and rel <= dctol)
                it += 1
            if not converged_dc:
                unconverged += not_converged(f"DC loop did not converge: {it} iterations, relative displacement "
                                             f"change {rel} > tol {dctol} (step {n + 1})", keep_going)
            dc_total += it
            b_new = np.abs(chi)
            db = b_new - b_seen
            dT = T1 - T_prev
            fp_residual = math.sqrt(dT.dot(dT)) / math.sqrt(T1.dot(T1))
            converged_fp = not db.any() or (fp_its >= 2 and fp_residual <= fptol)
            T_prev = T1
            b_used = b_seen
            if not converged_fp:
                # Anderson mixing of depth 1 (a secant step on the fractions), clamped to [0, 1].
                b_seen = b_new
                if fp_its >= 2:
                    dF = db - last_F
                    dFF = dF.dot(dF)
                    if dFF > 0:
                        b_seen = b_new - (dF.dot(db) / dFF) * (b_new - last_G)
                    b_seen = np.minimum(np.maximum(b_seen, 0.0), 1.0)
                last_F, last_G = db, b_new
        if not converged_fp:
            unconverged += not_converged(f"DCT fixed point did not converge: {fp_its} iterations, relative "
                                         f"change of T {fp_residual} > tol {fptol} (step {n + 1})", keep_going)
        # The step's heat balance: stored = entered through the boundary + latent released.
        S_sum = rhoL / dt * (w_first.dot(b_used - b_start) + w_second.dot(b_used - b_start))
        boundary = dt * (theta * G1.dot(Text_node - T1) + (1 - theta) * G0.dot(Text_node - T))
        stored = capacity.dot(T1 - T)
        budget = boundary + dt * S_sum
        scale = max(abs(stored), abs(boundary) + abs(dt * S_sum))
        if scale > 0:
            heat_balance_max = max(heat_balance_max, abs(stored - budget) / scale)
        b_start = b_seen   # (= b_used once converged; -keepgoing: the mixed next guess, as dct.idp)
        T = T1
        g_prev = g_now
        # Chatter watch (edp/solvers/dct.idp ChatterStep): reversals and pressure zigzags.
        grow = np.abs(chi) - np.abs(chi_start)
        reversal_steps += bool(np.any((grow > 1e-9) & reverted))
        reverted |= grow < -1e-9
        pressure = reaction / r[0]
        dp = pressure - zig[0]
        zig[3] = max(zig[3], abs(pressure))
        floor = 1e-6 * zig[3]
        zigzag_steps += (dp * zig[1] < 0 and zig[1] * zig[2] < 0 and abs(dp) > floor and abs(zig[1]) > floor
                         and abs(zig[2]) > floor)
        zig[:3] = [pressure, dp, zig[1]]
        latent = np.abs(chi)
        cols["t"][n] = (n + 1) * dt
        cols["T_inner_mean"][n] = T[0]
        cols["T_min"][n] = T.min()
        cols["T_max"][n] = T.max()
        cols["fraction_m1"][n] = 0.5 * area.dot(chi + latent) / total_area
        cols["fraction_m2"][n] = 0.5 * area.dot(latent - chi) / total_area
        cols["fraction_austenite"][n] = 1.0 - area.dot(latent) / total_area
        cols["contact_nodes"][n] = reaction > 0
        cols["pressure_mean"][n] = pressure
        cols["fixed_point_iterations"][n] = fp_its
        cols["dc_iterations"][n] = dc_total
        cols["u_inner"][n] = u[0]
        cols["reaction_per_radian"][n] = reaction
    loop_seconds = time.perf_counter() - loop_start

    fa = cols["fraction_austenite"]
    in_contact = np.flatnonzero(cols["contact_nodes"] > 0)
    not_austenite = np.flatnonzero(fa < 1)
    austenite_step = int(not_austenite[-1]) + 2 if not_austenite.size and not_austenite[-1] + 1 < steps else \
        (1 if not not_austenite.size else None)
    summary = {
        "scene": "sleeve-radial (numpy, tools/bench/oracles/radial_numpy.py)",
        "parameters": {k: v for k, v in p.items() if k != "out"},
        "nr": nr, "nodes": nr + 1, "n_steps": steps, "dt": dt, "interference": -gap0,
        "loop_seconds": loop_seconds,
        "fixed_point_iterations_max": int(cols["fixed_point_iterations"].max()),
        "fixed_point_iterations_mean": float(cols["fixed_point_iterations"].mean()),
        "dc_iterations_max": int(cols["dc_iterations"].max()),
        "dc_iterations_mean": float(cols["dc_iterations"].mean()),
        "heat_balance_residual_max": heat_balance_max,
        "final_pressure_mean": float(cols["pressure_mean"][-1]), "lame_pressure": lame,
        "first_contact_step": int(in_contact[0]) + 1 if in_contact.size else None,  # null: never (as the scenes)
        "T_inner_first_contact": float(cols["T_inner_mean"][in_contact[0]]) if in_contact.size else None,
        "austenite_step": austenite_step,
        "peak_pressure_mean": float(cols["pressure_mean"].max()),
        "reversal_steps": reversal_steps, "pressure_zigzag_steps": zigzag_steps,
        "unconverged_loops": unconverged,
    }
    return cols, summary

