"""Lame's shrink fit: the contact pressure of a thick ring (inner radius Ri, outer Ro, free outside)
forced open by delta at Ri on a rigid shaft, the exact answer for the sleeves' all-austenite,
elastic final state and for the ring-lame scene.

Plane strain (the scenes' default): u(Ri) = (1 + nu) p Ri ((1 - 2 nu) Ri^2 + Ro^2) / (E (Ro^2 - Ri^2)),
solved for p. Plane stress replaces nu by nu / (1 + nu) and E by E (1 + 2 nu) / (1 + nu)^2 (the
in-plane Lame constants of the 2D model)."""


def lame_pressure(E, nu, Ri, Ro, delta, plane="strain"):
    if plane == "stress":
        E, nu = E * (1 + 2 * nu) / (1 + nu) ** 2, nu / (1 + nu)
    elif plane != "strain":
        raise ValueError(f"plane must be 'strain' or 'stress', not {plane!r}")
    return delta * E * (Ro * Ro - Ri * Ri) / ((1 + nu) * Ri * ((1 - 2 * nu) * Ri * Ri + Ro * Ro))
