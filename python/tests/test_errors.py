"""Bad input raises plascap.InputError, a ValueError, with the message section-calc prints."""
import glob
import os

import pytest

import plascap
from conftest import SOURCE_DIR, section_calc

BAD_FILES = sorted(glob.glob(os.path.join(SOURCE_DIR, "tests", "bad-input", "*.json")))


def test_input_error_is_a_value_error():
    assert issubclass(plascap.InputError, ValueError)


@pytest.mark.parametrize("path", BAD_FILES, ids=os.path.basename)
def test_a_bad_section_file_raises_what_section_calc_prints(path):
    code, _, cli_message = section_calc(path)
    if code == 0:
        pytest.skip("section-calc accepts it as a FILE (it is bad input for another option)")
    assert code == 2
    with pytest.raises(ValueError) as raised:
        plascap.Section.from_file(path)
    assert str(raised.value) == cli_message


def test_an_unknown_shape_names_the_nearest_ones():
    _, _, cli_message = section_calc("--shape", "IPE 999", "--material", "S355")
    with pytest.raises(ValueError) as raised:
        plascap.Section.shape("IPE 999", material="S355")
    assert str(raised.value) == cli_message
    assert "did you mean IPE 100" in cli_message


def test_an_unknown_material_names_the_nearest_ones():
    with pytest.raises(ValueError, match="S355"):
        plascap.Section.shape("IPE 300", material="S356")
    with pytest.raises(ValueError, match="S355"):
        plascap.material("S356")


@pytest.mark.parametrize("call, message", [
    (lambda: plascap.Section.rectangle(0.2, 0.1), "needs material"),
    (lambda: plascap.Section.rectangle(0.2, 0.1, fy=1e5, material="S355"), "not both"),
    (lambda: plascap.Section.rectangle(0.2, 0.1, fy=-1.0), "fy must be"),
    (lambda: plascap.Section.rectangle(0.2, 0.1, fy=1e5).capacities(method="fem"), "'exact' or 'cubature'"),
    (lambda: plascap.Section.rectangle(0.2, 0.1, fy=1e5).capacities(tolerance=1e-6), "method='cubature'"),
    (lambda: plascap.Section.rectangle(0.2, 0.1, fy=1e5).capacities(only="N,Qy"), "Qy"),
    (lambda: plascap.Section.rectangle(0.2, 0.1, fy=1e5, shear="mohr"), "mohr"),
    (lambda: plascap.Section.polygon([(0, 0), (1, 0)], fy=1e5), "part 0, outer ring: has 2 distinct vertices"),
    (lambda: plascap.Section.shape("IPE 300", fy=3.55e8, arc_tolerance=1.0), "1e-12"),
    (lambda: plascap.shapes("XYZ"), "XYZ"),
])
def test_bad_arguments_say_what_is_wrong(call, message):
    with pytest.raises(ValueError, match=message):
        call()
