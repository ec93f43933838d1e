"""Every published number in bearinglab.validation (the list `bearinglab validate` runs).

One parametrised case per number; each case carries its source, the printed value and
the reason for its tolerance (see the modules of bearinglab/validation/).
"""

import pytest

from bearinglab.validation import all_cases

CASES = all_cases()


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_published_case(case):
    result = case.run()
    if case.known_failure:  # strict: a known failure that starts passing must be updated
        assert not result.passed, f"{case.id} now passes ({result.computed:.4g}): update it"
        pytest.xfail(case.known_failure)
    assert result.passed, (
        f"{case.id}: published {case.published} {case.unit}, computed "
        f"{result.computed:.6g} ({result.error_percent:+.3f} %, allowed "
        f"{case.rel_tol * 100:.3g} %: {case.tolerance_reason})"
    )


def test_case_list_is_not_trivially_small():
    # seed 001 (6), the kinematic cases of seeds 003/004 (3), CWRU (8) and IMS (4)
    assert len(CASES) >= 76
