"""Ball kinematics under raceway control, cage speed, gyroscopic moment (layer 1).

Source: Harris T. A., Kotzalas M. N., *Advanced Concepts of Bearing Technology*, 5th ed.,
2007, ch. 3 (high-speed ball bearings; Jones' raceway control). With the outer raceway
controlling (the ball rolls without spinning on the outer race, lambda_o = 2, lambda_i = 0):

- ball attitude: tan(beta) = sin(alpha_o) / (cos(alpha_o) + gamma'), gamma' = D_w / d_m;
- orbital speed: omega_m / omega = (1 - gamma' cos(alpha_i)) / (1 + cos(alpha_i - alpha_o));
- spin speed: omega_R / omega = -1 / ([(cos(alpha_o) + tan(beta) sin(alpha_o)) /
  (1 + gamma' cos(alpha_o)) + (cos(alpha_i) + tan(beta) sin(alpha_i)) /
  (1 - gamma' cos(alpha_i))] gamma' cos(beta));
- gyroscopic moment: M_g = J omega_R omega_m sin(beta), J = rho pi D_w^5 / 60;
- it is held by friction at the outer contact, a force lambda_o M_g / D_w = 2 M_g / D_w on
  the ball, in the ball's plane and perpendicular to the outer contact normal.

Direction (derived here, since sign conventions differ between texts): in the cage frame
the spin vector omega_R = |omega_R| (sin(beta) e_rho - cos(beta) e_z) (for inner-ring
rotation about +z and an outer contact leaning to +z) is fixed, so in space the angular
momentum J omega_R turns with omega_m e_z and the moment the contacts must supply is
omega_m e_z x J omega_R = M_g e_psi. A friction force F t at the outer contact point
(D_w/2) u_o, t = u_o turned by +90 deg in the (rho, z) plane, gives the moment
-(D_w/2) F e_psi, so F = -2 M_g / D_w: the force on the ball is
(2 M_g / D_w) (sin(alpha_o) e_rho - cos(alpha_o) e_z), outward and away from the side the
outer contact leans to.

Other raceway controls (the same source; derived here in the ball's plane with the spin
axis at the attitude beta and pure rolling at both contact centres):
- inner raceway control: tan(beta) = sin(alpha_i) / (cos(alpha_i) - gamma');
- any beta: omega_m / omega = A / (A + B), omega_R / omega = -1 / (gamma' (A + B)) with
  A = cos(alpha_o - beta) / (1 + gamma' cos(alpha_o)), B = cos(alpha_i - beta) /
  (1 - gamma' cos(alpha_i)) (Jones's cage speed; with the outer-control beta this is the
  orbital-speed formula above);
- the friction that holds M_g is shared lambda_i at the inner and lambda_o = 2 - lambda_i
  at the outer contact: (lambda_o M_g / D_w) (sin(alpha_o) e_rho - cos(alpha_o) e_z) on
  the ball at the outer contact and (lambda_i M_g / D_w) (-sin(alpha_i) e_rho +
  cos(alpha_i) e_z) at the inner one (its reaction acts on the inner ring). Harris's
  choice: lambda_o = 2 under outer raceway control, lambda_i = lambda_o = 1 otherwise;
  pure inner raceway control is lambda_i = 2.
- Which race controls (``race_control="hybrid"``): Jones's criterion as Harris & Kotzalas
  give it, outer raceway control where Q_o a_o E(k_o) cos(alpha_i - alpha_o) >
  Q_i a_i E(k_i) (a the semi-major axis, E(k) the elliptic integral of the second kind),
  inner raceway control elsewhere.

The ball's centrifugal force F_c = m d_m omega_m^2 / 2 uses the same orbital speed
omega_m (Jones's, at the ball's own contact angles), so the centrifugal force and the
gyroscopic moment see one cage speed.

Assumes the friction available at the outer contact is enough to stop gyroscopic spinning
(Jones's criterion); the inner contact then spins. These are the classical hypotheses of
the quasi-static high-speed model, not a traction calculation.
"""

from __future__ import annotations

import math

import numpy as np


def outer_control_kinematics(inner_angle, outer_angle, gamma_prime):
    """Ball attitude beta [rad], orbital and spin speed ratios omega_m/omega, omega_R/omega
    under outer raceway control: :func:`raceway_control_kinematics` with ``"outer"``, whose
    general form equals Harris's printed outer-control formulas (module docstring;
    tests/unit/test_gyroscopic.py checks them against each other).

    >>> b, om, orr = outer_control_kinematics(0.0, 0.0, 0.2)
    >>> round(float(om), 6), round(float(-orr), 6)    # cage (1 - g)/2, spin (1 - g^2)/(2 g)
    (0.4, 2.4)
    """
    return raceway_control_kinematics(inner_angle, outer_angle, gamma_prime, "outer")


def raceway_control_kinematics(inner_angle, outer_angle, gamma_prime, control="outer"):
    """Ball attitude beta [rad], orbital and spin speed ratios omega_m/omega, omega_R/omega
    under outer or inner raceway control (Jones; see the module docstring).

    Parameters
    ----------
    inner_angle, outer_angle : float or array
        Contact angles alpha_i, alpha_o (magnitudes) [rad].
    gamma_prime : float
        D_w / d_m [-].
    control : {"outer", "inner"}
        The race at which the ball rolls without spinning [-].

    Examples
    --------
    >>> b, om, orr = raceway_control_kinematics(0.7, 0.7, 0.2, "inner")
    >>> round(float(om), 6) == round((1 - 0.2 * math.cos(0.7)) / 2, 6)
    True
    """
    ai, ao = np.asarray(inner_angle, float), np.asarray(outer_angle, float)
    g = gamma_prime
    if control == "outer":
        beta = np.arctan2(np.sin(ao), np.cos(ao) + g)
    elif control == "inner":
        beta = np.arctan2(np.sin(ai), np.cos(ai) - g)
    else:
        raise ValueError(f"control must be 'outer' or 'inner', not {control!r}")
    a = np.cos(ao - beta) / (1.0 + g * np.cos(ao))
    b = np.cos(ai - beta) / (1.0 - g * np.cos(ai))
    return beta, a / (a + b), -1.0 / (g * (a + b))


def gyroscopic_ball_force(
    ball_diameter, pitch_diameter, density, shaft_speed, inner_angle, outer_angle
):
    """Force on each ball (rho, z) from the friction that holds its gyroscopic moment [N].

    Parameters
    ----------
    ball_diameter, pitch_diameter : float
        D_w, d_m [m].
    density : float
        Ball density [kg/m^3].
    shaft_speed : float
        Inner-ring speed omega [rad/s].
    inner_angle, outer_angle : array (Z,)
        Signed contact angles of each ball's loaded inner and outer contact [rad]
        (positive when the contact line leans towards +z).
    """
    ao = np.asarray(outer_angle, float)
    beta, orbit, spin = outer_control_kinematics(
        np.abs(inner_angle), np.abs(ao), ball_diameter / pitch_diameter
    )
    inertia = density * math.pi * ball_diameter**5 / 60.0
    moment = inertia * np.abs(spin * orbit) * shaft_speed**2 * np.sin(beta)
    force = 2.0 * moment / ball_diameter
    side = np.sign(ao)
    return np.stack([force * np.sin(np.abs(ao)), -side * force * np.cos(ao)], axis=1)
