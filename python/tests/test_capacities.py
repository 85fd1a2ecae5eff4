"""Capacities, elastic properties and torsion against closed forms, a published table and the CLI.

References: a b x h rectangle of yield stress fy has N = fy*b*h, Mx = fy*b*h^2/4 (the plastic
modulus b*h^2/4), Mz = fy*h*b^2/4, Qx = Qz = tau_y*b*h with Tresca's tau_y = fy/2; J = beta*b*h^3
with beta(b/h = 2) = 0.229 (Timoshenko & Goodier, Theory of Elasticity, 1970, table of section 109);
the sand heap's T_p = tau_y*h^2*(3b - h)/6 (Nadai). IPE 300: Wpl,y = 628.4 cm^3, Iy = 8356 cm^4
(EN 10365:2017 / ArcelorMittal tables, as the shape catalogue records them).
"""
import math

import pytest

import plascap
from conftest import SOURCE_DIR, section_calc_json

B, H, FY = 0.2, 0.1, 1e5


def rel(a, b):
    return abs(a - b) / abs(b)


def test_rectangle_matches_closed_forms():
    c = plascap.Section.rectangle(B, H, fy=FY).capacities()
    assert rel(c.N, FY * B * H) < 1e-12
    assert rel(c.Mx, FY * B * H * H / 4) < 1e-12
    assert rel(c.Mz, FY * H * B * B / 4) < 1e-12
    assert rel(c.Qx, FY / 2 * B * H) < 1e-12 and rel(c.Qz, FY / 2 * B * H) < 1e-12
    assert c.N_neg == pytest.approx(c.N, rel=1e-12)
    assert c.area == pytest.approx(B * H, rel=1e-12)
    assert c.centroid == pytest.approx((0.0, 0.0), abs=1e-15)
    assert c.shear == "tresca" and c.method == "exact" and c.errors == {}


def test_rectangle_torsion_matches_timoshenko_and_the_sand_heap():
    s = plascap.Section.rectangle(B, H, fy=FY)
    j = s.torsion_constant()
    assert rel(j.J, 0.229 * B * H**3) < 0.005  # the table's three digits
    assert j.error < 1e-4 * j.J and j.converged
    t = s.plastic_torque()
    assert rel(t.T, FY / 2 * H * H * (3 * B - H) / 6) < 1e-4
    assert t.error < 1e-4 * t.T


def test_ipe300_matches_the_published_table():
    ipe = plascap.Section.shape("IPE 300", material="S355")
    assert rel(ipe.capacities().Mx, 628.4e-6 * 355e6) < 0.005
    e = ipe.elastic_properties()
    assert rel(e.Ixx, 8356e-8) < 0.005
    assert rel(e.EIxx, 210e9 * e.Ixx) < 1e-12  # S355's E = 210 GPa (EN 1993-1-1 3.2.6)


def test_cubature_agrees_with_the_exact_route_within_its_error_estimate():
    ipe = plascap.Section.shape("IPE 300", material="S355")
    exact, cubature = ipe.capacities(), ipe.capacities(method="cubature")
    assert cubature.triangles > 0
    for name, value in exact.as_dict().items():
        error = cubature.errors[name]
        assert abs(cubature.as_dict()[name] - value) <= max(10 * error, 1e-12 * abs(value)), name
        assert error < 1e-9 * abs(value), name


def test_only_computes_what_is_asked():
    c = plascap.Section.rectangle(B, H, fy=FY).capacities(only="N,My")
    assert set(c.as_dict()) == {"N", "My"} and c.Mx is None


@pytest.mark.parametrize("args, make", [
    (["--shape", "IPE 300", "--material", "S355"], lambda: plascap.Section.shape("IPE 300", material="S355")),
    (["--shape", "UPE 200", "--fy", "2.75e8"], lambda: plascap.Section.shape("UPE 200", fy=2.75e8)),
    ([f"{SOURCE_DIR}/sections/examples/t-section.json"],
     lambda: plascap.Section.from_file(f"{SOURCE_DIR}/sections/examples/t-section.json")),
    (["--rect", "0.2", "0.1", "--fy", "1e5"], lambda: plascap.Section.rectangle(0.2, 0.1, fy=1e5)),
])
def test_every_value_matches_section_calc(args, make):
    cli = section_calc_json(*args, "--elastic")
    s = make()
    for name, value in s.capacities().as_dict().items():
        assert value == pytest.approx(cli[name], rel=1e-13), name
    e = s.elastic_properties()
    for name in ("Ixx", "Izz", "Wx", "Wz", "rx", "rz", "I1", "I2"):
        assert getattr(e, name) == pytest.approx(cli[name], rel=1e-13), name
    assert s.torsion_constant().J == pytest.approx(cli["J"], rel=1e-13)
    assert s.plastic_torque().T == pytest.approx(cli["My_plastic_torsion"], rel=1e-13)


def test_section_files_match_section_calc(source_dir):
    import glob
    files = sorted(glob.glob(f"{source_dir}/sections/examples/*.json"))
    assert len(files) >= 5
    for path in files:
        cli = section_calc_json(path, "--method", "cubature")
        c = plascap.Section.from_file(path).capacities(method="cubature")
        for name, value in c.as_dict().items():
            assert value == pytest.approx(cli[name], rel=1e-13), f"{path}: {name}"


def test_polygon_with_a_hole_is_the_difference_of_two_rectangles():
    outer = [(-0.1, -0.05), (0.1, -0.05), (0.1, 0.05), (-0.1, 0.05)]
    hole = [(-0.05, -0.025), (0.05, -0.025), (0.05, 0.025), (-0.05, 0.025)]
    c = plascap.Section.polygon(outer, [hole], fy=FY).capacities()
    assert rel(c.N, FY * (0.2 * 0.1 - 0.1 * 0.05)) < 1e-12
    assert rel(c.Mx, FY * (0.2 * 0.1**2 - 0.1 * 0.05**2) / 4) < 1e-12  # Wpl of a doubly symmetric box


def test_reprs_say_what_they_hold():
    s = plascap.Section.rectangle(B, H, fy=FY)
    assert "2 part" not in repr(s) and "4 vertices" in repr(s)
    assert repr(s.capacities()).startswith("Capacities(N=2000")
    assert repr(plascap.material("S355")).startswith("Material('S355', fy=3.55e+08")
    assert math.isclose(plascap.material("S355").fy, 355e6)
