"""The materials and shape catalogues, as section-calc lists them."""
import json

import plascap
from conftest import section_calc


def test_materials_match_section_calc():
    _, out, _ = section_calc("--list-materials", "--json")
    cli = {m["name"]: m for m in json.loads(out)}
    ours = {m.name: m for m in plascap.materials()}
    assert set(ours) == set(cli)
    for name, m in ours.items():
        assert m.fy == cli[name]["fy"], name
        assert m.E == cli[name].get("E"), name
        assert m.sources == cli[name]["sources"], name


def test_s355_is_en_10025_2():
    s355 = plascap.material("S355")
    assert s355.fy == 355e6 and s355.E == 210e9 and s355.density == 7850
    assert "EN 1993-1-1" in s355.sources["fy"]


def test_shape_catalogue_matches_section_calc():
    _, out, _ = section_calc("--list-shapes", "--json")
    listed = json.loads(out)
    assert plascap.shapes() == [s["designation"] for f in listed["families"] for s in f["shapes"]]
    assert plascap.shape_families() == [f["name"] for f in listed["families"]]
    assert "IPE 300" in plascap.shapes("IPE") and "IPE 300" not in plascap.shapes("HEA")
    assert set(plascap.shape_families()) >= {"IPE", "HEA", "HEB", "CHS"}
