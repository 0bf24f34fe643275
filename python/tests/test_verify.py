"""dualhex.verify(), list_checks(), classify(): the checks of `dualhex verify`."""
import pytest

import dualhex


def test_the_registry_is_the_command_lines(cli):
    assert dualhex.list_checks() == cli("verify", "--list")["checks"]


def test_verify_runs_every_check_and_passes(cli):
    r = dualhex.verify()
    names = [c["name"] for c in dualhex.list_checks() if not c["on_request"]]  # the long ones: only when named
    assert [c["name"] for c in r["checks"]] == names
    failing = [(c["name"], c["summary"]) for c in r["checks"] if not c["ok"]]
    assert r["ok"] and not failing and r["failed"] == 0
    assert r["passed"] + r["skipped"] == len(names)
    strong = next(c for c in r["checks"] if c["name"] == "schemes.strong-exhaustive")
    assert strong["details"]["configurations"] == 256 and strong["details"]["passed"] == 256


def test_only_selects_by_substring():
    r = dualhex.verify(only="symmetry")
    assert [c["name"] for c in r["checks"]] == ["symmetry.group"] and r["ok"]
    assert r["checks"][0]["details"]["order"] == 48
    both = dualhex.verify(only=["grid.", "configurations"])
    assert sorted(c["name"] for c in both["checks"]) == ["configurations.classes", "grid.box-complex",
                                                         "grid.sub-box-complex"]


def test_only_matching_nothing_is_a_value_error():
    with pytest.raises(ValueError):
        dualhex.verify(only="no-such-check")


def test_classify_equals_the_command_line_and_the_paper(cli):
    c = dualhex.classify()
    assert (c["classes_full_group"], c["nontrivial_classes"], c["classes_rotations"]) == (22, 20, 23)
    assert c["matches_paper"] and sum(k["size"] for k in c["classes"]) == 256
    assert c == cli("classify")
