"""Lame's shrink fit: the contact pressure of a thick ring (inner radius Ri, outer Ro, free outside)
forced open by delta at Ri on a rigid shaft, the exact answer for the sleeves' all-austenite,
elastic final state and for the ring-lame scene.

Plane strain (the scenes' default): u(Ri) = (1 + nu) p Ri ((1 - 2 nu) Ri^2 + Ro^2) / (E (Ro^2 - Ri^2)),
solved for p. Plane stress replaces nu by nu / (1 + nu) and E by E (1 + 2 nu) / (1 + nu)^2 (the
in-plane Lame constants of the 2D model).

compound_pressure: the same ring on an elastic pipe (hollow or solid), the sleeves' final state with
-pipeE > 0, from the textbook thick-cylinder displacements written out for each plane model (not
through the substitution above, so that the two check each other in the rigid limit)."""


def lame_pressure(E, nu, Ri, Ro, delta, plane="strain"):
    if plane == "stress":
        E, nu = E * (1 + 2 * nu) / (1 + nu) ** 2, nu / (1 + nu)
    elif plane != "strain":
        raise ValueError(f"plane must be 'strain' or 'stress', not {plane!r}")
    return delta * E * (Ro * Ro - Ri * Ri) / ((1 + nu) * Ri * ((1 - 2 * nu) * Ri * Ri + Ro * Ro))


def _ring_opening(E, nu, Ri, Ro, plane):
    """Outward displacement of the inner surface of a ring Ri < r < Ro, free outside, per unit inner
    pressure (textbook thick cylinder; plane stress: the thin disc's form, not the substitution above)."""
    if plane == "strain":
        return (1 + nu) * Ri * ((1 - 2 * nu) * Ri * Ri + Ro * Ro) / (E * (Ro * Ro - Ri * Ri))
    if plane == "stress":
        return Ri / E * ((Ro * Ro + Ri * Ri) / (Ro * Ro - Ri * Ri) + nu)
    raise ValueError(f"plane must be 'strain' or 'stress', not {plane!r}")


def _pipe_closing(E, nu, ri, ro, plane):
    """Inward displacement of the outer surface of a cylinder ri < r < ro (ri = 0: solid), free
    inside, per unit outer pressure (textbook thick cylinder under external pressure)."""
    if plane == "strain":
        return (1 + nu) * ro * ((1 - 2 * nu) * ro * ro + ri * ri) / (E * (ro * ro - ri * ri))
    if plane == "stress":
        return ro / E * ((ro * ro + ri * ri) / (ro * ro - ri * ri) - nu)
    raise ValueError(f"plane must be 'strain' or 'stress', not {plane!r}")


def compound_pressure(E, nu, Ri, Ro, E_pipe, nu_pipe, pipe_inner, pipe_outer, plane="strain"):
    """Compound cylinders: the ring (E, nu, Ri < r < Ro) shrink-fitted on an elastic pipe (E_pipe,
    nu_pipe, pipe_inner < r < pipe_outer; pipe_inner = 0: a solid shaft), interference
    pipe_outer - Ri. Small displacements on each body's reference configuration, as the scenes: the
    two exchange a force F per radian (action and reaction), a pressure F / Ri on the ring's inner
    surface and F / pipe_outer on the pipe's outer one; the ring opens by (F / Ri) c_ring, the pipe
    closes by (F / pipe_outer) c_pipe, and the two take up the interference. Returns the ring's
    pressure F / Ri (Pa); E_pipe = inf gives lame_pressure."""
    if not (0 <= pipe_inner < pipe_outer and 0 < Ri < Ro):
        raise ValueError("radii must satisfy 0 <= pipe_inner < pipe_outer and 0 < Ri < Ro")
    delta = pipe_outer - Ri
    ring = _ring_opening(E, nu, Ri, Ro, plane) / Ri
    pipe = _pipe_closing(E_pipe, nu_pipe, pipe_inner, pipe_outer, plane) / pipe_outer
    return delta / (ring + pipe) / Ri


def pipe_inner_displacement(E, nu, ri, ro, q, plane="strain"):
    """Radial displacement (outward positive) of the inner surface r = ri > 0 of a cylinder
    ri < r < ro, free inside, under the outer pressure q: -2 q ro^2 ri / (E (ro^2 - ri^2)) in plane
    stress, times (1 - nu^2) in plane strain."""
    if not 0 < ri < ro:
        raise ValueError("radii must satisfy 0 < ri < ro")
    u = -2 * q * ro * ro * ri / (E * (ro * ro - ri * ri))
    if plane == "strain":
        return u * (1 - nu * nu)
    if plane == "stress":
        return u
    raise ValueError(f"plane must be 'strain' or 'stress', not {plane!r}")
