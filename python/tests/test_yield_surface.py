"""The exact yield condition and its interaction curves, against section-calc and a closed form.

Closed form: a rectangle under N and Mx meets the surface where (N/Np)^2 + |Mx|/Mxp = 1 (e.g.
Neal, The Plastic Methods of Structural Analysis, 1977, section 6.2).
"""
import pytest

import plascap
from conftest import section_calc_json

IPE = ("--shape", "IPE 300", "--material", "S355")


def ipe():
    return plascap.Section.shape("IPE 300", material="S355")


@pytest.mark.parametrize("load", [
    {"N": 1e5, "Mx": 1e5, "Qz": 1e5},
    {"N": -8e5, "Mz": 2e4},
    {"Mx": 1.5e5, "Mz": 1e4, "T": 2e3, "Qx": 5e4},
])
def test_utilisation_matches_section_calc(load):
    cli_load = ",".join(f"{'My' if k == 'T' else k}={v}" for k, v in load.items())
    cli = section_calc_json(*IPE, "--load", cli_load)
    ours = ipe().yield_condition().evaluate(**load)
    assert ours["utilisation"] == pytest.approx(cli["utilisation"], rel=1e-12)
    assert ours["nm_utilisation"] == pytest.approx(cli["load_check"]["nm_utilisation"], rel=1e-12)
    assert ours["shear_torsion_share"] == pytest.approx(cli["load_check"]["shear_torsion_share"], rel=1e-12, abs=1e-15)


def test_interaction_curves_match_section_calc():
    cli = section_calc_json(*IPE, "--interaction", "--samples", "16")["interaction"]
    s = ipe()
    assert cli["Mx_Mz"]["N"] == 0.0
    for cut, points in (("N-Mx", cli["N_Mx"]), ("N-Mz", cli["N_Mz"]), ("Mx-Mz", cli["Mx_Mz"]["points"])):
        ours = s.interaction_curve(cut, samples=16)
        assert len(ours) == len(points) == 16
        for (a, b), (c, d) in zip(ours, points):
            assert a == pytest.approx(c, rel=1e-12, abs=1e-6) and b == pytest.approx(d, rel=1e-12, abs=1e-6), cut


def test_a_rectangle_curve_is_n_squared_plus_m():
    b, h, fy = 0.2, 0.1, 1e5
    Np, Mxp = fy * b * h, fy * b * h * h / 4
    points = plascap.Section.rectangle(b, h, fy=fy).interaction_curve("N-Mx", samples=64)
    for N, Mx in points:
        assert (N / Np) ** 2 + abs(Mx) / Mxp == pytest.approx(1.0, abs=1e-9)
    assert plascap.Section.rectangle(b, h, fy=fy).yield_condition().utilisation(Mx=Mxp) == pytest.approx(1.0, rel=1e-9)


def test_bad_cuts_and_samples_say_so():
    with pytest.raises(ValueError, match="'N-Mx', 'N-Mz' or 'Mx-Mz'"):
        ipe().interaction_curve("N-My")
    with pytest.raises(ValueError, match="8 to 100000"):
        ipe().interaction_curve("N-Mx", samples=4)
    with pytest.raises(ValueError, match="torsion"):
        ipe().yield_condition(torsion="elastic")
