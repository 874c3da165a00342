"""Closed forms of normal, frictionless penetration (pencore.closedform): the three-term
law against the cavity-expansion literature's printed equations, and its limits."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from scipy.integrate import quad

from pencore import closedform
from pencore.inputs.library import MEDIA, get_projectile

# the rods' outlines with their printed density (the source's m = pi a^2 rho (L + k a)); the
# library rods carry the measured mean mass, 0.01 % and 0.06 % from these
ROD = replace(get_projectile("al_ogive_var4340"), mass=None)
SPHERE = replace(get_projectile("al_sphere_var4340"), mass=None)
AL3 = MEDIA["aluminium_3term"]


def piekutowski_eq1(vs: float, psi: float, rho_p: float, length: float, a: float) -> float:
    """Penetration depth P (m) by Piekutowski et al. (1999), IJIE 23:723-734, Eqs. (1)-(2e)
    as printed, with the constants of p. 731 (Y = 276 MPa, rho_t = 2710 kg/m3, A = 5.04,
    B = 0.983, C = 0.940); written out here apart from pencore.closedform."""
    y, rho_t, a_, b, c = 276e6, 2710.0, 5.04, 0.983, 0.940
    k = (4 * psi**2 - 4 * psi / 3 + 1 / 3) * math.sqrt(4 * psi - 1) - 4 * psi**2 * (
        2 * psi - 1
    ) * math.asin(math.sqrt(4 * psi - 1) / (2 * psi))
    n = (8 * psi - 1) / (24 * psi**2)
    theta0 = math.asin((2 * psi - 1) / (2 * psi))
    n1 = (
        (4 * psi - 1) ** 1.5 / (3 * psi)
        + (2 * psi - 1) ** 2 * math.sqrt(4 * psi - 1) / (2 * psi)
        - psi * (2 * psi - 1) * (math.pi - 2 * theta0)
    )
    cy = math.sqrt(y / rho_t)
    x = vs / cy
    root = math.sqrt(4 * a_ * c * n - b**2 * n1**2)
    term1 = (rho_p / rho_t) / (2 * c * n) * math.log(1 + b * n1 / a_ * x + c * n / a_ * x**2)
    term2 = (
        (rho_p / rho_t)
        * b
        * n1
        / (c * n * root)
        * (math.atan(b * n1 / root) - math.atan((b * n1 + 2 * c * n * x) / root))
    )
    return (length + k * a) * (term1 + term2)


@pytest.mark.parametrize("vs", [500.0, 1000.0, 1500.0, 2000.0])
def test_tunnel_depth_is_the_printed_equation_of_the_source(vs):
    # Piekutowski et al. (1999): L = 59.3 mm, 2a = 7.11 mm, psi = 3, rho_p = 7830 kg/m3.
    # The rod's mass from pencore's geometry is pi a^2 rho_p (L + k a) (the source's m), so
    # the two agree to the band quadrature of N1 (1e-7, see linear_nose_factor).
    printed = piekutowski_eq1(vs, 3.0, 7830.0, 0.0593, 0.00711 / 2)
    assert closedform.tunnel_depth(ROD, AL3, vs) == pytest.approx(printed, rel=1e-6)


def test_linear_nose_factor_closed_forms():
    # hemisphere: int 2 pi r na^2 dl / (pi a^2) = 2/3; CRH 3 ogive: the source's Eq. (2c)
    assert closedform.linear_nose_factor(SPHERE) == pytest.approx(2.0 / 3.0, rel=1e-6)
    psi = 3.0
    theta0 = math.asin((2 * psi - 1) / (2 * psi))
    n1 = (
        (4 * psi - 1) ** 1.5 / (3 * psi)
        + (2 * psi - 1) ** 2 * math.sqrt(4 * psi - 1) / (2 * psi)
        - psi * (2 * psi - 1) * (math.pi - 2 * theta0)
    )
    assert closedform.linear_nose_factor(ROD) == pytest.approx(n1, rel=1e-6)


def test_three_term_tunnel_depth_against_quadrature():
    a = ROD.radius
    m = ROD.mass_properties().mass
    a0, a1, a2 = AL3.coefficients
    n1, n2 = closedform.linear_nose_factor(ROD), ROD.nose_factor()
    for v in (300.0, 1200.0, 2500.0):
        val, _ = quad(lambda u: m * u / (math.pi * a * a * (a0 + a1 * n1 * u + a2 * n2 * u * u)),
                      0.0, v, epsrel=1e-12)  # fmt: skip
        assert closedform.tunnel_depth(ROD, AL3, v) == pytest.approx(val, rel=1e-10)


def test_three_term_reduces_to_two_term_as_a1_vanishes():
    two = MEDIA["aluminium"]
    nearly = replace(two, coefficients=(two.coefficients[0], 1e-6, two.coefficients[2]))
    for v in (500.0, 1500.0):
        assert closedform.tunnel_depth(ROD, nearly, v) == pytest.approx(
            closedform.tunnel_depth(ROD, two, v), rel=1e-9
        )
        # the entry phase is integrated two ways (exact per band for a1 = 0; an ODE over the
        # interpolated profile otherwise): they agree to the profile's quadrature, 1e-4
        assert closedform.depth(ROD, nearly, v) == pytest.approx(
            closedform.depth(ROD, two, v), rel=1e-4
        )


def test_exact_entry_is_deeper_than_full_nose_force_by_less_than_a_nose():
    for v in (400.0, 1000.0, 2000.0):
        exact, full = closedform.depth(ROD, AL3, v), closedform.tunnel_depth(ROD, AL3, v)
        assert 0.0 < exact - full < ROD.nose_length


def test_three_term_axial_force():
    a0, a1, a2 = AL3.coefficients
    n1 = closedform.linear_nose_factor(SPHERE)
    v = 800.0
    expected = math.pi * SPHERE.radius**2 * (a0 + a1 * n1 * v + 0.5 * a2 * v * v)
    assert closedform.axial_force(SPHERE, AL3, v) == pytest.approx(expected, rel=1e-12)


def test_source_three_term_constants():
    # Piekutowski et al. (1999) p. 731: sigma_n = Y (A + B Vn/c + C Vn^2/c^2), c^2 = Y/rho
    y, rho = 276e6, 2710.0
    a0, a1, a2 = AL3.coefficients
    assert a0 == pytest.approx(5.04 * y, rel=1e-15)
    assert a1 == pytest.approx(0.983 * math.sqrt(y * rho), rel=1e-15)
    assert a2 == pytest.approx(0.940 * rho, rel=1e-15)
